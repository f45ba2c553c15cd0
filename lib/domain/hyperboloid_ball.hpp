// Points and geodesic lines of the hyperboloid model, on balls. A disk point
// z is X = (1 + |z|^2, 2 Re z, 2 Im z) / (1 - |z|^2), with the Minkowski form
// <X, Y> = -X0 Y0 + X1 Y1 + X2 Y2: cosh d(X, Y) = -<X, Y>. A geodesic line
// is a unit spacelike normal n (<n, n> = 1), and <X, n> = sinh of the signed
// distance from X to the line, positive on the side n points to.
#pragma once

#include "domain/ball.hpp"

namespace hdt::domain {

struct HyperboloidBall {
  RealBall x0, x1, x2;
};

HyperboloidBall hyperboloid(const ComplexBall &z);  // z in the open disk
RealBall minkowski(const HyperboloidBall &X, const HyperboloidBall &Y);

// The line through the disk points u and v, its normal pointing away from
// the point `inside` (which must not be on it: std::domain_error when the
// balls cannot tell).
HyperboloidBall line_normal(const ComplexBall &u, const ComplexBall &v, const HyperboloidBall &inside);

}  // namespace hdt::domain
