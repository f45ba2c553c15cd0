// A disk isometry as a ball matrix of SU(1,1): [[a, b], [conj b, conj a]]
// with |a|^2 - |b|^2 = 1, up to sign. The exact projective pairings of K(i)
// are scaled to determinant 1 once (the square root is taken on balls),
// and their products stay in SU(1,1): entries of the size of the motion
// (|a| = cosh(d(0, g0) / 2)) instead of the growing numerators and
// denominators of exact products.
#pragma once

#include <array>

#include "domain/ball.hpp"
#include "domain/pairing.hpp"

namespace hdt::domain {

struct BallIsometry {
  ComplexBall a, b;

  ComplexBall apply(const ComplexBall &z) const;  // (a z + b) / (conj b z + conj a)
  // cosh(l/2) = |tr| / 2 = |Re a|, l the translation length (0 for the identity).
  RealBall cosh_half_translation() const { return abs(real(a)); }
  // The same map on hyperboloid vectors (x0, x1, x2) (hyperboloid_ball.hpp),
  // row-major: X' = L X. With w = x1 + i x2, x0' = (|a|^2 + |b|^2) x0 +
  // 2 Re(a conj(b) w) and w' = 2ab x0 + a^2 w + b^2 conj(w): the point z is
  // the Hermitian matrix v v* / (1 - |z|^2), v = (z, 1), with x0 its trace
  // and w twice its corner, and the isometry sends it to h (v v*) h*.
  std::array<RealBall, 9> lorentz() const;
};

BallIsometry ball_isometry(const Moebius &m);
BallIsometry ball_identity();
BallIsometry operator*(const BallIsometry &f, const BallIsometry &g);  // f after g

}  // namespace hdt::domain
