// The Voronoi vertex of a face: move one corner to the origin, where the
// hyperbolic circle through it is a Euclidean circle through 0, read off its
// hyperbolic centre on the diameter from 0, and move back. Every step is a
// well-conditioned double formula for the faces of a triangulation (circum-
// diameter < sys/2, so the circle stays away from the unit circle), and
// small faces lose nothing to cancellation: the differences z_k - z_0 are
// formed before anything is squared.
#include "triangulation/constructions.hpp"

// No fused multiply-add, as in lib/picture: the Voronoi diagram drawn by
// hdt_svg comes from here, and the committed pictures must be the same
// numbers on every machine (GCC contracts by default where FMA exists).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("fp-contract=off")
#endif

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "triangulation/precise_circumcircle.hpp"

namespace hdt::triangulation {

namespace {

// (z - w) / (1 - conj(w) z): the isometry taking w to 0, applied to z.
Point to_origin(const Point &w, const Point &z) {
  const double nr = z.re - w.re, ni = z.im - w.im;
  const double dr = 1 - (w.re * z.re + w.im * z.im), di = -(w.re * z.im - w.im * z.re);
  const double r = 1 / (dr * dr + di * di);
  return {(nr * dr + ni * di) * r, (ni * dr - nr * di) * r};
}

// (z + w) / (1 + conj(w) z): its inverse.
Point from_origin(const Point &w, const Point &z) {
  const double nr = z.re + w.re, ni = z.im + w.im;
  const double dr = 1 + (w.re * z.re + w.im * z.im), di = w.re * z.im - w.im * z.re;
  const double r = 1 / (dr * dr + di * di);
  return {(nr * dr + ni * di) * r, (ni * dr - nr * di) * r};
}

// 1 - |z|^2, within a few units of 2^-53 absolutely: its relative error
// grows like 1 / (1 - |z|^2), the disk's own conformal factor, which bounds
// the accuracy of any double point there anyway. (No hypot: the points are
// in the unit disk, nothing overflows, and hypot costs more than the rest.)
double one_minus_norm2(const Point &z) { return 1 - (z.re * z.re + z.im * z.im); }

}  // namespace

Point face_corner(const Triangulation &tri, const Face &f, int i) {
  const Vertex &u = tri.vertices()[f.v[i]];
  // A point stored near the unit circle is far from F_g, and the long
  // translation t to the face loses about log2(1 / (1 - |z|^2)) bits in
  // double (every bit for a point 5e-5 from the circle: a corner came out at
  // (0.6, 0.8), on it). Up to 1 - |z|^2 = 1/16 (4 bits, the points users
  // give in or near F_g, and refinement's Steiner points), the stored point
  // is used; beyond, its representative (cached, accurate) under the short
  // t h^-1, which loses nothing but costs two table look-ups.
  if (u.home == 0 || 1 - (u.x * u.x + u.y * u.y) > 0.0625)
    return f.t[i] == 0 ? Point{u.x, u.y} : tri.table().moebius(f.t[i]).apply(Point{u.x, u.y});
  group::TranslationTable &T = tri.table();
  const TranslationId relative = T.compose(f.t[i], T.inverse(u.home));
  double x, y;
  tri.vertex_point(f.v[i], &x, &y);
  return relative == 0 ? Point{x, y} : T.moebius(relative).apply(Point{x, y});
}

bool try_circumcircle(const Point &p0, const Point &p1, const Point &p2, bool rounded, Circle *circle) {
  const Point w1 = to_origin(p0, p1), w2 = to_origin(p0, p2);
  // The Euclidean circle through 0, w1, w2: its centre c has 2 c.w = |w|^2.
  const double n1 = w1.re * w1.re + w1.im * w1.im, n2 = w2.re * w2.re + w2.im * w2.im;
  const double cross = 2 * (w1.re * w2.im - w1.im * w2.re);
  // Resolved in double when nothing underflows (|w| > 2^-250) and the
  // angle at p0 has sine > 2^-15: the differences are formed first, so the
  // centre's relative error is then within about 2^-52 / sin. Corners that
  // are rounded (translated, or a dummy's algebraic point) carry errors of
  // a few ulps, which move the circle by about ulp / (edge x sin): that
  // product must exceed 2^-30 too (a relative error below 2^-20 at worst,
  // and far below on any face not built from nearly coincident points).
  if (!(n1 > 0x1p-500 && n2 > 0x1p-500 && cross * cross > 0x1p-28 * (n1 * n2))) return false;
  if (rounded) {
    const double dr = w1.re - w2.re, di = w1.im - w2.im;
    const double shortest = std::min({n1, n2, dr * dr + di * di}), sine2 = cross * cross / (4 * n1 * n2);
    if (!(shortest * sine2 > 0x1p-60)) return false;
  }
  const Point c{(n1 * w2.im - n2 * w1.im) / cross, (n2 * w1.re - n1 * w2.re) / cross};
  // Its diameter from 0 ends at 2c, Euclidean length s < 1, hyperbolic
  // length 2 atanh(s); the hyperbolic centre is that diameter's midpoint,
  // at Euclidean distance tanh(atanh(s) / 2) = s / (1 + sqrt(1 - s^2)).
  const double s = 2 * std::sqrt(c.re * c.re + c.im * c.im);
  if (!(s < 1)) return false;
  const double k = 2 / (1 + std::sqrt((1 - s) * (1 + s)));
  *circle = {from_origin(p0, Point{k * c.re, k * c.im}), std::atanh(s)};
  return true;
}

Circle circumcircle(const Triangulation &tri, const Face &f, const Point p[3]) {
  bool rounded = false;
  for (int i = 0; i < 3; ++i) rounded |= f.t[i] != 0 || tri.site_of(f.v[i]) >= 0;
  Circle c;
  if (try_circumcircle(p[0], p[1], p[2], rounded, &c)) return c;
  return precise_circumcircle(tri, f);
}

double distance(const Point &p, const Point &q) {
  const double dx = p.re - q.re, dy = p.im - q.im, d = std::sqrt(dx * dx + dy * dy);
  return 2 * std::asinh(d / std::sqrt(one_minus_norm2(p) * one_minus_norm2(q)));
}

Point translate(const Triangulation &tri, group::TranslationId h, const Point &p) {
  if (h == 0) return p;
  return tri.table().moebius(h).apply(p);
}

}  // namespace hdt::triangulation
