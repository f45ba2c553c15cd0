#include "domain/representative.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>

#include "domain/base_point.hpp"
#include "domain/klein.hpp"

namespace hdt::domain {

struct Reduction::Walk {
  Complex from, to;              // t(c) and t(z)
  Element t;                     // the pull-back so far
  std::vector<int> applied;      // the pairings applied, first first
  std::size_t crossings = 0;
};

Reduction::Reduction(const FundamentalPolygon &P)
    : P_(P), klein_(P), base_(base_point(P)), g_(pairing_elements(P)), floating_(P, base_) {}

Representative Reduction::operator()(double x, double y) const {
  const std::optional<std::vector<int>> applied = floating_.pairings_applied(x, y);
  if (!applied) return (*this)(P_.exact_point(x, y));
  // The exact walk's pull-backs, without its exact decisions.
  Complex to = P_.exact_point(x, y);
  Element t = identity_element(base_.re);
  for (const int k : *applied) to = g_[std::size_t(k)].apply(to), t = g_[std::size_t(k)] * t;
  std::vector<int> letters(applied->rbegin(), applied->rend());
  return {{std::move(letters), std::move(t)}, std::move(to), applied->size()};
}

std::vector<int> Reduction::pairings_applied(double x, double y) const {
  if (std::optional<std::vector<int>> applied = floating_.pairings_applied(x, y)) return std::move(*applied);
  const std::vector<int> letters = (*this)(P_.exact_point(x, y)).word.letters;
  return {letters.rbegin(), letters.rend()};
}

// The least exit root among the sides whose f decreases from A to B; on a
// tie the smaller index (see representative.hpp: either is right).
int Reduction::exit_side(const Complex &from, const Complex &to) const {
  const Complex A = klein(from), B = klein(to);
  if (klein_.contains(B)) return -1;
  int best = -1;
  Number best_root;
  for (int k = 0; k < klein_.side_count(); ++k) {
    const Number fa = klein_.side_value(k, A), fb = klein_.side_value(k, B);
    if (fb >= fa) continue;
    const Number root = fa / (fa - fb);
    if (best < 0 || root < best_root) best = k, best_root = root;
  }
  if (best < 0) throw std::logic_error("domain::Reduction: a point outside P with no exit side");
  return best;
}

void Reduction::pull_back(Walk &w, int k) const {
  const Element &g = g_[std::size_t(k)];
  w.from = g.apply(w.from);
  w.to = g.apply(w.to);
  w.t = g * w.t;
  w.applied.push_back(k);
}

// Along v -> paired(v) + 1 until the cycle's smallest vertex.
void Reduction::to_smallest_vertex(Walk &w, int v) const {
  const auto &cycles = P_.cycles();
  const auto cycle = std::find_if(cycles.begin(), cycles.end(), [v](const std::vector<int> &c) {
    return std::find(c.begin(), c.end(), v) != c.end();
  });
  const int smallest = *std::min_element(cycle->begin(), cycle->end());
  for (; v != smallest; v = (P_.paired(v) + 1) % P_.side_count()) pull_back(w, P_.paired(v));
}

// The sides whose line holds the point: none (interior), one (inside a
// side), or two consecutive ones k - 1 and k (the vertex v_k).
void Reduction::into_fundamental_set(Walk &w) const {
  const Complex x = klein(w.to);
  std::vector<int> on;
  for (int k = 0; k < klein_.side_count(); ++k)
    if (klein_.side_value(k, x).is_zero()) on.push_back(k);
  if (on.size() == 1 && on[0] > P_.paired(on[0])) pull_back(w, P_.paired(on[0]));
  if (on.size() == 2) to_smallest_vertex(w, on[1] - on[0] == 1 ? on[1] : 0);
}

namespace {

// Rational coordinates moved into the field of `like`, so that all the
// arithmetic has one parent (as FundamentalPolygon does for its vertices).
Number in_field(const Number &x, const Number &like) {
  return x.is_rational() ? Number(like.parent(), static_cast<mpq_class>(x)) : x;
}

// More crossings than any segment in the disk meets at the precision a
// caller can give: only a bug of this file would get there.
constexpr std::size_t crossing_limit = 10000000;

}  // namespace

Representative Reduction::operator()(const Complex &z) const {
  const Complex start{in_field(z.re, base_.re), in_field(z.im, base_.re)};
  if (norm2(start) >= 1) throw std::domain_error("domain::Reduction: a point outside the open unit disk");
  Walk w{base_, start, identity_element(base_.re), {}};
  for (int k; (k = exit_side(w.from, w.to)) >= 0; ++w.crossings) {
    if (w.crossings > crossing_limit) throw std::logic_error("domain::Reduction: the walk does not end");
    pull_back(w, P_.paired(k));
  }
  into_fundamental_set(w);
  std::vector<int> letters(w.applied.rbegin(), w.applied.rend());
  return {{std::move(letters), w.t}, w.to, w.crossings};
}

Representative representative(const FundamentalPolygon &P, const Complex &z) { return Reduction(P)(z); }

}  // namespace hdt::domain
