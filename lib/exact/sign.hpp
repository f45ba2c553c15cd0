// A sign, or `undecided` when an evaluation's error bound does not separate
// the value from zero (or the evaluation does not apply): what Field::sign
// returns (always decided) and what each stage of the predicate pipeline
// returns (predicates/kernel.cpp runs the stages until one decides; the
// exact stages always do).
#pragma once

#include <cstdint>

namespace hdt::exact {

enum class Sign : int8_t { negative = -1, zero = 0, positive = 1, undecided = 2 };

constexpr bool decided(Sign s) { return s != Sign::undecided; }
// -1, 0, +1 of a decided sign.
constexpr int to_int(Sign s) { return int(s); }
constexpr Sign sign_of_int(int v) { return v > 0 ? Sign::positive : v < 0 ? Sign::negative : Sign::zero; }
// The sign of -x; undecided stays undecided.
constexpr Sign operator-(Sign s) { return decided(s) ? Sign(-int(s)) : s; }

// +1 or -1 when |value| exceeds bound, otherwise undecided (a floating-point
// evaluation never decides a zero).
template <class Real>
constexpr Sign sign_beyond(const Real &value, double bound) {
  return value > bound ? Sign::positive : value < -bound ? Sign::negative : Sign::undecided;
}

}  // namespace hdt::exact
