// The Klein model of the disk, exactly: the map from the Poincare disk,
// k(z) = 2z / (1 + |z|^2), is rational in z's coordinates, and geodesics
// are straight chords there. So "is x left of the geodesic through p and q"
// and "where does a geodesic segment cross a side" are linear questions in
// K, decided exactly, with no square root (the inverse map would need one).
#pragma once

#include "domain/complex.hpp"

namespace hdt::domain {

inline Complex klein(const Complex &z) {
  const Number s = Number(z.re.parent(), 2) / (1 + norm2(z));
  return s * z;
}

// Im(conj(to - from) (x - from)): positive when the Klein point x is left of
// the directed chord from `from` to `to`, zero on its line. Affine in x, so
// along a chord x(s) = A + s (B - A) it is affine in s.
inline Number side_value(const Complex &from, const Complex &to, const Complex &x) {
  return (conj(to - from) * (x - from)).im;
}

}  // namespace hdt::domain
