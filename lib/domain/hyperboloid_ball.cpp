#include "domain/hyperboloid_ball.hpp"

#include <stdexcept>

namespace hdt::domain {

HyperboloidBall hyperboloid(const ComplexBall &z) {
  const RealBall one(1.0), two(2.0), r2 = norm2(z);
  const RealBall s = one / (one - r2);
  return {(one + r2) * s, two * real(z) * s, two * imag(z) * s};
}

RealBall minkowski(const HyperboloidBall &X, const HyperboloidBall &Y) {
  return X.x1 * Y.x1 + X.x2 * Y.x2 - X.x0 * Y.x0;
}

// n = J (U x V), J = diag(-1, 1, 1): <n, U> = (U x V) . U = 0, and likewise V.
HyperboloidBall line_normal(const ComplexBall &u, const ComplexBall &v, const HyperboloidBall &inside) {
  const HyperboloidBall U = hyperboloid(u), V = hyperboloid(v);
  HyperboloidBall n{RealBall(0.0) - (U.x1 * V.x2 - U.x2 * V.x1), U.x2 * V.x0 - U.x0 * V.x2, U.x0 * V.x1 - U.x1 * V.x0};
  const RealBall norm = sqrt(minkowski(n, n));
  n = {n.x0 / norm, n.x1 / norm, n.x2 / norm};
  const RealBall side = minkowski(inside, n), zero(0.0);
  if (certainly_less(side, zero)) return n;
  if (certainly_less(zero, side)) return {zero - n.x0, zero - n.x1, zero - n.x2};
  throw std::domain_error("domain::line_normal: the point is not certainly off the line");
}

}  // namespace hdt::domain
