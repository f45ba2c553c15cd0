// A point of the Poincare disk in double, and a circle of it: what the
// constructions (constructions.hpp) and their multiprecision fallback
// (precise_circumcircle.hpp) both return.
#pragma once

#include "group/moebius.hpp"

namespace hdt::dual {

using Point = group::Complex<double>;

struct Circle {
  Point centre;
  double radius;  // hyperbolic
};

}  // namespace hdt::dual
