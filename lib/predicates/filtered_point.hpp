// A translated point on the hyperboloid in double precision, with a
// certified bound on the error of each coordinate. Input to the filters.
#pragma once

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "group/lorentz.hpp"

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

// N = L p^ / w for the disk point (x, y), L the translation's Lorentz
// matrix with each entry within u |L_ij| + 2^-64 L_00 (TranslationTable). w = 1 - x^2 - y^2 is computed with error-free
// products and sums, so it keeps full relative precision near the circle.
inline FilteredPoint filtered_point(double x, double y, const group::Lorentz<double> &L) {
  const double xx = x * x, exx = square_error(x, xx);
  const double yy = y * y, eyy = square_error(y, yy);
  const double s = xx + yy, b = s - xx, es = (xx - (s - b)) + (yy - b);  // s + es = xx + yy exactly
  const double tail = es + exx + eyy;
  // Relative errors: w <= 4u (1 - s is exact for s in [1/2, 2]), p0 <= 2u;
  // and w absolutely up to 2^-103 more, the rounding of tail (|tail| <=
  // 2^-51), which matters only within about 2^-50 of the circle.
  const double w = (1.0 - s) - tail;
  const double p[3] = {(1.0 + s) + tail, 2 * x, 2 * y};
  FilteredPoint r;
  double worst = 0;
  for (int i = 0; i < 3; ++i) {
    const double P = L.m[i][0] * p[0] + L.m[i][1] * p[1] + L.m[i][2] * p[2];
    const double S = std::abs(L.m[i][0]) * p[0] + std::abs(L.m[i][1] * p[1]) + std::abs(L.m[i][2] * p[2]);
    r.n[i] = P / w;
    worst = std::max(worst, S);
  }
  // Each product sum: u (L rounded) + 2u (p0) + 3u (arithmetic) per unit of
  // S; the division and w add 5u of |P| <= S; 16u of the worst S covers all
  // with room, also the absolute part of L's error: 2^-64 L_00 (p0 + |p1| +
  // |p2|) <= 2^-62.4 L_00 p0 <= 2^-62.4 S_0 (|p1|, |p2| <= p0). w's absolute
  // error adds 2^-103 / w relative (2^-102 / w with the roundings here).
  r.error = (16 * kUnit + 0x1p-102 / w) * worst / w;
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
