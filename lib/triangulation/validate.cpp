// The full check of every invariant, with exact predicates. It also
// certifies the dummy point set at construction: a triangulation of M_g
// whose faces are counterclockwise, surround each vertex exactly once, are
// locally Delaunay across every edge and have circumdiameter < sys/2 lifts to
// the Delaunay triangulation of the periodic point set, so delta < sys/2.
#include <cmath>
#include <stdexcept>
#include <string>

#include "predicates/filtered_point.hpp"
#include "surface/representative.hpp"
#include "triangulation/triangulation.hpp"

namespace hdt::triangulation {

namespace {

[[noreturn]] void broken(const std::string &what) { throw std::logic_error("invalid triangulation: " + what); }

std::string face_name(uint32_t f) { return "face " + std::to_string(f); }

// The number of turns of the closed fan L around P: the sum of the angles
// at P between consecutive points, divided by 2 pi. On the hyperboloid, with
// A' = A - <A, P> P the tangent direction, an angle is atan2(det[P, A, B],
// -<A', B'>). Returns -1 when rounding could reach a quarter turn (tiny
// triangles far from the origin), and the caller counts exactly instead.
long turns_by_angles(const std::array<double, 3> &P, const std::vector<std::array<double, 3>> &L) {
  auto minkowski = [](const std::array<double, 3> &a, const std::array<double, 3> &b) {
    return a[0] * b[0] - a[1] * b[1] - a[2] * b[2];
  };
  auto tangent = [&](const std::array<double, 3> &a) {
    const double c = minkowski(a, P);
    return std::array<double, 3>{a[0] - c * P[0], a[1] - c * P[1], a[2] - c * P[2]};
  };
  auto size = [](const std::array<double, 3> &a) { return std::abs(a[0]) + std::abs(a[1]) + std::abs(a[2]); };
  double sum = 0, error = 0;
  for (std::size_t j = 0; j < L.size(); ++j) {
    const auto &a = L[j], &b = L[(j + 1) % L.size()];
    const auto ta = tangent(a), tb = tangent(b);
    const double na = std::sqrt(std::max(0.0, -minkowski(ta, ta))), nb = std::sqrt(std::max(0.0, -minkowski(tb, tb)));
    // Inputs carry a few ulps of |P| |A| and cancel down to |A'|: a generous
    // bound on the angle's error is that ratio times 1e3 ulps.
    if (!(na > 0 && nb > 0)) return -1;
    error += 1e3 * 0x1p-53 * (size(P) * size(a) / na + size(P) * size(b) / nb) * size(P);
    sum += std::atan2(predicates::det3_value(P.data(), a.data(), b.data()), -minkowski(ta, tb));
  }
  const long turns = std::lround(sum / (2 * M_PI));
  if (!(error < 1) || std::abs(sum - 2 * M_PI * double(turns)) > 1) return -1;
  return turns;
}

}  // namespace

void Triangulation::validate() {
  group::TranslationTable &T = kernel_->table();
  const std::size_t F = faces_.size();
  std::size_t live = 0, dummies = 0;
  for (uint32_t v = 0; v < vertices_.size(); ++v)
    if (vertices_[v].alive()) ++live, dummies += dummy_[v];
  if (live != live_vertices_ || dummies != dummies_) broken("vertex counts are out of date");
  if (F != 2 * (live + 2 * std::size_t(genus_) - 2))
    broken(std::to_string(F) + " faces for " + std::to_string(live) + " vertices: Euler's formula fails");

  for (uint32_t f = 0; f < F; ++f) {
    const Face &A = faces_[f];
    for (int i = 0; i < 3; ++i)
      if (A.v[i] >= vertices_.size() || !vertices_[A.v[i]].alive())
        broken(face_name(f) + " holds a dead vertex");
    if (A.v[0] == A.v[1] || A.v[1] == A.v[2] || A.v[2] == A.v[0]) broken(face_name(f) + " repeats a vertex (a loop)");
    int m = 0;
    for (int i = 1; i < 3; ++i)
      if (A.v[i] < A.v[m]) m = i;
    if (A.t[m] != vertices_[A.v[m]].home) broken(face_name(f) + " is not stored in its canonical copy");
    if (kernel_->orientation(corner(A, 0), corner(A, 1), corner(A, 2)) <= 0)
      broken(face_name(f) + " is not counterclockwise");
    if (kernel_->large_circumdisk(corner(A, 0), corner(A, 1), corner(A, 2)) > 0)
      broken(face_name(f) + " has circumdiameter >= sys/2");
    for (int i = 0; i < 3; ++i) {
      if (A.n[i] >= F) broken(face_name(f) + " has no neighbour across an edge");
      const int k = twin(f, i);
      if (k < 0) broken(face_name(f) + " and its neighbour do not share the edge");
      const Face &B = faces_[A.n[i]];
      if (B.nt[k] != T.inverse(A.nt[i])) broken(face_name(f) + ": neighbour translations disagree");
      if (T.compose(A.nt[i], B.t[prev(k)]) != A.t[next(i)] || T.compose(A.nt[i], B.t[next(k)]) != A.t[prev(i)])
        broken(face_name(f) + ": the copies across an edge do not meet");
      const uint32_t d = B.v[k];
      if (d == A.v[0] || d == A.v[1] || d == A.v[2])
        broken(face_name(f) + ": the vertex across an edge is one of its own (a double edge)");
      const TranslatedPoint pd = point(d, T.compose(A.nt[i], B.t[k]));
      if (kernel_->in_circle_perturbed({corner(A, 0), corner(A, 1), corner(A, 2), pd}, {A.v[0], A.v[1], A.v[2], d}) >= 0)
        broken(face_name(f) + " is not locally Delaunay");
    }
  }

  std::size_t corners = 0;
  for (uint32_t v = 0; v < vertices_.size(); ++v) {
    const Vertex &u = vertices_[v];
    if (!u.alive()) continue;
    if (u.face >= F) broken("vertex " + std::to_string(v) + " points to no face");
    corner_of(faces_[u.face], v);
    // (The sites are v_0 and the m_k, k < 2g, in the half-open domain by its
    // definition; they lie on side lines, where the test is exact and slow.)
    if (site_of(v) < 0 && surface::representative(*kernel_, point(v, u.home)).translation != u.home)
      broken("vertex " + std::to_string(v) + " is not stored at its representative");
    star(v, &star_);
    corners += star_.size();
    // The link: distinct vertices (no double edges), turning once around v.
    std::vector<std::array<double, 3>> link;
    link.reserve(star_.size());
    bool rough = false;  // a lifted point is not accurate to 1e-9: count exactly
    auto lift = [&](const TranslatedPoint &q) {
      bool accurate = false;
      const std::array<double, 3> n = kernel_->hyperboloid(q, &accurate);
      if (!accurate) rough = true;
      return n;
    };
    for (std::size_t i = 0; i < star_.size(); ++i) {
      const Face &A = faces_[star_[i].face];
      const int a = next(star_[i].corner);
      for (std::size_t j = 0; j < i; ++j)
        if (faces_[star_[j].face].v[next(star_[j].corner)] == A.v[a])
          broken("vertex " + std::to_string(v) + " has a double edge");
      link.push_back(lift(point(A.v[a], T.compose(star_[i].frame, A.t[a]))));
    }
    // The angles at v add up to 2 pi times the number of turns of the
    // faces around it. Each angle is positive (counterclockwise faces,
    // checked exactly) and computed to far better than the 1 radian margin
    // used, so rounding the sum is a certified count.
    const Face &first = faces_[star_[0].face];
    const std::array<double, 3> centre_lift = lift(corner(first, star_[0].corner));
    long winding = rough ? -1 : turns_by_angles(centre_lift, link);
    if (winding < 0) {
      // Exactly: count the turns that pass the direction of link[0]; each
      // turn is < pi (counterclockwise faces), so two signs decide.
      std::vector<TranslatedPoint> exact;
      for (const StarFace &s : star_) {
        const Face &A = faces_[s.face];
        exact.push_back(point(A.v[next(s.corner)], T.compose(s.frame, A.t[next(s.corner)])));
      }
      const TranslatedPoint centre = corner(first, star_[0].corner);
      winding = 0;
      for (std::size_t j = 1; j < exact.size(); ++j) {
        const TranslatedPoint &b = j + 1 < exact.size() ? exact[j + 1] : exact[0];
        if (kernel_->orientation(centre, exact[j], exact[0]) > 0 && kernel_->orientation(centre, exact[0], b) >= 0)
          ++winding;
      }
    }
    if (winding != 1)
      broken("the faces around vertex " + std::to_string(v) + " turn " + std::to_string(winding) + " times");
  }
  if (corners != 3 * F) broken("some face corners are not in their vertex's star");
}

}  // namespace hdt::triangulation
