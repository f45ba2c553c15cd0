#include "domain/klein_polygon.hpp"

#include "domain/klein.hpp"

namespace hdt::domain {

KleinPolygon::KleinPolygon(const FundamentalPolygon &P) {
  for (int k = 0; k < P.side_count(); ++k) vertices_.push_back(klein(P.vertex(k)));
}

Number KleinPolygon::side_value(int k, const Complex &x) const {
  return hdt::domain::side_value(vertex(k), vertex(k + 1), x);
}

bool KleinPolygon::contains(const Complex &x) const {
  for (int k = 0; k < side_count(); ++k)
    if (side_value(k, x) < 0) return false;
  return true;
}

bool KleinPolygon::contains_strictly(const Complex &x) const {
  for (int k = 0; k < side_count(); ++k)
    if (side_value(k, x) <= 0) return false;
  return true;
}

}  // namespace hdt::domain
