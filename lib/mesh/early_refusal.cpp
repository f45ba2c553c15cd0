#include "mesh/early_refusal.hpp"

#include <cmath>
#include <optional>

#include "predicates/filtered_point.hpp"

namespace hdt::mesh {

using predicates::Kernel;
using predicates::TranslatedPoint;

namespace {

using Vec3 = std::array<double, 3>;

double minkowski(const Vec3 &a, const Vec3 &b) { return a[0] * b[0] - a[1] * b[1] - a[2] * b[2]; }

// Whether d(x, p) >= the distance whose cosh is `cosh_limit` for every
// vertex p of the polygon, certified: cosh d = <N_x, N_p> (Minkowski form),
// less the error that the lifts' errors and the roundings (3 products, 2
// sums: 4u of the terms) can make.
bool far_from_all(const Vec3 &x, double ex, const std::vector<HoleVertex> &polygon, double cosh_limit) {
  for (const HoleVertex &h : polygon) {
    const Vec3 &p = h.lift;
    const double ep = h.lift_error;
    double bound = 0;
    for (int i = 0; i < 3; ++i)
      bound += std::abs(x[i]) * ep + std::abs(p[i]) * ex + ex * ep + 4 * predicates::kUnit * std::abs(x[i] * p[i]);
    if (!(minkowski(x, p) - 1.01 * bound >= cosh_limit)) return false;  // also for an infinite error
  }
  return true;
}

// The vertex of the polygon nearest to x, in double: its index and cosh d.
std::pair<std::size_t, double> nearest(const Vec3 &x, const std::vector<HoleVertex> &polygon) {
  std::size_t best = 0;
  double c = INFINITY;
  for (std::size_t i = 0; i < polygon.size(); ++i)
    if (const double ci = minkowski(x, polygon[i].lift); ci < c) c = ci, best = i;
  return {best, c};
}

// x moved by distance s along the geodesic from p through x (away from p).
Vec3 away(const Vec3 &x, const Vec3 &p, double s) {
  const double c = minkowski(x, p), norm = std::sqrt(std::max(c * c - 1, 1e-300));
  const double a = std::cosh(s), b = std::sinh(s) / norm;
  return {a * x[0] + b * (c * x[0] - p[0]), a * x[1] + b * (c * x[1] - p[1]), a * x[2] + b * (c * x[2] - p[2])};
}

// Whether the disk point x (its own frame: the hole's) lies in the closed
// star triangle (removed, p_i, p_i+1) of some i, certified; false also when
// only the exact stage could tell (x was moved along the line from a link
// vertex through the removed one: near-degenerate by construction, and the
// exact stage's matrices over K_g, dense at large genus, would cost far more
// than the removal they might spare).
// The star-shaped polygon is the union of those triangles.
bool in_hole(Kernel &kernel, const std::vector<HoleVertex> &polygon, const HoleVertex &removed,
             const TranslatedPoint &x, const Vec3 &lift) {
  auto det = [](const Vec3 &a, const Vec3 &b, const Vec3 &c) {
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  };
  const std::size_t k = polygon.size();
  for (std::size_t i = 0; i < k; ++i) {
    const HoleVertex &p = polygon[i], &q = polygon[(i + 1) % k];
    // The double orientations (det of the lifts) pick the triangle; the
    // kernel decides.
    if (det(removed.lift, p.lift, lift) < 0 || det(removed.lift, q.lift, lift) > 0) continue;
    auto inside = [&](const HoleVertex &a, const HoleVertex &b) {
      const std::optional<int> s = kernel.orientation_before_exact(a.point, b.point, x);
      return s && *s >= 0;
    };
    return inside(removed, p) && inside(p, q) && inside(q, removed);
  }
  return false;
}

}  // namespace

bool refusal_is_certain(Kernel &kernel, const std::vector<HoleVertex> &polygon, const HoleVertex &removed) {
  // cosh(sys/4), rounded up (cos, sqrt and the sum err by a few ulps).
  const double limit = kernel.surface().quarter_systole_cosh_rounded() * (1 + 1e-14);
  // x = the removed vertex first.
  if (far_from_all(removed.lift, removed.lift_error, polygon, limit)) return true;
  // Otherwise a short ascent of the distance to the nearest vertex, in
  // double, from the removed vertex: a step away from the nearest vertex
  // while that gains, shorter when it does not. Its end, if far enough, is
  // rounded to a disk point and certified. Skipped when the removed vertex
  // is much nearer than sys/4 to the link (the ascent would have far to go).
  Vec3 x = removed.lift;
  auto [j, c] = nearest(x, polygon);
  if (c < std::cosh(std::acosh(limit) / 4)) return false;
  double step = 0.2;
  for (int evaluations = 1; evaluations < 8 && c < limit; ++evaluations) {
    const Vec3 y = away(x, polygon[j].lift, step);
    const auto [jy, cy] = nearest(y, polygon);
    if (cy > c) {
      x = y, j = jy, c = cy, step *= 1.5;
    } else {
      step /= 2;
    }
  }
  if (c < limit) return false;
  const TranslatedPoint point{x[1] / (1 + x[0]), x[2] / (1 + x[0]), 0, -1};
  if (!(point.x * point.x + point.y * point.y < 1)) return false;
  const predicates::FilteredPoint f = predicates::filtered_point(point.x, point.y);
  const Vec3 lift{f.n[0], f.n[1], f.n[2]};
  return far_from_all(lift, f.error, polygon, limit) && in_hole(kernel, polygon, removed, point, lift);
}

}  // namespace hdt::mesh
