#include "exact/field.hpp"

#include <cfloat>
#include <cmath>
#include <map>
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
  evaluators_.resize(7);
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
  // Zero needs u = v = 0, unless sigma lies in Q(zeta) (then u^2 = v^2 sigma^2
  // and the signs of u and v decide); no evaluation otherwise.
  if (a.u.is_zero() || a.v.is_zero()) return a.u.is_zero() && a.v.is_zero();
  return norm_vanishes(a) && sign(a.u) != sign(a.v);
}

bool Field::norm_vanishes(const FieldElement &a) const {
  return base_.sub(base_.mul(a.u, a.u), base_.mul(base_.mul(a.v, a.v), sigma_squared_)).is_zero();
}

template <class T>
const Field::Evaluator<T> &Field::evaluator() const {
  constexpr int slot = std::is_same_v<T, double> ? 0 : std::numeric_limits<T>::digits10 <= 40 ? 1
                                                     : std::numeric_limits<T>::digits10 <= 160 ? 2
                                                     : std::numeric_limits<T>::digits10 <= 640 ? 3
                                                     : std::numeric_limits<T>::digits10 <= 2560 ? 4
                                                     : std::numeric_limits<T>::digits10 <= 10240 ? 5
                                                                                                 : 6;
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
int Field::sign_at(const FieldElement &a) const {
  T value, bound;
  int e;
  evaluate(a, &value, &bound, &e);
  if constexpr (std::is_same_v<T, double>)
    if (!std::isfinite(value) || !std::isfinite(bound)) return 2;
  if (value > bound) return 1;
  if (value < -bound) return -1;
  return 2;
}

int Field::sign(const Cyclotomic &a) const { return sign(FieldElement{a, {}}); }

int Field::sign(const FieldElement &a) const {
  if (a.u.is_zero() && a.v.is_zero()) return 0;
  if (!a.u.is_zero() && !a.v.is_zero()) {
    // u + v sigma = 0 with v != 0 would put sigma in Q(zeta); then
    // u^2 = v^2 sigma^2 and the value is 0 or 2u.
    if (norm_vanishes(a)) {
      const int su = sign(a.u), sv = sign(a.v);
      return su == sv ? su : 0;
    }
  }
  // Non-zero: rising precision terminates.
  int s = sign_at<double>(a);
  if (s != 2) return s;
  s = sign_at<mp_real<40>>(a);
  if (s != 2) return s;
  s = sign_at<mp_real<160>>(a);
  if (s != 2) return s;
  s = sign_at<mp_real<640>>(a);
  if (s != 2) return s;
  s = sign_at<mp_real<2560>>(a);
  if (s != 2) return s;
  s = sign_at<mp_real<10240>>(a);
  if (s != 2) return s;
  s = sign_at<mp_real<40960>>(a);
  if (s != 2) return s;
  throw std::logic_error("Field::sign: 136000 bits could not decide a non-zero value");
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
