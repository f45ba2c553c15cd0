// The generators g_k of Gamma_g in a number type T (double or mp_real<D>):
// g_k = [[A, B_k], [conj B_k, A]], A = cot(pi/4g), B_k = sqrt(A^2 - 1) e^{i k pi/2g}.
// g_k maps side s_{k+2g} of F_g onto side s_k; g_{k+2g} = g_k^{-1}.
#pragma once

#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <type_traits>
#include <vector>

#include "exact/multiprecision.hpp"
#include "group/lorentz.hpp"
#include "group/moebius.hpp"
#include "group/presentation.hpp"

namespace hdt::group {

// A = cot(pi/4g), the diagonal entry of every g_k: cosh of half a
// generator's translation length. Every formula in the library that needs
// it calls this (in double: 1 / tan(M_PI / 4g), a few ulps off).
template <class T>
T half_trace(int genus) {
  using std::tan;
  return T(1) / tan(exact::pi<T>() / T(4 * genus));
}

template <class T>
Moebius<T> generator(const Presentation &p, Letter k) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const T pi = exact::pi<T>();
  const T A = half_trace<T>(p.genus());
  const T modulus = sqrt(A * A - T(1));
  const T angle = pi * T(k) / T(2 * p.genus());
  return Moebius<T>{{A, T(0)}, {modulus * cos(angle), modulus * sin(angle)}};
}

// The 4g generators of one genus, as Moebius and Lorentz matrices, computed
// once so that word products cost only multiplications.
template <class T>
class GeneratorSet {
 public:
  explicit GeneratorSet(const Presentation &p) : presentation_(p) {
    if constexpr (std::is_same_v<T, double>) {
      for (Letter k = 0; k < p.letter_count(); ++k) moebius_.push_back(generator<T>(p, k));
    } else {
      // In multiprecision the trigonometry is most of the cost (15% of a
      // first hdt_create at genus 32): A and |B| once, and cos(a pi/2g)
      // for a = 0..g only; every angle k pi/2g folds onto one of them with
      // a sign, sin(a pi/2g) = cos((g - a) pi/2g), as in surface/polygon.cpp.
      // The folded arguments are at most pi/2, so each value is at least as
      // accurate as generator<T>'s.
      using std::cos;
      using std::sqrt;
      const int g = p.genus();
      const T pi = exact::pi<T>();
      const T A = half_trace<T>(g);
      const T modulus = sqrt(A * A - T(1));
      std::vector<T> c(std::size_t(g) + 1);
      for (int a = 0; a <= g; ++a) c[a] = a == g ? T(0) : modulus * cos(pi * T(a) / T(2 * g));
      for (Letter k = 0; k < p.letter_count(); ++k) {
        // k pi/2g = q pi/2 + a pi/2g, 0 <= a < g; the quadrant q gives the signs.
        const int q = k / g, a = k % g;
        const T &ca = c[a], &sa = c[g - a];  // |B| cos, |B| sin of a pi/2g
        Complex<T> b;
        switch (q) {
          case 0: b = {ca, sa}; break;
          case 1: b = {-sa, ca}; break;
          case 2: b = {-ca, -sa}; break;
          default: b = {sa, -ca}; break;
        }
        moebius_.push_back(Moebius<T>{{A, T(0)}, b});
      }
    }
    for (const Moebius<T> &m : moebius_) lorentz_.push_back(Lorentz<T>::from_moebius(m));
    // e^{i k pi/2g} = B_k / |B|, for rotated_products.hpp.
    const T inverse_modulus = T(1) / moebius_[0].b.re;  // B_0 = |B|
    for (const Moebius<T> &m : moebius_) rotation_.push_back({m.b.re * inverse_modulus, m.b.im * inverse_modulus});
  }

  const Presentation &presentation() const { return presentation_; }
  const Moebius<T> &moebius(Letter k) const { return moebius_[k]; }
  const Lorentz<T> &lorentz(Letter k) const { return lorentz_[k]; }
  // The rotation by k pi/2g about O as the unit complex number e^{i k pi/2g}.
  const Complex<T> &rotation(int k) const { return rotation_[k]; }

  // The product g_w0 g_w1 ... as written (letters must be valid).
  Moebius<T> moebius(const Letter *w, std::size_t length) const {
    Moebius<T> m = Moebius<T>::identity();
    for (std::size_t i = 0; i < length; ++i) m = m * moebius_[w[i]];
    return m;
  }
  Moebius<T> moebius(const Word &w) const { return moebius(w.data(), w.size()); }

  Lorentz<T> lorentz(const Letter *w, std::size_t length) const {
    Lorentz<T> m = Lorentz<T>::identity();
    for (std::size_t i = 0; i < length; ++i) m = m * lorentz_[w[i]];
    return m;
  }
  Lorentz<T> lorentz(const Word &w) const { return lorentz(w.data(), w.size()); }

  // The image of a hyperboloid point under the word: the last letter acts first.
  HyperboloidPoint<T> apply(const Word &w, HyperboloidPoint<T> x) const {
    for (std::size_t i = w.size(); i-- > 0;) x = lorentz_[w[i]].apply(x);
    return x;
  }

 private:
  Presentation presentation_;
  std::vector<Moebius<T>> moebius_;
  std::vector<Lorentz<T>> lorentz_;
  std::vector<Complex<T>> rotation_;
};

// The generators of one genus at one precision, built once per process and
// never freed (building them costs trigonometry at full precision). Safe to
// call from several threads; the result is read-only.
template <class T>
const GeneratorSet<T> &shared_generators(const Presentation &p) {
  static std::mutex mutex;
  static std::map<int, std::unique_ptr<const GeneratorSet<T>>> cache;
  std::lock_guard<std::mutex> lock(mutex);
  auto &slot = cache[p.genus()];
  if (!slot) slot = std::make_unique<const GeneratorSet<T>>(p);
  return *slot;
}

}  // namespace hdt::group
