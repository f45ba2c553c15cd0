// An independent Delaunay oracle for polygon surfaces: the Delaunay faces of
// the orbit set Gamma{z_0 .. z_{n-1}} of points of a FundamentalPolygon P, by
// brute force over images of the points, one face per orbit of faces. The
// tests of the polygon-surface triangulation compare with it, as
// tests/brute_force.h serves the built-in M_g. It shares no predicate with
// PolygonKernel: images come from the canonical matrices, (z + b)/(c z + d),
// and the tests are the Euclidean determinants of the Poincare-disk points.
//
// Method. (1) The tiles h(P) within 2r of P: breadth-first over the side
// pairings from the identity, each element interned once (ElementTable's
// exact equality), a tile kept unless Arb proves d(c, h c) > R_P + 2r + R_P
// (c the base point, R_P >= max_k d(c, v_k), so P lies in the ball of
// radius R_P about c: hyperbolic balls are convex). Why this finds every
// tile h(P) holding a point q within 2r of a point p of P: the geodesic from
// c to q has length <= R_P + 2r; each tile h' it meets, at x, has
// d(c, h'c) <= d(c, x) + d(x, h'c) <= R_P + 2r + R_P, so it is kept; the
// tiles along the geodesic follow each other across a side, or around a
// vertex x on it, through the tiles at x, which all contain x and so are
// kept too. So the search reaches h through kept tiles.
// (2) For each i, the set S_i of images w = h z_j (other than z_i itself)
// that Arb cannot prove farther than 2r from z_i (tiles first, by
// d(z_i, h c) > 2r + R_P). A face at z_i of circumradius rho <= r has its
// corners, and every point strictly inside its circle, within 2 rho <= 2r
// of z_i: in h(P) for an h of (1), so in S_i.
// (3) Candidates (z_i, a, b), a, b in S_i (so within 2r of z_i, and of each
// other once the radius is proved <= r), counterclockwise; a face when its
// circle is proved a circle of radius <= r (tanh rho = 2R / (1 - |U|^2 + R^2)
// for the Euclidean centre U and radius R) and no point of S_i lies
// strictly inside. Every sign is Arb's (kBallBits) where it decides, else
// exact in K(i); doubles only order the search and sum the areas. A point
// exactly on the circle of an otherwise empty candidate is a degeneracy,
// reported as such. What is kept is a true face: its circle is empty of
// S_i, so by (2) of the whole orbit. A candidate of radius > r is dropped,
// face or not (its circle may hold images not searched); the completeness
// check below says whether all faces were found.
// (4) Each surface face is found three times, once with each corner at the
// identity. Kept: the rotation whose vertex indices (v0, v1, v2) are
// lexicographically least; with all three indices equal, the one whose
// (t1, t2) element ids are least. The lifts found must be three per kept
// face.
// Completeness: with n vertices a triangulation of a genus-g surface has
// 2n + 4(g - 1) faces of total area 4 pi (g - 1) (each pi minus its
// angles). Since every face kept is a true Delaunay face, the count alone
// proves that all were found; the area (in double, 1e-9 relative) is a
// second check. Either failing means r was too small or the points too few
// for a triangulation: the result is a failure, never partial success.
//
// Orientation: three points on a circle inside the disk
// are in the same cyclic order hyperbolically and Euclidean-ly, so the
// Euclidean orientation of the disk points is the hyperbolic one for every
// face kept (a candidate whose circle is not a circle is dropped anyway).
#pragma once

#include <arb.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <map>
#include <memory>
#include <queue>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "domain/ball.hpp"
#include "domain/base_point.hpp"
#include "domain/distance.hpp"
#include "domain/element_table.hpp"
#include "domain/field_lock.hpp"
#include "domain/fundamental_polygon.hpp"
#include "domain/representative.hpp"
#include "random.hpp"

