#include "group/translation_table.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "group/canonical.hpp"
#include "group/dehn.hpp"
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
  if (neighbour_count_ >= std::size_t(INT32_MAX)) throw std::length_error("translation ids of N exceed int32");
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
  if (size() >= std::size_t(INT32_MAX)) throw std::length_error("translation table is full");
  const auto id = static_cast<TranslationId>(size());
  extra_words_.push_back(canonical);
  ids_.emplace(canonical, id);
  return id;
}

const TranslationTable::Matrices &TranslationTable::compute_matrices(TranslationId id) {
  const Word &w = word(id);  // checks the id
  Matrices &m = matrices_.at(std::size_t(id));
  accurate_matrices(presentation_, w, &m.moebius, &m.lorentz, &m.moebius_low, &m.moebius_error);
  m.known = true;
  // Column 0 is the centre h(O), each entry within 2^-66 L_00 before its
  // rounding (u relative).
  const Lorentz<double> &L = m.lorentz;
  centres_.add(id, L.m[1][0], L.m[2][0],
               0x1p-53 * std::max(std::abs(L.m[1][0]), std::abs(L.m[2][0])) + 0x1p-64 * L.m[0][0]);
  return m;
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
  // (a b)(O) = L_a (L_b e_0). Entries of L_a, L_b within u |L_ij| + 2^-66 L_00
  // (u = 2^-53, accurate_matrices); each coordinate sums three products:
  // within (2u + 3u) S_i (1 + 6u) of S_i = sum_j |L_a,ij| |L_b,j0|, plus the
  // absolute parts, at most 2^-66 (3 A_00 B_00 + 3 A_00 B_00) (1 + 2^-60)
  // (|L_ij| <= L_00 for Lorentz matrices): 6u S_i + 2^-62 A_00 B_00 covers it.
  const Lorentz<double> &A = lorentz(a);
  const Lorentz<double> &B = lorentz(b);
  double *coordinate[3] = {nullptr, p1, p2}, size = 0;
  for (int i = 1; i < 3; ++i) {
    *coordinate[i] = A.m[i][0] * B.m[0][0] + A.m[i][1] * B.m[1][0] + A.m[i][2] * B.m[2][0];
    size = std::max(size, std::abs(A.m[i][0] * B.m[0][0]) + std::abs(A.m[i][1] * B.m[1][0]) +
                              std::abs(A.m[i][2] * B.m[2][0]));
  }
  *error = 6 * 0x1p-53 * size + 0x1p-62 * A.m[0][0] * B.m[0][0];
}

TranslationId TranslationTable::inverse_interned(TranslationId a) {
  if (std::size_t(a) >= inverses_.size()) inverses_.resize(std::size_t(a) + 1, -1);
  if (inverses_.at(a) < 0) {
    // The centre of a^-1 is L_a^-1 e_0 = (L_00, -L_01, -L_02) (L^-1 = J L^T J,
    // J = diag(1, -1, -1)): entries of L_a, each within u relative plus
    // 2^-66 L_00.
    const Lorentz<double> &L = lorentz(a);
    const double p1 = -L.m[0][1], p2 = -L.m[0][2];
    const double error = 0x1p-53 * std::max(std::abs(p1), std::abs(p2)) + 0x1p-64 * L.m[0][0];
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
