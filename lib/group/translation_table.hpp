// Compact ids for the group elements a triangulation uses.
//
// Faces store, per corner, a translation id (int32). Ids 0..|N|-1 are the
// neighbour set N in the fixed order of neighbour_words (id 0 = identity),
// the same for every table of a genus; elements outside N get the next ids as
// they are first met. Each id caches its canonical word and its double
// matrices, and products of ids are cached, so the hot path never touches
// words or multiprecision. A product or inverse not cached yet is named by
// its tile centre, computed from the factors' double matrices, when the
// centre index knows it (centre_index.hpp); only the others have their word
// canonicalised.
//
// N itself is not stored: its ids and words are known in closed form
// (neighbours.hpp), and matrices are kept in pages that follow the ids in
// use, so a table costs memory for what it meets, not (4g-1)^2 words
// (hundreds of megabytes at genus 128).
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "group/centre_index.hpp"
#include "group/lorentz.hpp"
#include "group/moebius.hpp"
#include "group/paged_vector.hpp"
#include "group/product_cache.hpp"
#include "group/presentation.hpp"

namespace hdt::group {

using TranslationId = int32_t;

class TranslationTable {
 public:
  explicit TranslationTable(const Presentation &p);

  const Presentation &presentation() const { return presentation_; }
  std::size_t size() const { return neighbour_count_ + extra_words_.size(); }
  std::size_t neighbour_count() const { return neighbour_count_; }

  // The id of a word already known to be canonical, or -1 when the table
  // has not met it (no arithmetic).
  TranslationId find_canonical(const Word &w) const;
  // The id of a word the caller knows to be canonical (a copy of another
  // table's), added if new, without recomputing its canonical form.
  TranslationId intern_canonical(const Word &w) { return add_canonical(w); }
  // The id of the element of any word (canonicalised first), added if new.
  TranslationId intern(const Word &w);
  // The id of a * b (apply b first), cached. The identity and known
  // inverses are answered inline: they are most calls on the hot path.
  TranslationId compose(TranslationId a, TranslationId b) {
    if (a == 0) return b;
    if (b == 0) return a;
    return compose_cached(a, b);
  }
  TranslationId inverse(TranslationId a) {
    if (a == 0) return 0;
    if (std::size_t(a) < inverses_.size() && inverses_[a] >= 0) return inverses_[a];
    return inverse_interned(a);
  }

  // The canonical word of id (words of N are spelled on first request).
  const Word &word(TranslationId id) const;
  // Matrices accurate to the last bit (accurate_matrices: Lorentz entries
  // within u |L_ij| + 2^-66 L_00), computed on first use (building them for
  // all of N up front would cost seconds at large genus). The Lorentz matrix
  // only serves the surface's sites under a translation: it is computed
  // apart, when first asked for (its multiprecision entries cost more than
  // the Moebius product, which every new id needs).
  const Moebius<double> &moebius(TranslationId id) {
    const Moebius<double> &m = moebius_.get(std::size_t(id)).m;
    if (m.a.re != 0 || m.a.im != 0) return m;  // |a| >= 1 once computed
    return compute_matrices(id);
  }
  const Lorentz<double> &lorentz(TranslationId id) {
    const auto it = lorentz_.find(id);
    return it != lorentz_.end() ? it->second : compute_lorentz(id);
  }
  // The Moebius matrix to about twice double precision, for the
  // double-double stage: each part of a, b is moebius + moebius_low within
  // 2^-106 of itself plus moebius_error (|a| + |b|).
  const Moebius<double> &moebius_low(TranslationId id) {
    moebius(id);
    return low_.get(std::size_t(id)).moebius_low;
  }
  double moebius_error(TranslationId id) {
    moebius(id);
    return low_.get(std::size_t(id)).moebius_error;
  }

 private:
  // The double matrix, which every translated point of the double stage
  // reads, in a 32-byte slot of its own (one cache line, where the three
  // matrices together took 80 bytes and often two lines); a = 0 until
  // computed. The double-double parts beside it, read far less often.
  struct alignas(32) Hot {
    Moebius<double> m{{0, 0}, {0, 0}};
  };
  struct Low {
    Moebius<double> moebius_low;
    double moebius_error = 0;
  };
  struct WordHash {
    std::size_t operator()(const Word &w) const noexcept;
  };
  TranslationId add_canonical(const Word &canonical);
  TranslationId compose_cached(TranslationId a, TranslationId b);
  // Elements that move O far (log2 of their matrix norm above
  // kFarLog2Norm: the homes of points near the unit circle, and their
  // corners): a centre from their double matrices is too coarse to name a
  // product, and those matrices would cost a multiprecision product each,
  // so compose_cached names their products by the words alone.
  static constexpr double kFarLog2Norm = 24;
  bool far(TranslationId id) const {
    return std::size_t(id) >= neighbour_count_ && far_[std::size_t(id) - neighbour_count_];
  }
  TranslationId inverse_interned(TranslationId a);
  const Moebius<double> &compute_matrices(TranslationId id);
  const Lorentz<double> &compute_lorentz(TranslationId id);
  // The centre of a * b from the factors' Moebius matrices, and its error in
  // each coordinate.
  void product_centre(TranslationId a, TranslationId b, double *p1, double *p2, double *error);

  Presentation presentation_;
  std::size_t neighbour_count_ = 0;
  std::vector<Word> extra_words_;  // ids from |N| on
  std::vector<bool> far_;          // by id from |N| on: far() (above)
  mutable std::unordered_map<TranslationId, Word> neighbour_words_;  // the words of N asked for
  PagedVector<Hot> moebius_;
  PagedVector<Low> low_;
  // The Lorentz matrices asked for (a few thousand ids at genus 128), apart
  // from moebius_ and low_: a slot per id there would hold 72 bytes for every id
  // met, 14 MB at genus 128 with 10^5 points.
  std::unordered_map<TranslationId, Lorentz<double>> lorentz_;
  std::unordered_map<Word, TranslationId, WordHash> ids_;  // ids from |N| on
  ProductCache products_;
  std::vector<TranslationId> inverses_;  // -1: not known yet; as long as the largest id met
  CentreIndex centres_;  // the ids whose matrices are computed, and products named by word
};

}  // namespace hdt::group
