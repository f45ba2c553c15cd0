#include "surface/polygon.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace hdt::surface {

namespace {

// r cos(a pi/4g) for a in 0..2g, correctly rounded; r^2 is given by
// radius_squared(out, g, rnd), rounded in direction rnd. cos(a pi/4g) is
// mpfr_cosu(a/4, 2g): MPFR rounds it correctly from an exact argument (no
// rounded pi), and gives exactly 0 at a = 2g.
template <class RadiusSquared>
double magnitude(int64_t g, int64_t a, RadiusSquared radius_squared) {
  return round_to_nearest([&](mpfr_ptr out, mpfr_rnd_t rnd) {
    MpfrNumber c(mpfr_get_prec(out));
    radius_squared(out, g, rnd);
    mpfr_sqrt(out, out, rnd);
    mpfr_set_ui_2exp(c, static_cast<unsigned long>(a), -2, MPFR_RNDN);  // a/4, exact
    mpfr_cosu(c, c, static_cast<unsigned long>(2 * g), rnd);
    mpfr_mul(out, out, c, rnd);
  });
}

// The magnitudes r cos(a pi/4g), a = 0..2g, of one kind of point for the
// genus last asked for (NaN until needed): a loop over k computes each once.
// One table per thread and kind: no lock, at most 2049 doubles.
struct Magnitudes {
  int genus = 0;
  std::vector<double> value;
};

// The point at angle j pi/4g (j = 2k + 1 for v_k, 2k for m_k). The angle is
// folded in integers onto a pi/4g, a in 0..2g: |x| = r cos(a pi/4g) and
// |y| = r sin(a pi/4g) = r cos((2g - a) pi/4g). So equal exact coordinates
// (x = y at pi/4, the images under the symmetries of F_g) are equal doubles,
// and a zero is +0 (x = 0 only at j = 2g, 6g and y = 0 at j = 0, 4g, where
// no sign is applied).
template <class RadiusSquared>
Complex<double> polygon_point(Magnitudes &cache, int genus, int64_t j, RadiusSquared radius_squared) {
  const int64_t g = genus, n = 8 * g;
  j = group::cyclic(j, n);
  const int64_t half_turn = j % (4 * g), a = std::min(half_turn, 4 * g - half_turn);
  if (cache.genus != genus) {
    cache.value.assign(2 * g + 1, std::numeric_limits<double>::quiet_NaN());
    cache.genus = genus;
  }
  auto m = [&](int64_t b) {
    double &v = cache.value[b];
    if (std::isnan(v)) v = magnitude(g, b, radius_squared);
    return v;
  };
  const double x = m(a), y = m(2 * g - a);
  return {j > 2 * g && j < 6 * g ? -x : x, j > 4 * g ? -y : y};
}

}  // namespace

Complex<double> vertex(const group::Presentation &p, int k) {
  thread_local Magnitudes cache;
  // r^2 = cos(pi/2g) = cosu(1/2, 2g).
  return polygon_point(cache, p.genus(), 2 * int64_t(k) + 1, [](mpfr_ptr out, int64_t g, mpfr_rnd_t rnd) {
    mpfr_set_ui_2exp(out, 1, -1, MPFR_RNDN);
    mpfr_cosu(out, out, static_cast<unsigned long>(2 * g), rnd);
  });
}

Complex<double> side_midpoint(const group::Presentation &p, int k) {
  thread_local Magnitudes cache;
  // r^2 = (A - 1)/(A + 1) = tan(pi/4 - pi/4g) = tanu((g - 1)/4, 2g): one
  // increasing function of an exact argument, easy to bound from each side.
  return polygon_point(cache, p.genus(), 2 * int64_t(k), [](mpfr_ptr out, int64_t g, mpfr_rnd_t rnd) {
    mpfr_set_ui_2exp(out, static_cast<unsigned long>(g - 1), -2, MPFR_RNDN);
    mpfr_tanu(out, out, static_cast<unsigned long>(2 * g), rnd);
  });
}

}  // namespace hdt::surface
