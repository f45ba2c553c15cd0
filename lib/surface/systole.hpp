// The systole of M_g (paper, Theorem 3.1): cosh(sys/2) = 1 + 2 cos(pi/2g).
// Realised by a generator for g = 2 and by g_0 g_{2g+1} for g >= 3.
#pragma once

#include <cmath>

#include "exact/multiprecision.hpp"

namespace hdt::surface {

template <class T>
T systole(int genus) {
  using std::acosh;
  using std::cos;
  return T(2) * acosh(T(1) + T(2) * cos(exact::pi<T>() / (T(2) * T(genus))));
}

// The systole correctly rounded to double (systole<double> can be an ulp
// off); NaN when genus < 2.
double systole_or_nan(int genus);

}  // namespace hdt::surface
