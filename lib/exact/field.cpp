#include "exact/field.hpp"

#include <mpfr.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <iterator>
#include <map>
#include <optional>
#include <stdexcept>

#include "exact/multiprecision.hpp"

namespace hdt::exact {

// cos(2 pi j / n) for the basis powers and sigma, at the precision of T.
template <class T>
struct Field::Evaluator {
  std::vector<T> cosines;
  T sigma;
  T unit;  // 2^-p: the relative rounding unit of T (a double underflows to 0 beyond 1074 bits)

  Evaluator(const CyclotomicField &base, int genus) {
    using std::cos;
    using std::sqrt;
    const T two_pi = T(2) * exact::pi<T>();
    for (int j = 0; j < base.degree(); ++j) cosines.push_back(cos(two_pi * T(j) / T(base.order())));
    sigma = sqrt(cos(exact::pi<T>() / T(2 * genus)));
    using std::ldexp;
    unit = ldexp(T(1), -int(std::numeric_limits<T>::digits));
  }

  // sum c_j cos(2 pi j/n), unscaled by 2^exponent, and sum |c_j|.
  void evaluate(const Cyclotomic &c, T &value, T &magnitude) const {
    value = 0;
    magnitude = 0;
    const auto &coefficients = c.coefficients();
    for (std::size_t j = 0; j < coefficients.size(); ++j) {
      if (coefficients[j] == 0) continue;
      const T x = convert(coefficients[j]);
      value += x * cosines[j];
      magnitude += x < 0 ? T(-x) : x;
    }
  }

