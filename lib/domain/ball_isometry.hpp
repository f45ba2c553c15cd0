// A disk isometry as a ball matrix of SU(1,1): [[a, b], [conj b, conj a]]
// with |a|^2 - |b|^2 = 1, up to sign. The exact projective pairings of K(i)
// are scaled to determinant 1 once (the square root is taken on balls),
// and their products stay in SU(1,1): entries of the size of the motion
// (|a| = cosh(d(0, g0) / 2)) instead of the growing numerators and
// denominators of exact products.
#pragma once

#include "domain/ball.hpp"
#include "domain/pairing.hpp"

namespace hdt::domain {

struct BallIsometry {
  ComplexBall a, b;

  ComplexBall apply(const ComplexBall &z) const;  // (a z + b) / (conj b z + conj a)
  // cosh(l/2) = |tr| / 2 = |Re a|, l the translation length (0 for the identity).
  RealBall cosh_half_translation() const { return abs(real(a)); }
};

BallIsometry ball_isometry(const Moebius &m);
BallIsometry ball_identity();
BallIsometry operator*(const BallIsometry &f, const BallIsometry &g);  // f after g

}  // namespace hdt::domain
