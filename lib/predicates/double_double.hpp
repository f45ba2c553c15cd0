// Double-double ("double-word") reals for the kernel's fast refined stage.
//
// A value is the unevaluated sum hi + lo of two doubles, normalised:
// hi = RN(hi + lo), so |lo| <= ulp(hi)/2 <= u |hi| with u = 2^-53. Every
// operation below returns a normalised pair within a relative error of the
// exact result of the operation on its (exact) inputs, the standard model
// |op~(a, b) - a op b| <= e |a op b| with (u^2 = 2^-106):
//   +, -  e <= 3u^2 / (1 - 4u)   (accurate DW+DW, Joldes, Muller & Popescu,
//                                 ACM TOMS 44(2), 2017, Algorithm 6);
//   *     e <= 8.01 u^2          (derived at operator*);
//   /     e <= 12.2 u^2          (derived at operator/).
// All are below 13u^2 < 2^-102, so a caller may use the unit 2^-100 (64u^2)
// wherever an analysis assumes correctly rounded operations of that unit.
// These bounds hold without underflow (every pair's lo a normal double, so
// |hi| >= 2^-969) and overflow; in underflow each operation adds at most a
// few 2^-1074 absolutely, which callers must make negligible (they keep all
// magnitudes above 2^-200).
//
// Products are exact by TwoProduct: an FMA where the target has one,
// otherwise Dekker's splitting (no FMA contraction can happen then).
#pragma once

#include <cfloat>
#include <cmath>

// The error-free transformations need IEEE double operations rounded to
// nearest, each rounded once (SSE2, not x87 extended registers), and no
// value-changing optimisation.
static_assert(FLT_EVAL_METHOD == 0, "double-double needs double evaluation of double expressions");
#if defined(__FAST_MATH__)
#error "double-double arithmetic is not valid under -ffast-math"
#endif

namespace hdt::predicates {

struct DoubleDouble {
  double hi = 0, lo = 0;

  constexpr DoubleDouble() = default;
  constexpr explicit DoubleDouble(double x) : hi(x), lo(0) {}
  explicit operator double() const { return hi; }  // RN(hi + lo) by normalisation

  // Fast2Sum (Dekker): a + b = s + e exactly when a == 0 or exponent(a) >=
  // exponent(b) (so in particular when |a| >= |b|); s = RN(a + b).
  static DoubleDouble fast_two_sum(double a, double b) {
    const double s = a + b;
    return from_parts(s, b - (s - a));
  }
  // TwoSum (Knuth/Moller): a + b = s + e exactly, s = RN(a + b), any a, b.
  static DoubleDouble two_sum(double a, double b) {
    const double s = a + b, bb = s - a;
    return from_parts(s, (a - (s - bb)) + (b - bb));
  }
  // TwoProduct: a b = p + e exactly, p = RN(a b) (no underflow; |a|, |b| <
  // 2^995 for the splitting).
  static DoubleDouble two_product(double a, double b) {
    const double p = a * b;
#if defined(__FMA__) || defined(__FP_FAST_FMA)
    return from_parts(p, std::fma(a, b, -p));
#else
    auto split = [](double x, double &h, double &l) {
      const double c = 134217729.0 * x;  // 2^27 + 1
      h = c - (c - x);
      l = x - h;
    };
    double ah, al, bh, bl;
    split(a, ah, al);
    split(b, bh, bl);
    return from_parts(p, ((ah * bh - p) + ah * bl + al * bh) + al * bl);
#endif
  }

  DoubleDouble operator-() const { return from_parts(-hi, -lo); }

 private:
  static constexpr DoubleDouble from_parts(double h, double l) {
    DoubleDouble r;
    r.hi = h, r.lo = l;
    return r;
  }
};

// Accurate DW+DW (Algorithm 6 of Joldes, Muller & Popescu 2017; the QD
// library's ieee_add): relative error <= 3u^2 / (1 - 4u) even under
// cancellation.
inline DoubleDouble operator+(const DoubleDouble &x, const DoubleDouble &y) {
  const DoubleDouble s = DoubleDouble::two_sum(x.hi, y.hi);
  const DoubleDouble t = DoubleDouble::two_sum(x.lo, y.lo);
  const DoubleDouble v = DoubleDouble::fast_two_sum(s.hi, s.lo + t.hi);
  return DoubleDouble::fast_two_sum(v.hi, t.lo + v.lo);
}

inline DoubleDouble operator-(const DoubleDouble &x, const DoubleDouble &y) { return x + (-y); }

// x y with x = xh + xl, y = yh + yl, |xl| <= u |xh|, |yl| <= u |yh|, and
// P = |xh yh|:
//   (ph, pl) = TwoProduct(xh, yh)     exact, |pl| <= u P;
//   t1 = RN(xh yl), t2 = RN(xl yh)    each within u * u P;
//   t3 = RN(t1 + t2)                  |t1 + t2| <= 2u(1+u) P, within 2u^2(1+u) P;
//   t4 = RN(pl + t3)                  |pl + t3| <= 3u(1+u)^2 P, within 3u^2(1+u)^2 P;
//   xl yl is dropped                  <= u^2 P;
//   Fast2Sum(ph, t4)                  exact (|t4| < |ph|).
// Total <= 8u^2 (1 + 2u)^2 P, and P <= |x y| / (1 - u)^2: <= 8.01 u^2 |x y|.
inline DoubleDouble operator*(const DoubleDouble &x, const DoubleDouble &y) {
  const DoubleDouble p = DoubleDouble::two_product(x.hi, y.hi);
  const double t3 = x.hi * y.lo + x.lo * y.hi;
  return DoubleDouble::fast_two_sum(p.hi, p.lo + t3);
}

// x / y, |Q| = |x / y| (no underflow, y != 0):
//   q0 = RN(xh / yh)                  xh / yh = Q (1+b) / (1+a), |a|, |b| <= u:
//                                      |q0 - Q| <= 3.01u |Q|;
//   p = y * q0 (dd x double, as operator* with ql = 0: three roundings, u^2
//       + 2u^2(1+u) of |yh q0|)       |p - y q0| <= 3.01u^2 |y q0| <= 3.02u^2 |x|;
//   r = x - p (accurate DW+DW)        r_e = x - y q0 = y (Q - q0), |r_e| <= 3.01u |x|;
//                                      |r - (x - p)| <= 3.0001u^2 |x - p| <= 9.1u^3 |x|,
//                                      so |r - r_e| <= (3.02u^2 + 9.1u^3) |x|;
//   q1 = RN(rh / yh)                  within 3.01u of |r / y| <= 3.03u |Q|: 9.13u^2 |Q|;
//   Fast2Sum(q0, q1)                  exact (|q1| <= 3.1u |q0|).
// Q = q0 + r_e / y, so |q0 + q1 - Q| <= |q1 - r / y| + |r - r_e| / |y|
// <= (9.13 + 3.03) u^2 |Q| < 12.2 u^2 |Q|.
inline DoubleDouble operator/(const DoubleDouble &x, const DoubleDouble &y) {
  const double q0 = x.hi / y.hi;
  const DoubleDouble p = DoubleDouble::two_product(y.hi, q0);
  const DoubleDouble yq = DoubleDouble::fast_two_sum(p.hi, p.lo + y.lo * q0);
  const DoubleDouble r = x - yq;
  return DoubleDouble::fast_two_sum(q0, r.hi / y.hi);
}

}  // namespace hdt::predicates
