// Face shapes in double. The angle at a corner is read where it is exact to
// compute: with that corner moved to the origin, the geodesics from it are
// diameters, and the hyperbolic angle is the Euclidean one between them
// (the disk model is conformal). The law of cosines would cancel badly on
// small faces.
#include "triangulation/quality.hpp"

// No fused multiply-add, as in constructions.cpp: both compile the inline
// isometries of disk_isometry.hpp, and the copy the linker keeps must not
// depend on which file it came from.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("fp-contract=off")
#endif

#include <algorithm>
#include <cmath>
#include <limits>

#include "triangulation/disk_isometry.hpp"

namespace hdt::triangulation {

namespace {

double angle_at(const Point &p, const Point &q, const Point &r) {
  // The images of q and r with p moved to the origin, times positive
  // factors: only their directions matter.
  Point a = to_origin_scaled(p, q), b = to_origin_scaled(p, r);
  double cross = a.re * b.im - a.im * b.re, dot = a.re * b.re + a.im * b.im;
  if (cross == 0 && dot == 0) {
    // Underflow on a face at the scale of 1e-200 (or corners that round to
    // one point, angle 0): scaled by powers of two, the angle is the same.
    const int ea = std::ilogb(std::max(std::fabs(a.re), std::fabs(a.im)));
    const int eb = std::ilogb(std::max(std::fabs(b.re), std::fabs(b.im)));
    if (ea == FP_ILOGB0 || eb == FP_ILOGB0) return 0;
    a = {std::scalbn(a.re, -ea), std::scalbn(a.im, -ea)}, b = {std::scalbn(b.re, -eb), std::scalbn(b.im, -eb)};
    cross = a.re * b.im - a.im * b.re, dot = a.re * b.re + a.im * b.im;
  }
  return std::atan2(std::fabs(cross), dot);
}

}  // namespace

double shortest_edge(const Point p[3]) {
  // By a monotone function of the length, |p - q|^2 / (w_p w_q) =
  // sinh^2(d / 2), and one asinh (refinement asks this of every new face;
  // three asinh were a tenth of its time).
  double w[3], s = HUGE_VAL;
  for (int i = 0; i < 3; ++i) w[i] = 1 - (p[i].re * p[i].re + p[i].im * p[i].im);
  for (int i = 0; i < 3; ++i) {
    const Point &a = p[i], &b = p[next(i)];
    const double dx = a.re - b.re, dy = a.im - b.im;
    s = std::min(s, (dx * dx + dy * dy) / (w[i] * w[next(i)]));
  }
  return 2 * std::asinh(std::sqrt(s));
}

FaceShape face_shape(const Triangulation &tri, const Face &f) {
  const Point p[3] = {face_corner(tri, f, 0), face_corner(tri, f, 1), face_corner(tri, f, 2)};
  return {circumcircle(tri, f, p), shortest_edge(p)};
}

double smallest_angle(const Triangulation &tri, const Face &f) {
  const Point p[3] = {face_corner(tri, f, 0), face_corner(tri, f, 1), face_corner(tri, f, 2)};
  return std::min({angle_at(p[0], p[1], p[2]), angle_at(p[1], p[2], p[0]), angle_at(p[2], p[0], p[1])});
}

Quality quality(const Triangulation &tri) {
  Quality q{std::numeric_limits<double>::infinity(), 0, 0, std::numeric_limits<double>::infinity()};
  for (const Face &f : tri.faces()) {
    const FaceShape s = face_shape(tri, f);
    q.min_angle = std::min(q.min_angle, smallest_angle(tri, f));
    q.max_ratio = std::max(q.max_ratio, s.circle.radius / s.shortest_edge);
    q.max_radius = std::max(q.max_radius, s.circle.radius);
    // Every edge of the surface is an edge of some face, and the closest
    // pair of vertices is joined by a Delaunay edge.
    q.min_edge = std::min(q.min_edge, s.shortest_edge);
  }
  return q;
}

}  // namespace hdt::triangulation
