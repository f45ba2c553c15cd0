#include "domain/real_bounds.hpp"

#include <mpfr.h>

#include <cmath>
#include <stdexcept>

namespace hdt::domain {

namespace {

// Exact, and canonical (the e-antic pitfall: a fraction not in lowest terms
// breaks equality).
mpq_class exact_rational(double d) {
  mpq_class q(d);
  q.canonicalize();
  return q;
}

// One MPFR number of 53 bits (a double's), freed on scope exit.
struct Mpfr {
  mpfr_t v;
  Mpfr() { mpfr_init2(v, 53); }
  ~Mpfr() { mpfr_clear(v); }
  Mpfr(const Mpfr &) = delete;
  Mpfr &operator=(const Mpfr &) = delete;
};

mpq_class rational_stepping(const Number &x, double toward, bool (*confirmed)(const Number &, const mpq_class &)) {
  double d = static_cast<double>(x);
  while (std::isfinite(d) && !confirmed(x, exact_rational(d))) d = std::nextafter(d, toward);
  if (!std::isfinite(d)) throw std::overflow_error("domain::real_bounds: a number beyond the range of double");
  return exact_rational(d);
}

// 2 arccosh(sqrt(max(x, 1))), every step rounded in the direction rnd.
double twice_arccosh_sqrt(const mpq_class &x, mpfr_rnd_t rnd) {
  Mpfr m;
  mpfr_set_q(m.v, x.get_mpq_t(), rnd);
  mpfr_sqrt(m.v, m.v, rnd);
  if (mpfr_cmp_ui(m.v, 1) < 0) mpfr_set_ui(m.v, 1, rnd);
  mpfr_acosh(m.v, m.v, rnd);
  mpfr_mul_2ui(m.v, m.v, 1, rnd);
  return mpfr_get_d(m.v, rnd);
}

}  // namespace

mpq_class rational_above(const Number &x) {
  return rational_stepping(x, INFINITY, [](const Number &y, const mpq_class &q) { return y <= q; });
}

mpq_class rational_below(const Number &x) {
  return rational_stepping(x, -INFINITY, [](const Number &y, const mpq_class &q) { return q <= y; });
}

DoubleInterval length_from_cosh2_half(const Number &X) {
  return {twice_arccosh_sqrt(rational_below(X), MPFR_RNDD), twice_arccosh_sqrt(rational_above(X), MPFR_RNDU)};
}

double arccosh_above(const Number &x) {
  Mpfr m;
  mpfr_set_q(m.v, rational_above(x).get_mpq_t(), MPFR_RNDU);
  mpfr_acosh(m.v, m.v, MPFR_RNDU);
  return mpfr_get_d(m.v, MPFR_RNDU);
}

mpq_class cosh_above(double t) {
  Mpfr m;
  mpfr_set_d(m.v, t, MPFR_RNDU);  // exact: t is a double
  mpfr_cosh(m.v, m.v, MPFR_RNDU);
  return exact_rational(mpfr_get_d(m.v, MPFR_RNDU));
}

double sum_above(double a, double b) {
  Mpfr m;
  mpfr_set_d(m.v, a, MPFR_RNDU);
  mpfr_add_d(m.v, m.v, b, MPFR_RNDU);
  return mpfr_get_d(m.v, MPFR_RNDU);
}

}  // namespace hdt::domain
