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

// cosh^2(sys/4) = (1 + cosh(sys/2)) / 2 = 1 + cos(pi/2g), in [1, 2]: a circle
// has diameter < sys/2 when cosh^2 of its radius is below it (the
// dummy-point condition). Exactly: Surface::quarter_systole_cosh2.
template <class T>
T quarter_systole_cosh2(int genus) {
  using std::cos;
  return T(1) + cos(exact::pi<T>() / T(2 * genus));
}

// The systole correctly rounded to double (systole<double> can be an ulp
// off); NaN when genus < 2.
double systole_or_nan(int genus);

}  // namespace hdt::surface
