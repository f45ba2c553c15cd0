#include "surface/home_image.hpp"

#include <cmath>

#include "group/certified_image.hpp"

namespace hdt::surface {

std::optional<HomeImage> make_home_image(const group::Presentation &p, group::TranslationTable &table, double x,
                                         double y, group::TranslationId home) {
  HomeImage h;
  if (!group::certified_image(p, table.word(home), x, y, &h.approximation)) return std::nullopt;
  using R = SiteReal;
  const R &a = h.approximation.re, &b = h.approximation.im;
  // N = (1 + s, 2a, 2b) / (1 - s), s = a^2 + b^2. With a, b within d =
  // 2^-128 (and the 133-bit roundings, 2^-131 of each term), s, 1 + s and
  // 1 - s are within 5d, 2a and 2b within 2d + 2^-131: each numerator
  // within 5d, so N_i within 5d (1 + N_0) / (w - 5d), w = 1 - s, plus the
  // quotient's rounding and the rounding to double (u N_0 each at most).
  const R s = a * a + b * b, w = R(1) - s;
  const double wd = static_cast<double>(w), d = 0x1p-128;
  if (!(wd > 10 * d)) return std::nullopt;
  const R n[3] = {(R(1) + s) / w, (a + a) / w, (b + b) / w};
  for (int i = 0; i < 3; ++i) h.vector[i] = static_cast<double>(n[i]);
  h.vector_error = (5 * d * (1 + h.vector[0]) / (wd - 5 * d) + 0x1p-52 * h.vector[0]) * 1.01;
  h.rounded = {static_cast<double>(a), static_cast<double>(b)};
  h.x = x, h.y = y, h.home = home;
  h.home_inverse = table.inverse(home);
  return h;
}

}  // namespace hdt::surface
