#include "group/canonical.hpp"

#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "exact/precision_ladder.hpp"
#include "group/dehn.hpp"
#include "group/generators.hpp"
#include "group/word_matrix.hpp"

namespace hdt::group {

namespace {

// Bits needed to decide every separation test on a word of m letters: the
// amplified rounding error (word_precision_bits) must stay far below the
// margin 2(A^2 - 1) >= 2.
double bits_needed(const Presentation &p, std::size_t m) { return 64.0 + word_precision_bits(p, m); }

// The least letter k such that the line of side s_k separates O from h(O),
// h the element of the Dehn-reduced, non-empty word w.
template <class T>
Letter least_first_letter(const Presentation &p, const Word &w) {
  const GeneratorSet<T> &gens = shared_generators<T>(p);
  const HyperboloidPoint<T> origin{};
  const HyperboloidPoint<T> P = gens.apply(w, origin);
  const T A = gens.moebius(0).a.re;
  const T margin = A * A - T(1);  // half the proven bound 2(A^2 - 1)
  for (Letter k = 0; k < p.letter_count(); ++k) {
    const HyperboloidPoint<T> Q = gens.lorentz(k).apply(origin);  // g_k(O)
    const T side = P.t * (T(1) - Q.t) + P.u * Q.u + P.v * Q.v;  // <P, O - Q>
    using std::abs;
    if (abs(side) < margin)
      throw std::logic_error("canonical_word: separation test below its certified margin for " + word_to_string(w));
    if (side > 0) return k;
  }
  // No line separates: h(O) = O, so h is the identity, impossible for a
  // non-empty Dehn-reduced word.
  throw std::logic_error("canonical_word: no separating side for the Dehn-reduced word " + word_to_string(w));
}

// The generators' Lorentz matrices rounded from multiprecision (within one
// ulp per entry), once per genus.
const std::vector<Lorentz<double>> &rounded_generators(const Presentation &p) {
  static std::mutex mutex;
  static std::map<int, std::unique_ptr<std::vector<Lorentz<double>>>> cache;
  std::lock_guard<std::mutex> lock(mutex);
  auto &slot = cache[p.genus()];
  if (!slot) {
    auto v = std::make_unique<std::vector<Lorentz<double>>>();
    for (Letter k = 0; k < p.letter_count(); ++k) v->push_back(accurate_lorentz(p, Word{k}));
    slot = std::move(v);
  }
  return *slot;
}

// least_first_letter in double precision with a running error bound; false
// when the bound cannot certify every test (long words), and the
// multiprecision ladder decides. Most words met by a triangulation are short.
bool least_first_letter_double(const Presentation &p, const Word &w, Letter *out) {
  constexpr double u = 0x1p-53;
  const std::vector<Lorentz<double>> &L = rounded_generators(p);
  double P[3] = {1, 0, 0}, E[3] = {0, 0, 0};  // h(O) and a bound on its error
  for (std::size_t i = w.size(); i-- > 0;) {
    const auto &m = L[w[i]].m;
    double Q[3], F[3];
    for (int r = 0; r < 3; ++r) {
      Q[r] = m[r][0] * P[0] + m[r][1] * P[1] + m[r][2] * P[2];
      const double S = std::abs(m[r][0] * P[0]) + std::abs(m[r][1] * P[1]) + std::abs(m[r][2] * P[2]);
      const double carried = std::abs(m[r][0]) * E[0] + std::abs(m[r][1]) * E[1] + std::abs(m[r][2]) * E[2];
      // One ulp in each entry of m, three roundings in the sum, slack.
      F[r] = (carried + 6 * u * S) * (1 + 8 * u);
    }
    for (int r = 0; r < 3; ++r) P[r] = Q[r], E[r] = F[r];
  }
  const double A = L[0].m[0][0];  // cosh of the translation length = 2 A'^2 - 1 with A' = cot(pi/4g)
  const double margin = (A + 1) / 2 - 1;  // A'^2 - 1, the proven half-gap (less a hair below)
  for (Letter k = 0; k < p.letter_count(); ++k) {
    const auto &m = L[k].m;  // g_k(O) is the first column
    const double n[3] = {1 - m[0][0], m[1][0], m[2][0]};
    const double side = P[0] * n[0] + P[1] * n[1] + P[2] * n[2];
    const double size = std::abs(P[0] * n[0]) + std::abs(P[1] * n[1]) + std::abs(P[2] * n[2]);
    const double error = (E[0] * std::abs(n[0]) + E[1] * std::abs(n[1]) + E[2] * std::abs(n[2]) + 8 * u * size) * 1.01;
    if (!(error < 0.5 * margin) || std::abs(side) <= error) return false;
    if (side > 0) {
      *out = k;
      return true;
    }
  }
  return false;
}

Letter least_first_letter_at(const Presentation &p, const Word &w) {
  if (Letter k; least_first_letter_double(p, w, &k)) return k;
  return exact::with_precision(bits_needed(p, w.size()),
                               [&](auto zero) { return least_first_letter<decltype(zero)>(p, w); });
}

}  // namespace

std::size_t canonical_max_length(const Presentation &p) {
  // bits_needed(m) = 64 + b m + 2 log2(m + 2) with b = word_precision_bits(p, 1) - 2 log2(3);
  // bound the logarithm by that of the top and keep 2 letters of slack for
  // the peeled words.
  const double top = exact::ladder_top_bits();
  const double per_letter = (word_precision_bits(p, 1) - 2.0 * std::log2(3.0));
  const double m = std::floor((top - 64.0 - 2.0 * std::log2(top + 2.0)) / per_letter) - 2.0;
  return m > 0 ? std::size_t(m) : 0;
}

bool shortlex_less(const Word &a, const Word &b) {
  if (a.size() != b.size()) return a.size() < b.size();
  return a < b;
}

Word canonical_word(const Presentation &p, const Letter *input, std::size_t length) {
  p.check_word(input, length);
  Word w = dehn_reduce(p, input, length);
  const std::size_t limit = canonical_max_length(p);
  if (w.size() > limit)
    throw std::length_error("the Dehn-reduced word has " + std::to_string(w.size()) +
                            " letters; canonical words are computed up to " + std::to_string(limit) +
                            " letters for genus " + std::to_string(p.genus()));
  // Peel the least possible first letter off h until nothing is left. Each
  // step lowers the geodesic length by one, so there are at most |w| steps.
  Word out;
  const std::size_t bound = w.size();
  while (!w.empty()) {
    if (out.size() >= bound) throw std::logic_error("canonical_word: peeling did not shorten the word");
    const Letter k = least_first_letter_at(p, w);
    out.push_back(k);
    Word rest;
    rest.reserve(w.size() + 1);
    rest.push_back(p.inverse(k));
    rest.insert(rest.end(), w.begin(), w.end());
    w = dehn_reduce(p, rest);
    if (w.size() > limit + 1) throw std::logic_error("canonical_word: a peeled word outgrew the precision");
  }
  return out;
}

}  // namespace hdt::group