namespace hdt::domain::test {

struct OracleFace {
  std::array<int, 3> v;        // point indices
  std::array<ElementId, 3> t;  // corner i is t[i](z_{v[i]}); t[0] is the identity
  std::array<std::complex<double>, 3> w;  // the corners, rounded (areas, the tests' keys)
};

enum class OracleStatus { complete, degenerate, incomplete };

struct OracleResult {
  OracleStatus status = OracleStatus::incomplete;
  std::string why;  // what failed, for incomplete and degenerate
  std::vector<OracleFace> faces;
  std::unique_ptr<ElementTable> table;  // the ids of faces and tiles
  std::vector<ElementId> tiles;         // the tiles of step (1)
  double area = 0;                      // the faces' total area
  std::size_t lifts = 0, candidates = 0, exact_signs = 0;
};

namespace oracle_detail {

inline ComplexBall apply_ball(const Element &g, const ComplexBall &z) {
  const Moebius &m = g.matrix();
  return (ball_of(m.a) * z + ball_of(m.b)) / (ball_of(m.c) * z + ball_of(m.d));
}

inline const Number &real(const Complex &z) { return z.re; }
inline const Number &imag(const Complex &z) { return z.im; }

inline RealBall cosh_distance_ball(const ComplexBall &a, const ComplexBall &b) {
  const RealBall one(1.0), two(2.0);
  return one + two * norm2(a - b) / ((one - norm2(a)) * (one - norm2(b)));
}

// The sign a ball proves, or 2.
inline int ball_sign(const RealBall &x) { return arb_is_positive(x.get()) ? 1 : arb_is_negative(x.get()) ? -1 : 2; }
inline int exact_sign(const Number &x) { return x > 0 ? 1 : x < 0 ? -1 : 0; }

// Euclidean orientation of three disk points, and the in-circle determinant
// (+ when d is strictly inside the circle of a, b, c counterclockwise), with
// rows relative to the last point. C: ComplexBall or Complex (R: RealBall, Number).
template <class R, class C>
R cross(const C &a, const C &b, const C &c) {
  const C u = b - a, v = c - a;
  return real(u) * imag(v) - imag(u) * real(v);
}
template <class R, class C>
R in_circle_det(const C &a, const C &b, const C &c, const C &d) {
  const C u = a - d, v = b - d, w = c - d;
  const R nu = norm2(u), nv = norm2(v), nw = norm2(w);
  return real(u) * (imag(v) * nw - nv * imag(w)) - imag(u) * (real(v) * nw - nv * real(w)) +
         nu * (real(v) * imag(w) - imag(v) * real(w));
}

}  // namespace oracle_detail

class PolygonBruteForce {
 public:
  // exact_only: every orientation and in-circle sign in K(i), for tests of
  // the exact stage (the radius test stays Arb's).
  PolygonBruteForce(const FundamentalPolygon &P, const std::vector<std::complex<double>> &z, double r,
                    bool exact_only = false)
      : P_(P), z_(z), r_(r), exact_only_(exact_only), lock_(P.field() != nullptr) {
    out_.table = std::make_unique<ElementTable>(P.vertex(0).re);
  }

  OracleResult run() {
    for (const auto &p : z_) exact_z_.push_back(P_.exact_point(p.real(), p.imag()));
    for (const Complex &e : exact_z_) ball_z_.push_back(ball_of(e));
    find_tiles();
    make_images();
    std::vector<OracleFace> lifts;
    for (int i = 0; i < int(z_.size()) && !degenerate_; ++i) faces_at(i, near_images(i), &lifts);
    if (degenerate_) return finish(OracleStatus::degenerate, why_);
    out_.lifts = lifts.size();
    for (const OracleFace &f : lifts)
      if (least_rotation(f)) out_.faces.push_back(f);
    return check_complete();
  }

 private:
  struct Image {
    int tile, j;  // out_.tiles[tile](z_j)
    double dist;  // search order only
  };

  const FundamentalPolygon &P_;
  std::vector<std::complex<double>> z_;
  double r_;
  bool exact_only_;
  FieldLock lock_;
  OracleResult out_;
  std::vector<Complex> exact_z_;
  std::vector<ComplexBall> ball_z_;
  std::vector<ComplexBall> centre_;                    // tile u's image of c
  std::vector<std::vector<ComplexBall>> image_ball_;   // [tile][j]
  std::vector<std::vector<std::complex<double>>> image_double_;
  std::map<std::pair<int, int>, Complex> exact_images_;
  RealBall radius_P_;  // an upper bound on R_P, exact in the ball
  bool degenerate_ = false;
  std::string why_;

