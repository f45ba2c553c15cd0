#include "domain/ball.hpp"

#include <e-antic/renf_class.hpp>
#include <flint/fmpq.h>

#include <stdexcept>

namespace hdt::domain {

namespace {

void set_rational(arb_ptr out, const mpq_class &q) {
  fmpq_t f;
  fmpq_init(f);
  fmpq_set_mpq(f, q.get_mpq_t());
  arb_set_fmpq(out, f, kBallBits);
  fmpq_clear(f);
}

template <class F>
RealBall real_op(F f) {
  RealBall r;
  f(r.get());
  return r;
}

template <class F>
ComplexBall complex_op(F f) {
  ComplexBall r;
  f(r.get());
  return r;
}

}  // namespace

double RealBall::upper() const {
  arf_t u;
  arf_init(u);
  arb_get_ubound_arf(u, x_, 53);
  const double d = arf_get_d(u, ARF_RND_CEIL);
  arf_clear(u);
  return d;
}

double RealBall::lower() const {
  arf_t l;
  arf_init(l);
  arb_get_lbound_arf(l, x_, 53);
  const double d = arf_get_d(l, ARF_RND_FLOOR);
  arf_clear(l);
  return d;
}

// A number of K: e-antic's enclosure at our precision (it refines the
// field's embedding as needed: the caller holds the field lock).
RealBall ball_of(const Number &x) {
  RealBall r;
  if (x.is_rational())
    set_rational(r.get(), static_cast<mpq_class>(x));
  else
    renf_elem_get_arb(r.get(), x.renf_elem_t(), x.parent().renf_t(), kBallBits);
  if (!arb_is_finite(r.get())) throw std::overflow_error("domain::ball_of: no finite enclosure");
  return r;
}

ComplexBall ball_of(const Complex &z) {
  const RealBall re = ball_of(z.re), im = ball_of(z.im);
  ComplexBall c;
  arb_set(acb_realref(c.get()), re.get());
  arb_set(acb_imagref(c.get()), im.get());
  return c;
}

ComplexBall complex_ball(double re, double im) {
  ComplexBall c;
  acb_set_d_d(c.get(), re, im);
  return c;
}

RealBall operator+(const RealBall &a, const RealBall &b) {
  return real_op([&](arb_ptr r) { arb_add(r, a.get(), b.get(), kBallBits); });
}
RealBall operator-(const RealBall &a, const RealBall &b) {
  return real_op([&](arb_ptr r) { arb_sub(r, a.get(), b.get(), kBallBits); });
}
RealBall operator*(const RealBall &a, const RealBall &b) {
  return real_op([&](arb_ptr r) { arb_mul(r, a.get(), b.get(), kBallBits); });
}
RealBall operator/(const RealBall &a, const RealBall &b) {
  return real_op([&](arb_ptr r) { arb_div(r, a.get(), b.get(), kBallBits); });
}
ComplexBall operator+(const ComplexBall &a, const ComplexBall &b) {
  return complex_op([&](acb_ptr r) { acb_add(r, a.get(), b.get(), kBallBits); });
}
ComplexBall operator-(const ComplexBall &a, const ComplexBall &b) {
  return complex_op([&](acb_ptr r) { acb_sub(r, a.get(), b.get(), kBallBits); });
}
ComplexBall operator*(const ComplexBall &a, const ComplexBall &b) {
  return complex_op([&](acb_ptr r) { acb_mul(r, a.get(), b.get(), kBallBits); });
}
ComplexBall operator/(const ComplexBall &a, const ComplexBall &b) {
  return complex_op([&](acb_ptr r) { acb_div(r, a.get(), b.get(), kBallBits); });
}
ComplexBall conj(const ComplexBall &a) {
  return complex_op([&](acb_ptr r) { acb_conj(r, a.get()); });
}
ComplexBall sqrt(const ComplexBall &a) {
  return complex_op([&](acb_ptr r) { acb_sqrt(r, a.get(), kBallBits); });
}
RealBall real(const ComplexBall &a) {
  return real_op([&](arb_ptr r) { arb_set(r, acb_realref(a.get())); });
}
RealBall imag(const ComplexBall &a) {
  return real_op([&](arb_ptr r) { arb_set(r, acb_imagref(a.get())); });
}
RealBall norm2(const ComplexBall &a) {
  return real_op([&](arb_ptr r) {
    arb_t t;
    arb_init(t);
    arb_sqr(r, acb_realref(a.get()), kBallBits);
    arb_sqr(t, acb_imagref(a.get()), kBallBits);
    arb_add(r, r, t, kBallBits);
    arb_clear(t);
  });
}
RealBall abs(const RealBall &a) {
  return real_op([&](arb_ptr r) { arb_abs(r, a.get()); });
}
RealBall sqrt(const RealBall &a) {
  return real_op([&](arb_ptr r) { arb_sqrt(r, a.get(), kBallBits); });
}
RealBall sinh(const RealBall &a) {
  return real_op([&](arb_ptr r) { arb_sinh(r, a.get(), kBallBits); });
}
RealBall cosh(const RealBall &a) {
  return real_op([&](arb_ptr r) { arb_cosh(r, a.get(), kBallBits); });
}
RealBall asinh(const RealBall &a) {
  return real_op([&](arb_ptr r) { arb_asinh(r, a.get(), kBallBits); });
}
RealBall acosh(const RealBall &a) {
  return real_op([&](arb_ptr r) { arb_acosh(r, a.get(), kBallBits); });
}

ErrorDouble error_double(const RealBall &x) {
  const double v = x.mid();
  return {v, abs(x - RealBall(v)).upper()};
}

}  // namespace hdt::domain
