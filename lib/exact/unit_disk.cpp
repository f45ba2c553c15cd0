#include "exact/unit_disk.hpp"

#include <boost/multiprecision/gmp.hpp>
#include <cfloat>

namespace hdt::exact {

bool inside_unit_disk(double x, double y) {
  // Each square and the sum add at most one rounding of relative size
  // DBL_EPSILON/2 to a value at most about 1 near the boundary: 2 DBL_EPSILON
  // bounds the total error with room to spare.
  const double s = x * x + y * y;
  const double bound = 2.0 * DBL_EPSILON;
  if (s < 1.0 - bound) return true;
  if (s > 1.0 + bound) return false;
  using boost::multiprecision::mpq_rational;
  const mpq_rational qx(x), qy(y);
  return qx * qx + qy * qy < 1;
}

}  // namespace hdt::exact
