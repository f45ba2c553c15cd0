// Arb's balls (FLINT/Arb): certified enclosures of real and complex numbers.
// Every operation returns a ball that holds the exact result of the same
// operation on any numbers inside its arguments, so a comparison that Arb
// decides (certainly_less) is true of the exact numbers; one it cannot decide
// says so. The systole's walk (systole.hpp) runs on them: the exact numbers
// of K(i) only enter at its start and its end.
#pragma once

#include <acb.h>
#include <arb.h>

#include "domain/complex.hpp"
#include "domain/error_double.hpp"

namespace hdt::domain {

// Working precision: 128 bits keep balls far narrower than the gaps the walk
// decides on (tiles at cosh-distances up to 10^12 from the base point).
constexpr slong kBallBits = 128;

class RealBall {
 public:
  RealBall() { arb_init(x_); }
  explicit RealBall(double v) : RealBall() { arb_set_d(x_, v); }
  RealBall(const RealBall &o) : RealBall() { arb_set(x_, o.x_); }
  RealBall &operator=(const RealBall &o) {
    arb_set(x_, o.x_);
    return *this;
  }
  ~RealBall() { arb_clear(x_); }
  arb_ptr get() { return x_; }
  arb_srcptr get() const { return x_; }
  double mid() const { return arf_get_d(arb_midref(x_), ARF_RND_NEAR); }
  double upper() const;  // >= every number in the ball
  double lower() const;  // <= every number in the ball

 private:
  arb_t x_;
};

class ComplexBall {
 public:
  ComplexBall() { acb_init(z_); }
  ComplexBall(const ComplexBall &o) : ComplexBall() { acb_set(z_, o.z_); }
  ComplexBall &operator=(const ComplexBall &o) {
    acb_set(z_, o.z_);
    return *this;
  }
  ~ComplexBall() { acb_clear(z_); }
  acb_ptr get() { return z_; }
  acb_srcptr get() const { return z_; }

 private:
  acb_t z_;
};

RealBall ball_of(const Number &x);
ComplexBall ball_of(const Complex &z);
ComplexBall complex_ball(double re, double im);

RealBall operator+(const RealBall &a, const RealBall &b);
RealBall operator-(const RealBall &a, const RealBall &b);
RealBall operator*(const RealBall &a, const RealBall &b);
RealBall operator/(const RealBall &a, const RealBall &b);
ComplexBall operator+(const ComplexBall &a, const ComplexBall &b);
ComplexBall operator-(const ComplexBall &a, const ComplexBall &b);
ComplexBall operator*(const ComplexBall &a, const ComplexBall &b);
ComplexBall operator/(const ComplexBall &a, const ComplexBall &b);
ComplexBall conj(const ComplexBall &a);
ComplexBall sqrt(const ComplexBall &a);
RealBall real(const ComplexBall &a);
RealBall imag(const ComplexBall &a);
RealBall norm2(const ComplexBall &a);  // |a|^2
RealBall abs(const RealBall &a);
RealBall sqrt(const RealBall &a);
RealBall sinh(const RealBall &a);
RealBall cosh(const RealBall &a);
RealBall asinh(const RealBall &a);
RealBall acosh(const RealBall &a);

// The nearest double to the ball's centre, with the ball's distance from it
// rounded up (infinite for a ball that is not finite): the double stages
// (error_double.hpp) start from these.
ErrorDouble error_double(const RealBall &x);

// Decided by Arb: true only when every number of a is below every number of b.
inline bool certainly_less(const RealBall &a, const RealBall &b) { return arb_lt(a.get(), b.get()); }

}  // namespace hdt::domain