  ElementTable &table() { return *out_.table; }

  OracleResult finish(OracleStatus s, std::string why) {
    out_.status = s;
    out_.why = std::move(why);
    if (s != OracleStatus::complete) out_.faces.clear();
    return std::move(out_);
  }

  void find_tiles() {
    const Complex c = base_point(P_);
    const ComplexBall cb = ball_of(c);
    double R = 0;
    for (int k = 0; k < P_.side_count(); ++k) R = std::max(R, acosh(ball_of(cosh_distance(c, P_.vertex(k)))).upper());
    radius_P_ = RealBall(R);
    const RealBall bound = cosh(RealBall(2.0) * radius_P_ + RealBall(2.0) * RealBall(r_));
    std::vector<ElementId> gens;
    for (int k = 0; k < P_.side_count(); ++k) gens.push_back(table().intern(Element(P_.pairing(k))));
    std::unordered_set<ElementId> seen{kIdentityId};
    std::queue<ElementId> queue;
    queue.push(kIdentityId);
    while (!queue.empty()) {
      const ElementId h = queue.front();
      queue.pop();
      const ComplexBall hc = oracle_detail::apply_ball(table().element(h), cb);
      if (certainly_less(bound, oracle_detail::cosh_distance_ball(cb, hc))) continue;
      out_.tiles.push_back(h);
      centre_.push_back(hc);
      for (const ElementId g : gens) {
        const ElementId n = table().compose(h, g);  // the tile across side k of h(P)
        if (seen.insert(n).second) queue.push(n);
      }
    }
  }

  // Every tile's images of the points: balls, and their centres as doubles.
  void make_images() {
    for (const ElementId h : out_.tiles) {
      image_ball_.emplace_back();
      image_double_.emplace_back();
      for (const ComplexBall &zb : ball_z_) {
        const ComplexBall w = oracle_detail::apply_ball(table().element(h), zb);
        image_ball_.back().push_back(w);
        image_double_.back().push_back({real(w).mid(), imag(w).mid()});
      }
    }
  }

  // S_i, nearest first.
  std::vector<Image> near_images(int i) {
    const RealBall tile_bound = cosh(RealBall(2.0) * RealBall(r_) + radius_P_);
    const RealBall point_bound = cosh(RealBall(2.0) * RealBall(r_));
    const ComplexBall &zi = ball_z_[std::size_t(i)];
    std::vector<Image> S;
    for (int u = 0; u < int(out_.tiles.size()); ++u) {
      if (certainly_less(tile_bound, oracle_detail::cosh_distance_ball(zi, centre_[std::size_t(u)]))) continue;
      for (int j = 0; j < int(z_.size()); ++j) {
        if (u == 0 && j == i) continue;
        const RealBall d = oracle_detail::cosh_distance_ball(zi, image_ball_[std::size_t(u)][std::size_t(j)]);
        if (!certainly_less(point_bound, d)) S.push_back({u, j, d.mid()});
      }
    }
    std::sort(S.begin(), S.end(), [](const Image &a, const Image &b) { return a.dist < b.dist; });
    return S;
  }

  const ComplexBall &ball(const Image &w) const { return image_ball_[std::size_t(w.tile)][std::size_t(w.j)]; }
  const Complex &exact(const Image &w) {
    auto it = exact_images_.find({w.tile, w.j});
    if (it == exact_images_.end()) {
      const Element &h = table().element(out_.tiles[std::size_t(w.tile)]);
      it = exact_images_.emplace(std::make_pair(w.tile, w.j), h.apply(exact_z_[std::size_t(w.j)])).first;
    }
    return it->second;
  }

  int orientation(const Image &a, const Image &b, const Image &c) {
    const int s = exact_only_ ? 2 : oracle_detail::ball_sign(oracle_detail::cross<RealBall>(ball(a), ball(b), ball(c)));
    if (s != 2) return s;
    ++out_.exact_signs;
    return oracle_detail::exact_sign(oracle_detail::cross<Number>(exact(a), exact(b), exact(c)));
  }
  int in_circle(const Image &a, const Image &b, const Image &c, const Image &d) {
    const int s = exact_only_ ? 2
                              : oracle_detail::ball_sign(
                                    oracle_detail::in_circle_det<RealBall>(ball(a), ball(b), ball(c), ball(d)));
    if (s != 2) return s;
    ++out_.exact_signs;
    return oracle_detail::exact_sign(oracle_detail::in_circle_det<Number>(exact(a), exact(b), exact(c), exact(d)));
  }

