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
#include <limits>
#include <new>
#include <stdexcept>

#include "triangulation/disk_isometry.hpp"
#include "triangulation/precise_circumcircle.hpp"

namespace hdt::triangulation {

namespace {

// Forced inline: GCC keeps them as calls otherwise, a tenth of a
// circumcentre's instructions.
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
HDT_INLINE bool stored_point_serves(const Vertex &u) { return u.home == 0 || 1 - (u.x * u.x + u.y * u.y) > 0.0625; }

// The corners of face f's canonical copy: most faces lie inside F_g, with
// no translation at all.
HDT_INLINE void corners(const Triangulation &tri, const Face &f, Point p[3]) {
  const std::vector<Vertex> &V = tri.vertices();
  for (int i = 0; i < 3; ++i) {
    const Vertex &u = V[f.v[i]];
    if (!stored_point_serves(u)) p[i] = face_corner(tri, f, i);
    else p[i] = f.t[i] == 0 ? Point{u.x, u.y} : tri.table().moebius(f.t[i]).apply(Point{u.x, u.y});
  }
}

// The vertices of face f + 32, fetched ahead: the loops over the faces
// read their corners' points scattered over the vertices.
HDT_INLINE void fetch_ahead(const Triangulation &tri, std::size_t f) {
  const std::vector<Face> &F = tri.faces();
  if (f + 32 >= F.size()) return;
  const Face &A = F[f + 32];
  for (int i = 0; i < 3; ++i) __builtin_prefetch(&tri.vertices()[A.v[i]]);
}

// Whether some corner of f is rounded: translated, or a dummy's algebraic point.
HDT_INLINE bool rounded_corners(const Triangulation &tri, const Face &f) {
  if ((f.t[0] | f.t[1] | f.t[2]) != 0) return true;
  return tri.site_of(f.v[0]) >= 0 || tri.site_of(f.v[1]) >= 0 || tri.site_of(f.v[2]) >= 0;
}

// The radius from s2, the squared Euclidean length of the circle's
// diameter from 0 once a corner is moved to the origin (below).
HDT_INLINE double radius_of(double s2) {
  const double s = std::sqrt(s2);
  // atanh(s) = log1p(2s / (1 - s)) / 2, without atanh's case split.
  return 0.5 * std::log1p(2 * s / (1 - s));
}

// The circumcentre of p0, p1, p2, and its radius when asked (radius may be
// null); *diameter2 (may be null) receives s2 for radius_of. With
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
HDT_INLINE bool centre_of(const Point &p0, const Point &p1, const Point &p2, bool rounded, Point *centre,
                          double *radius, double *diameter2 = nullptr) {
  const Point a1 = to_origin_scaled(p0, p1), a2 = to_origin_scaled(p0, p2);
  const double n1r = p1.re - p0.re, n1i = p1.im - p0.im, n2r = p2.re - p0.re, n2i = p2.im - p0.im;
  const double m1 = n1r * n1r + n1i * n1i, m2 = n2r * n2r + n2i * n2i;
  const double cross = 2 * (a1.re * a2.im - a1.im * a2.re);
  const double norms = (a1.re * a1.re + a1.im * a1.im) * (a2.re * a2.re + a2.im * a2.im), cross2 = cross * cross;
  if (!(m1 > 0x1p-500 && m2 > 0x1p-500 && cross2 > 0x1p-28 * norms)) return false;
  if (rounded) {
    const double er = p1.re - p2.re, ei = p1.im - p2.im;
    if (!(std::min({m1, m2, er * er + ei * ei}) * cross2 > 0x1p-58 * norms)) return false;
  }
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

// The multiprecision circle, for the rare faces double cannot resolve
// (centre_of false); the radius into *radius when not null.
Point precise_centre(const Triangulation &tri, const Face &f, double *radius) {
  const Circle precise = precise_circumcircle(tri, f);
  if (radius) *radius = precise.radius;
  return precise.centre;
}

// centre_of, or the fallback.
HDT_INLINE Point face_centre(const Triangulation &tri, const Face &f, const Point p[3], double *radius) {
  Point c;
  if (centre_of(p[0], p[1], p[2], rounded_corners(tri, f), &c, radius)) return c;
  return precise_centre(tri, f, radius);
}

// The same, for the centre cache: *kept is the radius when asked (or from
// the fallback, which computes it anyway), else -s2, from which
// CentreCache::radius_held computes the same radius later, a logarithm
// without the rest.
HDT_INLINE Point face_centre_kept(const Triangulation &tri, const Face &f, const Point p[3], bool radius,
                                  double *kept) {
  Point c;
  double s2 = 0;
  if (centre_of(p[0], p[1], p[2], rounded_corners(tri, f), &c, radius ? kept : nullptr, &s2)) {
    if (!radius) *kept = -s2;
    return c;
  }
  return precise_centre(tri, f, kept);
}

// 2 asinh(x) = log1p(2 x^2 + 2 x sqrt(1 + x^2)) for x^2 = q: one square
// root and one logarithm.
HDT_INLINE double length_of(const Point &p, const Point &q, double wp, double wq) {
  const double dx = p.re - q.re, dy = p.im - q.im;
  const double x2 = (dx * dx + dy * dy) / (wp * wq);
  return std::log1p(2 * (x2 + std::sqrt(x2 * (1 + x2))));
}

}  // namespace

Point face_corner(const Triangulation &tri, const Face &f, int i) {
  const Vertex &u = tri.vertices()[f.v[i]];
  if (stored_point_serves(u))
    return f.t[i] == 0 ? Point{u.x, u.y} : tri.table().moebius(f.t[i]).apply(Point{u.x, u.y});
  group::TranslationTable &T = tri.table();
  const TranslationId relative = T.compose(f.t[i], T.inverse(u.home));
  double x, y;
  tri.vertex_point(f.v[i], &x, &y);
  return relative == 0 ? Point{x, y} : T.moebius(relative).apply(Point{x, y});
}

bool try_circumcircle(const Point &p0, const Point &p1, const Point &p2, bool rounded, Circle *circle) {
  Point c;
  double r;
  if (!centre_of(p0, p1, p2, rounded, &c, &r)) return false;
  *circle = {c, r};
  return true;
}

Circle circumcircle(const Triangulation &tri, const Face &f, const Point p[3]) {
  Circle c;
  c.centre = face_centre(tri, f, p, &c.radius);
  return c;
}

Point circumcentre(const Triangulation &tri, const Face &f, const Point p[3], double *radius) {
  return face_centre(tri, f, p, radius);
}

double distance(const Point &p, const Point &q) {
  return length_of(p, q, 1 - (p.re * p.re + p.im * p.im), 1 - (q.re * q.re + q.im * q.im));
}

Point translate(const Triangulation &tri, group::TranslationId h, const Point &p) {
  if (h == 0) return p;
  return tri.table().moebius(h).apply(p);
}

void warm_corner_matrices(const Triangulation &tri, bool across) {
  group::TranslationTable &T = tri.table();
  for (const Face &f : tri.faces()) {
    if ((f.t[0] | f.t[1] | f.t[2]) != 0)
      for (int i = 0; i < 3; ++i)
        if (f.t[i] != 0) T.moebius(f.t[i]);
    if (across && (f.nt[0] | f.nt[1] | f.nt[2]) != 0)
      for (int i = 0; i < 3; ++i)
        if (f.nt[i] != 0) T.moebius(f.nt[i]);
  }
}

void face_points(const Triangulation &tri, double *xy) {
  const std::vector<Face> &F = tri.faces();
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
HDT_INLINE Point cached_centre(const Triangulation &tri, uint32_t f, double *radius, CentreCache *cache) {
  if (cache && cache->holds(tri, f)) return cache->centre_held(f, radius);
  // Computed here, inline; the radius (a logarithm) only when asked.
  const Face &A = tri.faces()[f];
  Point p[3];
  double kept;
  corners(tri, A, p);
  const Point c = face_centre_kept(tri, A, p, radius != nullptr, &kept);
  if (radius) *radius = kept;
  if (cache) cache->store(tri, f, c, kept);
  return c;
}

}  // namespace

void voronoi_vertices(const Triangulation &tri, double *xy, double *radii, CentreCache *cache) {
  const std::size_t F = tri.faces().size();
  if (!cache) {  // the loop without the cache's tests (they cost 28 instructions a face)
    for (std::size_t f = 0; f < F; ++f) {
      fetch_ahead(tri, f);
      const Face &A = tri.faces()[f];
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

void face_centres(const Triangulation &tri, Point *out, CentreCache *cache, bool across) {
  face_centres(tri, out, cache, across, 0, tri.faces().size());
}

void face_centres(const Triangulation &tri, Point *out, CentreCache *cache, bool across, std::size_t begin,
                  std::size_t end) {
  group::TranslationTable &T = tri.table();
  const auto warm = [&](const Face &A) {
    if (across && (A.nt[0] | A.nt[1] | A.nt[2]) != 0)
      for (int i = 0; i < 3; ++i)
        if (A.nt[i] != 0) T.moebius(A.nt[i]);
  };
  if (!cache) {
    for (std::size_t f = begin; f < end; ++f) {
      fetch_ahead(tri, f);
      const Face &A = tri.faces()[f];
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

void write_edges(const Triangulation &tri, std::size_t count, uint32_t *vertices, uint32_t *faces, double *lengths) {
  const std::vector<Face> &F = tri.faces();
  std::size_t k = 0;
  for (uint32_t f = 0; f < F.size(); ++f) {
    const Face &A = F[f];
    // The smaller face of an edge lists it (adjacency.hpp); a face's
    // corners and their factors 1 - |z|^2 serve all the edges it lists.
    fetch_ahead(tri, f);
    if (!(A.n[0] > f || A.n[1] > f || A.n[2] > f)) continue;
    Point p[3];
    double w[3];
    if (lengths) {
      corners(tri, A, p);
      for (int i = 0; i < 3; ++i) w[i] = 1 - (p[i].re * p[i].re + p[i].im * p[i].im);
    }
    for (int i = 0; i < 3; ++i) {
      if (!(A.n[i] > f)) continue;
      if (k == count) throw std::logic_error("write_edges: more edges than 3F/2");
      const int a = next(i), b = prev(i);
      if (vertices) vertices[2 * k] = A.v[a], vertices[2 * k + 1] = A.v[b];
      if (faces) faces[2 * k] = f, faces[2 * k + 1] = A.n[i];
      if (lengths) lengths[k] = length_of(p[a], p[b], w[a], w[b]);
      ++k;
    }
  }
  if (k != count) throw std::logic_error("write_edges: fewer edges than 3F/2");
}

void CentreCache::reserve(const Triangulation &tri) {
  // A never-used entry names vertex kNone, which no face holds.
  const std::size_t n = tri.faces().size();
  if (keys_.size() < n) {
    centres_.resize(n);
    radii_.resize(n, std::numeric_limits<double>::quiet_NaN());
    keys_.resize(n, Key{{kNone, kNone, kNone}, {}});  // last: ready() only once all three fit
  }
}

Point CentreCache::compute(const Triangulation &tri, uint32_t f, double *radius) {
  const Face &F = tri.faces()[f];
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

}  // namespace hdt::triangulation
