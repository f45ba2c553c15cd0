// Face shapes in double, from the faces' frames (constructions.hpp: sides
// accurate to their own length however short). The angle at a corner is
// read where it is exact to compute: with that corner moved to the origin,
// the geodesics from it are diameters, and the hyperbolic angle is the
// Euclidean one between them (the disk model is conformal). The law of
// cosines would cancel badly on small faces.
#include "dual/quality.hpp"

// No fused multiply-add, as in constructions.cpp: both compile the inline
// isometries of disk_isometry.hpp, and the copy the linker keeps must not
// depend on which file it came from.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("fp-contract=off")
#endif

#include <algorithm>
#include <cmath>
#include <limits>

#include "dual/disk_isometry.hpp"
#include "mesh/polygon_triangulation.hpp"

namespace hdt::dual {


double shortest_edge(const Point p[3]) {
  // By a monotone function of the length, |p - q|^2 / (w_p w_q) =
  // sinh^2(d / 2), and one asinh (refinement asks this of every new face;
  // three asinh were a tenth of its time).
  double w[3], s = HUGE_VAL;
  for (int i = 0; i < 3; ++i) w[i] = 1 - (p[i].re * p[i].re + p[i].im * p[i].im);
  for (int i = 0; i < 3; ++i) {
    const Point &a = p[i], &b = p[mesh::next(i)];
    const double dx = a.re - b.re, dy = a.im - b.im;
    s = std::min(s, (dx * dx + dy * dy) / (w[i] * w[mesh::next(i)]));
  }
  return 2 * std::asinh(std::sqrt(s));
}

namespace {

template <class Tri>
FaceFrame frame(const Tri &tri, const mesh::Face &f) {
  const Point p[3] = {face_corner(tri, f, 0), face_corner(tri, f, 1), face_corner(tri, f, 2)};
  return face_frame(tri, f, p);
}

// The shortest by |d|^2 / (w_p w_q), a monotone function of the length,
// then one logarithm (as shortest_edge).
double shortest_side(const FaceFrame &fr) {
  double w[3], s = HUGE_VAL;
  int k = 0;
  for (int i = 0; i < 3; ++i) w[i] = 1 - (fr.p[i].re * fr.p[i].re + fr.p[i].im * fr.p[i].im);
  for (int i = 0; i < 3; ++i) {
    const Point &d = fr.side[i];
    const double x2 = (d.re * d.re + d.im * d.im) / (w[mesh::next(i)] * w[mesh::prev(i)]);
    if (x2 < s) s = x2, k = i;
  }
  // Squares that underflow compare as 0: the three sides by length then.
  if (!(s > 0x1p-960)) {
    double best = HUGE_VAL;
    for (int i = 0; i < 3; ++i) best = std::min(best, side_length(fr.side[i], w[mesh::next(i)], w[mesh::prev(i)]));
    return best;
  }
  return side_length(fr.side[k], w[mesh::next(k)], w[mesh::prev(k)]);
}

double smallest_angle(const FaceFrame &fr) {
  return std::min({corner_angle(fr, 0), corner_angle(fr, 1), corner_angle(fr, 2)});
}

}  // namespace

template <class Tri>
FaceShape face_shape(const Tri &tri, const mesh::Face &f) {
  const FaceFrame fr = frame(tri, f);
  return {circumcircle(tri, f, fr), shortest_side(fr)};
}

template <class Tri>
double smallest_angle(const Tri &tri, const mesh::Face &f) { return smallest_angle(frame(tri, f)); }

template <class Tri>
Quality quality(const Tri &tri) {
  Quality q{std::numeric_limits<double>::infinity(), 0, 0, std::numeric_limits<double>::infinity()};
  for (const mesh::Face &f : tri.faces()) {
    const FaceFrame fr = frame(tri, f);
    const FaceShape s{circumcircle(tri, f, fr), shortest_side(fr)};
    q.min_angle = std::min(q.min_angle, smallest_angle(fr));
    q.max_ratio = std::max(q.max_ratio, s.circle.radius / s.shortest_edge);
    q.max_radius = std::max(q.max_radius, s.circle.radius);
    // Every edge of the surface is an edge of some face, and the closest
    // pair of vertices is joined by a Delaunay edge.
    q.min_edge = std::min(q.min_edge, s.shortest_edge);
  }
  return q;
}

// Both kinds of triangulation: M_g's and a polygon surface's.
#define HDT_DUAL_INSTANTIATE(Tri) \
  template FaceShape face_shape(const Tri &, const mesh::Face &); \
  template double smallest_angle(const Tri &, const mesh::Face &); \
  template Quality quality(const Tri &);
HDT_DUAL_INSTANTIATE(mesh::Triangulation)
HDT_DUAL_INSTANTIATE(mesh::PolygonTriangulation)
#undef HDT_DUAL_INSTANTIATE

}  // namespace hdt::dual
