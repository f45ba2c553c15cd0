// The full check of every invariant, with exact predicates. It also
// certifies the dummy point set at construction: a triangulation of M_g
// whose faces are counterclockwise, surround each vertex exactly once, are
// locally Delaunay across every edge and have circumdiameter < sys/2 lifts to
// the Delaunay triangulation of the periodic point set, so delta < sys/2.
#include <stdexcept>
#include <string>
#include <vector>

#include "predicates/representative.hpp"
#include "mesh/polygon_triangulation.hpp"
#include "mesh/triangulation.hpp"

namespace hdt::mesh {

namespace {

[[noreturn]] void broken(const std::string &what) { throw std::logic_error("invalid triangulation: " + what); }

std::string face_name(uint32_t f) { return "face " + std::to_string(f); }

// How far ahead the loops below fetch the records they will read. At 10^6
// vertices (120 MB of faces and vertices) each face's vertices and
// neighbours, and each vertex's star, are cache misses that the predicates'
// arithmetic does not hide: the two loops ran at low IPC, memory-bound.
// The face loop reads face f + kAhead's vertices and neighbours in advance;
// the vertex loop reads vertex v + 2 kAhead's stored face, then at v +
// kAhead (that face in cache by then) its vertices and neighbours, which
// hold three of the star's faces and most of its link. (Any distance that
// covers a miss will do; without the fetches the loops wait on memory:
// docs/format.md.)
constexpr uint32_t kAhead = 16;

}  // namespace

template <class Geometry>
void BasicTriangulation<Geometry>::validate() const {
  auto &T = table();
  const std::size_t F = faces_.size();
  std::size_t live = 0, dummies = 0;
  for (uint32_t v = 0; v < vertices_.size(); ++v)
    if (vertices_[v].alive()) ++live, dummies += dummy_[v];
  if (live != live_vertices_ || dummies != dummies_) broken("vertex counts are out of date");
  if (F != 2 * (live + 2 * std::size_t(genus_) - 2))
    broken(std::to_string(F) + " faces for " + std::to_string(live) + " vertices: Euler's formula fails");

  const auto fetch_around = [&](const Face &P) {  // (indices not checked yet: only fetched)
    for (int i = 0; i < 3; ++i) {
      if (P.v[i] < vertices_.size()) __builtin_prefetch(&vertices_[P.v[i]]);
      if (P.n[i] < F) __builtin_prefetch(&faces_[P.n[i]]);
    }
  };
  for (uint32_t f = 0; f < F; ++f) {
    const Face &A = faces_[f];
    if (f + kAhead < F) fetch_around(faces_[f + kAhead]);
    for (int i = 0; i < 3; ++i)
      if (A.v[i] >= vertices_.size() || !vertices_[A.v[i]].alive())
        broken(face_name(f) + " holds a dead vertex");
    if (A.v[0] == A.v[1] || A.v[1] == A.v[2] || A.v[2] == A.v[0]) broken(face_name(f) + " repeats a vertex (a loop)");
    int m = 0;
    for (int i = 1; i < 3; ++i)
      if (A.v[i] < A.v[m]) m = i;
    if (A.t[m] != vertices_[A.v[m]].home) broken(face_name(f) + " is not stored in its canonical copy");
    // The corners once: every predicate below takes them.
    const TranslatedPoint c0 = corner(A, 0), c1 = corner(A, 1), c2 = corner(A, 2);
    if (kernel_->orientation(c0, c1, c2) <= 0)
      broken(face_name(f) + " is not counterclockwise");
    if (kernel_->large_circumdisk(c0, c1, c2) > 0)
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
      // Each edge once, from its smaller face: the perturbed in-circle
      // determinant is alternating (one global perturbation, kernel.hpp),
      // and the neighbour's test, (b, a, d, c) for this (a, b, c, d), is an
      // even permutation of it, so it has the same sign. (A face that is
      // its own neighbour failed as a double edge above.)
      if (A.n[i] < f) continue;
      const TranslatedPoint pd = point(d, T.compose(A.nt[i], B.t[k]));
      if (kernel_->in_circle_perturbed({c0, c1, c2, pd}, {A.v[0], A.v[1], A.v[2], d}) >= 0)
        broken(face_name(f) + " is not locally Delaunay");
    }
  }

