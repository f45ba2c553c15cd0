// Exact arithmetic in the cyclotomic field Q(zeta_n), zeta_n = e^{2 pi i/n}.
//
// An element is a vector of phi(n) integer coefficients over the power basis
// 1, zeta, ..., zeta^{phi(n)-1} times a power of two (2^exponent): every
// constant libhdt needs (cos and sin of multiples of pi/4g, points given as
// doubles) is dyadic over this basis, so no rational arithmetic (and no gcd)
// is needed. Products are reduced modulo the n-th cyclotomic polynomial.
// Zero is decided exactly (all coefficients zero); the real value of an
// element that is real is evaluated in MPFR by Field::sign (field.hpp).
#pragma once

#include <boost/multiprecision/gmp.hpp>
#include <memory>
#include <vector>

namespace hdt::exact {

using Integer = boost::multiprecision::mpz_int;

class CyclotomicField;

class Cyclotomic {
 public:
  Cyclotomic() = default;

  bool is_zero() const;
  int exponent() const { return exponent_; }
  const std::vector<Integer> &coefficients() const { return coefficients_; }

 private:
  friend class CyclotomicField;
  std::vector<Integer> coefficients_;  // empty means zero
  int exponent_ = 0;                   // value = 2^exponent * sum c_j zeta^j
};

class CyclotomicField {
 public:
  explicit CyclotomicField(int n);

  int order() const { return n_; }       // n
  int degree() const { return degree_; }  // phi(n)

  Cyclotomic zero() const { return Cyclotomic(); }
  Cyclotomic integer(long v) const;
  // A double is exactly m 2^e: the element m 2^e.
  Cyclotomic from_double(double v) const;
  // zeta^k for any integer k.
  Cyclotomic zeta_power(long k) const;
  // cos(2 pi k / n) = (zeta^k + zeta^-k)/2 and sin(2 pi k/n).
  Cyclotomic cos_2pi(long k) const;
  Cyclotomic sin_2pi(long k) const;

  Cyclotomic add(const Cyclotomic &a, const Cyclotomic &b) const;
  Cyclotomic sub(const Cyclotomic &a, const Cyclotomic &b) const;
  Cyclotomic neg(const Cyclotomic &a) const;
  Cyclotomic mul(const Cyclotomic &a, const Cyclotomic &b) const;
  Cyclotomic mul_2exp(const Cyclotomic &a, int e) const;
  // a zeta^k for 0 <= k < n: a shift and k steps of the reduction, each a
  // pass over Phi_n's nonzero coefficients; far cheaper than mul for small
  // k (rotating a point by a multiple of 2 pi/n).
  Cyclotomic mul_zeta_power(const Cyclotomic &a, long k) const;

 private:
  Cyclotomic normalised(std::vector<Integer> c, int exponent) const;
  Cyclotomic combine(const Cyclotomic &a, const Cyclotomic &b, bool subtract) const;
  void reduce(std::vector<Integer> &c) const;

  int n_;
  int degree_;
  std::vector<Integer> modulus_;  // Phi_n, monic, degree_ + 1 coefficients, low first
  // The indices of Phi_n's nonzero coefficients below the leading one, the
  // reduction's only work: for 8g = 2^(3+j) m, m odd > 1, Phi_8g(x) =
  // Phi_m(-x^(4 2^j)) has them at multiples of 4 only.
  std::vector<std::size_t> modulus_nonzero_;
  bool negacyclic_;                // Phi_n = x^degree + 1 (n a power of two)
};

}  // namespace hdt::exact
