// Double-precision matrices of words, accurate to the last bits.
//
// A plain double product of m generators loses about log2 of the product of
// their norms: the relator of genus 32 (128 letters) comes out 1e-9 from the
// identity. These functions multiply at a multiprecision rung chosen from the
// word length and round once at the end.
//
// The element_* functions serve the C API: they Dehn-reduce the word first
// and report results that do not fit in double instead of rounding them to
// infinity or onto the unit circle.
#pragma once

#include <cstddef>

#include "group/lorentz.hpp"
#include "group/moebius.hpp"
#include "group/presentation.hpp"

namespace hdt::group {

// Bits that rounding errors may lose while m generators are multiplied:
// each Lorentz generator has entries at most 2A^2 - 1 (A = cot(pi/4g)), so
// a product of m of them at most (3(2A^2))^m in any entry.
double word_precision_bits(const Presentation &p, std::size_t m);
// Bits that certify a product of m letters with 64 to spare: the 53 bits
// of a double result and a guard, or the margin of canonical.cpp's
// separation tests, whose rounding error must stay far below it.
double word_certified_bits(const Presentation &p, std::size_t m);

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

// Both matrices of a word from one Moebius product, on the lowest rung whose
// error bound computed along the product (not the a priori one above)
// certifies a, b within 2^-72 (|a| + |b|): each Lorentz entry within
// 2^-66 L_00 before the rounding to double. Products are cached through the
// rotation symmetry (rotated_products.hpp). Throws exact::Unsupported when
// even the top rung cannot certify the word (not met: a word of N needs a
// few dozen bits above the target). The Moebius matrix also to about twice
// double precision: each part of a and b split into moebius + moebius_low
// (within 2^-106 of the product's value), which is within moebius_error
// (|a| + |b|) of the exact one (the bound computed along the product, at most
// 2^-72, usually far less: about 2^-100 for the words of N at genus 128).
// lorentz may be null: the multiprecision Lorentz matrix costs more than the
// rest together.
void accurate_matrices(const Presentation &p, const Word &w, Moebius<double> *moebius, Lorentz<double> *lorentz,
                       Moebius<double> *moebius_low, double *moebius_error);

// The word's Lorentz matrix as accurate_matrices computes it, with every entry
// within 2^-(d + 4) L_00 before its rounding to T = mp_real<D> (d bits):
// within 2^-d |L_ij| + 2^-(d + 4) L_00 after it.
template <class T>
Lorentz<T> accurate_lorentz_as(const Presentation &p, const Word &w);

// The image of the disk point z under the word, computed in multiprecision
// (enough for the word and for z's distance to the unit circle) and rounded.
Complex<double> accurate_image(const Presentation &p, const Word &w, Complex<double> z);

// ---- Elements, for hdt_word_matrix, hdt_word_lorentz and hdt_word_apply ----
//
// The word is Dehn-reduced first (linear time). That keeps the SU(1,1)
// matrix itself, not only the element: the relator's product is +I. The
// identity then comes out exact, and a long reduced word runs away from O
// (reduced words are quasi-geodesics), so its matrix is huge: one pass in double
// (norm_log2_lower_bound) proves that it overflows double, and only the
// other words get the multiprecision product, on the lowest rung whose error
// bound, computed along the product, meets the target. Failures throw
// std::domain_error (the result does not fit in double; the message says
// how) or, as a safety net not met in practice, exact::Unsupported (even the
// top rung cannot certify the product).

// A certified lower bound on log2(|a| + |b|), the operator norm of the
// word's matrix [[a, b], [conj b, conj a]]; 0 for the empty word. One pass
// in double over the letters; for Dehn-reduced words within a quarter of a
// bit of the true value in every test (the analysis is in word_matrix.cpp).
double norm_log2_lower_bound(const Presentation &p, const Letter *w, std::size_t length);

// The element's matrices rounded to double from one Moebius product with a,
// b within 2^-72 (|a| + |b|): each Lorentz entry within 2^-66 L_00 before the
// rounding. Throw std::domain_error when an entry rounds outside the double
// range.
Moebius<double> element_moebius(const Presentation &p, const Letter *w, std::size_t length);
Lorentz<double> element_lorentz(const Presentation &p, const Letter *w, std::size_t length);

// Images closer than 2^-kImageMargin to the unit circle may be refused
// without being computed (their double coordinates cannot tell them from the
// circle).
constexpr int kImageMargin = 100;

// The image of the disk point z (in the open disk) within about 2^-75, rounded
// to double; the identity returns z itself. Throws std::domain_error when
// the rounded image is not in the open unit disk, or when the image is shown
// to lie within 2^-kImageMargin of the circle.
Complex<double> element_image(const Presentation &p, const Letter *w, std::size_t length, Complex<double> z);

}  // namespace hdt::group
