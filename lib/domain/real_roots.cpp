#include "domain/real_roots.hpp"

#include <flint/fmpq_poly.h>
#include <flint/fmpz_poly.h>

namespace hdt::domain {

namespace {

mpq_class value_at(const std::vector<mpq_class> &c, const mpq_class &x) {
  mpq_class v = 0;
  for (std::size_t k = c.size(); k-- > 0;) v = v * x + c[k];
  return v;
}

// c / (x - r) for a root r (synthetic division, exact).
std::vector<mpq_class> divided(const std::vector<mpq_class> &c, const mpq_class &r) {
  std::vector<mpq_class> out(c.size() - 1);
  mpq_class carry = 0;
  for (std::size_t k = c.size(); k-- > 1;) out[k - 1] = carry = c[k] + carry * r;
  return out;
}

// A FLINT polynomial of one linear factor u + v t.
void set_linear(fmpq_poly_t p, const mpq_class &u, const mpq_class &v) {
  fmpq_poly_zero(p);
  fmpq_poly_set_coeff_mpq(p, 0, u.get_mpq_t());
  fmpq_poly_set_coeff_mpq(p, 1, v.get_mpq_t());
}

// Roots of p in the open interval (a, b): positive roots of q (see the header).
long interior_roots(const std::vector<mpq_class> &c, const mpq_class &a, const mpq_class &b) {
  const slong d = slong(c.size()) - 1;
  fmpq_poly_t q, term, x, one_t;
  fmpq_poly_init(q), fmpq_poly_init(term), fmpq_poly_init(x), fmpq_poly_init(one_t);
  set_linear(x, a, b);
  set_linear(one_t, 1, 1);
  for (slong i = 0; i <= d; ++i) {
    fmpq_poly_pow(term, x, ulong(i));
    fmpq_poly_t rest;
    fmpq_poly_init(rest);
    fmpq_poly_pow(rest, one_t, ulong(d - i));
    fmpq_poly_mul(term, term, rest);
    fmpq_poly_scalar_mul_mpq(term, term, c[std::size_t(i)].get_mpq_t());
    fmpq_poly_add(q, q, term);
    fmpq_poly_clear(rest);
  }
  fmpz_poly_t z;
  fmpz_poly_init(z);
  fmpq_poly_get_numerator(z, q);
  slong negative = 0, positive = 0;
  if (fmpz_poly_length(z) > 1) _fmpz_poly_num_real_roots_sturm(&negative, &positive, z->coeffs, z->length);
  fmpz_poly_clear(z);
  fmpq_poly_clear(q), fmpq_poly_clear(term), fmpq_poly_clear(x), fmpq_poly_clear(one_t);
  return long(positive);
}

}  // namespace

long real_roots_in(const std::vector<mpq_class> &c, const mpq_class &a, const mpq_class &b) {
  if (c.size() < 2) return 0;  // a nonzero constant
  if (c.size() == 2) {  // one root, rational
    const mpq_class r = -c[0] / c[1];
    return long(a <= r && r <= b);
  }
  // A root at an end would make q(0) = 0 (or drop q's degree), which the
  // Sturm count does not allow: divide it out first (squarefree: once).
  for (const mpq_class *end : {&a, &b})
    if (value_at(c, *end) == 0) return 1 + real_roots_in(divided(c, *end), a, b);
  return interior_roots(c, a, b);
}

}  // namespace hdt::domain
