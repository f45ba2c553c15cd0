#include "surface/systole.hpp"

#include <limits>

#include "surface/polygon.hpp"

namespace hdt::surface {

double systole_or_nan(int genus) {
  if (genus < 2) return std::numeric_limits<double>::quiet_NaN();
  // 2 arccosh(1 + 2 cos(pi/2g)), correctly rounded: every step increases
  // with the previous one, so directed roundings bound it (round_to_nearest).
  // cos(pi/2g) is mpfr_cosu(1/2, 2g), of an exact argument (2g < 2^32).
  return round_to_nearest([genus](mpfr_ptr out, mpfr_rnd_t rnd) {
    mpfr_set_ui_2exp(out, 1, -1, MPFR_RNDN);
    mpfr_cosu(out, out, 2 * static_cast<unsigned long>(genus), rnd);
    mpfr_mul_2ui(out, out, 1, rnd);
    mpfr_add_ui(out, out, 1, rnd);
    mpfr_acosh(out, out, rnd);
    mpfr_mul_2ui(out, out, 1, rnd);
  });
}

}  // namespace hdt::surface
