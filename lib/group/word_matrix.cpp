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

double moebius_precision_bits(const Presentation &p, std::size_t m, double target) {
  // The product [[a, b], [b~, a~]] at p bits (eps = 2^-p). Generators
  // g = [[A, B], [B~, A]], |B| < A = cot(pi/4g): A within 4.5 eps (pi, the
  // quotient, tan, 1/tan), |B| within 7.6 eps (A^2 - 1 cancels at most a
  // factor 1.21 for A >= cot(pi/8)), cos and sin of angles up to 2 pi within
  // 20 eps absolute: each real part of g within 29 eps A. The exact partial
  // products P_k have |a_k|, |b_k| <= (2A)^k; a step's error is
  // 2A (1 + 30 eps) E_{k-1} (propagated) + 46 eps A (2A)^{k-1} (g's error)
  // + 8.5 eps A (2A)^{k-1} (two complex products and a sum), so
  // E_m <= 32 m eps (2A)^m on |a|, |b| for m letters. from_moebius's entries
  // are quadratic in a, b: within 4 (|a| + |b|) E + 8 eps (|a|^2 + |b|^2)
  // <= (4 sqrt2 E + 8 eps) L_00 (L_00 = |a|^2 + |b|^2 >= 1). With
  // p >= target + 8 + log2(m + 1) + m log2(2A):
  // eps (182 m (2A)^m + 8) <= 2^-target L_00 (and E <= 2^-target).
  const double A = 1 / std::tan(M_PI / (4.0 * p.genus()));
  return target + 8 + std::log2(double(m) + 1) + double(m) * std::log2(2 * A * (1 + 1e-9));
}

void accurate_matrices(const Presentation &p, const Word &w, Moebius<double> *moebius, Lorentz<double> *lorentz) {
  exact::with_precision(moebius_precision_bits(p, w.size(), 66), [&](auto zero) {
    using T = decltype(zero);
    const Moebius<T> m = shared_generators<T>(p).moebius(w.data(), w.size());
    *moebius = Moebius<double>{{to_double(m.a.re), to_double(m.a.im)}, {to_double(m.b.re), to_double(m.b.im)}};
    const Lorentz<T> L = Lorentz<T>::from_moebius(m);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) lorentz->m[i][j] = to_double(L.m[i][j]);
    return 0;
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
