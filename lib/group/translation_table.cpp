#include "group/translation_table.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "exact/unsupported.hpp"
#include "group/canonical.hpp"
#include "group/dehn.hpp"
#include "group/moebius_centre.hpp"
#include "group/neighbours.hpp"
#include "group/word_matrix.hpp"

namespace hdt::group {

std::size_t TranslationTable::WordHash::operator()(const Word &w) const noexcept {
  uint64_t h = 1469598103934665603ull;  // FNV-1a over the letters
  for (Letter k : w) h = (h ^ uint64_t(uint32_t(k))) * 1099511628211ull;
  return std::size_t(h);
}

TranslationTable::TranslationTable(const Presentation &p)
    : presentation_(p), neighbour_count_(group::neighbour_count(p)), centres_(p) {
  if (neighbour_count_ >= std::size_t(INT32_MAX)) throw exact::Unsupported("translation ids of N exceed int32");
}

const Word &TranslationTable::word(TranslationId id) const {
  if (id < 0 || std::size_t(id) >= size()) throw std::out_of_range("translation id " + std::to_string(id) + " unknown");
  if (std::size_t(id) >= neighbour_count_) return extra_words_[std::size_t(id) - neighbour_count_];
  auto it = neighbour_words_.find(id);
  if (it == neighbour_words_.end()) it = neighbour_words_.emplace(id, neighbour_word(presentation_, std::size_t(id))).first;
  return it->second;
}

TranslationId TranslationTable::find_canonical(const Word &w) const {
  if (const int64_t id = neighbour_id(presentation_, w); id >= 0) return TranslationId(id);
  auto it = ids_.find(w);
  return it == ids_.end() ? -1 : it->second;
}

TranslationId TranslationTable::add_canonical(const Word &canonical) {
  if (const TranslationId id = find_canonical(canonical); id >= 0) return id;
  if (size() >= std::size_t(INT32_MAX)) throw exact::Unsupported("translation table is full");
  const auto id = static_cast<TranslationId>(size());
  // One pass in double over the letters (far_ is a vector<bool>: room for
  // it first, so that a failure adds nothing).
  const bool is_far = norm_log2_lower_bound(presentation_, canonical.data(), canonical.size()) > kFarLog2Norm;
  far_.reserve(extra_words_.size() + 1);
  extra_words_.push_back(canonical);
  try {
    ids_.emplace(canonical, id);
  } catch (...) {
    extra_words_.pop_back();
    throw;
  }
  far_.push_back(is_far);
  return id;
}

const Moebius<double> &TranslationTable::compute_matrices(TranslationId id) {
  const Word &w = word(id);  // checks the id
  Moebius<double> m;
  Low &low = low_.at(std::size_t(id));
  accurate_matrices(presentation_, w, &m, nullptr, &low.moebius_low, &low.moebius_error);
  Hot &hot = moebius_.at(std::size_t(id));
  hot.m = m;
  double p1, p2, error;
  centre_of(m, false, &p1, &p2, &error);
  centres_.add(id, p1, p2, error);
  return hot.m;
}

const Lorentz<double> &TranslationTable::compute_lorentz(TranslationId id) {
  Moebius<double> moebius, low;
  double error;
  Lorentz<double> L;
  accurate_matrices(presentation_, word(id), &moebius, &L, &low, &error);  // word() checks the id
  return lorentz_.emplace(id, L).first->second;
}

TranslationId TranslationTable::intern(const Word &w) {
  // A word spelled like a known canonical word is that element: the
  // Dehn-reduced word often is (most elements met lie in N, whose runs are
  // their own geodesic words), and reducing costs no arithmetic.
  const Word reduced = dehn_reduce(presentation_, w);
  if (const TranslationId id = find_canonical(reduced); id >= 0) return id;
  // A half relator (a run of 2g letters) has a second geodesic spelling,
  // the inverse of the rest of its relator, and only the shortlex-least is
  // canonical: try the other before canonicalising, which at large genus
  // costs the most precision of any element of N.
  const std::size_t half = std::size_t(presentation_.half_relator());
  if (reduced.size() == half) {
    const int n = presentation_.letter_count();
    const int step = (reduced[1] - reduced[0] + n) % n;
    bool run = presentation_.is_run_step(step);
    for (std::size_t i = 1; run && i < half; ++i) run = (reduced[i] - reduced[i - 1] + n) % n == step;
    if (run) {
      Word other(half);  // rest = r_last + step, r_last + 2 step, ...; other = rest^-1
      for (std::size_t j = 1; j <= half; ++j)
        other[half - j] = presentation_.inverse(Letter((reduced.back() + int(j) * step) % n));
      if (const TranslationId id = find_canonical(other); id >= 0) return id;
    }
  }
  return add_canonical(canonical_word(presentation_, reduced));
}

TranslationId TranslationTable::compose_cached(TranslationId a, TranslationId b) {
  if (const TranslationId known = products_.find(a, b); known >= 0) return known;
  // Factors of long words (the homes of points near the circle, and their
  // corners): their double matrices would cost a multiprecision product
  // each, and a centre from them is too coarse to name the product anyway.
  // The words name it.
  if (far(a) || far(b)) {
    Word w = word(a);
    const Word &wb = word(b);
    w.insert(w.end(), wb.begin(), wb.end());
    const TranslationId id = intern(w);
    products_.add(a, b, id);
    return id;
  }
  double p1, p2, error;
  product_centre(a, b, &p1, &p2, &error);
  TranslationId id = centres_.find(p1, p2, error);
  if (id < 0) {
    Word w = word(a);
    const Word &wb = word(b);
    w.insert(w.end(), wb.begin(), wb.end());
    id = intern(w);
    centres_.add(id, p1, p2, error);
  }
  products_.add(a, b, id);
  return id;
}

void TranslationTable::product_centre(TranslationId a, TranslationId b, double *p1, double *p2, double *error) {
  const Moebius<double> &A = moebius(a);
  product_centre_of(A, moebius(b), p1, p2, error);
}

TranslationId TranslationTable::inverse_interned(TranslationId a) {
  if (std::size_t(a) >= inverses_.size()) inverses_.resize(std::size_t(a) + 1, -1);
  if (inverses_.at(a) < 0) {
    double p1, p2, error;
    centre_of(moebius(a), true, &p1, &p2, &error);
    TranslationId b = centres_.find(p1, p2, error);
    if (b < 0) {
      b = intern(presentation_.inverse(word(a)));
      centres_.add(b, p1, p2, error);
    }
    if (std::size_t(b) >= inverses_.size()) inverses_.resize(std::size_t(b) + 1, -1);
    inverses_[a] = b;
    inverses_[b] = a;
  }
  return inverses_[a];
}

}  // namespace hdt::group
