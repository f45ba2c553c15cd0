// Certified real bounds for exact numbers of K, for the places where an
// exact number only has to be bounded: a threshold that may be rounded
// outward (the walk then accepts a superset) and a length reported as an
// interval.
//
// How each bound is certified. A rational bound of x in K starts from the
// double nearest x and steps it outward one ulp at a time until an exact
// e-antic comparison confirms it (x <= q or q <= x): nothing is assumed of
// the conversion's accuracy. Transcendental functions (sqrt, arccosh, cosh)
// and sums are then evaluated by MPFR, whose results are correctly rounded
// in the direction asked for; each function used is increasing on its
// domain, so rounding the argument and each step downward (upward) gives a
// lower (upper) bound of the exact value.
#pragma once

#include <gmpxx.h>

#include "domain/complex.hpp"

namespace hdt::domain {

struct DoubleInterval {
  double lo, hi;  // lo <= the value <= hi
};

// Rationals q with q >= x and q <= x. Throw std::overflow_error when x is
// beyond the range of double.
mpq_class rational_above(const Number &x);
mpq_class rational_below(const Number &x);

// l = 2 arccosh(sqrt(X)) for X = cosh^2(l/2) >= 1: the translation length.
DoubleInterval length_from_cosh2_half(const Number &X);
// >= arccosh(x), for x >= 1.
double arccosh_above(const Number &x);
// >= cosh(t), as a rational.
mpq_class cosh_above(double t);
// >= a + b.
double sum_above(double a, double b);

}  // namespace hdt::domain
