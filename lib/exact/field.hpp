// The field K_g = Q(zeta_{8g})(sigma), sigma = sqrt(cos(pi/2g)), exactly.
//
// Every coordinate libhdt meets is in K_g: the generators' Lorentz matrices
// (up to the positive factor sin(pi/4g)^-2 per letter, which no sign
// depends on), the points of Q0, and every translated image of a point given
// as doubles. An element is u + v sigma with u, v in Q(zeta_{8g}); it is zero
// exactly when u = v = 0, since sigma never lies in Q(zeta_{8g})
// (Field::is_zero in field.cpp has the argument). The sign of a real
// element is found by evaluation at rising precision with a rigorous error
// bound: double, then the rungs of
// FieldLadder (precision_ladder.hpp) up to 136063 bits, then its run-time
// rungs up to one that a lower bound on |a| from its norm proves
// sufficient, so every sign is decided, with no cap. Points placed far from
// O at genus 256 once needed more than the former top of 8503 bits.
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "exact/cyclotomic.hpp"
#include "exact/multiprecision.hpp"
#include "exact/precision_ladder.hpp"
#include "exact/sign.hpp"

namespace hdt::exact {

// The rungs of Field::sign after double: each about four times the last in
// digits, so a hard sign costs a few evaluations, the last dominating.
using FieldLadder = Ladder<40, 160, 640, 2560, 10240, 40960>;

struct FieldElement {
  Cyclotomic u, v;  // u + v sigma
};

class Field {
 public:
  explicit Field(int genus);
  Field(const Field &) = delete;
  Field &operator=(const Field &) = delete;

  int genus() const { return genus_; }
  const CyclotomicField &cyclotomic() const { return base_; }

  FieldElement zero() const { return {}; }
  FieldElement from_double(double x) const { return {base_.from_double(x), {}}; }
  FieldElement from_cyclotomic(const Cyclotomic &u) const { return {u, {}}; }
  FieldElement sigma() const { return {{}, base_.integer(1)}; }

  FieldElement add(const FieldElement &a, const FieldElement &b) const;
  FieldElement sub(const FieldElement &a, const FieldElement &b) const;
  FieldElement neg(const FieldElement &a) const;
  FieldElement mul(const FieldElement &a, const FieldElement &b) const;
  FieldElement mul(const FieldElement &a, const Cyclotomic &b) const;

  bool is_zero(const FieldElement &a) const;
  // Sign of a real element, exactly (never undecided).
  Sign sign(const FieldElement &a) const;
  // Sign of a real element of Q(zeta).
  Sign sign(const Cyclotomic &a) const;
  // The real element a in about 133 bits (*value) and a bound on that
  // value's error (*bound; 0 for a zero element), certified as sign()'s
  // evaluation: for computations that would rather not form exact products.
  void evaluate_133(const FieldElement &a, mp_real<40> *value, mp_real<40> *bound) const;
  // A double approximation (for tests and heuristics only).
  double approximate(const FieldElement &a) const;

 private:
  template <class T>
  struct Evaluator;
  template <class T>
  const Evaluator<T> &evaluator() const;
  // a's value at the precision of T and a bound on its error, both in
  // units of 2^*exponent.
  template <class T>
  void evaluate(const FieldElement &a, T *value, T *bound, int *exponent) const;
  // Sign at one precision, undecided when it cannot tell.
  template <class T>
  Sign sign_at(const FieldElement &a) const;
  // The same at a precision chosen at run time (FieldLadder's run-time rungs).
  Sign sign_at_bits(const FieldElement &a, long bits) const;
  // A precision at which sign_at_bits decides every non-zero a, from a
  // lower bound on |a| by its norm (field.cpp has the argument).
  long sufficient_bits(const FieldElement &a) const;

  int genus_;
  CyclotomicField base_;
  Cyclotomic sigma_squared_;  // cos(pi/2g)
  mutable std::mutex mutex_;
  mutable std::vector<std::shared_ptr<void>> evaluators_;
};

// One shared Field per genus, built on first use, alive for the process.
const Field &field_of_genus(int genus);

}  // namespace hdt::exact
