// Thinning of the dummy point set (dummy_thinning.hpp).
//
// Every move keeps the invariant: new dummies go in by Bowyer-Watson
// insertion (the invariant holds before it), old ones leave through
// Triangulation::remove, which refuses, with exact predicates on the hole
// alone, a removal that would leave a circle of diameter >= sys/2. A move
// whose removal is refused is undone from a copy of the vertices and faces.
// Where to put the new points is decided in double precision: it only
// chooses what to try.
#include "dummies/dummy_thinning.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "dummies/mesh_names.hpp"
#include "predicates/representative.hpp"
#include "dummies/dummy_relaxation.hpp"
#include "dummies/hyperboloid_vectors.hpp"
#include "mesh/editor.hpp"

namespace hdt::dummies {

namespace {

using hyperboloid::cosh_circumradius;
using hyperboloid::dot;
using Vector = hyperboloid::Vector;

// The disk point of a p + b q + c r normalised: a point of the geodesic
// triangle pqr for non-negative weights.
bool blend(double a, const Vector &p, double b, const Vector &q, double c, const Vector &r, double *x, double *y) {
  const Vector m{a * p[0] + b * q[0] + c * r[0], a * p[1] + b * q[1] + c * r[1], a * p[2] + b * q[2] + c * r[2]};
  const double mm = dot(m, m);
  if (!(mm > 0) || !(m[0] > 0)) return false;
  const double s = 1 / std::sqrt(mm);
  *x = m[1] * s / (1 + m[0] * s), *y = m[2] * s / (1 + m[0] * s);
  return true;
}

// The point p of the disk, searched from (x, y) by compass steps, that
// minimises the largest circle of the fan (p, L_i, L_i+1) over the closed
// polygon L; returns that cosh(radius). A guess at the best new vertex for a
// star-shaped hole (the Delaunay faces need not be the fan's).
double best_fan_point(const std::vector<Vector> &L, double *x, double *y) {
  auto largest = [&](double px, double py) {
    const double w = 1 - px * px - py * py;
    if (!(w > 0)) return double(INFINITY);
    const Vector P{(2 - w) / w, 2 * px / w, 2 * py / w};
    double r = 0;
    for (std::size_t i = 0; i < L.size(); ++i) r = std::max(r, cosh_circumradius(P, L[i], L[(i + 1) % L.size()]));
    return r;
  };
  double f = largest(*x, *y);
  for (double h = 0.25; h > 0.002;) {  // hyperbolic step length
    const double scale = h * (1 - *x * *x - *y * *y) / 2;
    bool moved = false;
    for (int d = 0; d < 8 && !moved; ++d) {
      const double nx = *x + scale * std::cos(d * M_PI / 4), ny = *y + scale * std::sin(d * M_PI / 4);
      const double fn = largest(nx, ny);
      if (fn < f) *x = nx, *y = ny, f = fn, moved = true;
    }
    if (!moved) h /= 2;
  }
  return f;
}

}  // namespace

class DummyThinning {
 public:
  explicit DummyThinning(mesh::Editor &e)
      : e_(e),
        t_(e.triangulation()),
        K_(t_.kernel()),
        T_(t_.table()),
        fixed_(uint32_t(2 * t_.genus() + 2)),
        limit_(t_.surface().quarter_systole_cosh_rounded()) {}

  void run() {
    // Genus 3 and up: the relaxation alone, from the refined set (the
    // rounds below, run first, left it nothing more to find, and cost as
    // much as the relaxation, which grows fast with the genus). Genus 2
    // keeps the 14-point set of the rounds.
    if (t_.genus() >= 3) {
      if (relax()) {
        e_.compact_ids();
        return;
      }
    }
    // Eight rounds at most: later ones gained nothing at genus 2 .. 32.
    for (int round = 0, idle = 0; round < 8 && idle < 2; ++round) {
      const std::size_t before = t_.dummy_count();
      for (uint32_t v = fixed_; v < t_.vertices().size(); ++v)
        if (removable(v)) t_.remove(v);
      if (exhaustive()) merge_triples();
      merge_pairs();
      smooth();
      idle = t_.dummy_count() < before ? 0 : idle + 1;
    }
    e_.compact_ids();
  }

 private:
  // The double-precision relaxation's set (dummy_relaxation.hpp): its new
  // points go in by Bowyer-Watson, then the old dummies it dropped leave
  // through the certified removal; one it still needs stays.
  bool relax() {
    const RelaxedDummies r = relax_dummy_points(t_);
    if (r.removed.empty()) return false;
    for (std::size_t i = 0; i < r.added.size(); ++i) insert_dummy(r.added[i][0], r.added[i][1], r.near[i]);
    for (uint32_t v : r.removed) t_.remove(v);
    return true;
  }

