// The fundamental polygon F_g: the regular hyperbolic 4g-gon centred at 0
// with interior angles pi/2g.
//
// Side s_k has its midpoint m_k at angle k pi/2g and joins v_{k-1} and v_k;
// vertex v_k is at angle (2k+1) pi/4g. The side pairing: g_k maps s_{k+2g}
// onto s_k. Euclidean radii: vertices sqrt(cos(pi/2g)); midpoints
// tanh(d/2) = sqrt((A-1)/(A+1)) with cosh d = A = cot(pi/4g).
#pragma once

#include <cmath>

#include "exact/multiprecision.hpp"
#include "group/moebius.hpp"
#include "group/presentation.hpp"

namespace hdt::surface {

using group::Complex;

template <class T>
Complex<T> polygon_vertex(int genus, int k) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const int n = 4 * genus;
  k = ((k % n) + n) % n;
  const T pi = exact::pi<T>();
  const T radius = sqrt(cos(pi / T(2 * genus)));
  const T angle = pi * T(2 * k + 1) / T(4 * genus);
  return {radius * cos(angle), radius * sin(angle)};
}

template <class T>
Complex<T> polygon_side_midpoint(int genus, int k) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  using std::tan;
  const int n = 4 * genus;
  k = ((k % n) + n) % n;
  const T pi = exact::pi<T>();
  const T A = T(1) / tan(pi / T(4 * genus));
  const T radius = sqrt((A - T(1)) / (A + T(1)));
  const T angle = pi * T(k) / T(2 * genus);
  return {radius * cos(angle), radius * sin(angle)};
}

// The side paired with s_k (by g_k: s_{k+2g} -> s_k).
inline int paired_side(const group::Presentation &p, int k) { return p.inverse(k); }

// Double-precision values, checked arguments (genus >= 2).
Complex<double> vertex(const group::Presentation &p, int k);
Complex<double> side_midpoint(const group::Presentation &p, int k);

}  // namespace hdt::surface
