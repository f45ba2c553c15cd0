// The Voronoi vertex of a face: move one corner to the origin, where the
// hyperbolic circle through it is a Euclidean circle through 0, read off its
// hyperbolic centre on the diameter from 0, and move back. Every step is a
// well-conditioned double formula for the faces of a triangulation (circum-
// diameter < sys/2, so the circle stays away from the unit circle), and
// small faces lose nothing to cancellation: the differences z_k - z_0 are
// formed before anything is squared.
#include "dual/constructions.hpp"

// No fused multiply-add, as in lib/picture: the Voronoi diagram drawn by
// hdt_svg comes from here, and the committed pictures must be the same
// numbers on every machine (GCC contracts by default where FMA exists).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("fp-contract=off")
#endif

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <stdexcept>

#include "predicates/double_double.hpp"
#include "dual/disk_isometry.hpp"
#include "dual/precise_circumcircle.hpp"
#include "mesh/polygon_triangulation.hpp"

namespace hdt::dual {

namespace {

// Forced inline: GCC keeps them as calls otherwise, and these small
// helpers run several times per circumcentre.
#if defined(__GNUC__)
#define HDT_INLINE inline __attribute__((always_inline))
#else
#define HDT_INLINE inline
#endif

// Whether a corner of vertex u is its stored point under the corner's
// translation. A point stored near the unit circle is far from F_g, and
// the long translation t to the face loses about log2(1 / (1 - |z|^2))
// bits in double (every bit for a point 5e-5 from the circle: a corner came
// out at (0.6, 0.8), on it). Up to 1 - |z|^2 = 1/16 (4 bits: the points
// users give in or near F_g, refinement's Steiner points) the stored point
// serves; beyond, face_corner takes its representative (cached, accurate)
// under the short t h^-1, which loses nothing but costs two table look-ups.
HDT_INLINE bool stored_point_serves(const mesh::Vertex &u) { return u.home == 0 || 1 - (u.x * u.x + u.y * u.y) > 0.0625; }

// The corners of face f's canonical copy: most faces lie inside F_g, with
// no translation at all.
template <class Tri>
HDT_INLINE void corners(const Tri &tri, const mesh::Face &f, Point p[3]) {
  const std::vector<mesh::Vertex> &V = tri.vertices();
  for (int i = 0; i < 3; ++i) {
    const mesh::Vertex &u = V[f.v[i]];
    if (!stored_point_serves(u)) p[i] = face_corner(tri, f, i);
    else p[i] = f.t[i] == 0 ? Point{u.x, u.y} : tri.table().moebius(f.t[i]).apply(Point{u.x, u.y});
  }
}

// The vertices of face f + 32, fetched ahead: the loops over the faces
// read their corners' points scattered over the vertices.
template <class Tri>
HDT_INLINE void fetch_ahead(const Tri &tri, std::size_t f) {
  const std::vector<mesh::Face> &F = tri.faces();
  if (f + 32 >= F.size()) return;
  const mesh::Face &A = F[f + 32];
  for (int i = 0; i < 3; ++i) __builtin_prefetch(&tri.vertices()[A.v[i]]);
}

// Whether some corner of f is rounded: translated, a dummy's algebraic
// point, or a representative moved back (stored_point_serves false).
template <class Tri>
HDT_INLINE bool rounded_corners(const Tri &tri, const mesh::Face &f) {
  if ((f.t[0] | f.t[1] | f.t[2]) != 0) return true;
  if (tri.site_of(f.v[0]) >= 0 || tri.site_of(f.v[1]) >= 0 || tri.site_of(f.v[2]) >= 0) return true;
  const std::vector<mesh::Vertex> &V = tri.vertices();
  return !stored_point_serves(V[f.v[0]]) || !stored_point_serves(V[f.v[1]]) || !stored_point_serves(V[f.v[2]]);
}

constexpr double kUnit = 0x1p-53;

// The square of a bound on the error of corner i as corners() computes it
// (p): 0 for a stored point, an ulp for a site's double, and for one double
// Moebius map z -> (a z + b) / den: its numerator and denominator within
// 5u (|a| + |b|) each (parts of a, b within an ulp, three roundings a
// product), the quotient 6u more, so within 16u (|a| + |b|) / |den|, with
// (|a| + |b|)^2 <= 4 |a|^2 and 1 / |den|^2 = (1 - |p|^2) / (1 - |z|^2), the
// map's derivative, which also scales z's own error. Infinite for a
// representative moved back (its relative translation is not at hand).
template <class Tri>
double corner_error2(const Tri &tri, const mesh::Face &f, int i, const Point &p) {
  const mesh::Vertex &u = tri.vertices()[f.v[i]];
  if (!stored_point_serves(u)) return HUGE_VAL;
  const double ez = tri.site_of(f.v[i]) >= 0 ? kUnit : 0;
  if (f.t[i] == 0) return ez * ez;
  const group::Moebius<double> &M = tri.table().moebius(f.t[i]);
  const double derivative = (1 - norm2(p)) / (1 - (u.x * u.x + u.y * u.y));
  return 2 * (1024 * kUnit * kUnit * norm2(M.a) * derivative) + 2 * ez * ez * derivative * derivative;
}

using DD = predicates::DoubleDouble;
struct PointDD {
  DD re, im;
};

template <class R>
DD round_dd(const R &x) {
  const double hi = static_cast<double>(x);
  return DD::fast_two_sum(hi, static_cast<double>(x - R(hi)));
}

// Corner i of f from the exact data in double-double: the stored point (a
// site's 2^-128 coordinates rounded, 2^-105 off) under the corner's
// translation with the table's double-double matrix (parts within
// moebius_error (|a| + |b|) + 2^-105 |part|), every operation within
// 2^-100: within 16 (error + 2^-100) (|a| + |b|) / |den| as above, and
// z's error times the derivative. *error2 receives the square of that.
template <class Tri>
PointDD corner_dd(const Tri &tri, const mesh::Face &f, int i, double *error2) {
  const mesh::Vertex &u = tri.vertices()[f.v[i]];
  PointDD z{DD(u.x), DD(u.y)};
  double ez = 0;
  if constexpr (kMg<Tri>) {  // a polygon surface's vertices are doubles
    if (const int32_t site = tri.site_of(f.v[i]); site >= 0) {
      const surface::Site &s = tri.surface().site(site);
      if (s.has_approximation) z = {round_dd(s.approximation.re), round_dd(s.approximation.im)}, ez = 0x1p-104;
      else ez = kUnit;
    }
  }
  if (f.t[i] == 0) {
    *error2 = ez * ez;
    return z;
  }
  auto &T = tri.table();
  const group::Moebius<double> &hi = T.moebius(f.t[i]), &lo = T.moebius_low(f.t[i]);
  const double me = T.moebius_error(f.t[i]) + 0x1p-100;
  const DD ar = DD::fast_two_sum(hi.a.re, lo.a.re), ai = DD::fast_two_sum(hi.a.im, lo.a.im);
  const DD br = DD::fast_two_sum(hi.b.re, lo.b.re), bi = DD::fast_two_sum(hi.b.im, lo.b.im);
  // num = a z + b, den = conj(b) z + conj(a), the image num conj(den) / |den|^2.
  const DD nr = ar * z.re - ai * z.im + br, ni = ar * z.im + ai * z.re + bi;
  const DD dr = br * z.re + bi * z.im + ar, di = br * z.im - bi * z.re - ai;
  const DD d2 = dr * dr + di * di;
  const PointDD w{(nr * dr + ni * di) / d2, (ni * dr - nr * di) / d2};
  const double derivative = 1 / d2.hi;
  *error2 = 2 * (1024 * me * me * norm2(hi.a) * derivative) + 2 * ez * ez * derivative * derivative;
  return w;
}

// dq x dr = dq x e = dr x e for e = dr - dq: the cross product of the two
// shorter (twice the triangle's area, without the cancellation of the
// longest side against another).
HDT_INLINE double area_cross(const Point &dq, const Point &dr, const Point &e, double mq, double mr, double me) {
  if (mq >= mr && mq >= me) return dr.re * e.im - dr.im * e.re;
  if (mr >= me) return dq.re * e.im - dq.im * e.re;
  return dq.re * dr.im - dq.im * dr.re;
}
HDT_INLINE double area_cross(const Point &dq, const Point &dr, const Point &e) {
  return area_cross(dq, dr, e, norm2(dq), norm2(dr), norm2(e));
}

// The frame's corners and sides from the exact data (face_frame, when the
// a-priori bound fails): in double-double, each side then within 2^-60 of
// itself, or else at 200 bits (two corners within 1e-30 of each other).
template <class Tri>
__attribute__((noinline)) void exact_frame(const Tri &tri, const mesh::Face &f, FaceFrame *frame) {
  PointDD z[3];
  double e2[3];
  for (int i = 0; i < 3; ++i) z[i] = corner_dd(tri, f, i, &e2[i]);
  bool enough = true;
  for (int i = 0; i < 3; ++i) {
    const PointDD &a = z[mesh::next(i)], &b = z[mesh::prev(i)];
    const Point d{static_cast<double>(b.re - a.re), static_cast<double>(b.im - a.im)};
    frame->side[i] = d;
    // (e_a + e_b)^2 <= 2 (e_a^2 + e_b^2) <= 2^-120 |d|^2.
    enough = enough && 2 * (e2[mesh::next(i)] + e2[mesh::prev(i)]) <= 0x1p-120 * norm2(d);
  }
  for (int i = 0; i < 3; ++i) frame->p[i] = {z[i].re.hi, z[i].im.hi};
  if (!enough) precise_frame(tri, f, frame->p, frame->side);
  frame->rounded = false;
}

// The face's frame: sides from the corners in double, unless some corner
// is rounded and the corners' error bounds, twice the largest for a side,
// could move a side, an angle or the circle by more than 2^-46 relative:
// each moves by at most about 4 (side error) / (smallest altitude), the
// altitude |n1 x n2| / (longest side). Most faces have no rounded corner.
template <class Tri>
HDT_INLINE FaceFrame frame_of(const Tri &tri, const mesh::Face &f, const Point p[3]) {
  FaceFrame frame;
  for (int i = 0; i < 3; ++i) {
    frame.p[i] = p[i];
    frame.side[i] = {p[mesh::prev(i)].re - p[mesh::next(i)].re, p[mesh::prev(i)].im - p[mesh::next(i)].im};
  }
  frame.rounded = rounded_corners(tri, f);
  if (!frame.rounded) return frame;
  double e2 = 0, m = 0;
  for (int i = 0; i < 3; ++i) e2 = std::max(e2, corner_error2(tri, f, i, p[i])), m = std::max(m, norm2(frame.side[i]));
  const Point &n1 = frame.side[2], n2{-frame.side[1].re, -frame.side[1].im};  // p1 - p0, p2 - p0
  const double cross = area_cross(n1, n2, frame.side[0]);
  // 4 (2 sqrt(e2)) sqrt(m) <= 2^-46 |cross|.
  if (!(64 * e2 * m <= 0x1p-92 * cross * cross)) exact_frame(tri, f, &frame);
  return frame;
}

// Im and Re of conj(a) b for a = to_origin_scaled(p, q, dq) and
// b = to_origin_scaled(p, r, dr), e = r - q: conj(a) b = X Y with
// X = conj(dq) dr and Y = D_q conj(D_r), D_z = 1 - conj(p) z, whose
// imaginary parts are formed from the sides (Im X by area_cross,
// Im Y = Im(conj(p) e) + |p|^2 Im(q conj(e))), so that a thin angle at p
// and a short side keep their relative accuracy. X is scaled by a power of two where its
// products would underflow (a side of 1e-160 and less).
HDT_INLINE void angle_parts(const Point &p, const Point &q, const Point &r, Point dq, Point dr, Point e,
                            double *cross, double *dot) {
  double mq = norm2(dq), mr = norm2(dr), me = norm2(e);
  if (std::max(mq, mr) < 0x1p-800) {
    const double big = std::max({std::fabs(dq.re), std::fabs(dq.im), std::fabs(dr.re), std::fabs(dr.im)});
    if (big > 0) {
      const int k = -std::ilogb(big);
      dq = {std::scalbn(dq.re, k), std::scalbn(dq.im, k)}, dr = {std::scalbn(dr.re, k), std::scalbn(dr.im, k)};
      e = {std::scalbn(e.re, k), std::scalbn(e.im, k)};
      mq = norm2(dq), mr = norm2(dr), me = norm2(e);
    }
  }
  const double xr = dq.re * dr.re + dq.im * dr.im, xi = area_cross(dq, dr, e, mq, mr, me);
  const double qr = 1 - (p.re * q.re + p.im * q.im), qi = -(p.re * q.im - p.im * q.re);
  const double rr = 1 - (p.re * r.re + p.im * r.im), ri = -(p.re * r.im - p.im * r.re);
  const double yr = qr * rr + qi * ri;
  const double yi = (p.re * e.im - p.im * e.re) + norm2(p) * (q.im * e.re - q.re * e.im);
  *cross = xr * yi + xi * yr;
  *dot = xr * yr - xi * yi;
}

// The radius from s2, the squared Euclidean length of the circle's
// diameter from 0 once a corner is moved to the origin (below).
HDT_INLINE double radius_of(double s2) {
  const double s = std::sqrt(s2);
  // atanh(s) = log1p(2s / (1 - s)) / 2, without atanh's case split.
  return 0.5 * std::log1p(2 * s / (1 - s));
}

// The circumcentre of p0, p1, p2, and its radius when asked (radius may be
// null), from A_1, A_2, |N_1|^2, |N_2|^2, m3 = |p2 - p1|^2 and
// cross = 2 A_1 x A_2 (below); *diameter2 (may be null) receives s2 for
// radius_of. With
// N_k = p_k - p0 and D_k = 1 - conj(p0) p_k, the corners moved
// to the origin are w_k = A_k / |D_k|^2, A_k = N_k conj(D_k)
// (to_origin_scaled), and |w_k|^2 = |N_k|^2 / |D_k|^2: the Euclidean centre
// c of 0, w1, w2 (2 c.w_k = |w_k|^2) is then free of the |D_k|^2,
// c = i (|N_1|^2 A_2 - |N_2|^2 A_1) / (2 A_1 x A_2) with the cross product
// A_1 x A_2 = Im(conj(A_1) A_2).
//
// False, nothing written, when double cannot resolve the face: something
// underflows (|N_k|^2 <= 2^-500), or the angle at p0 has sine <= 2^-15
// (the differences are formed first, so the centre's relative error is
// within about 2^-52 / sine otherwise), or, for rounded corners
// (translated, or a dummy's algebraic point: errors of a few ulps, which
// move the circle by about ulp / (edge x sine)), the shortest edge times
// the sine is at most 2^-30 (the Euclidean |p1 - p2| standing for the
// third edge; sine^2 = cross^2 / (4 |A_1|^2 |A_2|^2)), or the circle is no
// circle of the disk.
HDT_INLINE bool centre_from(const Point &p0, const Point &a1, const Point &a2, double m1, double m2, double m3,
                            double cross, bool rounded, Point *centre, double *radius, double *diameter2) {
  const double norms = norm2(a1) * norm2(a2), cross2 = cross * cross;
  if (!(m1 > 0x1p-500 && m2 > 0x1p-500 && cross2 > 0x1p-28 * norms)) return false;
  if (rounded && !(std::min({m1, m2, m3}) * cross2 > 0x1p-58 * norms)) return false;
  const double inv = 1 / cross;
  const double cr = (m1 * a2.im - m2 * a1.im) * inv, ci = (m2 * a1.re - m1 * a2.re) * inv;
  // The circle's diameter from 0 ends at 2c, Euclidean length s < 1,
  // hyperbolic length 2 atanh(s); the hyperbolic centre is its midpoint, at
  // Euclidean distance tanh(atanh(s) / 2) = s / (1 + sqrt(1 - s^2)). (s is
  // at most tanh(sys/4) < 0.9, so 1 - s^2 loses nothing.)
  const double s2 = 4 * (cr * cr + ci * ci);
  if (!(s2 < 1)) return false;
  const double k = 2 / (1 + std::sqrt(1 - s2));
  if (radius) *radius = radius_of(s2);
  if (diameter2) *diameter2 = s2;
  *centre = from_origin(p0, Point{k * cr, k * ci});
  return true;
}

// From the frame: the sides as the frame has them (accurate), the cross
// product from the sides (angle_parts), which keeps a thin angle's
// relative accuracy.
HDT_INLINE bool centre_of(const FaceFrame &frame, Point *centre, double *radius, double *diameter2 = nullptr) {
  const Point &p0 = frame.p[0], &p1 = frame.p[1], &p2 = frame.p[2];
  const Point n1 = frame.side[2], n2{-frame.side[1].re, -frame.side[1].im}, &e = frame.side[0];
  double cross, dot;
  angle_parts(p0, p1, p2, n1, n2, e, &cross, &dot);
  return centre_from(p0, to_origin_scaled(p0, p1, n1), to_origin_scaled(p0, p2, n2), norm2(n1), norm2(n2), norm2(e),
                     2 * cross, frame.rounded, centre, radius, diameter2);
}

// From the corners alone, the sides and the cross product in double as
// they come: refinement's circles, which refine no face thin or short
// enough for the frame to matter (refine.hpp's resolution): the frame's
// work would be paid for every new face of a refinement for nothing.
HDT_INLINE bool centre_of_corners(const Point p[3], bool rounded, Point *centre, double *radius) {
  const Point a1 = to_origin_scaled(p[0], p[1]), a2 = to_origin_scaled(p[0], p[2]);
  const Point n1{p[1].re - p[0].re, p[1].im - p[0].im}, n2{p[2].re - p[0].re, p[2].im - p[0].im};
  const Point e{p[2].re - p[1].re, p[2].im - p[1].im};
  return centre_from(p[0], a1, a2, norm2(n1), norm2(n2), rounded ? norm2(e) : 0, 2 * (a1.re * a2.im - a1.im * a2.re),
                     rounded, centre, radius, nullptr);
}

// The multiprecision circle, for the rare faces double cannot resolve
// (centre_of false); the radius into *radius when not null.
template <class Tri>
Point precise_centre(const Tri &tri, const mesh::Face &f, double *radius) {
  const Circle precise = precise_circumcircle(tri, f);
  if (radius) *radius = precise.radius;
  return precise.centre;
}

// centre_of, or the fallback.
template <class Tri>
HDT_INLINE Point face_centre(const Tri &tri, const mesh::Face &f, const Point p[3], double *radius) {
  Point c;
  if (centre_of(frame_of(tri, f, p), &c, radius)) return c;
  return precise_centre(tri, f, radius);
}

// The same, for the centre cache: *kept is the radius when asked (or from
// the fallback, which computes it anyway), else -s2, from which
// CentreCache::radius_held computes the same radius later, a logarithm
// without the rest.
template <class Tri>
HDT_INLINE Point face_centre_kept(const Tri &tri, const mesh::Face &f, const Point p[3], bool radius,
                                  double *kept) {
  Point c;
  double s2 = 0;
  if (centre_of(frame_of(tri, f, p), &c, radius ? kept : nullptr, &s2)) {
    if (!radius) *kept = -s2;
    return c;
  }
  return precise_centre(tri, f, kept);
}

// A side whose squares underflow: 2 asinh(|d| / sqrt(wp wq)) directly.
__attribute__((noinline)) double tiny_length(const Point &d, double wp, double wq) {
  return 2 * std::asinh(std::hypot(d.re, d.im) / std::sqrt(wp * wq));
}

// 2 asinh(x) = log1p(2 x^2 + 2 x sqrt(1 + x^2)) for x = |d| / sqrt(wp wq),
// d = q - p: one square root and one logarithm.
HDT_INLINE double length_of(const Point &d, double wp, double wq) {
  const double m = d.re * d.re + d.im * d.im;
  if (!(m >= 0x1p-960)) return tiny_length(d, wp, wq);
  const double x2 = m / (wp * wq);
  return std::log1p(2 * (x2 + std::sqrt(x2 * (1 + x2))));
}

}  // namespace

template <class Tri>
Point face_corner(const Tri &tri, const mesh::Face &f, int i) {
  const mesh::Vertex &u = tri.vertices()[f.v[i]];
  if (stored_point_serves(u))
    return f.t[i] == 0 ? Point{u.x, u.y} : tri.table().moebius(f.t[i]).apply(Point{u.x, u.y});
  auto &T = tri.table();
  const mesh::TranslationId relative = T.compose(f.t[i], T.inverse(u.home));
  double x, y;
  tri.vertex_point(f.v[i], &x, &y);
  return relative == 0 ? Point{x, y} : T.moebius(relative).apply(Point{x, y});
}

template <class Tri>
FaceFrame face_frame(const Tri &tri, const mesh::Face &f, const Point p[3]) { return frame_of(tri, f, p); }

template <class Tri>
Circle circumcircle(const Tri &tri, const mesh::Face &f, const Point p[3]) {
  Circle c;
  c.centre = face_centre(tri, f, p, &c.radius);
  return c;
}

template <class Tri>
Circle circumcircle(const Tri &tri, const mesh::Face &f, const FaceFrame &frame) {
  Circle c;
  if (centre_of(frame, &c.centre, &c.radius)) return c;
  c.centre = precise_centre(tri, f, &c.radius);
  return c;
}

template <class Tri>
Circle coarse_circumcircle(const Tri &tri, const mesh::Face &f, const Point p[3]) {
  Circle c;
  if (centre_of_corners(p, rounded_corners(tri, f), &c.centre, &c.radius)) return c;
  c.centre = precise_centre(tri, f, &c.radius);
  return c;
}

double distance(const Point &p, const Point &q) {
  return length_of(Point{q.re - p.re, q.im - p.im}, 1 - (p.re * p.re + p.im * p.im), 1 - (q.re * q.re + q.im * q.im));
}

double side_length(const Point &d, double wp, double wq) { return length_of(d, wp, wq); }

double corner_angle(const FaceFrame &frame, int i) {
  const int j = mesh::next(i), k = mesh::prev(i);
  // q - p = side[k], r - p = -side[j], r - q = side[i].
  const Point dq = frame.side[k], dr{-frame.side[j].re, -frame.side[j].im};
  double cross, dot;
  angle_parts(frame.p[i], frame.p[j], frame.p[k], dq, dr, frame.side[i], &cross, &dot);
  return std::atan2(std::fabs(cross), dot);
}

template <class Tri>
Point translate(const Tri &tri, group::TranslationId h, const Point &p) {
  if (h == 0) return p;
  return tri.table().moebius(h).apply(p);
}

template <class Tri>
void warm_corner_matrices(const Tri &tri, bool across) {
  auto &T = tri.table();
  for (const mesh::Face &f : tri.faces()) {
    if ((f.t[0] | f.t[1] | f.t[2]) != 0)
      for (int i = 0; i < 3; ++i)
        if (f.t[i] != 0) T.moebius(f.t[i]);
    if (across && (f.nt[0] | f.nt[1] | f.nt[2]) != 0)
      for (int i = 0; i < 3; ++i)
        if (f.nt[i] != 0) T.moebius(f.nt[i]);
  }
}

template <class Tri>
void face_points(const Tri &tri, double *xy) {
  const std::vector<mesh::Face> &F = tri.faces();
  for (std::size_t f = 0; f < F.size(); ++f) {
    fetch_ahead(tri, f);
    Point p[3];
    corners(tri, F[f], p);
    for (int i = 0; i < 3; ++i) xy[6 * f + 2 * i] = p[i].re, xy[6 * f + 2 * i + 1] = p[i].im;
  }
}

namespace {

// Face f's centre (and radius into *radius, which may be null), through the
// cache when there is one.
template <class Tri>
HDT_INLINE Point cached_centre(const Tri &tri, uint32_t f, double *radius, CentreCache *cache) {
  if (cache && cache->holds(tri, f)) return cache->centre_held(f, radius);
  // Computed here, inline; the radius (a logarithm) only when asked.
  const mesh::Face &A = tri.faces()[f];
  Point p[3];
  double kept;
  corners(tri, A, p);
  const Point c = face_centre_kept(tri, A, p, radius != nullptr, &kept);
  if (radius) *radius = kept;
  if (cache) cache->store(tri, f, c, kept);
  return c;
}

}  // namespace

template <class Tri>
void voronoi_vertices(const Tri &tri, double *xy, double *radii, CentreCache *cache) {
  const std::size_t F = tri.faces().size();
  if (!cache) {  // the loop without the cache's tests, which a call without a cache need not pay
    for (std::size_t f = 0; f < F; ++f) {
      fetch_ahead(tri, f);
      const mesh::Face &A = tri.faces()[f];
      Point p[3];
      corners(tri, A, p);
      const Point c = face_centre(tri, A, p, radii ? radii + f : nullptr);
      if (xy) xy[2 * f] = c.re, xy[2 * f + 1] = c.im;
    }
    return;
  }
  for (std::size_t f = 0; f < F; ++f) {
    const Point c = cached_centre(tri, uint32_t(f), radii ? radii + f : nullptr, cache);
    if (xy) xy[2 * f] = c.re, xy[2 * f + 1] = c.im;
  }
}

template <class Tri>
void face_centres(const Tri &tri, Point *out, CentreCache *cache, bool across) {
  face_centres(tri, out, cache, across, 0, tri.faces().size());
}

template <class Tri>
void face_centres(const Tri &tri, Point *out, CentreCache *cache, bool across, std::size_t begin,
                  std::size_t end) {
  auto &T = tri.table();
  const auto warm = [&](const mesh::Face &A) {
    if (across && (A.nt[0] | A.nt[1] | A.nt[2]) != 0)
      for (int i = 0; i < 3; ++i)
        if (A.nt[i] != 0) T.moebius(A.nt[i]);
  };
  if (!cache) {
    for (std::size_t f = begin; f < end; ++f) {
      fetch_ahead(tri, f);
      const mesh::Face &A = tri.faces()[f];
      warm(A);
      Point p[3];
      corners(tri, A, p);
      out[f] = face_centre(tri, A, p, nullptr);
    }
    return;
  }
  for (std::size_t f = begin; f < end; ++f) {
    warm(tri.faces()[f]);
    const Point c = cached_centre(tri, uint32_t(f), nullptr, cache);
    if (out) out[f] = c;
  }
}

template <class Tri>
void write_edges(const Tri &tri, std::size_t count, uint32_t *vertices, uint32_t *faces, double *lengths) {
  const std::vector<mesh::Face> &F = tri.faces();
  std::size_t k = 0;
  for (uint32_t f = 0; f < F.size(); ++f) {
    const mesh::Face &A = F[f];
    // The smaller face of an edge lists it (adjacency.hpp); a face's
    // corners and their factors 1 - |z|^2 serve all the edges it lists.
    fetch_ahead(tri, f);
    if (!(A.n[0] > f || A.n[1] > f || A.n[2] > f)) continue;
    FaceFrame frame;
    double w[3];
    if (lengths) {
      Point p[3];
      corners(tri, A, p);
      frame = frame_of(tri, A, p);
      for (int i = 0; i < 3; ++i) w[i] = 1 - norm2(frame.p[i]);
    }
    for (int i = 0; i < 3; ++i) {
      if (!(A.n[i] > f)) continue;
      if (k == count) throw std::logic_error("write_edges: more edges than 3F/2");
      const int a = mesh::next(i), b = mesh::prev(i);
      if (vertices) vertices[2 * k] = A.v[a], vertices[2 * k + 1] = A.v[b];
      if (faces) faces[2 * k] = f, faces[2 * k + 1] = A.n[i];
      if (lengths) lengths[k] = length_of(frame.side[i], w[a], w[b]);
      ++k;
    }
  }
  if (k != count) throw std::logic_error("write_edges: fewer edges than 3F/2");
}

template <class Tri>
void CentreCache::reserve(const Tri &tri) {
  // A never-used entry names vertex kNone, which no face holds.
  const std::size_t n = tri.faces().size();
  if (keys_.size() < n) {
    centres_.resize(n);
    radii_.resize(n, std::numeric_limits<double>::quiet_NaN());
    keys_.resize(n, Key{{mesh::kNone, mesh::kNone, mesh::kNone}, {}});  // last: ready() only once all three fit
  }
}

template <class Tri>
Point CentreCache::compute(const Tri &tri, uint32_t f, double *radius) {
  const mesh::Face &F = tri.faces()[f];
  Point p[3];
  corners(tri, F, p);
  // The radius only when asked: a Voronoi cell needs none, and its
  // logarithm is a third of a circumcentre's cost. (The centre's bits do
  // not depend on it.)
  double kept;
  const Point c = face_centre_kept(tri, F, p, radius != nullptr, &kept);
  store(tri, f, c, kept);
  if (radius) *radius = kept;
  return c;
}

double CentreCache::radius_held(uint32_t f) {
  double &r = radii_[f];
  if (r < 0) r = radius_of(-r);
  return r;
}

#undef HDT_INLINE

// Both kinds of triangulation: M_g's and a polygon surface's.
#define HDT_DUAL_INSTANTIATE(Tri) \
  template Point face_corner(const Tri &, const mesh::Face &, int);                                        \
  template FaceFrame face_frame(const Tri &, const mesh::Face &, const Point[3]);                         \
  template Circle circumcircle(const Tri &, const mesh::Face &, const Point[3]);                          \
  template Circle circumcircle(const Tri &, const mesh::Face &, const FaceFrame &);                       \
  template Circle coarse_circumcircle(const Tri &, const mesh::Face &, const Point[3]);                   \
  template Point translate(const Tri &, group::TranslationId, const Point &);                              \
  template void warm_corner_matrices(const Tri &, bool);                                                  \
  template void face_points(const Tri &, double *);                                                       \
  template void voronoi_vertices(const Tri &, double *, double *, CentreCache *);                         \
  template void face_centres(const Tri &, Point *, CentreCache *, bool);                                  \
  template void face_centres(const Tri &, Point *, CentreCache *, bool, std::size_t, std::size_t);        \
  template void write_edges(const Tri &, std::size_t, uint32_t *, uint32_t *, double *);                  \
  template void CentreCache::reserve(const Tri &);                                                        \
  template Point CentreCache::compute(const Tri &, uint32_t, double *);
HDT_DUAL_INSTANTIATE(mesh::Triangulation)
HDT_DUAL_INSTANTIATE(mesh::PolygonTriangulation)
#undef HDT_DUAL_INSTANTIATE

}  // namespace hdt::dual
