// Double-precision matrices of words, accurate to the last bits.
//
// A plain double product of m generators loses about log2 of the product of
// their norms: the relator of genus 32 (128 letters) comes out 1e-9 from the
// identity. These functions multiply at a multiprecision rung chosen from the
// word length and round once at the end.
#pragma once

#include "group/lorentz.hpp"
#include "group/moebius.hpp"
#include "group/presentation.hpp"

namespace hdt::group {

// Bits that rounding errors may lose while m generators are multiplied:
// each Lorentz generator has entries at most 2A^2 - 1 (A = cot(pi/4g)), so
// a product of m of them at most (3(2A^2))^m in any entry.
double word_precision_bits(const Presentation &p, std::size_t m);

// Letters must be valid.
Moebius<double> accurate_moebius(const Presentation &p, const Letter *w, std::size_t length);
Lorentz<double> accurate_lorentz(const Presentation &p, const Letter *w, std::size_t length);
inline Moebius<double> accurate_moebius(const Presentation &p, const Word &w) {
  return accurate_moebius(p, w.data(), w.size());
}
inline Lorentz<double> accurate_lorentz(const Presentation &p, const Word &w) {
  return accurate_lorentz(p, w.data(), w.size());
}

// Bits for the Moebius product of m letters from which
// Lorentz<T>::from_moebius gives every entry within 2^-target L_00, and a, b
// within 2^-target (|a| >= 1); the analysis is in word_matrix.cpp.
double moebius_precision_bits(const Presentation &p, std::size_t m, double target);

// Both matrices of a word from one Moebius product at
// moebius_precision_bits(66) (half the bits of a Lorentz product, with
// cheaper steps): a, b within 2^-66 and each Lorentz entry within
// 2^-66 L_00 before the rounding to double.
void accurate_matrices(const Presentation &p, const Word &w, Moebius<double> *moebius, Lorentz<double> *lorentz);

// The word's Lorentz matrix rounded once to the type T = mp_real<D>: the
// product runs at a rung with enough bits for the word and for T.
template <class T>
Lorentz<T> accurate_lorentz_as(const Presentation &p, const Word &w);

// The image of the disk point z under the word, computed in multiprecision
// (enough for the word and for z's distance to the unit circle) and rounded.
Complex<double> accurate_image(const Presentation &p, const Word &w, Complex<double> z);

}  // namespace hdt::group
