// Orientation-preserving isometries of the Poincare disk as SU(1,1) matrices
// [[a, b], [conj b, conj a]] with |a|^2 - |b|^2 = 1, acting by
// z -> (a z + b) / (conj(b) z + conj(a)).
//
// T is double or an exact::mp_real<D>; complex arithmetic is spelled out on
// real and imaginary parts so that it works for both.
#pragma once

#include <cmath>

namespace hdt::group {

template <class T>
struct Complex {
  T re{0}, im{0};
};

template <class T>
Complex<T> operator*(const Complex<T> &p, const Complex<T> &q) {
  return {p.re * q.re - p.im * q.im, p.re * q.im + p.im * q.re};
}
template <class T>
Complex<T> operator+(const Complex<T> &p, const Complex<T> &q) {
  return {p.re + q.re, p.im + q.im};
}
template <class T>
Complex<T> conj(const Complex<T> &p) {
  return {p.re, -p.im};
}
template <class T>
T norm2(const Complex<T> &p) {
  return p.re * p.re + p.im * p.im;
}

template <class T>
struct Moebius {
  Complex<T> a{T(1), T(0)};
  Complex<T> b{T(0), T(0)};

  static Moebius identity() { return Moebius{}; }

  // this * other: apply other first, then this.
  Moebius operator*(const Moebius &o) const {
    // [[a, b], [b~, a~]] [[a', b'], [b'~, a'~]] keeps the SU(1,1) shape.
    return Moebius{a * o.a + b * conj(o.b), a * o.b + b * conj(o.a)};
  }

  Moebius inverse() const { return Moebius{conj(a), Complex<T>{-b.re, -b.im}}; }

  // Image of the disk point z.
  Complex<T> apply(const Complex<T> &z) const {
    const Complex<T> num = a * z + b;
    const Complex<T> den = conj(b) * z + conj(a);
    const T d = norm2(den);
    return {(num.re * den.re + num.im * den.im) / d, (num.im * den.re - num.re * den.im) / d};
  }

  // Hyperbolic translation length 2 arccosh |Re a| (0 for elliptic elements).
  T translation_length() const {
    using std::abs;
    using std::acosh;
    const T t = abs(a.re);
    return t > T(1) ? T(2) * acosh(t) : T(0);
  }

  // |a|^2 - |b|^2, which is 1 for an exact SU(1,1) matrix.
  T determinant() const { return norm2(a) - norm2(b); }
};

}  // namespace hdt::group
