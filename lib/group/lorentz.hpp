// Isometries of the hyperboloid t^2 - u^2 - v^2 = 1 (t > 0) as 3x3 Lorentz
// matrices acting linearly on (t, u, v). The disk point z = x + iy is the
// hyperboloid point ((1 + |z|^2), 2x, 2y) / (1 - |z|^2). Far from the origin
// these coordinates keep full relative precision, where disk coordinates lose
// it near |z| = 1.
#pragma once

#include <array>

#include "group/moebius.hpp"

namespace hdt::group {

template <class T>
struct HyperboloidPoint {
  T t{1}, u{0}, v{0};
};

// Minkowski product t t' - u u' - v v'; equals cosh of the distance between
// two points of the hyperboloid.
template <class T>
T minkowski(const HyperboloidPoint<T> &p, const HyperboloidPoint<T> &q) {
  return p.t * q.t - p.u * q.u - p.v * q.v;
}

template <class T>
HyperboloidPoint<T> to_hyperboloid(const Complex<T> &z) {
  const T r2 = norm2(z);
  const T s = T(1) / (T(1) - r2);
  return {(T(1) + r2) * s, T(2) * z.re * s, T(2) * z.im * s};
}

template <class T>
struct Lorentz {
  std::array<std::array<T, 3>, 3> m{{{T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(1)}}};

  static Lorentz identity() { return Lorentz{}; }

  // The matrix of the Moebius map f: to_hyperboloid(f(z)) = L to_hyperboloid(z).
  static Lorentz from_moebius(const Moebius<T> &f) {
    const Complex<T> &a = f.a, &b = f.b;
    const Complex<T> ab = a * b, abc = a * conj(b), aa = a * a, bb = b * b;
    Lorentz L;
    L.m[0] = {norm2(a) + norm2(b), T(2) * abc.re, T(-2) * abc.im};
    L.m[1] = {T(2) * ab.re, aa.re + bb.re, bb.im - aa.im};
    L.m[2] = {T(2) * ab.im, aa.im + bb.im, aa.re - bb.re};
    return L;
  }

  Lorentz operator*(const Lorentz &o) const {
    Lorentz r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r.m[i][j] = m[i][0] * o.m[0][j] + m[i][1] * o.m[1][j] + m[i][2] * o.m[2][j];
    return r;
  }

  HyperboloidPoint<T> apply(const HyperboloidPoint<T> &p) const {
    return {m[0][0] * p.t + m[0][1] * p.u + m[0][2] * p.v, m[1][0] * p.t + m[1][1] * p.u + m[1][2] * p.v,
            m[2][0] * p.t + m[2][1] * p.u + m[2][2] * p.v};
  }

  // Translation length l from trace = 1 + 2 cosh l.
  T translation_length() const {
    using std::acosh;
    const T c = (m[0][0] + m[1][1] + m[2][2] - T(1)) / T(2);
    return c > T(1) ? acosh(c) : T(0);
  }
};

}  // namespace hdt::group