  // Small sets try every merge; larger ones only those the fan estimate
  // finds promising (a try costs an insertion and removals).
  bool exhaustive() const { return t_.dummy_count() < 64; }
  bool removable(uint32_t v) const { return v >= fixed_ && t_.vertices()[v].alive(); }
  Vector at(const Corner &c) { return K_.hyperboloid(t_.point(c.v, c.t)); }

  // Edges between two removable dummies, shortest first (the closest pairs
  // are the most redundant).
  std::vector<std::pair<double, std::array<uint32_t, 2>>> edges() {
    std::vector<std::pair<double, std::array<uint32_t, 2>>> out;
    for (const Face &F : t_.faces())
      for (int i = 0; i < 3; ++i) {
        const int a = next(i), b = prev(i);
        if (F.v[a] < F.v[b] && removable(F.v[a]) && removable(F.v[b]))
          out.push_back({dot(K_.hyperboloid(t_.corner(F, a)), K_.hyperboloid(t_.corner(F, b))), {F.v[a], F.v[b]}});
      }
    std::sort(out.begin(), out.end());
    return out;
  }

  // The link of u, counterclockwise, in the frame base(u's star frame);
  // *self receives u's own corner there.
  void link_of(uint32_t u, TranslationId base, std::vector<Corner> *out, Corner *self) {
    t_.star(u, &star_);
    out->clear();
    for (const StarFace &s : star_) {
      const Face &F = t_.faces()[s.face];
      const int a = next(s.corner);
      out->push_back({F.v[a], T_.compose(base, T_.compose(s.frame, F.t[a]))});
    }
    const Face &F0 = t_.faces()[star_[0].face];
    *self = {u, T_.compose(base, F0.t[star_[0].corner])};
  }

  // The boundary of the union of the stars of the edge uv, counterclockwise
  // in u's star frame; false if it is not the polygon expected.
  bool edge_link(uint32_t u, uint32_t v, std::vector<Corner> *polygon, Corner *cu, Corner *cv) {
    link_of(u, 0, &lu_, cu);
    const auto iv = std::find_if(lu_.begin(), lu_.end(), [&](const Corner &c) { return c.v == v; });
    if (iv == lu_.end()) return false;
    std::rotate(lu_.begin(), iv, lu_.end());
    *cv = lu_[0];
    t_.star(v, &star_);
    const TranslationId own = t_.faces()[star_[0].face].t[star_[0].corner];
    Corner self;
    link_of(v, T_.compose(cv->t, T_.inverse(own)), &lv_, &self);
    const auto iu = std::find_if(lv_.begin(), lv_.end(), [&](const Corner &c) { return c.v == u; });
    if (iu == lv_.end() || iu->t != cu->t) return false;
    std::rotate(lv_.begin(), iu, lv_.end());
    auto same = [](const Corner &a, const Corner &b) { return a.v == b.v && a.t == b.t; };
    if (lu_.size() < 3 || lv_.size() < 3 || !same(lu_.back(), lv_[1]) || !same(lu_[1], lv_.back())) return false;
    polygon->assign(lu_.begin() + 1, lu_.end());
    polygon->insert(polygon->end(), lv_.begin() + 2, lv_.end() - 1);
    return true;
  }

  // Two dummies u, v become one: at the best fan point of their union's
  // boundary when that estimate is below the limit, else (small sets, or
  // estimates within 10%) also at their midpoint.
  void merge_pairs() {
    std::vector<Corner> polygon;
    std::vector<Vector> L;
    for (const auto &e : edges()) {
      const uint32_t u = e.second[0], v = e.second[1];
      Corner cu, cv;
      if (!removable(u) || !removable(v) || !edge_link(u, v, &polygon, &cu, &cv)) continue;
      L.clear();
      for (const Corner &c : polygon) L.push_back(at(c));
      const Vector pu = at(cu), pv = at(cv);
      double mx, my;
      if (!blend(1, pu, 1, pv, 0, pu, &mx, &my)) continue;
      double x = mx, y = my;
      const double estimate = best_fan_point(L, &x, &y);
      const bool midpoint_too = exhaustive() || estimate < limit_ * 1.1;
      if (estimate < limit_ && try_move({{x, y}}, {u, v}, u)) continue;
      if (midpoint_too) try_move({{mx, my}}, {u, v}, u);
    }
  }

