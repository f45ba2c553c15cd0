// An element of the surface's Fuchsian group: an orientation-preserving
// isometry of the disk with entries in K(i), kept as a projective matrix in
// a canonical form so that equal maps have equal entries.
//
// Canonical form. A disk isometry is lambda [[a, b], [conj b, conj a]] with
// |a|^2 - |b|^2 = 1, so its top-left entry lambda a is never zero. Dividing
// all four entries by it gives [[1, b'], [c', d']]; two matrices of the same
// map differ by a scalar, which this division removes. So equality of maps
// is equality of the three remaining entries, exact in K(i). The hash is
// taken from their nearest doubles: equal exact numbers give equal doubles,
// and the equality itself is decided exactly.
//
// Translation length. For hyperbolic g, with g = lambda U, U in SU(1,1),
// |tr U| = 2 cosh(l/2); tr g = lambda tr U and det g = lambda^2, so
// cosh^2(l/2) = tr(g)^2 / (4 det g), in K (the square root of det, which
// would normalise to SU(1,1), is never taken).
#pragma once

#include <cstddef>

#include "domain/pairing.hpp"

namespace hdt::domain {

class Element {
 public:
  // Throws std::domain_error when the top-left entry is zero: not a disk isometry.
  explicit Element(const Moebius &m);

  const Moebius &matrix() const { return matrix_; }
  std::size_t hash() const { return hash_; }
  Complex apply(const Complex &z) const { return matrix_.apply(z); }
  bool is_identity() const { return matrix_.is_identity(); }
  bool operator==(const Element &o) const;
  bool operator!=(const Element &o) const { return !(*this == o); }

 private:
  Moebius matrix_;  // top-left entry exactly 1
  std::size_t hash_;
};

struct ElementHash {
  std::size_t operator()(const Element &g) const { return g.hash(); }
};

Element operator*(const Element &f, const Element &g);  // f after g
Element inverse(const Element &g);
Element identity_element(const Number &like);

// tr^2 / (4 det): cosh^2(l/2) for hyperbolic g of translation length l, 1 for
// the identity, in [0, 1) for elliptic g. Real and exact.
Number cosh2_half_translation(const Element &g);
// cosh d(p, g p), exact.
Number cosh_displacement(const Element &g, const Complex &p);

}  // namespace hdt::domain
