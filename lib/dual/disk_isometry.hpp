// The isometry of the Poincare disk that moves a point w to the origin,
// z -> (z - w) / (1 - conj(w) z), and its inverse z -> (z + w) / (1 + conj(w) z).
// The constructions move a corner to the origin, where the circles through it
// are Euclidean circles and the geodesics from it are diameters. One
// spelling for double (constructions, quality) and for exact::mp_real
// (the multiprecision circumcircle), so that the formulas cannot drift apart.
// The differences z - w are formed first: nearby points keep their relative
// accuracy.
#pragma once

#include "group/moebius.hpp"

// Inlined always: they are small and run several times per circumcentre,
// and GCC does not inline them by itself.
#if defined(__GNUC__)
#define HDT_ISOMETRY_INLINE inline __attribute__((always_inline))
#else
#define HDT_ISOMETRY_INLINE inline
#endif

namespace hdt::dual {

// (z - w) conj(1 - conj(w) z): the image of z, times the positive factor
// |1 - conj(w) z|^2. A direction or a ratio of such images needs no division.
// n = z - w is given: a difference known more accurately than the
// corners' (FaceFrame).
template <class T>
HDT_ISOMETRY_INLINE group::Complex<T> to_origin_scaled(const group::Complex<T> &w, const group::Complex<T> &z,
                                                       const group::Complex<T> &n) {
  const T dr = 1 - (w.re * z.re + w.im * z.im), di = -(w.re * z.im - w.im * z.re);
  return {n.re * dr + n.im * di, n.im * dr - n.re * di};
}
template <class T>
HDT_ISOMETRY_INLINE group::Complex<T> to_origin_scaled(const group::Complex<T> &w, const group::Complex<T> &z) {
  return to_origin_scaled(w, z, group::Complex<T>{z.re - w.re, z.im - w.im});
}

// |1 - conj(w) z|^2, the factor above.
template <class T>
HDT_ISOMETRY_INLINE T to_origin_factor(const group::Complex<T> &w, const group::Complex<T> &z) {
  const T dr = 1 - (w.re * z.re + w.im * z.im), di = -(w.re * z.im - w.im * z.re);
  return dr * dr + di * di;
}

// (z - w) / (1 - conj(w) z).
template <class T>
HDT_ISOMETRY_INLINE group::Complex<T> to_origin(const group::Complex<T> &w, const group::Complex<T> &z) {
  const group::Complex<T> a = to_origin_scaled(w, z);
  const T r = 1 / to_origin_factor(w, z);
  return {a.re * r, a.im * r};
}

// (z + w) / (1 + conj(w) z), the inverse of to_origin(w, .).
template <class T>
HDT_ISOMETRY_INLINE group::Complex<T> from_origin(const group::Complex<T> &w, const group::Complex<T> &z) {
  return to_origin(group::Complex<T>{-w.re, -w.im}, z);
}

}  // namespace hdt::dual
