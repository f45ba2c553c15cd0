// A double with a certified bound on its error: the real number it stands
// for lies in [v - e, v + e]. The systole's walk (systole.cpp) decides most
// of its tests with these, in a few dozen floating-point operations, and
// asks Arb's balls (ball.hpp) only where they cannot decide.
//
// The bound of a sum of products. With round-to-nearest (unit roundoff
// u = 2^-53), a dot product of n terms computed left to right is off by at
// most gamma_n sum |a_i b_i|, gamma_n = n u / (1 - n u) [Higham, Accuracy
// and Stability, 3.1]; the inputs' own errors add sum e_a |b| + |a| e_b +
// e_a e_b. The bound is itself a sum of non-negative terms computed in
// double, each rounding off by a factor within (1 - u, 1 + u); the factor
// 1 + 2^-40 covers the two dozen such roundings (and gamma_3), and the
// absolute 2^-1000 covers underflow of its tiny terms.
#pragma once

#include <cmath>

#include "domain/ball.hpp"

namespace hdt::domain {

struct BoundedDouble {
  double v = 0, e = 0;
};

// The ball's midpoint rounded to double, with |x - v| <= e for every x in it.
inline BoundedDouble bounded(const RealBall &x) {
  const double v = x.mid();
  return {v, std::fmax(x.upper() - v, v - x.lower()) * (1 + 0x1p-40)};
}

constexpr double kDotSlack = 1 + 0x1p-40;
constexpr double kTiny = 0x1p-1000;

// a_0 b_0 + a_1 b_1 + a_2 b_2 with its bound.
inline BoundedDouble dot3(const BoundedDouble a[3], const BoundedDouble b[3]) {
  double v = 0, magnitude = 0, inherited = 0;
  for (int i = 0; i < 3; ++i) {
    v += a[i].v * b[i].v;
    magnitude += std::fabs(a[i].v * b[i].v);
    inherited += a[i].e * (std::fabs(b[i].v) + b[i].e) + std::fabs(a[i].v) * b[i].e;
  }
  return {v, (inherited + 4 * 0x1p-53 * magnitude) * kDotSlack + kTiny};
}

// True only when every number within x's bound exceeds every number within
// y's: v_x - e_x > v_y + e_y, checked so that the roundings of the check
// cannot make it true wrongly (all terms added are non-negative).
inline bool certainly_greater(const BoundedDouble &x, const BoundedDouble &y) {
  const double d = x.v - y.v;  // within a factor (1 +- u) of the exact difference
  return d > 0 && d * (1 - 0x1p-50) > (x.e + y.e) * kDotSlack;
}

}  // namespace hdt::domain
