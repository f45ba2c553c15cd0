#include "domain/ball_isometry.hpp"

namespace hdt::domain {

ComplexBall BallIsometry::apply(const ComplexBall &z) const { return (a * z + b) / (conj(b) * z + conj(a)); }

std::array<RealBall, 9> BallIsometry::lorentz() const {
  const ComplexBall c = a * conj(b), d = a * b, p = a * a, q = b * b;
  const RealBall two(2.0);
  return {norm2(a) + norm2(b), two * real(c),          RealBall(0.0) - two * imag(c),
          two * real(d),       real(p) + real(q),      imag(q) - imag(p),
          two * imag(d),       imag(p) + imag(q),      real(p) - real(q)};
}

// [[A, B], [C, D]] = lambda [[a, b], [conj b, conj a]] with lambda^2 = AD - BC;
// either root of it gives the same map. A ball across the negative axis
// (Arb's branch cut) would make the root's ball wide, so there the root is
// taken as i sqrt(-det).
BallIsometry ball_isometry(const Moebius &m) {
  const ComplexBall A = ball_of(m.a), B = ball_of(m.b), C = ball_of(m.c), D = ball_of(m.d);
  const ComplexBall det = A * D - B * C;
  const bool left = real(det).upper() < 0 || (real(det).lower() <= 0 && abs(imag(det)).upper() <= abs(real(det)).lower());
  const ComplexBall lambda = left ? complex_ball(0, 1) * sqrt(complex_ball(0, 0) - det) : sqrt(det);
  return {A / lambda, B / lambda};
}

BallIsometry ball_identity() { return {complex_ball(1, 0), complex_ball(0, 0)}; }

BallIsometry operator*(const BallIsometry &f, const BallIsometry &g) {
  return {f.a * g.a + f.b * conj(g.b), f.a * g.b + f.b * conj(g.a)};
}

}  // namespace hdt::domain
