// Hyperbolic distance in the Poincare disk through its cosh, which is in the
// field of the coordinates: cosh d(a, b) = 1 + 2 |a - b|^2 / ((1 - |a|^2)(1 - |b|^2)).
// cosh is increasing on [0, inf), so comparing distances is comparing these
// numbers exactly.
#pragma once

#include "domain/complex.hpp"

namespace hdt::domain {

inline Number cosh_distance(const Complex &a, const Complex &b) {
  return 1 + 2 * norm2(a - b) / ((1 - norm2(a)) * (1 - norm2(b)));
}

}  // namespace hdt::domain
