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

// cos(a pi/2g) for a = 0..g in the multiprecision type T, each within one
// ulp of T (cos(g pi/2g) = 0 exactly). Why not a cos per angle: mpfr_cos
// at thousands of digits is costly, and every new rung's generator set
// takes g + 1 of them. Here one sin_cos gives
// z = e^{i pi/2g} and the powers z^a follow by complex products, 32 bits
// above T's precision: each product adds at most 3 units of 2^-prec to the
// error of z^a (|z^a| = 1), z's own error is at most 2 units, so z^a is
// within 6a <= 2^13 units for a <= g <= 1024, 2^-19 ulp of T before the
// final rounding to T.
template <class T>
std::vector<T> quarter_turn_cosines(int g) {
  std::vector<T> c(std::size_t(g) + 1);
  const mpfr_prec_t prec = mpfr_get_prec(c[0].backend().data()) + 32;
  mpfr_t angle, cz, sz, re, im, next;
  for (mpfr_ptr x : {angle, cz, sz, re, im, next}) mpfr_init2(x, prec);
  mpfr_const_pi(angle, MPFR_RNDN);
  mpfr_div_ui(angle, angle, 2 * static_cast<unsigned long>(g), MPFR_RNDN);
  mpfr_sin_cos(sz, cz, angle, MPFR_RNDN);
  mpfr_set_ui(re, 1, MPFR_RNDN);
  mpfr_set_ui(im, 0, MPFR_RNDN);
  c[0] = T(1);
  for (int a = 1; a < g; ++a) {
    // (re + i im) (cz + i sz), each part rounded once.
    mpfr_fmms(next, re, cz, im, sz, MPFR_RNDN);
    mpfr_fmma(im, re, sz, im, cz, MPFR_RNDN);
    mpfr_swap(re, next);
    mpfr_set(c[a].backend().data(), re, MPFR_RNDN);
  }
  c[g] = T(0);
  for (mpfr_ptr x : {angle, cz, sz, re, im, next}) mpfr_clear(x);
  return c;
}

// The Lorentz matrix of g_{k + qg} from that of g_k, 0 <= k < g: B turns by
// q quarter turns, which negates or swaps its parts, and every entry of
// Lorentz::from_moebius (A real) is then the same rounded expression up to
// sign. With b = (c, s): m01 = 2Ac, m02 = 2As, m11 = A^2 + D, m22 = A^2 - D,
// m12 = m21 = E for D = c^2 - s^2 and E = cs + sc; a quarter turn
// (c, s) -> (-s, c) negates D and E.
template <class T>
Lorentz<T> quarter_turned(const Lorentz<T> &L, int q) {
  const auto &m = L.m;
  const T &N = m[0][0], &X = m[0][1], &Y = m[0][2], &P = m[1][1], &Q = m[2][2], &E = m[1][2];
  Lorentz<T> r;
  switch (q) {
    case 1: r.m = {{{N, -Y, X}, {-Y, Q, -E}, {X, -E, P}}}; break;
    case 2: r.m = {{{N, -X, -Y}, {-X, P, E}, {-Y, E, Q}}}; break;
    default: r.m = {{{N, Y, -X}, {Y, Q, -E}, {-X, -E, P}}}; break;
  }
  return r;
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
      // In multiprecision the trigonometry is most of the cost: A and |B|
      // once, and cos(a pi/2g) for a = 0..g only (quarter_turn_cosines);
      // every angle k pi/2g folds onto one of them with a sign,
      // sin(a pi/2g) = cos((g - a) pi/2g), as in surface/polygon.cpp.
      using std::sqrt;
      const int g = p.genus();
      const T A = half_trace<T>(g);
      const T modulus = sqrt(A * A - T(1));
      std::vector<T> c = quarter_turn_cosines<T>(g);
      for (T &x : c) x *= modulus;
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
    if constexpr (std::is_same_v<T, double>) {
      for (const Moebius<T> &m : moebius_) lorentz_.push_back(Lorentz<T>::from_moebius(m));
    } else {
      // from_moebius for the first quadrant only (a quarter of a 2560-digit
      // set's cost): the others are its matrices turned, value for value.
      const int g = p.genus();
      for (Letter k = 0; k < g; ++k) lorentz_.push_back(Lorentz<T>::from_moebius(moebius_[k]));
      for (Letter k = g; k < p.letter_count(); ++k) lorentz_.push_back(quarter_turned(lorentz_[k % g], k / g));
    }
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