  static T convert(const Integer &z) {
    if constexpr (std::is_same_v<T, double>)
      return z.template convert_to<double>();
    else
      return T(z);
  }
};

namespace {

template <class T>
T scale2(const T &x, int e) {
  using std::ldexp;
  return ldexp(x, e);
}

}  // namespace

Field::Field(int genus) : genus_(genus), base_(8 * genus), sigma_squared_(base_.cos_2pi(2)) {
  if (genus < 2) throw std::invalid_argument("Field: genus must be at least 2");
  evaluators_.resize(1 + std::size(kRungDigits10));
}

FieldElement Field::add(const FieldElement &a, const FieldElement &b) const {
  return {base_.add(a.u, b.u), base_.add(a.v, b.v)};
}
FieldElement Field::sub(const FieldElement &a, const FieldElement &b) const {
  return {base_.sub(a.u, b.u), base_.sub(a.v, b.v)};
}
FieldElement Field::neg(const FieldElement &a) const { return {base_.neg(a.u), base_.neg(a.v)}; }

FieldElement Field::mul(const FieldElement &a, const FieldElement &b) const {
  // (u + v s)(u' + v' s) = u u' + v v' s^2 + (u v' + v u') s
  const Cyclotomic vv = base_.mul(a.v, b.v);
  return {base_.add(base_.mul(a.u, b.u), base_.mul(vv, sigma_squared_)),
          base_.add(base_.mul(a.u, b.v), base_.mul(a.v, b.u))};
}

FieldElement Field::mul(const FieldElement &a, const Cyclotomic &b) const {
  return {base_.mul(a.u, b), base_.mul(a.v, b)};
}

bool Field::is_zero(const FieldElement &a) const {
  // u + v sigma = 0 with v != 0 would put sigma = -u/v in Q(zeta_8g), and it
  // never is: Q(zeta_8g) is abelian over Q, so its real subfield Q(sigma)
  // would be Galois, hence totally real; but sigma^2 = cos(pi/2g) has the
  // conjugate cos((2g-1) pi/2g) = -cos(pi/2g) < 0 (2g-1 is prime to 4g), whose
  // square roots are not real. So zero is exactly u = v = 0.
  return a.u.is_zero() && a.v.is_zero();
}

template <class T>
const Field::Evaluator<T> &Field::evaluator() const {
  // Slot 0 for double, then one per rung of the table.
  constexpr std::size_t slot = [] {
    if constexpr (std::is_same_v<T, double>)
      return std::size_t(0);
    else
      return 1 + rung_index(RungOf<T>::digits10);
  }();
  static_assert(slot <= std::size(kRungDigits10), "an evaluator of double or of a rung");
  std::lock_guard<std::mutex> lock(mutex_);
  if (!evaluators_[slot]) evaluators_[slot] = std::make_shared<Evaluator<T>>(base_, genus_);
  return *static_cast<const Evaluator<T> *>(evaluators_[slot].get());
}

template <class T>
void Field::evaluate(const FieldElement &a, T *value_out, T *bound_out, int *exponent) const {
  const Evaluator<T> &ev = evaluator<T>();
  T U, Um, V, Vm;
  ev.evaluate(a.u, U, Um);
  ev.evaluate(a.v, V, Vm);
  // Bring both parts to the smaller exponent (the larger one is scaled up).
  const int e = std::min(a.u.is_zero() ? a.v.exponent() : a.u.exponent(),
                         a.v.is_zero() ? a.u.exponent() : a.v.exponent());
  if (!a.u.is_zero()) {
    U = scale2(U, a.u.exponent() - e);
    Um = scale2(Um, a.u.exponent() - e);
  }
  if (!a.v.is_zero()) {
    V = scale2(V, a.v.exponent() - e);
    Vm = scale2(Vm, a.v.exponent() - e);
  }
  const T value = U + ev.sigma * V;
  // Rounding of the coefficients, the cosines (argument rounding included),
  // sigma, the products and the sums: far below (d + 64) units per unit of
  // magnitude (sigma < 1, counted as 2). Both in units of 2^e.
  *value_out = value;
  *bound_out = (Um + T(2) * Vm) * (T(double(ev.cosines.size() + 64)) * ev.unit);
  *exponent = e;
}

template <class T>
Sign Field::sign_at(const FieldElement &a) const {
  T value, bound;
  int e;
  evaluate(a, &value, &bound, &e);
  if constexpr (std::is_same_v<T, double>)
    if (!std::isfinite(value) || !std::isfinite(bound)) return Sign::undecided;
  if (value > bound) return Sign::positive;
  if (value < -bound) return Sign::negative;
  return Sign::undecided;
}

Sign Field::sign(const Cyclotomic &a) const { return sign(FieldElement{a, {}}); }

Sign Field::sign(const FieldElement &a) const {
  // Zero exactly when u = v = 0 (is_zero); otherwise rising precision
  // terminates.
  if (is_zero(a)) return Sign::zero;
  if (const Sign s = sign_at<double>(a); decided(s)) return s;
  // Past the compile-time rungs, the run-time ones up to the precision that
  // the norm bound proves sufficient (sufficient_bits), where a non-zero
  // value is always decided.
  const auto if_decided = [](Sign s) { return decided(s) ? std::optional<Sign>(s) : std::nullopt; };
  long enough = 0;
  return *FieldLadder::climb(
      0, [&](auto zero) { return if_decided(sign_at<decltype(zero)>(a)); },
      [&](long bits) {
        if (enough == 0) enough = sufficient_bits(a);
        const std::optional<Sign> s = if_decided(sign_at_bits(a, std::min(bits, enough)));
        if (!s && bits >= enough)
          throw std::logic_error("Field::sign: the norm bound's precision did not decide (a bug)");
        return s;
      });
}

namespace {

// An MPFR value of a run-time precision, freed on scope exit.
struct Mpfr {
  explicit Mpfr(long bits) { mpfr_init2(x, mpfr_prec_t(bits)); }
  ~Mpfr() { mpfr_clear(x); }
  Mpfr(const Mpfr &) = delete;
  Mpfr &operator=(const Mpfr &) = delete;
  mpfr_t x;
};

// log2 of sum |c_j| 2^shift over the coefficients, rounded up.
double log2_magnitude(const Cyclotomic &c, int shift) {
  double most = -HUGE_VAL;
  for (const Integer &z : c.coefficients())
    if (z != 0) most = std::max(most, double(msb(abs(z)) + 1));
  return most + std::log2(double(c.coefficients().size())) + shift;
}

}  // namespace

long Field::sufficient_bits(const FieldElement &a) const {
  // Scaled by 2^-e (evaluate's common exponent), a is y = u' + v' sigma with
  // integer coefficients over the powers of zeta; sqrt 2 y is an algebraic
  // integer (sqrt 2 and sqrt 2 sigma are: (sqrt 2 sigma)^2 = 2 cos(pi/2g),
  // and sqrt 2 lies in Q(zeta_8g)). Its D <= 2 phi(8g) conjugates have
  // modulus at most sqrt 2 M, M = sum |u'_j| + sum |v'_j| (each power of
  // zeta maps to a root of unity, sigma to a square root of a cosine), and
  // their product, the norm, is a non-zero integer: |y| >= (sqrt 2 M)^-(D-1)
  // / sqrt 2. evaluate's error is at most 2 M (d + 64) 2^-p, so p bits with
  // 2^-p 4 M (d + 64) below that bound decide the sign.
  const int e = std::min(a.u.is_zero() ? a.v.exponent() : a.u.exponent(),
                         a.v.is_zero() ? a.u.exponent() : a.v.exponent());
  const double lu = a.u.is_zero() ? -HUGE_VAL : log2_magnitude(a.u, a.u.exponent() - e);
  const double lv = a.v.is_zero() ? -HUGE_VAL : log2_magnitude(a.v, a.v.exponent() - e);
  const double L = std::max(lu, lv) + 1;  // log2 M, rounded up
  const double D = 2.0 * base_.degree(), d = base_.degree();
  return long(std::ceil((D - 1) * (0.5 + L) + L + std::log2(d + 64) + 4));
}

Sign Field::sign_at_bits(const FieldElement &a, long bits) const {
  // evaluate<T> with T of `bits` bits, operation for operation, so that its
  // error bound holds with the unit 2^-bits.
  const int e = std::min(a.u.is_zero() ? a.v.exponent() : a.u.exponent(),
                         a.v.is_zero() ? a.u.exponent() : a.v.exponent());
  Mpfr two_pi(bits), t(bits), x(bits), value(bits), magnitude(bits), part(bits), part_magnitude(bits), sigma(bits);
  mpfr_const_pi(two_pi.x, MPFR_RNDN);
  mpfr_mul_2ui(two_pi.x, two_pi.x, 1, MPFR_RNDN);
  mpfr_set_zero(value.x, 1);
  mpfr_set_zero(magnitude.x, 1);
  for (int k = 0; k < 2; ++k) {
    const Cyclotomic &c = k == 0 ? a.u : a.v;
    mpfr_set_zero(part.x, 1);
    mpfr_set_zero(part_magnitude.x, 1);
    if (c.is_zero()) continue;
    const auto &coefficients = c.coefficients();
    for (std::size_t j = 0; j < coefficients.size(); ++j) {
      if (coefficients[j] == 0) continue;
      mpfr_mul_ui(t.x, two_pi.x, (unsigned long)j, MPFR_RNDN);  // cos(two_pi * j / n), as the rungs do
      mpfr_div_ui(t.x, t.x, (unsigned long)base_.order(), MPFR_RNDN);
      mpfr_cos(t.x, t.x, MPFR_RNDN);
      mpfr_set_z(x.x, coefficients[j].backend().data(), MPFR_RNDN);
      mpfr_mul(t.x, t.x, x.x, MPFR_RNDN);
      mpfr_add(part.x, part.x, t.x, MPFR_RNDN);
      mpfr_abs(x.x, x.x, MPFR_RNDN);
      mpfr_add(part_magnitude.x, part_magnitude.x, x.x, MPFR_RNDN);
    }
    mpfr_mul_2si(part.x, part.x, c.exponent() - e, MPFR_RNDN);  // exact
    mpfr_mul_2si(part_magnitude.x, part_magnitude.x, c.exponent() - e, MPFR_RNDN);
    if (k == 0) {
      mpfr_set(value.x, part.x, MPFR_RNDN);
      mpfr_set(magnitude.x, part_magnitude.x, MPFR_RNDN);
    } else {
      mpfr_const_pi(sigma.x, MPFR_RNDN);  // sqrt(cos(pi / 2g))
      mpfr_div_ui(sigma.x, sigma.x, (unsigned long)(2 * genus_), MPFR_RNDN);
      mpfr_cos(sigma.x, sigma.x, MPFR_RNDN);
      mpfr_sqrt(sigma.x, sigma.x, MPFR_RNDN);
      mpfr_mul(part.x, part.x, sigma.x, MPFR_RNDN);
      mpfr_add(value.x, value.x, part.x, MPFR_RNDN);
      mpfr_mul_2ui(part_magnitude.x, part_magnitude.x, 1, MPFR_RNDN);  // sigma counted as 2
      mpfr_add(magnitude.x, magnitude.x, part_magnitude.x, MPFR_RNDN);
    }
  }
  // bound = magnitude (d + 64) 2^-bits
  mpfr_mul_ui(magnitude.x, magnitude.x, (unsigned long)(base_.degree() + 64), MPFR_RNDU);
  mpfr_mul_2si(magnitude.x, magnitude.x, -bits, MPFR_RNDU);
  if (mpfr_cmp(value.x, magnitude.x) > 0) return Sign::positive;
  mpfr_neg(magnitude.x, magnitude.x, MPFR_RNDN);
  if (mpfr_cmp(value.x, magnitude.x) < 0) return Sign::negative;
  return Sign::undecided;
}

void Field::evaluate_133(const FieldElement &a, mp_real<40> *value, mp_real<40> *bound) const {
  if (a.u.is_zero() && a.v.is_zero()) {
    *value = *bound = 0;
    return;
  }
  int e;
  evaluate(a, value, bound, &e);
  *value = scale2(*value, e);  // exact
  *bound = scale2(*bound, e);
}

double Field::approximate(const FieldElement &a) const {
  using T = mp_real<40>;
  const Evaluator<T> &ev = evaluator<T>();
  T U, Um, V, Vm;
  ev.evaluate(a.u, U, Um);
  ev.evaluate(a.v, V, Vm);
  const T value = scale2(U, a.u.exponent()) + ev.sigma * scale2(V, a.v.exponent());
  return value.convert_to<double>();
}

const Field &field_of_genus(int genus) {
  static std::mutex mutex;
  static std::map<int, std::unique_ptr<const Field>> fields;
  std::lock_guard<std::mutex> lock(mutex);
  auto &slot = fields[genus];
  if (!slot) slot = std::make_unique<const Field>(genus);
  return *slot;
}

}  // namespace hdt::exact
