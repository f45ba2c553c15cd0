// A fundamental polygon seen in the Klein model, where it is a convex
// Euclidean polygon with vertices k(v_0) .. k(v_{n-1}) in K(i) (klein.hpp).
// Side k is the chord from k(v_k) to k(v_{k+1}); the polygon is on its left,
// so a Klein point x is in the closed polygon exactly when every
// side_value(k, x) >= 0, and in its interior when every one is > 0.
#pragma once

#include <vector>

#include "domain/fundamental_polygon.hpp"

namespace hdt::domain {

class KleinPolygon {
 public:
  explicit KleinPolygon(const FundamentalPolygon &P);

  int side_count() const { return int(vertices_.size()); }
  const Complex &vertex(int k) const { return vertices_[std::size_t(k % side_count())]; }
  // > 0 left of side k's line, 0 on it.
  Number side_value(int k, const Complex &x) const;
  bool contains(const Complex &x) const;           // the closed polygon
  bool contains_strictly(const Complex &x) const;  // its interior

 private:
  std::vector<Complex> vertices_;
};

}  // namespace hdt::domain
