// Run a computation at the smallest multiprecision rung that has a given
// number of bits (or the top rung when none has).
//
// with_precision(bits, f) calls f(mp_real<D>()) and returns its result; f is
// a generic lambda, so the computation is compiled once per rung.
#pragma once

#include "exact/multiprecision.hpp"

namespace hdt::exact {

constexpr unsigned kLadderDigits10[] = {40, 160, 640, 2560};

// Bits of the top rung.
constexpr unsigned ladder_top_bits() { return bits_of_digits10(kLadderDigits10[3]); }

template <class F>
auto with_precision(double bits, F &&f) {
  if (bits <= bits_of_digits10(kLadderDigits10[0])) return f(mp_real<kLadderDigits10[0]>());
  if (bits <= bits_of_digits10(kLadderDigits10[1])) return f(mp_real<kLadderDigits10[1]>());
  if (bits <= bits_of_digits10(kLadderDigits10[2])) return f(mp_real<kLadderDigits10[2]>());
  return f(mp_real<kLadderDigits10[3]>());
}

}  // namespace hdt::exact
