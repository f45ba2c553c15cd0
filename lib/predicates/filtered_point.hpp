// A translated point on the hyperboloid in double precision, with a
// certified bound on the error of each coordinate. Input to the filters.
#pragma once

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "group/moebius.hpp"

namespace hdt::predicates {

struct FilteredPoint {
  double n[3];   // the hyperboloid vector N = L p^ / w
  double error;  // |computed - exact| <= error for each coordinate
};

constexpr double kUnit = DBL_EPSILON / 2;  // u = 2^-53

// The rounding error of x * x, exactly (Dekker's product: no fma call on
// targets built without FMA instructions).
inline double square_error(double x, double xx) {
  const double c = 134217729.0 * x;  // 2^27 + 1
  const double hi = c - (c - x), lo = x - hi;
  return ((hi * hi - xx) + 2 * hi * lo) + lo * lo;
}

// N for the disk point z = (x, y) under a translation given by its Moebius
// matrix [[a, b], [conj b, conj a]], each component of a and b within
// u |.| + 2^-72 (|a| + |b|) (TranslationTable). With Num = a z + b and
// D = conj(b) z + conj(a), 1 - |h z|^2 = w / |D|^2, w = 1 - |z|^2, so
//   N = (2 |D|^2 / w - 1, 2 Num conj(D) / w).
// The rounding errors of a and b meet the exact z only in Num and D: a
// relative error of about |a| / |D| u, where the Lorentz product L p^ / w
// loses its square (L's entries are about 2 |a|^2): near the sides and
// corners of F_g at large genus translations with entries of 10^7 and more
// map points with N of 10^2 .. 10^4, and the Lorentz form left a third of
// the double stage's in-circle tests at genus 128 undecided.
// w = 1 - x^2 - y^2 is computed with error-free products and sums, so it
// keeps full relative precision near the circle.
inline FilteredPoint filtered_point(double x, double y, const group::Moebius<double> &M) {
  const double xx = x * x, exx = square_error(x, xx);
  const double yy = y * y, eyy = square_error(y, yy);
  const double s = xx + yy, b = s - xx, es = (xx - (s - b)) + (yy - b);  // s + es = xx + yy exactly
  // w within 4u relative (1 - s is exact for s in [1/2, 2]) and 2^-103
  // absolute (the rounding of es + exx + eyy, which is at most 2^-51).
  const double w = (1.0 - s) - (es + exx + eyy);
  const double ar = M.a.re, ai = M.a.im, br = M.b.re, bi = M.b.im;
  const double n1 = ar * x - ai * y + br, n2 = ar * y + ai * x + bi;
  const double d1 = br * x + bi * y + ar, d2 = br * y - bi * x - ai;
  const double p1 = n1 * d1 + n2 * d2, p2 = n2 * d1 - n1 * d2, q = d1 * d1 + d2 * d2;
  FilteredPoint r;
  r.n[0] = 2 * q / w - 1;
  r.n[1] = 2 * p1 / w;
  r.n[2] = 2 * p2 / w;
  // With S = |a_re| + |a_im| + |b_re| + |b_im| (>= |a| + |b|): the matrix
  // components are within 1.01 u S, which (1 + |x| + |y| <= 2.42) and three
  // roundings of terms summing to at most S put each of n1, n2, d1, d2
  // within e1 = 5.5 u S. With m their largest size plus e1, p1, p2 and q are
  // within 4 m e1 (inputs) + 4.02 u m^2 (two roundings each), and at most
  // 2 m^2. Dividing by w adds 5u and 2^-102 / w relative to 2 m^2 / w, the
  // last subtraction u of |N0| + 1 <= 4 m^2 / w: 1.02 covers the products
  // of the (1 + u) factors.
  const double S = std::abs(ar) + std::abs(ai) + std::abs(br) + std::abs(bi);
  const double e1 = 5.5 * kUnit * S;
  const double m = std::max(std::max(std::abs(n1), std::abs(n2)), std::max(std::abs(d1), std::abs(d2))) + e1;
  r.error = 1.02 * (8 * m * e1 + (36 * kUnit + 0x1p-100 / w) * m * m) / w;
  return r;
}

// The same for the identity translation: N = p^ / w, without a product.
inline FilteredPoint filtered_point(double x, double y) {
  const double xx = x * x, exx = square_error(x, xx);
  const double yy = y * y, eyy = square_error(y, yy);
  const double s = xx + yy, b = s - xx, es = (xx - (s - b)) + (yy - b);
  const double tail = es + exx + eyy;
  const double w = (1.0 - s) - tail;
  const double p0 = (1.0 + s) + tail;
  FilteredPoint r;
  r.n[0] = p0 / w;
  r.n[1] = 2 * x / w;
  r.n[2] = 2 * y / w;
  // Relative errors: w 4u (and 2^-103 / w, as above), p0 2u, the division u:
  // 8u + 2^-102 / w of p0 / w covers all.
  r.error = (8 * kUnit + 0x1p-102 / w) * r.n[0];
  return r;
}

// det[a; b; c] of 3-vectors with a certified error bound, given per-row
// magnitude bounds m (max |entry|) and absolute entry errors e.
struct Det3 {
  double value, bound;
};

inline double det3_value(const double *a, const double *b, const double *c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

inline double max_abs3(const double *a) { return std::max(std::abs(a[0]), std::max(std::abs(a[1]), std::abs(a[2]))); }

inline Det3 det3_filtered(const double *a, double ea, const double *b, double eb, const double *c, double ec) {
  const double ma = max_abs3(a) + ea, mb = max_abs3(b) + eb, mc = max_abs3(c) + ec;
  // Input errors move the determinant by at most 6 (ea mb mc + ma eb mc +
  // ma mb ec) (each cofactor is at most 2 products of magnitudes, 3 of them);
  // evaluating it rounds each of its 6 terms by at most 5u relative.
  const double input = 6 * (ea * mb * mc + ma * eb * mc + ma * mb * ec);
  const double rounding = 6 * 6 * kUnit * ma * mb * mc;
  return {det3_value(a, b, c), (input + rounding) * (1 + 8 * kUnit) * 1.01};
}

}  // namespace hdt::predicates
