// The analysis shared by the refined stages (stage_double_double.cpp,
// stage_mpfr.cpp): the double stage's determinants and the other predicates
// in more precise arithmetic with a certified error bound. Near the corners
// of F_g a translation of N has entries up to cosh(2R) (3.4e5 at genus 16)
// and its image of a point cancels most of them, so double precision can
// lose 20 bits there.
//
// The double-double stage (double_double.hpp: about 106 bits, a few hundred
// instructions per point) runs first; the 133-bit MPFR stage (some 27,000
// instructions per point) when it cannot decide; the exact stage after
// both, at milliseconds.
//
// Both stages share one analysis (the templates below), and the double
// stage uses it for large_circumdisk. It assumes only the standard model
// for each arithmetic operation of the stage's reals T:
// |op~(a, b) - a op b| <= U |a op b|, with U = `unit`:
//   MPFR at 133 bits rounds correctly: u = 2^-133, and U = MpfrStage::kUnit = 2^-132
//     keeps a bit to spare;
//   double-double operations are within 13u^2 < 2^-102 (u = 2^-53; see
//     double_double.hpp): U = DoubleDoubleStage::kUnit = 2^-100 keeps two bits to spare;
//   double rounds correctly: U = u = 2^-53.
// Inputs rounded into T are within U as well (matrices, sites' coordinates,
// the constant of large_circumdisk, the side normals; see where they are
// rounded). Bounds are first-order in U; the factors 1.01 and 1.02 cover the
// higher-order terms and the rounding of the bounds' own double evaluation.
// Double-double has the exponent range of double: a stage gives up unless
// every magnitude that enters a product lies in [2^-200, 2^200], so that no
// operation underflows or overflows beyond a few 2^-1074 absolutely, far
// below every bound. (They always do: every error bound is at least 2^-97,
// see refined_point.)
#pragma once

#include <algorithm>
#include <cmath>

#include "group/lorentz.hpp"
#include "group/moebius.hpp"
#include "predicates/sign.hpp"

