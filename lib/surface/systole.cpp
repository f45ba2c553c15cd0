#include "surface/systole.hpp"

#include <limits>

namespace hdt::surface {

double systole_or_nan(int genus) {
  if (genus < 2) return std::numeric_limits<double>::quiet_NaN();
  return systole<double>(genus);
}

}  // namespace hdt::surface