  std::size_t corners = 0;
  std::vector<TranslatedPoint> link;  // one allocation for all the vertices
  for (uint32_t v = 0; v < vertices_.size(); ++v) {
    const Vertex &u = vertices_[v];
    if (v + 2 * kAhead < vertices_.size() && vertices_[v + 2 * kAhead].face < F)
      __builtin_prefetch(&faces_[vertices_[v + 2 * kAhead].face]);
    if (v + kAhead < vertices_.size() && vertices_[v + kAhead].face < F) fetch_around(faces_[vertices_[v + kAhead].face]);
    if (!u.alive()) continue;
    if (u.face >= F) broken("vertex " + std::to_string(v) + " points to no face");
    corner_of(faces_[u.face], v);
    // (The sites are v_0 and the m_k, k < 2g, in the half-open domain by its
    // definition; they lie on side lines, where the test is exact and slow.)
    // A vertex at home in F_g (most) takes the double point's test, whose
    // first step is a disk inside F_g: insertion's, and a tenth the cost.
    if (site_of(v) < 0 && !geometry_->is_home(u.x, u.y, u.home))
      broken("vertex " + std::to_string(v) + " is not stored at its representative");
    star(v, &scratch_.star);
    corners += scratch_.star.size();
    // The link: distinct vertices (no double edges), turning once around v.
    link.clear();
    for (std::size_t i = 0; i < scratch_.star.size(); ++i) {
      const Face &A = faces_[scratch_.star[i].face];
      const int a = next(scratch_.star[i].corner);
      for (std::size_t j = 0; j < i; ++j)
        if (faces_[scratch_.star[j].face].v[next(scratch_.star[j].corner)] == A.v[a])
          broken("vertex " + std::to_string(v) + " has a double edge");
      link.push_back(point(A.v[a], T.compose(scratch_.star[i].frame, A.t[a])));
    }
    // The number of turns of the faces around v, counted exactly: each face's
    // angle at v is in (0, pi) (counterclockwise faces, checked above), so a
    // turn passes the direction of link[0] at the step from link[j] to
    // link[j + 1] when link[j] is strictly clockwise of it and link[j + 1] is
    // not. (Summed angles in double were wrong for vertices a few ulps apart
    // near the circle: the tangent directions cancel to nothing.)
    // With o_j = orientation(centre, link[j], link[0]) (o_0 = 0: link[0]
    // twice), the step from j to j + 1 passes when o_j > 0 and o_{j+1} <= 0
    // (orientation(centre, link[0], b) = -o for b = link[j + 1], exactly):
    // one exact orientation per face around v, none on the degenerate
    // triple (which no filter decides: it cost an exact evaluation per
    // vertex).
    const TranslatedPoint centre = corner(faces_[scratch_.star[0].face], scratch_.star[0].corner);
    long winding = 0;
    int o = link.size() > 1 ? kernel_->orientation(centre, link[1], link[0]) : 0;
    for (std::size_t j = 1; j < link.size(); ++j) {
      const int o_next = j + 1 < link.size() ? kernel_->orientation(centre, link[j + 1], link[0]) : 0;
      if (o > 0 && o_next <= 0) ++winding;
      o = o_next;
    }
    if (winding != 1)
      broken("the faces around vertex " + std::to_string(v) + " turn " + std::to_string(winding) + " times");
  }
  if (corners != 3 * F) broken("some face corners are not in their vertex's star");
}


template void Triangulation::validate() const;

template void PolygonTriangulation::validate() const;

}  // namespace hdt::mesh