namespace hdt::predicates {

// A point of a refined stage: the hyperboloid vector in the stage's reals
// and a certified bound on each coordinate's error.
template <class Real>
struct RefinedPoint {
  Real n[3];
  double error;  // on each coordinate
};

namespace refined {

constexpr double kTiny = 0x1p-200, kHuge = 0x1p200;

// An upper bound on |x|: |double(x)| = |RN(x)| <= |x| (1 + 2^-53) for MPFR;
// for double-double double(x) = hi and |hi + lo| <= |hi| (1 + 2^-53).
template <class T>
double magnitude(const T &x) {
  return std::abs(static_cast<double>(x)) * (1 + 1e-15);
}

inline bool in_range(double m) { return m >= kTiny && m <= kHuge; }

template <class T>
struct Difference {
  T d[3];
  double error, size;  // error per entry; max |entry| + error
};

template <class T>
Difference<T> difference(const RefinedPoint<T> &a, const RefinedPoint<T> &b, double unit) {
  // Input errors add; the subtraction rounds by U of the result.
  Difference<T> r;
  double m = 0;
  for (int i = 0; i < 3; ++i) {
    r.d[i] = a.n[i] - b.n[i];
    m = std::max(m, magnitude(r.d[i]));
  }
  r.error = (a.error + b.error + unit * m) * 1.01;
  r.size = m + r.error;
  return r;
}

// Sign of det[a; b; c] when certain, else undecided. ea, ma: row a's entry error and
// magnitude bound (max |entry| + error), likewise for b, c.
template <class T>
Sign det3_sign(const T *a, double ea, double ma, const T *b, double eb, double mb, const T *c, double ec, double mc,
              double unit) {
  if (!in_range(ma) || !in_range(mb) || !in_range(mc)) return Sign::undecided;
  const T value =
      a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  // Input errors: each of the 6 terms of the expansion moves by at most
  // ea mb mc + ma eb mc + ma mb ec. Rounding: each term passes through 5
  // operations (2 products, a difference, a product, the outer sums: at most
  // 2 of them), each U of at most 2 ma mb mc per cofactor, 6 terms: 36 U.
  const double bound = (6 * (ea * mb * mc + ma * eb * mc + ma * mb * ec) + 36 * unit * ma * mb * mc) * 1.02;
  return sign_beyond(static_cast<double>(value), bound);
}

// N = L p^ / w for the disk point (x, y) (within coordinate_error in each
// coordinate), L the translation's matrix (each entry within U relative;
// null for the identity).
template <class T>
bool refined_point(const T &x, const T &y, double coordinate_error, const group::Lorentz<T> *L, double unit,
                   RefinedPoint<T> *out) {
  const T s = x * x + y * y;
  const T hat[3] = {T(1) + s, x + x, y + y};
  const T w = T(1) - s;
  const double wd = static_cast<double>(w);
  if (!(wd > 0x1p-100)) return false;
  double h[3];
  for (int j = 0; j < 3; ++j) h[j] = magnitude(hat[j]);
  double worst = 0, row = 1;
  if (!L) {
    for (int i = 0; i < 3; ++i) out->n[i] = hat[i] / w;
    worst = h[0];  // >= |hat_1|, |hat_2|
  } else {
    row = 0;
    for (int i = 0; i < 3; ++i) {
      const T v = L->m[i][0] * hat[0] + L->m[i][1] * hat[1] + L->m[i][2] * hat[2];
      out->n[i] = v / w;
      const double l[3] = {magnitude(L->m[i][0]), magnitude(L->m[i][1]), magnitude(L->m[i][2])};
      worst = std::max(worst, l[0] * h[0] + l[1] * h[1] + l[2] * h[2]);
      row = std::max(row, l[0] + l[1] + l[2]);
    }
  }
  // Relative to worst (>= sum |L_ij hat_j|, and >= 1 since L_00, hat_0 >= 1):
  // L within U and hat within 2U (hat_0 = 1 + s: s = x^2 + y^2 within 2U s,
  // then U (1 + s), and (1 + 3s) <= 2(1 + s); 2x, 2y exact): 3U; products U,
  // the two sums 2U: 7U; the quotient U: 8U. w = 1 - s within 2U s + U w, at
  // most 2U (1 + s) / w relative, which moves N by at most worst/w * 4U/w.
  // A site's coordinates, off by coordinate_error each, move hat / w by at
  // most (2/w + 4/w^2) <= 6/w^2 per unit in each, and L multiplies by at most
  // its row sum. (The error is at least 8U >= 2^-129: never below 2^-200.)
  out->error = (worst / wd * (8 * unit + 4 * unit / wd) + row * 12 * coordinate_error / (wd * wd)) * 1.01;
  return true;
}

// The same N for the disk point (x, y) (exact) under a translation given by
// its Moebius matrix [[a, b], [conj b, conj a]], each part of a and b within
// matrix_error (|a_re| + |a_im| + |b_re| + |b_im|): with Num = a z + b and
// D = conj(b) z + conj(a), N = (2 |D|^2 / w - 1, 2 Num conj(D) / w), whose
// error is about |a| / |D| relative to the matrix's where the Lorentz
// product's is |a|^2 / |D|^2 (filtered_point.hpp has the same in double).
template <class T>
bool refined_point_moebius(const T &x, const T &y, const group::Moebius<T> &M, double matrix_error, double unit,
                           RefinedPoint<T> *out) {
  const T w = T(1) - (x * x + y * y);
  const double wd = static_cast<double>(w);
  if (!(wd > 0x1p-100)) return false;
  const T n1 = M.a.re * x - M.a.im * y + M.b.re, n2 = M.a.re * y + M.a.im * x + M.b.im;
  const T d1 = M.b.re * x + M.b.im * y + M.a.re, d2 = M.b.re * y - M.b.im * x - M.a.im;
  const T p1 = n1 * d1 + n2 * d2, p2 = n2 * d1 - n1 * d2, q = d1 * d1 + d2 * d2;
  out->n[0] = (q + q) / w - T(1);
  out->n[1] = (p1 + p1) / w;
  out->n[2] = (p2 + p2) / w;
  // With S >= |a_re| + |a_im| + |b_re| + |b_im| (magnitude() rounds up; the
  // parts' own errors are inside the 1.01): each of n1, n2, d1, d2 within
  // e1 = 2.42 matrix_error S (1 + |x| + |y| <= 2.42) + 3.01 U S (three
  // roundings of terms summing to at most S). With m their largest size
  // plus e1, p1, p2 and q are within 4 m e1 + 4.02 U m^2 and at most 2 m^2.
  // w = 1 - s within 2U s + U w <= 3U; the doubling, the division and the
  // final subtraction (|N0| + 1 <= 4 m^2 / w) add U each of 4 m^2 / w:
  // error <= (8 m e1 + (8.04 + 12 + 12 / w) U m^2) / w, 1.02 for the rest.
  const double S = (magnitude(M.a.re) + magnitude(M.a.im) + magnitude(M.b.re) + magnitude(M.b.im)) * 1.01;
  const double e1 = (2.42 * matrix_error + 3.01 * unit) * S;
  const double m =
      std::max(std::max(magnitude(n1), magnitude(n2)), std::max(magnitude(d1), magnitude(d2))) + e1;
  if (!in_range(m)) return false;
  out->error = 1.02 * (8 * m * e1 + (20.04 + 12 / wd) * unit * m * m) / wd;
  return true;
}

template <class T>
Sign orientation_sign(const RefinedPoint<T> &a, const RefinedPoint<T> &b, const RefinedPoint<T> &c, double unit) {
  const Difference<T> db = difference(b, a, unit), dc = difference(c, a, unit);
  // det[N_p; N_q; N_r] = det[N_p; N_q - N_p; N_r - N_p].
  double ma = 0;
  for (const T &v : a.n) ma = std::max(ma, magnitude(v));
  return det3_sign(a.n, a.error, ma + a.error, db.d, db.error, db.size, dc.d, dc.error, dc.size, unit);
}

template <class T>
Sign in_circle_sign(const RefinedPoint<T> &a, const RefinedPoint<T> &b, const RefinedPoint<T> &c,
                   const RefinedPoint<T> &e, double unit) {
  const Difference<T> db = difference(b, a, unit), dc = difference(c, a, unit), de = difference(e, a, unit);
  // det[N 1] = -det[N_q - N_p; N_r - N_p; N_s - N_p].
  return -det3_sign(db.d, db.error, db.size, dc.d, dc.error, dc.size, de.d, de.error, de.size, unit);
}

// large_circumdisk (kernel.hpp): +1 when the circle through a, b, e has
// hyperbolic diameter >= sys/2 or is no circle, -1 when smaller. With
// d2 = N_b - N_a, d3 = N_e - N_a, c = d2 x d3 (Euclidean cross product) and
// c_3 = -c . N_a, the plane through the lifted points is (c, c_3), <m, m> =
// c0^2 - c1^2 - c2^2, and the test is Q = c_3^2 - k <m, m> >= 0 where
// <m, m> > 0, for k = 1 + cos(pi/2g) in [1, 2] given within 4U relative.
template <class T>
Sign large_circumdisk_sign(const RefinedPoint<T> &a, const RefinedPoint<T> &b, const RefinedPoint<T> &e, const T &k,
                          double unit) {
  const Difference<T> d2 = difference(b, a, unit), d3 = difference(e, a, unit);
  double amax = 0;
  for (int i = 0; i < 3; ++i) amax = std::max(amax, magnitude(a.n[i]));
  amax += a.error;
  if (!in_range(d2.size) || !in_range(d3.size) || !in_range(amax)) return Sign::undecided;
  const T c[3] = {d2.d[1] * d3.d[2] - d2.d[2] * d3.d[1], d2.d[2] * d3.d[0] - d2.d[0] * d3.d[2],
                  d2.d[0] * d3.d[1] - d2.d[1] * d3.d[0]};
  // Each entry of c: two products of entries (errors d2.error, d3.error on
  // magnitudes d2.size, d3.size) and their difference: 2 U each.
  const double ec = 2 * (d2.error * d3.size + d2.size * d3.error) + 4 * unit * d2.size * d3.size;
  double cmax = 0;
  for (int i = 0; i < 3; ++i) cmax = std::max(cmax, magnitude(c[i]));
  cmax += ec;
  if (!in_range(cmax)) return Sign::undecided;
  const T c3 = -(c[0] * a.n[0] + c[1] * a.n[1] + c[2] * a.n[2]);
  const double e3 = 3 * (ec * amax + cmax * a.error) + 4 * unit * 3 * cmax * amax;
  const double c3max = magnitude(c3) + e3;
  const T mm = c[0] * c[0] - c[1] * c[1] - c[2] * c[2];
  const double emm = 3 * (2 * cmax * ec) + 6 * unit * 3 * cmax * cmax;
  const T Q = c3 * c3 - k * mm;
  const double eQ = 2 * c3max * e3 + 2 * emm + 8 * unit * 2 * 3 * cmax * cmax + 4 * unit * c3max * c3max;
  const double mmd = static_cast<double>(mm), Qd = static_cast<double>(Q);
  if (mmd < -emm * 1.02) return Sign::positive;  // not a circle
  if (mmd > emm * 1.02) return sign_beyond(Qd, eQ * 1.02);
  return Sign::undecided;
}

// Sign of <N, n> = n0 N0 + n1 N1 + n2 N2 (the Minkowski signs folded into
// n) for beyond_side: n = (1 - L00, L10, L20), L the side's generator g_k,
// so <N, n> is the Minkowski product <N, O - g_k(O)>. Column 0 of a Lorentz
// matrix is timelike, L00^2 = 1 + L10^2 + L20^2, so |n_i| <= L00; with each
// L_i0 within U L00 and the subtraction 1 - L00 rounded (U |n0| <= U L00),
// every n_i is within en = 2U L00 (the caller's side_error).
// Input errors: sum_i (|n_i| e + en (|N_i| + e)) <= 3 (L00 e + en ma), ma =
// max |N_i| + e. Rounding: each of the 3 products passes through its own
// rounding and at most 2 sums: 3U sum |n_i N_i| <= 9U L00 ma.
template <class T>
Sign beyond_side_sign(const RefinedPoint<T> &a, const T *n, double L00, double side_error, double unit) {
  double ma = 0;
  for (const T &v : a.n) ma = std::max(ma, magnitude(v));
  ma += a.error;
  if (!in_range(ma) || !in_range(L00)) return Sign::undecided;
  const T value = n[0] * a.n[0] + n[1] * a.n[1] + n[2] * a.n[2];
  const double bound = (3 * (L00 * a.error + side_error * ma) + 9 * unit * L00 * ma) * 1.02;
  return sign_beyond(static_cast<double>(value), bound);
}

// Sign of <N_p, N_a - N_b> = p0 d0 - p1 d1 - p2 d2 (d = N_a - N_b) for
// compare_distance: cosh d(p, a) = <N_p, N_a> and cosh is increasing.
// Input errors: d within d.error (difference), p within p.error: each term
// moves by at most p.error d.size + mp d.error, mp = max |p_i| + p.error.
// Rounding: 3 products and 2 sums, 3U sum |p_i d_i| <= 9U mp d.size.
template <class T>
Sign compare_distance_sign(const RefinedPoint<T> &p, const RefinedPoint<T> &a, const RefinedPoint<T> &b,
                           double unit) {
  const Difference<T> d = difference(a, b, unit);
  double mp = 0;
  for (const T &v : p.n) mp = std::max(mp, magnitude(v));
  mp += p.error;
  if (!in_range(mp) || !in_range(d.size)) return Sign::undecided;
  const T value = p.n[0] * d.d[0] - p.n[1] * d.d[1] - p.n[2] * d.d[2];
  const double bound = (3 * (p.error * d.size + mp * d.error) + 9 * unit * mp * d.size) * 1.02;
  return sign_beyond(static_cast<double>(value), bound);
}

// positive when N_a != N_b for certain: some computed coordinate of
// N_a - N_b exceeds its error bound (difference: input errors and the
// subtraction's rounding; |double(x)| >= |x| (1 - 2^-53), inside the 1.02),
// else undecided.
template <class T>
Sign distinct_sign(const RefinedPoint<T> &a, const RefinedPoint<T> &b, double unit) {
  const Difference<T> d = difference(a, b, unit);
  for (int i = 0; i < 3; ++i)
    if (std::abs(static_cast<double>(d.d[i])) > d.error * 1.02) return Sign::positive;
  return Sign::undecided;
}

}  // namespace refined
}  // namespace hdt::predicates
