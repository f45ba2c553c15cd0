// A double with a certified bound on its error: the pair (v, e) stands for a
// real number x with |x - v| <= e. The polygon kernel's first stage
// (polygon_kernel.hpp) and the systole's tests of its cover (systole.cpp)
// run their formulas on these; a sign is taken only when |v| > e, so it is
// the sign of x.
//
// Why each bound holds, u = 2^-53 the unit roundoff of round-to-nearest:
//   x + y: |x + y - fl(a + b)| <= e_a + e_b + |a + b - fl(a + b)|, and the
//     rounding is <= u |a + b| <= 2^-52 |fl(a + b)| (exact when subnormal);
//   x y: |x y - a b| <= |a| e_b + |b| e_a + e_a e_b, and the rounding of a b
//     is <= 2^-52 |fl(a b)|, or below 2^-1074 when subnormal.
// kTiny (2^-1000) covers every underflow: of the product and of the
// bound's own terms. The bound itself is computed in double with at most
// six roundings in a chain, each losing a factor >= 1 - u; the final factor
// 1 + 2^-50 = 1 + 8u more than makes up for them ((1 - u)^7 (1 + 8u) > 1).
// Overflow gives an infinite or NaN bound, and |v| > e is then false. A fused
// multiply-add, if the compiler contracts one, only drops a rounding that the
// bound already counts.
#pragma once

#include <cmath>

namespace hdt::domain {

struct ErrorDouble {
  double v = 0, e = 0;

  ErrorDouble() = default;
  constexpr explicit ErrorDouble(double exact) : v(exact), e(0) {}
  constexpr ErrorDouble(double value, double error) : v(value), e(error) {}
};

namespace error_double_constants {
constexpr double kRound = 0x1p-52;      // 2 u: the rounding, relative to the rounded result
constexpr double kTiny = 0x1p-1000;     // above any sum of a few underflows
constexpr double kGrow = 1 + 0x1p-50;   // the bound's own roundings
}  // namespace error_double_constants

inline ErrorDouble operator+(const ErrorDouble &a, const ErrorDouble &b) {
  using namespace error_double_constants;
  const double v = a.v + b.v;
  return {v, (a.e + b.e + kRound * std::fabs(v) + kTiny) * kGrow};
}

inline ErrorDouble operator-(const ErrorDouble &a, const ErrorDouble &b) {
  using namespace error_double_constants;
  const double v = a.v - b.v;
  return {v, (a.e + b.e + kRound * std::fabs(v) + kTiny) * kGrow};
}

inline ErrorDouble operator*(const ErrorDouble &a, const ErrorDouble &b) {
  using namespace error_double_constants;
  const double v = a.v * b.v;
  return {v, (std::fabs(a.v) * b.e + std::fabs(b.v) * a.e + a.e * b.e + kRound * std::fabs(v) + kTiny) * kGrow};
}

// +1 or -1 when the bound excludes 0, else 0 (undecided).
inline int certain_sign(const ErrorDouble &x) {
  if (x.v > x.e) return 1;
  if (-x.v > x.e) return -1;
  return 0;
}

}  // namespace hdt::domain
