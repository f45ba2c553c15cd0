#include "group/word_matrix.hpp"

#include <cmath>
#include <limits>

#include "exact/precision_ladder.hpp"
#include "group/generators.hpp"

namespace hdt::group {

double word_precision_bits(const Presentation &p, std::size_t m) {
  const double A = 1.0 / std::tan(M_PI / (4.0 * p.genus()));
  return (std::log2(6.0 * A * A) + 1.0) * double(m) + 2.0 * std::log2(double(m) + 2.0);
}

namespace {

// 53 bits of the result plus a guard.
double bits_for(const Presentation &p, std::size_t m) { return 64.0 + word_precision_bits(p, m); }

template <class T>
double to_double(const T &x) {
  return x.template convert_to<double>();
}

}  // namespace

Moebius<double> accurate_moebius(const Presentation &p, const Letter *w, std::size_t length) {
  return exact::with_precision(bits_for(p, length), [&](auto zero) {
    using T = decltype(zero);
    const Moebius<T> m = shared_generators<T>(p).moebius(w, length);
    return Moebius<double>{{to_double(m.a.re), to_double(m.a.im)}, {to_double(m.b.re), to_double(m.b.im)}};
  });
}

Lorentz<double> accurate_lorentz(const Presentation &p, const Letter *w, std::size_t length) {
  return exact::with_precision(bits_for(p, length), [&](auto zero) {
    using T = decltype(zero);
    const Lorentz<T> m = shared_generators<T>(p).lorentz(w, length);
    Lorentz<double> r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r.m[i][j] = to_double(m.m[i][j]);
    return r;
  });
}

Complex<double> accurate_image(const Presentation &p, const Word &w, Complex<double> z) {
  // Mapping a point near the circle inwards cancels about log2(1/(1 - |z|))
  // bits in the denominator: add them, with a margin.
  const double gap = 1.0 - std::hypot(z.re, z.im);
  const double extra = 64.0 + (gap > 0 ? 2.0 * std::log2(1.0 / gap) : 2200.0);
  return exact::with_precision(bits_for(p, w.size()) + extra, [&](auto zero) {
    using T = decltype(zero);
    const Complex<T> image = shared_generators<T>(p).moebius(w).apply(Complex<T>{T(z.re), T(z.im)});
    return Complex<double>{to_double(image.re), to_double(image.im)};
  });
}

template <class T>
Lorentz<T> accurate_lorentz_as(const Presentation &p, const Word &w) {
  const double bits = bits_for(p, w.size()) + double(std::numeric_limits<T>::digits);
  return exact::with_precision(bits, [&](auto zero) {
    using U = decltype(zero);
    const Lorentz<U> m = shared_generators<U>(p).lorentz(w.data(), w.size());
    Lorentz<T> r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r.m[i][j] = static_cast<T>(m.m[i][j]);
    return r;
  });
}

template Lorentz<exact::mp_real<40>> accurate_lorentz_as(const Presentation &, const Word &);

}  // namespace hdt::group