  // Proved: the circle through the three is a circle of hyperbolic radius
  // < r (tanh rho = 2R / (1 - |U|^2 + R^2); for a circle crossing the unit
  // circle the quotient is >= 1 or its denominator <= 0, and one enclosing
  // the disk has no point inside it).
  bool small_circle(const Image &a, const Image &b, const Image &c) const {
    const ComplexBall &p = ball(a), &q = ball(b), &s = ball(c);
    const RealBall D = RealBall(2.0) * oracle_detail::cross<RealBall>(p, q, s);
    const RealBall np = norm2(p), nq = norm2(q), ns = norm2(s);
    const RealBall ux = (np * (imag(q) - imag(s)) + nq * (imag(s) - imag(p)) + ns * (imag(p) - imag(q))) / D;
    const RealBall uy = (np * (real(s) - real(q)) + nq * (real(p) - real(s)) + ns * (real(q) - real(p))) / D;
    const RealBall dx = real(p) - ux, dy = imag(p) - uy;
    const RealBall R2 = dx * dx + dy * dy, U2 = ux * ux + uy * uy;
    RealBall t;
    arb_tanh(t.get(), RealBall(r_).get(), kBallBits);
    return certainly_less(RealBall(2.0) * sqrt(R2), t * (RealBall(1.0) - U2 + R2));
  }

  void faces_at(int i, const std::vector<Image> &S, std::vector<OracleFace> *lifts) {
    const Image zi{0, i, 0};
    for (std::size_t x = 0; x < S.size(); ++x)
      for (std::size_t y = x + 1; y < S.size(); ++y) {
        const int o = orientation(zi, S[x], S[y]);
        if (o == 0) continue;
        const Image &a = o > 0 ? S[x] : S[y], &b = o > 0 ? S[y] : S[x];
        if (!small_circle(zi, a, b)) continue;
        ++out_.candidates;
        if (!empty_circle(zi, a, b, S, x, y)) continue;
        if (degenerate_) return;
        lifts->push_back({{i, a.j, b.j},
                          {kIdentityId, out_.tiles[std::size_t(a.tile)], out_.tiles[std::size_t(b.tile)]},
                          {point(zi), point(a), point(b)}});
      }
  }

  // No point of S strictly inside; a point on the circle sets degenerate_.
  bool empty_circle(const Image &zi, const Image &a, const Image &b, const std::vector<Image> &S, std::size_t x,
                    std::size_t y) {
    bool on_circle = false;
    for (std::size_t k = 0; k < S.size(); ++k) {
      if (k == x || k == y) continue;
      const int s = in_circle(zi, a, b, S[k]);
      if (s > 0) return false;
      on_circle |= s == 0;
    }
    if (on_circle) {
      degenerate_ = true;
      why_ = "cocircular images at point " + std::to_string(zi.j);
    }
    return true;
  }

  // Rule (4) of the header.
  bool least_rotation(const OracleFace &f) {
    const std::array<int, 3> k0 = f.v, k1{f.v[1], f.v[2], f.v[0]}, k2{f.v[2], f.v[0], f.v[1]};
    if (k0 > k1 || k0 > k2) return false;
    if (k0 < k1 && k0 < k2) return true;
    ElementTable &T = table();
    const ElementId i1 = T.inverse(f.t[1]), i2 = T.inverse(f.t[2]);
    const std::pair<ElementId, ElementId> t0{f.t[1], f.t[2]}, t1{T.compose(i1, f.t[2]), i1},
        t2{i2, T.compose(i2, f.t[1])};
    return (k0 < k1 || t0 <= t1) && (k0 < k2 || t0 <= t2);
  }

  std::complex<double> point(const Image &w) const { return image_double_[std::size_t(w.tile)][std::size_t(w.j)]; }

  static double cosh_d(std::complex<double> a, std::complex<double> b) {
    return 1 + 2 * std::norm(a - b) / ((1 - std::norm(a)) * (1 - std::norm(b)));
  }

