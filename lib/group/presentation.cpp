#include "group/presentation.hpp"

#include <stdexcept>

#include "group/cyclic.hpp"

namespace hdt::group {

Presentation::Presentation(int genus) : genus_(genus) {
  if (genus < 2) throw std::invalid_argument("genus must be at least 2, got " + std::to_string(genus));
}

Letter Presentation::relator_letter(int j) const {
  const int64_t n = letter_count();
  const int64_t jj = cyclic<int64_t>(j, n);
  return static_cast<Letter>((jj * relator_step()) % n);
}

Word Presentation::relator() const {
  Word r(letter_count());
  for (int j = 0; j < letter_count(); ++j) r[j] = relator_letter(j);
  return r;
}

Word Presentation::inverse(const Word &w) const {
  Word r(w.rbegin(), w.rend());
  for (Letter &k : r) k = inverse(k);
  return r;
}

void Presentation::check_word(const Letter *w, std::size_t length) const {
  for (std::size_t i = 0; i < length; ++i)
    if (!is_letter(w[i]))
      throw std::invalid_argument("letter " + std::to_string(w[i]) + " at position " + std::to_string(i) +
                                  " is outside 0.." + std::to_string(letter_count() - 1));
}

std::string word_to_string(const Word &w) {
  std::string s = "[";
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (i) s += ' ';
    s += std::to_string(w[i]);
  }
  return s + "]";
}

}  // namespace hdt::group
