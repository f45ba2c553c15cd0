// Orientation-preserving isometries of the Poincare disk with entries in
// K(i), as projective 2x2 matrices: [[a, b], [c, d]] acts as
// z -> (a z + b) / (c z + d), and a matrix and its nonzero multiples are the
// same map. No normalisation to SU(1,1) (it would need the square root of a
// determinant), so equality and the identity are tested up to scalar.
#pragma once

#include "domain/complex.hpp"

namespace hdt::domain {

struct Moebius {
  Complex a, b, c, d;

  Complex apply(const Complex &z) const;  // z must not be the pole (c z + d != 0)
  bool is_identity() const;  // b = c = 0 and a = d (!= 0), exactly
};

Moebius operator*(const Moebius &f, const Moebius &g);  // f after g
Moebius inverse(const Moebius &f);                       // the adjugate: inverse up to scalar
Moebius identity(const Number &like);

// T_p(z) = (z - p) / (1 - conj(p) z): the disk isometry that sends p to 0 with
// positive real derivative 1 / (1 - |p|^2) at p.
Moebius to_origin(const Complex &p);

// The side pairing, CGAL's convention: the isometry that sends the segment
// from p to q onto the segment from p2 to q2 (p -> p2, q -> q2), the two of
// equal hyperbolic length (the caller checks). With
// u = T_{p2}(q2) / T_p(q), a unit complex number because |T_p(q)| =
// tanh(d(p, q) / 2), it is T_{p2}^{-1} o (z -> u z) o T_p.
Moebius segment_map(const Complex &p, const Complex &q, const Complex &p2, const Complex &q2);

}  // namespace hdt::domain
