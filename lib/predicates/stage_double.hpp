// The double stage: every predicate on certified double points
// (filtered_point.hpp), with error bounds computed along with the value
// (dynamic, unlike the disk stage's static ones). It decides nearly every
// call on points away from the corners of F_g.
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "predicates/filtered_point.hpp"
#include "predicates/sign.hpp"
#include "predicates/stage_disk.hpp"
#include "predicates/translated_point.hpp"
#include "surface/surface.hpp"
#include "surface/systole.hpp"

namespace hdt::predicates {

// The difference a - b of filtered points and its error bound.
struct Difference {
  double d[3];
  double error;
};

inline Difference difference(const FilteredPoint &a, const FilteredPoint &b) {
  Difference r;
  for (int i = 0; i < 3; ++i) r.d[i] = a.n[i] - b.n[i];
  r.error = (a.error + b.error) * (1 + kUnit) + kUnit * max_abs3(r.d) * 1.01;
  return r;
}

class DoubleStage {
 public:
  explicit DoubleStage(surface::Surface &surface)
      : surface_(surface), quarter_systole_cosh2_(surface::quarter_systole_cosh2<double>(surface.genus())) {}

  // The double point of p (cached); a site's rounding error is folded into
  // the error bound. By value: a later call may reuse the slot.
  FilteredPoint point(const TranslatedPoint &p) {
    return cache_.get(p, [this](const TranslatedPoint &q) { return compute_point(q); });
  }
  // The stored point (x, y) got a home image: its cached points go.
  void forget(double x, double y) { cache_.forget(x, y); }

  static Sign orientation(const FilteredPoint &a, const FilteredPoint &b, const FilteredPoint &c) {
    // det[N_p; N_q; N_r] = det[N_p; N_q - N_p; N_r - N_p].
    const Difference db = difference(b, a), dc = difference(c, a);
    const Det3 d = det3_filtered(a.n, a.error, db.d, db.error, dc.d, dc.error);
    return sign_of(d.value, d.bound);
  }
  static Sign in_circle(const FilteredPoint &a, const FilteredPoint &b, const FilteredPoint &c,
                        const FilteredPoint &e) {
    const Difference db = difference(b, a), dc = difference(c, a), de = difference(e, a);
    // det[N 1] = -det[N_q - N_p; N_r - N_p; N_s - N_p].
    const Det3 d = det3_filtered(db.d, db.error, dc.d, dc.error, de.d, de.error);
    return sign_of(-d.value, d.bound);
  }
  // The same two predicates from the points' disk coordinates: the disk
  // stage's determinants (stage_disk.hpp: the hyperbolic in-circle is the
  // Euclidean one, the orientation a lifted 3x3 determinant) with the
  // coordinates' errors added to their bounds. For points near the circle,
  // at hyperboloid height N0 and hyperbolic distance d apart, the disk
  // determinants lose N0 / d of their size to those errors where the
  // hyperboloid's lose N0^3 / d^2 (their differences are N0 d long, their
  // determinant invariant): near the corners of F_g at large genus the
  // difference between deciding in double and in double-double.
  static Sign disk_orientation(const FilteredPoint &a, const FilteredPoint &b, const FilteredPoint &c);
  static Sign disk_in_circle(const FilteredPoint &a, const FilteredPoint &b, const FilteredPoint &c,
                             const FilteredPoint &e);
  Sign beyond_side(const FilteredPoint &a, int side) const {
    const auto &n = surface_.side_normal(side);
    // <N, n> with the Minkowski signs folded into n (n = (1 - Q0, Q1, Q2)).
    const double value = a.n[0] * n[0] + a.n[1] * n[1] + a.n[2] * n[2];
    const double size = std::abs(a.n[0] * n[0]) + std::abs(a.n[1] * n[1]) + std::abs(a.n[2] * n[2]);
    const double norm = std::abs(n[0]) + std::abs(n[1]) + std::abs(n[2]);
    // n is rounded (u per entry, 1 - Q0 one more), the sum rounds 3u.
    return sign_of(value, (8 * kUnit * size + a.error * norm * (1 + 4 * kUnit)) * 1.01);
  }
  static Sign compare_distance(const FilteredPoint &p, const FilteredPoint &a, const FilteredPoint &b) {
    const Difference d = difference(a, b);
    // <N_p, N_a - N_b>; cosh is increasing, so its sign is the answer.
    const double value = p.n[0] * d.d[0] - p.n[1] * d.d[1] - p.n[2] * d.d[2];
    const double size = std::abs(p.n[0] * d.d[0]) + std::abs(p.n[1] * d.d[1]) + std::abs(p.n[2] * d.d[2]);
    return sign_of(value, (3 * (p.error * (max_abs3(d.d) + d.error) + (max_abs3(p.n) + p.error) * d.error) +
                           4 * kUnit * size) * 1.01);
  }
  // positive when the points differ (some coordinate of N_p - N_q is
  // certainly non-zero), else undecided: a floating stage never proves
  // equality.
  static Sign distinct(const FilteredPoint &a, const FilteredPoint &b) {
    for (int i = 0; i < 3; ++i)
      if (std::abs(a.n[i] - b.n[i]) > (a.error + b.error) * (1 + 4 * kUnit) + kUnit * std::abs(a.n[i] - b.n[i]))
        return Sign::positive;
    return Sign::undecided;
  }
  // The refined stages' formula (stage_refined.hpp) with U = u.
  Sign large_circumdisk(const FilteredPoint &a, const FilteredPoint &b, const FilteredPoint &c) const;

 private:
  FilteredPoint compute_point(const TranslatedPoint &p);
  // A stored point with a home image (home_image.hpp) under its translation.
  FilteredPoint image_point(const TranslatedPoint &p, const surface::HomeImage &image);

  surface::Surface &surface_;
  double quarter_systole_cosh2_;  // within 4u of exact (cos rounded, one sum)
  PointCache<FilteredPoint, 10> cache_;  // 57 KiB: see PointCache
};

}  // namespace hdt::predicates
