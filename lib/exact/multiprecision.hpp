// Multiprecision reals for certified and high-precision work.
//
// Precision is a compile-time parameter of the type (decimal digits), so no
// code path depends on a global or thread-local default precision: an MPFR
// value of mp_real<D> always carries D digits, whatever else runs in the
// process.
#pragma once

#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/mpfr.hpp>

namespace hdt::exact {

// The rungs up to 160 digits keep their limbs inside the value (no malloc
// and free per temporary): the matrices of each new translation id are
// products on the 40-digit rung, and at genus 128 they met tens of thousands
// of ids, 3 million GMP allocations in 10^5 insertions. Larger rungs are
// rare and would make every value kilobytes: on the heap.
template <unsigned Digits10>
using mp_real = boost::multiprecision::number<
    boost::multiprecision::mpfr_float_backend<Digits10, (Digits10 <= 160 ? boost::multiprecision::allocate_stack
                                                                          : boost::multiprecision::allocate_dynamic)>,
    boost::multiprecision::et_off>;

// Bits of precision of the rung Digits10.
constexpr unsigned bits_of_digits10(unsigned digits10) {
  // log2(10) < 3.3220, rounded down: a safe lower bound on the bit count.
  return digits10 * 33219u / 10000u;
}

// pi in the type T (double or mp_real<D>).
template <class T>
T pi() {
  return boost::math::constants::pi<T>();
}

}  // namespace hdt::exact
