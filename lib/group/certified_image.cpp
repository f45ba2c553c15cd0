#include "group/certified_image.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "exact/precision_ladder.hpp"
#include "group/generators.hpp"

namespace hdt::group {

namespace {

// One run at the reals T (unit eps = 2^-bits: correct rounding, a bit to
// spare). The generators g = [[A, B], [conj B, A]], |B|^2 = A^2 - 1, have
// each real part within 29 eps A (see moebius_precision_bits in
// word_matrix.cpp). At a computed point w (|w| < 1) the numerator a w + b
// and the denominator conj(b) w + conj(a) are then within
// 2 * 41 eps A (coefficients) + 10 eps A (roundings) < e = 100 eps A of
// their values for the exact generator; the denominator has modulus at
// least A - |B| = 1 / (A + |B|) >= 1 / 2A, so the quotient (modulus < 1)
// is within 2e 2A / (1 - 2A e) of exact, and its rounding adds at most
// 8 eps: delta = (400 A^2 + 10) eps bounds one step while 2A e <= 1%.
//
// Hyperbolically: between the computed point and the exact generator's
// image of the previous computed point (Euclidean distance <= delta), the
// density 2 / (1 - |x|^2) <= 2 / (1 - |x|) is at most 2 / gap, gap a lower
// bound on 1 - |computed| - delta, so the step errs by at most
// 2 delta / gap. The later letters are isometries: the final point is
// within rho = the sum of those of h(z) hyperbolically, and since the
// density is at least 2 everywhere, within rho / 2 Euclidean.
template <class T>
bool tracked_image(const Presentation &p, const Word &w, double x, double y, double eps,
                   Complex<exact::mp_real<40>> *out) {
  const double A = half_trace<double>(p.genus()) * (1 + 1e-12);
  if (!(200 * eps * A * A <= 0.01)) return false;
  const double delta = (400 * A * A + 10) * eps;
  const GeneratorSet<T> &G = shared_generators<T>(p);
  Complex<T> z{T(x), T(y)};
  double rho = 0;
  for (std::size_t i = w.size(); i-- > 0;) {
    z = G.moebius(w[i]).apply(z);
    // 1 - |z| >= (1 - |z|^2) / 2; |z|^2 within a few eps.
    const double gap = static_cast<double>(T(1) - norm2(z)) * (1 - 1e-15) / 2 - 4 * eps - delta;
    if (!(gap > 0)) return false;
    rho += 2 * delta / gap * (1 + 1e-15);
  }
  // Rounding to 133 bits adds 2^-133 |coordinate| < 2^-133.
  if (!(rho / 2 <= 0x1p-129)) return false;
  using R = exact::mp_real<40>;
  *out = {R(z.re), R(z.im)};
  return true;
}

}  // namespace

using ImageLadder = exact::Ladder<40, 160, 640, 2560>;

bool certified_image(const Presentation &p, const Word &w, double x, double y, Complex<exact::mp_real<40>> *image) {
  // rho / 2 is about m delta / gap0: bits for 2^-130 with gap0 >= (1 - |z|^2) / 2
  // (computed exactly enough in double: x^2 + y^2 < 1), plus a margin.
  const double A = half_trace<double>(p.genus());
  const double gap = std::max(1.0 - (x * x + y * y), 0x1p-110) / 2;
  const double bits = 140 + std::log2(double(w.size()) + 1) + std::log2(400 * A * A + 10) + std::log2(2 / gap);
  // Each rung up has about four times the bits: the climb stops at the
  // first that certifies, or fails at the top.
  const std::size_t first = std::min(ImageLadder::rung_for(bits), ImageLadder::kSize - 1);
  return ImageLadder::climb(first, [&](auto zero) {
    using T = decltype(zero);
    const double eps = std::ldexp(1.0, 1 - int(std::numeric_limits<T>::digits));
    return tracked_image<T>(p, w, x, y, eps, image);
  });
}

}  // namespace hdt::group
