#include "domain/pairing.hpp"

namespace hdt::domain {

Complex Moebius::apply(const Complex &z) const { return (a * z + b) / (c * z + d); }

bool Moebius::is_identity() const { return b.is_zero() && c.is_zero() && !a.is_zero() && a == d; }

Moebius operator*(const Moebius &f, const Moebius &g) {
  return {f.a * g.a + f.b * g.c, f.a * g.b + f.b * g.d, f.c * g.a + f.d * g.c, f.c * g.b + f.d * g.d};
}

Moebius inverse(const Moebius &f) { return {f.d, -f.b, -f.c, f.a}; }

Moebius identity(const Number &like) {
  const Complex one = complex_one(like), zero = Complex(Number(like.parent(), 0));
  return {one, zero, zero, one};
}

Moebius to_origin(const Complex &p) {
  const Complex one = complex_one(p.re);
  return {one, -p, -conj(p), one};
}

Moebius segment_map(const Complex &p, const Complex &q, const Complex &p2, const Complex &q2) {
  const Complex u = to_origin(p2).apply(q2) / to_origin(p).apply(q);
  const Complex zero = Complex(Number(p.re.parent(), 0));
  const Moebius rotation{u, zero, zero, complex_one(p.re)};
  return inverse(to_origin(p2)) * rotation * to_origin(p);
}

}  // namespace hdt::domain
