#include "group/translation_table.hpp"

#include <stdexcept>

#include "group/canonical.hpp"
#include "group/neighbours.hpp"
#include "group/word_matrix.hpp"

namespace hdt::group {

std::size_t TranslationTable::WordHash::operator()(const Word &w) const noexcept {
  uint64_t h = 1469598103934665603ull;  // FNV-1a over the letters
  for (Letter k : w) h = (h ^ uint64_t(uint32_t(k))) * 1099511628211ull;
  return std::size_t(h);
}

TranslationTable::TranslationTable(const Presentation &p) : presentation_(p) {
  for (const Word &w : neighbour_words(p)) add_canonical(w);
  neighbour_count_ = words_.size();
}

TranslationId TranslationTable::add_canonical(const Word &canonical) {
  auto it = ids_.find(canonical);
  if (it != ids_.end()) return it->second;
  if (words_.size() >= std::size_t(INT32_MAX)) throw std::length_error("translation table is full");
  const auto id = static_cast<TranslationId>(words_.size());
  words_.push_back(canonical);
  moebius_.emplace_back();
  lorentz_.emplace_back();
  has_matrices_.push_back(false);
  ids_.emplace(canonical, id);
  return id;
}

void TranslationTable::compute_matrices(TranslationId id) {
  moebius_[id] = accurate_moebius(presentation_, words_[id]);
  lorentz_[id] = accurate_lorentz(presentation_, words_[id]);
  has_matrices_[id] = true;
}

TranslationId TranslationTable::intern(const Word &w) { return add_canonical(canonical_word(presentation_, w)); }

TranslationId TranslationTable::compose_cached(TranslationId a, TranslationId b) {
  const uint64_t key = (uint64_t(uint32_t(a)) << 32) | uint32_t(b);
  auto it = products_.find(key);
  if (it != products_.end()) return it->second;
  Word w = word(a);
  const Word &wb = word(b);
  w.insert(w.end(), wb.begin(), wb.end());
  const TranslationId id = intern(w);
  products_.emplace(key, id);
  return id;
}

TranslationId TranslationTable::inverse_interned(TranslationId a) {
  if (std::size_t(a) >= inverses_.size()) inverses_.resize(words_.size(), -1);
  if (inverses_.at(a) < 0) {
    const TranslationId b = intern(presentation_.inverse(word(a)));
    if (std::size_t(b) >= inverses_.size()) inverses_.resize(words_.size(), -1);
    inverses_[a] = b;
    inverses_[b] = a;
  }
  return inverses_[a];
}

}  // namespace hdt::group
