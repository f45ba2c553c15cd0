// Exact complex numbers over a real embedded number field K (or Q): the
// coordinates of a fundamental polygon and the entries of its pairings.
//
// A point z = re + i im of the disk is a pair of e-antic numbers, so every
// quantity the checks need (|z|^2, conj, products, quotients) stays in K(i)
// with no square root: K(i) is a field, and a quotient is a product with
// conj(w) / |w|^2, where |w|^2 is in K. Comparisons of real parts are exact
// (e-antic decides signs in K exactly).
#pragma once

#include <e-antic/renf_elem_class.hpp>

#include <stdexcept>
#include <utility>

namespace hdt::domain {

using Number = eantic::renf_elem_class;

struct Complex {
  Number re, im;

  Complex() = default;
  Complex(Number r, Number i) : re(std::move(r)), im(std::move(i)) {}
  explicit Complex(const Number &r) : re(r), im(r.parent(), 0) {}

  bool operator==(const Complex &o) const { return re == o.re && im == o.im; }
  bool operator!=(const Complex &o) const { return !(*this == o); }
  bool is_zero() const { return re.is_zero() && im.is_zero(); }
};

inline Complex operator+(const Complex &a, const Complex &b) { return {a.re + b.re, a.im + b.im}; }
inline Complex operator-(const Complex &a, const Complex &b) { return {a.re - b.re, a.im - b.im}; }
inline Complex operator-(const Complex &a) { return {-a.re, -a.im}; }
inline Complex operator*(const Complex &a, const Complex &b) {
  return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re};
}
inline Complex operator*(const Number &s, const Complex &a) { return {s * a.re, s * a.im}; }
inline Complex conj(const Complex &a) { return {a.re, -a.im}; }
inline Number norm2(const Complex &a) { return a.re * a.re + a.im * a.im; }

// a / b for b != 0: a conj(b) / |b|^2, exact. Throws std::domain_error on b == 0
// (a caller's bug: every division here has a denominator proved nonzero).
inline Complex operator/(const Complex &a, const Complex &b) {
  const Number n = norm2(b);
  if (n.is_zero()) throw std::domain_error("domain::Complex: division by zero");
  const Complex p = a * conj(b);
  return {p.re / n, p.im / n};
}

// The complex number 1 (or s) in the parent field of `like`.
inline Complex complex_one(const Number &like) { return Complex(Number(like.parent(), 1)); }

}  // namespace hdt::domain
