// Tile centres h(O) from the translation table's double Moebius matrices,
// with certified error bounds, for naming products and inverses
// (centre_index.hpp).
//
// On the hyperboloid h(O) = (|a|^2 + |b|^2, 2 Re ab, 2 Im ab) for
// h = [[a, b], [conj b, conj a]]; only coordinates 1 and 2 name the element.
// The table's components are within u |x| + 2^-72 (|a| + |b|) of the exact
// ones (accurate_matrices), so within 1.1 u S of them, with
// S = |Re a| + |Im a| + |Re b| + |Im b| of the rounded components
// (|a| + |b| <= S (1 + 5u)). The Lorentz matrices used before cost a
// multiprecision product per new id; these need none.
#pragma once

#include <algorithm>
#include <cmath>

#include "group/moebius.hpp"

namespace hdt::group {

inline double component_sum(const Moebius<double> &m) {
  return std::abs(m.a.re) + std::abs(m.a.im) + std::abs(m.b.re) + std::abs(m.b.im);
}

// The centre of h, or with `inverse` that of h^-1 (a -> conj a, b -> -b):
// coordinates 1 and 2 and a bound on the error of each. Each is twice a sum
// of two products of components: the inputs' errors move it by 1.11 u S^2,
// its three roundings by 2.01 u of the products' sizes, at most S^2 / 4; so
// 2 (1.11 + 0.51) u S^2 < 4 u S^2.
inline void centre_of(const Moebius<double> &m, bool inverse, double *p1, double *p2, double *error) {
  const double ar = m.a.re, ai = inverse ? -m.a.im : m.a.im;
  const double br = inverse ? -m.b.re : m.b.re, bi = inverse ? -m.b.im : m.b.im;
  *p1 = 2 * (ar * br - ai * bi);
  *p2 = 2 * (ar * bi + ai * br);
  const double S = component_sum(m);
  *error = 4 * 0x1p-53 * S * S;
}

// The centre of A B. A B = [[c, d], [conj d, conj c]] with
// c = a1 a2 + b1 conj b2 and d = a1 b2 + b1 conj a2, and its centre is 2 c d.
// Each part of c and d sums four products, one component of each factor in
// each (their sizes sum to at most S1 S2): the inputs' errors move it by
// 2.21 u S1 S2, its seven roundings by 4.01 u S1 S2; ec = 6.5 u S1 S2 covers
// both. With m >= every part's size plus ec, each coordinate of 2 c d is
// twice two products of parts: 8 m ec from the inputs, 8.04 u m^2 from its
// roundings; 1.01 covers the roundings of the bound itself.
inline void product_centre_of(const Moebius<double> &A, const Moebius<double> &B, double *p1, double *p2,
                              double *error) {
  const double ar1 = A.a.re, ai1 = A.a.im, br1 = A.b.re, bi1 = A.b.im;
  const double ar2 = B.a.re, ai2 = B.a.im, br2 = B.b.re, bi2 = B.b.im;
  const double cr = ar1 * ar2 - ai1 * ai2 + br1 * br2 + bi1 * bi2;
  const double ci = ar1 * ai2 + ai1 * ar2 + bi1 * br2 - br1 * bi2;
  const double dr = ar1 * br2 - ai1 * bi2 + br1 * ar2 + bi1 * ai2;
  const double di = ar1 * bi2 + ai1 * br2 + bi1 * ar2 - br1 * ai2;
  *p1 = 2 * (cr * dr - ci * di);
  *p2 = 2 * (cr * di + ci * dr);
  const double ec = 6.5 * 0x1p-53 * component_sum(A) * component_sum(B);
  const double m = std::max(std::max(std::abs(cr), std::abs(ci)), std::max(std::abs(dr), std::abs(di))) + ec;
  *error = 1.01 * (8 * m * ec + 8.1 * 0x1p-53 * m * m);
}

}  // namespace hdt::group
