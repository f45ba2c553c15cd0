#include "exact/cyclotomic.hpp"

#include <cmath>
#include <stdexcept>

namespace hdt::exact {

namespace {

using Poly = std::vector<Integer>;  // low coefficient first

// Exact division of a by the monic b.
Poly divide_exact(Poly a, const Poly &b) {
  const std::size_t db = b.size() - 1;
  Poly q(a.size() - db, Integer(0));
  for (std::size_t k = a.size(); k-- > db;) {
    const Integer c = a[k];
    q[k - db] = c;
    if (c != 0)
      for (std::size_t i = 0; i <= db; ++i) a[k - db + i] -= c * b[i];
  }
  for (const Integer &r : a)
    if (r != 0) throw std::logic_error("cyclotomic polynomial: inexact division");
  return q;
}

// Phi_n from the squarefree part: Phi_1 = x - 1; Phi_{mp}(x) = Phi_m(x^p) /
// Phi_m(x) for a prime p not dividing m; Phi_n(x) = Phi_rad(n)(x^{n/rad(n)}).
// Only exact divisions of polynomials of degree phi(rad(n)) p.
Poly cyclotomic_polynomial(int n) {
  std::vector<int> primes;
  int rest = n, radical = 1;
  for (int p = 2; p * p <= rest; ++p)
    if (rest % p == 0) {
      primes.push_back(p);
      radical *= p;
      while (rest % p == 0) rest /= p;
    }
  if (rest > 1) {
    primes.push_back(rest);
    radical *= rest;
  }
  Poly phi{Integer(-1), Integer(1)};  // Phi_1
  for (int p : primes) {
    Poly spread((phi.size() - 1) * p + 1, Integer(0));  // Phi_m(x^p)
    for (std::size_t i = 0; i < phi.size(); ++i) spread[i * p] = phi[i];
    phi = divide_exact(spread, phi);
  }
  const int stretch = n / radical;
  Poly result((phi.size() - 1) * stretch + 1, Integer(0));
  for (std::size_t i = 0; i < phi.size(); ++i) result[i * stretch] = phi[i];
  return result;
}

}  // namespace

bool Cyclotomic::is_zero() const { return coefficients_.empty(); }

CyclotomicField::CyclotomicField(int n) : n_(n) {
  if (n < 1) throw std::invalid_argument("cyclotomic field order must be positive");
  modulus_ = cyclotomic_polynomial(n);
  degree_ = int(modulus_.size()) - 1;
  for (std::size_t i = 0; i < std::size_t(degree_); ++i)
    if (modulus_[i] != 0) modulus_nonzero_.push_back(i);
  negacyclic_ = (n & (n - 1)) == 0 && n >= 2;
}

Cyclotomic CyclotomicField::normalised(std::vector<Integer> c, int exponent) const {
  // Drop trailing zeros; make the coefficients odd-content (divide out 2s)
  // so that equal values have equal representations.
  while (!c.empty() && c.back() == 0) c.pop_back();
  Cyclotomic r;
  if (c.empty()) return r;
  unsigned shift = ~0u;
  for (const Integer &x : c)
    if (x != 0) shift = std::min<unsigned>(shift, unsigned(boost::multiprecision::lsb(abs(x))));
  if (shift > 0 && shift != ~0u)
    for (Integer &x : c) x >>= shift;  // exact: every coefficient has `shift` trailing zero bits
  r.coefficients_ = std::move(c);
  r.exponent_ = exponent + int(shift == ~0u ? 0 : shift);
  return r;
}

void CyclotomicField::reduce(std::vector<Integer> &c) const {
  const std::size_t d = degree_;
  if (c.size() <= d) return;
  if (negacyclic_) {
    // x^d = -1
    for (std::size_t k = c.size(); k-- > d;) {
      if (c[k] != 0) c[k - d] -= c[k];
      c[k] = 0;
    }
  } else {
    for (std::size_t k = c.size(); k-- > d;) {
      // Phi_n is monic: its leading term cancels c[k], which the loop does
      // not write (and the resize drops), so t may refer to it.
      const Integer &t = c[k];
      if (t == 0) continue;
      for (const std::size_t i : modulus_nonzero_) c[k - d + i] -= t * modulus_[i];
    }
  }
  c.resize(d);
}

Cyclotomic CyclotomicField::integer(long v) const { return normalised({Integer(v)}, 0); }

Cyclotomic CyclotomicField::from_double(double v) const {
  if (!std::isfinite(v)) throw std::domain_error("from_double: not finite");
  if (v == 0) return zero();
  int e = 0;
  const double m = std::frexp(v, &e);  // v = m 2^e, 0.5 <= |m| < 1
  const double scaled = std::ldexp(m, 53);  // an integer
  return normalised({Integer(static_cast<long long>(scaled))}, e - 53);
}

Cyclotomic CyclotomicField::zeta_power(long k) const {
  k %= n_;
  if (k < 0) k += n_;
  if (negacyclic_) {
    // x^d = -1 and k < n = 2d: one coefficient, without building x^k (the
    // reduction of a vector of k + 1 coefficients was most of the cost of
    // the polygon's exact sites at genus 128).
    const std::size_t d = std::size_t(degree_);
    std::vector<Integer> c(std::size_t(k) < d ? std::size_t(k) + 1 : std::size_t(k) - d + 1);
    c.back() = std::size_t(k) < d ? 1 : -1;
    return normalised(std::move(c), 0);
  }
  std::vector<Integer> c(std::size_t(k) + 1, Integer(0));
  c[k] = 1;
  reduce(c);
  return normalised(std::move(c), 0);
}

Cyclotomic CyclotomicField::cos_2pi(long k) const {
  return mul_2exp(add(zeta_power(k), zeta_power(-k)), -1);
}

Cyclotomic CyclotomicField::sin_2pi(long k) const {
  // (zeta^k - zeta^-k) / 2i, and 1/i = -i = zeta^{3n/4}; needs 4 | n. The
  // factor goes into the exponents: no product.
  if (n_ % 4 != 0) throw std::invalid_argument("sin_2pi needs 4 | n");
  const long quarter = 3L * (n_ / 4);
  return mul_2exp(sub(zeta_power(k % n_ + quarter), zeta_power(quarter - k % n_)), -1);
}

Cyclotomic CyclotomicField::add(const Cyclotomic &a, const Cyclotomic &b) const { return combine(a, b, false); }

Cyclotomic CyclotomicField::sub(const Cyclotomic &a, const Cyclotomic &b) const { return combine(a, b, true); }

Cyclotomic CyclotomicField::combine(const Cyclotomic &a, const Cyclotomic &b, bool subtract) const {
  if (b.is_zero()) return a;
  if (a.is_zero()) return subtract ? neg(b) : b;
  // Align to the smaller exponent, shifting in place (no temporaries).
  const int e = std::min(a.exponent_, b.exponent_);
  const unsigned shift_a = unsigned(a.exponent_ - e), shift_b = unsigned(b.exponent_ - e);
  std::vector<Integer> c(std::max(a.coefficients_.size(), b.coefficients_.size()));  // zeros, unallocated
  for (std::size_t i = 0; i < a.coefficients_.size(); ++i) {
    c[i] = a.coefficients_[i];
    if (shift_a) c[i] <<= shift_a;
  }
  Integer shifted;
  for (std::size_t i = 0; i < b.coefficients_.size(); ++i) {
    const Integer *term = &b.coefficients_[i];
    if (shift_b) {
      shifted = *term << shift_b;
      term = &shifted;
    }
    if (subtract) c[i] -= *term;
    else c[i] += *term;
  }
  return normalised(std::move(c), e);
}

Cyclotomic CyclotomicField::neg(const Cyclotomic &a) const {
  Cyclotomic r = a;
  for (Integer &x : r.coefficients_) x = -x;
  return r;
}

Cyclotomic CyclotomicField::mul(const Cyclotomic &a, const Cyclotomic &b) const {
  if (a.is_zero() || b.is_zero()) return zero();
  const auto &x = a.coefficients_, &y = b.coefficients_;
  std::vector<Integer> c(x.size() + y.size() - 1);  // default-constructed: zero, no allocation
  // Only the nonzero coefficients of y (the constants of the polygon have a
  // few out of phi(n)).
  std::vector<std::size_t> nonzero;
  for (std::size_t j = 0; j < y.size(); ++j)
    if (y[j] != 0) nonzero.push_back(j);
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (x[i] == 0) continue;
    for (const std::size_t j : nonzero) c[i + j] += x[i] * y[j];
  }
  reduce(c);
  return normalised(std::move(c), a.exponent_ + b.exponent_);
}

Cyclotomic CyclotomicField::mul_zeta_power(const Cyclotomic &a, long k) const {
  if (k < 0 || k >= n_) throw std::invalid_argument("mul_zeta_power: k must be in [0, n)");
  if (a.is_zero()) return zero();
  std::vector<Integer> c(a.coefficients_.size() + std::size_t(k));  // zeros, unallocated
  for (std::size_t i = 0; i < a.coefficients_.size(); ++i) c[i + std::size_t(k)] = a.coefficients_[i];
  reduce(c);
  return normalised(std::move(c), a.exponent_);
}

Cyclotomic CyclotomicField::mul_2exp(const Cyclotomic &a, int e) const {
  Cyclotomic r = a;
  if (!r.is_zero()) r.exponent_ += e;
  return r;
}

}  // namespace hdt::exact
