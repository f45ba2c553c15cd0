// The precision ladder: how libhdt runs a computation at a precision chosen
// at run time.
//
// A rung is a precision. The compile-time rungs are mp_real<D> for D in
// kRungDigits10, the one table of them; past the top of a ladder come the
// run-time rungs, raw MPFR values of a precision known only at run time,
// each about sqrt 2 times the one below. A ladder is a selection of the
// table (each user climbs the rungs that its cost and error analysis asks
// for), and Ladder<D...> is its one dispatcher:
//
//   Ladder::at(rung, fixed, runtime): fixed(mp_real<D>()) on a compile-time
//     rung (fixed is a generic lambda, compiled once per rung), runtime(bits)
//     on a run-time one; without `runtime`, the top rung stands for those.
//   Ladder::rung_for(bits): the least rung with at least `bits` bits (a
//     run-time one past the top); with_bits(bits, ...) runs at it.
//   Ladder::climb(first, fixed, runtime): rung by rung from `first` until a
//     call returns an engaged std::optional, which climb returns. Without
//     `runtime` it stops at the top (nullopt when nothing decided); with it
//     it goes on for as long as runtime returns nullopt, so runtime must
//     decide (or throw) at some precision.
#pragma once

#include <cmath>
#include <cstddef>
#include <iterator>
#include <optional>
#include <type_traits>
#include <utility>

#include "exact/multiprecision.hpp"

namespace hdt::exact {

// Every compile-time rung any ladder climbs, in decimal digits.
constexpr unsigned kRungDigits10[] = {40, 80, 160, 320, 640, 800, 1280, 2560, 10240, 40960};

// The position of a rung in kRungDigits10 (for per-rung caches), or the
// table's size when it is not one.
constexpr std::size_t rung_index(unsigned digits10) {
  std::size_t i = 0;
  while (i < std::size(kRungDigits10) && kRungDigits10[i] != digits10) ++i;
  return i;
}

// The decimal digits D of T = mp_real<D>, and its bits: what a generic
// lambda run on a rung knows of its rung.
template <class T>
struct RungOf;
template <unsigned D, boost::multiprecision::mpfr_allocation_type A>
struct RungOf<boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<D, A>,
                                            boost::multiprecision::et_off>> {
  static constexpr unsigned digits10 = D;
  static constexpr long bits = long(bits_of_digits10(D));
};

template <unsigned... Digits10>
class Ladder {
 public:
  static_assert(sizeof...(Digits10) > 0, "a ladder has a rung");
  static_assert(((rung_index(Digits10) < std::size(kRungDigits10)) && ...), "a rung of kRungDigits10");

  static constexpr unsigned kDigits10[sizeof...(Digits10)] = {Digits10...};
  // The compile-time rungs are 0 .. kSize - 1, the run-time ones kSize on.
  static constexpr std::size_t kSize = sizeof...(Digits10);

  static constexpr bool is_runtime(std::size_t rung) { return rung >= kSize; }

  // Bits of a rung. Run-time rung kSize - 1 + k has the top's bits times
  // 2^(k/2), a multiple of 64 (MPFR's limbs).
  static long bits(std::size_t rung) {
    if (rung < kSize) return long(bits_of_digits10(kDigits10[rung]));
    const double k = double(rung - kSize + 1);
    return long(std::ceil(double(top_bits()) * std::exp2(0.5 * k) / 64.0) * 64.0);
  }
  static constexpr long top_bits() { return long(bits_of_digits10(kDigits10[kSize - 1])); }

  static std::size_t rung_for(double wanted) {
    std::size_t rung = 0;
    while (double(bits(rung)) < wanted) ++rung;
    return rung;
  }

  template <class Fixed, class Runtime>
  static auto at(std::size_t rung, Fixed &&fixed, Runtime &&runtime) {
    if (is_runtime(rung)) return runtime(bits(rung));
    return at_fixed<0>(rung, fixed);
  }
  template <class Fixed>
  static auto at(std::size_t rung, Fixed &&fixed) {
    return at_fixed<0>(rung < kSize ? rung : kSize - 1, fixed);
  }

  template <class Fixed, class Runtime>
  static auto with_bits(double wanted, Fixed &&fixed, Runtime &&runtime) {
    return at(rung_for(wanted), fixed, runtime);
  }
  template <class Fixed>
  static auto with_bits(double wanted, Fixed &&fixed) {
    return at(rung_for(wanted), fixed);
  }

  template <class Fixed, class Runtime>
  static auto climb(std::size_t first, Fixed &&fixed, Runtime &&runtime) {
    for (std::size_t rung = first;; ++rung)
      if (auto result = at(rung, fixed, runtime)) return result;
  }
  template <class Fixed>
  static auto climb(std::size_t first, Fixed &&fixed) {
    using Result = decltype(fixed(mp_real<kDigits10[0]>()));
    for (std::size_t rung = first; rung < kSize; ++rung)
      if (Result result = at_fixed<0>(rung, fixed)) return result;
    return Result();
  }

 private:
  // fixed(mp_real<kDigits10[rung]>()), by a chain of comparisons the
  // compiler folds into a jump.
  template <std::size_t I, class Fixed>
  static auto at_fixed(std::size_t rung, Fixed &fixed) {
    if constexpr (I + 1 == kSize) {
      return fixed(mp_real<kDigits10[I]>());
    } else {
      if (rung == I) return fixed(mp_real<kDigits10[I]>());
      return at_fixed<I + 1>(rung, fixed);
    }
  }
};

}  // namespace hdt::exact
