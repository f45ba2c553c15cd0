// The fundamental polygon F_g: the regular hyperbolic 4g-gon centred at 0
// with interior angles pi/2g.
//
// Side s_k has its midpoint m_k at angle k pi/2g and joins v_{k-1} and v_k;
// vertex v_k is at angle (2k+1) pi/4g. The side pairing: g_k maps s_{k+2g}
// onto s_k. Euclidean radii: vertices sqrt(cos(pi/2g)); midpoints
// tanh(d/2) = sqrt((A-1)/(A+1)) with cosh d = A = cot(pi/4g), that is
// sqrt(tan(pi/4 - pi/4g)).
#pragma once

#include <mpfr.h>

#include <cmath>

#include "exact/multiprecision.hpp"
#include "group/cyclic.hpp"
#include "group/generators.hpp"
#include "group/moebius.hpp"
#include "group/presentation.hpp"

// For mpfr_cosu and mpfr_tanu: cos and tan of exact multiples of pi/4g.
#if MPFR_VERSION < MPFR_VERSION_NUM(4, 2, 0)
#error "libhdt needs MPFR 4.2 or later"
#endif

namespace hdt::surface {

using group::Complex;

// An MPFR number of a fixed precision, freed with its scope.
class MpfrNumber {
 public:
  explicit MpfrNumber(mpfr_prec_t precision) { mpfr_init2(value_, precision); }
  ~MpfrNumber() { mpfr_clear(value_); }
  MpfrNumber(const MpfrNumber &) = delete;
  MpfrNumber &operator=(const MpfrNumber &) = delete;
  operator mpfr_ptr() { return value_; }

 private:
  mpfr_t value_;
};

// The double nearest to a real x >= 0 (ties to even), for certain.
// bound(out, rnd) sets out to x computed at out's precision with every MPFR
// operation rounded in direction rnd, by a formula increasing in each of its
// intermediate results: MPFR_RNDD then gives a lower bound, MPFR_RNDU an
// upper bound. Rounding to nearest is monotone, so when both bounds round to
// one double, x does too; otherwise the precision doubles (Ziv's strategy).
template <class Bound>
double round_to_nearest(Bound &&bound) {
  // 128 bits decide every value of genus <= 1024 at once. The cap only
  // stops a value sitting on a midpoint between doubles, which no precision
  // would separate.
  constexpr mpfr_prec_t kFirst = 128, kLast = 8192;
  for (mpfr_prec_t precision = kFirst;; precision *= 2) {
    MpfrNumber lower(precision), upper(precision);
    bound(static_cast<mpfr_ptr>(lower), MPFR_RNDD);
    bound(static_cast<mpfr_ptr>(upper), MPFR_RNDU);
    const double a = mpfr_get_d(lower, MPFR_RNDN);
    if (a == mpfr_get_d(upper, MPFR_RNDN) || precision >= kLast) return a;
  }
}

template <class T>
Complex<T> polygon_vertex(int genus, int k) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const int n = 4 * genus;
  k = group::cyclic(k, n);
  const T pi = exact::pi<T>();
  const T radius = sqrt(cos(pi / T(2 * genus)));
  const T angle = pi * T(2 * k + 1) / T(4 * genus);
  return {radius * cos(angle), radius * sin(angle)};
}

template <class T>
Complex<T> polygon_side_midpoint(int genus, int k) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  using std::tan;
  const int n = 4 * genus;
  k = group::cyclic(k, n);
  const T pi = exact::pi<T>();
  const T A = group::half_trace<T>(genus);
  const T radius = sqrt((A - T(1)) / (A + T(1)));
  const T angle = pi * T(k) / T(2 * genus);
  return {radius * cos(angle), radius * sin(angle)};
}

// The coordinates of v_k and m_k correctly rounded to double (k any int);
// polygon_vertex<double> and polygon_side_midpoint<double> are a few ulps
// off. Equal exact coordinates give equal doubles (x = y at angle pi/4,
// v_{4g-1-k} = conj(v_k) bit for bit), and a zero coordinate is +0.
Complex<double> vertex(const group::Presentation &p, int k);
Complex<double> side_midpoint(const group::Presentation &p, int k);

}  // namespace hdt::surface
