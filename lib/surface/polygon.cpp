#include "surface/polygon.hpp"

namespace hdt::surface {

Complex<double> vertex(const group::Presentation &p, int k) { return polygon_vertex<double>(p.genus(), k); }

Complex<double> side_midpoint(const group::Presentation &p, int k) {
  return polygon_side_midpoint<double>(p.genus(), k);
}

}  // namespace hdt::surface
