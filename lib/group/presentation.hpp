// The presentation of Gamma_g: 4g letters, their inverses, the relator.
//
// Letter k stands for the generator g_k; g_{k+2g} = g_k^{-1}. The single
// relator is prod_{j=0}^{4g-1} g_{j(2g+1) mod 4g}. Every letter occurs in it
// exactly once, so a subword of a cyclic rotation of the relator is a run of
// letters with a constant step: +(2g+1) for the relator, +(2g-1) for its
// inverse (all mod 4g). Dehn's algorithm works on these runs.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace hdt::group {

using Letter = int32_t;
using Word = std::vector<Letter>;

class Presentation {
 public:
  explicit Presentation(int genus);  // throws std::invalid_argument when genus < 2

  int genus() const { return genus_; }
  int letter_count() const { return 4 * genus_; }     // 4g
  int half_relator() const { return 2 * genus_; }     // 2g
  Letter inverse(Letter k) const { return (k + 2 * genus_) % (4 * genus_); }
  bool is_letter(Letter k) const { return k >= 0 && k < 4 * genus_; }

  // The relator's letter at position j (mod 4g).
  Letter relator_letter(int j) const;
  Word relator() const;

  // Steps between consecutive letters of a relator run: of the relator
  // (2g+1) and of its inverse (2g-1).
  int relator_step() const { return 2 * genus_ + 1; }
  int inverse_relator_step() const { return 2 * genus_ - 1; }
  // (b - a) mod 4g.
  int step(Letter a, Letter b) const { return ((b - a) % (4 * genus_) + 4 * genus_) % (4 * genus_); }
  bool is_run_step(int s) const { return s == relator_step() || s == inverse_relator_step(); }

  Word inverse(const Word &w) const;

  // Throws std::invalid_argument naming the first letter outside 0..4g-1.
  void check_word(const Letter *w, std::size_t length) const;

 private:
  int genus_;
};

std::string word_to_string(const Word &w);

}  // namespace hdt::group