  // Three dummies of a face become one, at a weighted centre of it.
  void merge_triples() {
    for (uint32_t f = 0; f < t_.faces().size(); ++f) {
      const Face F = t_.faces()[f];
      if (!removable(F.v[0]) || !removable(F.v[1]) || !removable(F.v[2])) continue;
      const Vector p = K_.hyperboloid(t_.corner(F, 0)), q = K_.hyperboloid(t_.corner(F, 1)),
                  r = K_.hyperboloid(t_.corner(F, 2));
      static const double weights[][3] = {{1, 1, 1}, {2, 1, 1}, {1, 2, 1}, {1, 1, 2}};
      for (const auto &w : weights) {
        double x, y;
        if (blend(w[0], p, w[1], q, w[2], r, &x, &y) && try_move({{x, y}}, {F.v[0], F.v[1], F.v[2]}, F.v[0])) break;
      }
    }
  }

  // Each removable dummy moves to the best fan point of its link, if that
  // makes its largest circle smaller: evenly spread points leave room for
  // merges.
  void smooth() {
    std::vector<Corner> link;
    std::vector<Vector> L;
    const auto end = uint32_t(t_.vertices().size());  // not the moved ones again
    for (uint32_t v = fixed_; v < end; ++v) {
      if (!removable(v)) continue;
      Corner self;
      link_of(v, 0, &link, &self);
      L.clear();
      for (const Corner &c : link) L.push_back(at(c));
      const Vector p = at(self);
      double x = p[1] / (1 + p[0]), y = p[2] / (1 + p[0]);
      const double best = best_fan_point(L, &x, &y), current = [&] {
        double r = 0;
        for (std::size_t i = 0; i < L.size(); ++i) r = std::max(r, cosh_circumradius(p, L[i], L[(i + 1) % L.size()]));
        return r;
      }();
      if (best < current * (1 - 1e-4)) try_move({{x, y}}, {v}, v);
    }
  }

  // Inserts dummies at `points`, then removes `old`; undoes it all unless
  // every step succeeds.
  bool try_move(const std::vector<std::array<double, 2>> &points, const std::vector<uint32_t> &old, uint32_t near) {
    e_.save(&saved_);
    bool ok = true;
    for (const auto &p : points) ok = ok && insert_dummy(p[0], p[1], near);
    for (uint32_t v : old) ok = ok && t_.remove(v);
    if (!ok) e_.roll_back(&saved_);
    return ok;
  }

  // Bowyer-Watson insertion of a new dummy at (x, y), the walk starting
  // around `near`. False when (x, y) is not usable (outside the disk, on a
  // vertex).
  bool insert_dummy(double x, double y, uint32_t near) {
    // A relative nudge of about 2^-20: new points of symmetric moves are
    // symmetric, and symmetric points cocircular (as in the refinement).
    rng_ = rng_ * 6364136223846793005ull + 1442695040888963407ull;
    x *= 1 + double(int64_t(rng_ >> 44) - (1 << 19)) * 0x1p-39;
    y *= 1 + double(int64_t((rng_ >> 24) & 0xFFFFF) - (1 << 19)) * 0x1p-39;
    if (!std::isfinite(x) || !std::isfinite(y) || x * x + y * y >= 1) return false;
    predicates::Representative r = predicates::representative(K_, x, y);
    if (r.translation != 0) {
      // Stored inside F_g where its image in double lands there: such a
      // vertex is its own representative (no multiprecision image later).
      const group::Complex<double> z = T_.moebius(r.translation).apply({x, y});
      if (std::isfinite(z.re) && std::isfinite(z.im) && z.re * z.re + z.im * z.im < 1) {
        const predicates::Representative home = predicates::representative(K_, z.re, z.im);
        if (home.translation == 0) x = z.re, y = z.im, r = home;
      }
    }
    return e_.insert_dummy(x, y, r.translation, near);
  }

  mesh::Editor &e_;
  Triangulation &t_;
  predicates::Kernel &K_;
  group::TranslationTable &T_;
  const uint32_t fixed_;  // vertex 0 and the sites stay
  const double limit_;    // cosh(sys/4)
  mesh::Editor::Checkpoint saved_;
  std::vector<StarFace> star_;
  std::vector<Corner> lu_, lv_;
  uint64_t rng_ = 0x9E3779B97F4A7C15ull;
};

void thin_dummy_points(mesh::Editor &e) { DummyThinning(e).run(); }

}  // namespace hdt::dummies
