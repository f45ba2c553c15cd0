// Points of the hyperboloid model in double, for the dummy construction's
// choices (where to move or place a dummy): heuristics whose results the
// exact predicates then check, never predicates themselves.
#pragma once

#include <array>
#include <cmath>

namespace hdt::dummies::hyperboloid {

using Vector = std::array<double, 3>;  // (t, u, v), t^2 - u^2 - v^2 = 1 on the sheet

// The Minkowski product t t' - u u' - v v'.
inline double dot(const Vector &p, const Vector &q) { return p[0] * q[0] - p[1] * q[1] - p[2] * q[2]; }

// The Minkowski normal of the plane through p, q, r: its dual is the
// circumcentre.
inline Vector normal(const Vector &p, const Vector &q, const Vector &r) {
  const double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, v[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
  return {u[1] * v[2] - u[2] * v[1], -(u[2] * v[0] - u[0] * v[2]), -(u[0] * v[1] - u[1] * v[0])};
}

// cosh of the circumradius of (p, q, r); infinite for a horocycle or
// hypercycle (as the refinement computes it).
inline double cosh_circumradius(const Vector &p, const Vector &q, const Vector &r) {
  const Vector m = normal(p, q, r);
  const double mm = dot(m, m);
  if (!(mm > 0)) return INFINITY;
  return (m[0] > 0 ? 1 : -1) * dot(m, p) / std::sqrt(mm);
}

}  // namespace hdt::dummies::hyperboloid
