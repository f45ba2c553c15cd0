#include "group/word_matrix.hpp"

#include <cmath>

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

}  // namespace hdt::group