  // pi minus the angles, each from the law of cosines.
  static double area(const OracleFace &f) {
    const std::array<std::complex<double>, 3> &w = f.w;
    double sum = 0;
    for (int c = 0; c < 3; ++c) {
      const auto &p = w[std::size_t(c)], &q = w[std::size_t((c + 1) % 3)], &s = w[std::size_t((c + 2) % 3)];
      const double cb = cosh_d(p, q), cc = cosh_d(p, s), ca = cosh_d(q, s);
      const double cosine = (cb * cc - ca) / std::sqrt((cb * cb - 1) * (cc * cc - 1));
      sum += std::acos(std::max(-1.0, std::min(1.0, cosine)));
    }
    return M_PI - sum;
  }

  OracleResult check_complete() {
    const int g = P_.genus(), n = int(z_.size());
    for (const OracleFace &f : out_.faces) out_.area += area(f);
    const std::size_t expected = std::size_t(2 * n + 4 * (g - 1));
    const double total = 4 * M_PI * (g - 1);
    if (out_.faces.size() != expected)
      return finish(OracleStatus::incomplete, std::to_string(out_.faces.size()) + " faces, a triangulation has " +
                                                  std::to_string(expected));
    if (out_.lifts != 3 * out_.faces.size())
      return finish(OracleStatus::incomplete, std::to_string(out_.lifts) + " lifts for " +
                                                  std::to_string(out_.faces.size()) + " faces");
    if (std::abs(out_.area - total) > 1e-9 * total)
      return finish(OracleStatus::incomplete, "area " + std::to_string(out_.area));
    return finish(OracleStatus::complete, "");
  }
};

// The oracle: the points z (each in P's fundamental set), the radius bound r.
inline OracleResult polygon_delaunay(const FundamentalPolygon &P, const std::vector<std::complex<double>> &z,
                                     double r, bool exact_only = false) {
  return PolygonBruteForce(P, z, r, exact_only).run();
}

// n random points of P's fundamental set, for the oracle's inputs: uniform
// in the disk of radius `reach`, kept when the double point is in the set
// (its representative is itself, reached with no crossing), so that no
// rounding moves it out of P. (seed: splitmix64's state.)
inline std::vector<std::complex<double>> fundamental_set_points(const FundamentalPolygon &P, int n, double reach,
                                                                uint64_t seed) {
  FieldLock lock(P.field() != nullptr);
  const Reduction reduce(P);
  std::vector<std::complex<double>> z;
  uint64_t s = seed;
  while (int(z.size()) < n) {
    const double x = reach * (2 * uniform01(&s) - 1), y = reach * (2 * uniform01(&s) - 1);
    if (x * x + y * y >= reach * reach) continue;
    const Complex e = P.exact_point(x, y);
    const Representative rep = reduce(e);
    if (rep.crossings == 0 && rep.point == e) z.push_back({x, y});
  }
  return z;
}

// Two points on each vertex's diagonal, a little inside P (hyperbolically
// about 0.3 and 0.8 from the vertex at Euclidean radius 0.93), at random
// radii and angles (symmetric points would be cocircular): uniform points
// of the disk are sparse, hyperbolically, in the corners. Each is checked
// to be in P's fundamental set.
inline std::vector<std::complex<double>> near_vertex_points(const FundamentalPolygon &P, uint64_t seed) {
  FieldLock lock(P.field() != nullptr);
  const Reduction reduce(P);
  std::vector<std::complex<double>> z;
  uint64_t state = seed;
  for (int k = 0; k < P.side_count(); ++k)
    for (const double s0 : {0.985, 0.95}) {
      const double s = s0 + 0.01 * uniform01(&state), turn = 0.002 * (uniform01(&state) - 0.5);
      const std::complex<double> c = P.vertex_double(k) * s * std::polar(1.0, turn);
      const Complex e = P.exact_point(c.real(), c.imag());
      const Representative rep = reduce(e);
      if (rep.crossings != 0 || rep.point != e) throw std::logic_error("near_vertex_points: a point outside P");
      z.push_back(c);
    }
  return z;
}

}  // namespace hdt::domain::test
