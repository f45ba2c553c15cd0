#include "group/neighbours.hpp"

#include <algorithm>
#include <stdexcept>

namespace hdt::group {

namespace {

Word run(const Presentation &p, Letter first, int step, int length) {
  Word w(length);
  for (int i = 0; i < length; ++i) w[i] = static_cast<Letter>((first + int64_t(i) * step) % p.letter_count());
  return w;
}

std::size_t elements_of_length(const Presentation &p, int length) {
  const std::size_t n = p.letter_count();
  if (length == 0) return 1;
  if (length == 1 || length == p.half_relator()) return n;
  return 2 * n;
}

// The canonical words of N of one length, sorted.
std::vector<Word> elements_of_length_sorted(const Presentation &p, int length) {
  const int n = p.letter_count(), h = p.half_relator();
  std::vector<Word> words;
  if (length == 0) {
    words.emplace_back();
    return words;
  }
  for (Letter y = 0; y < n; ++y) {
    if (length == 1) {
      words.push_back(Word{y});
      continue;
    }
    for (int step : {p.relator_step(), p.inverse_relator_step()}) {
      Word w = run(p, y, step, length);
      if (length == h) {
        // The half run equals the inverse of the other half of its relator.
        const Word other = p.inverse(run(p, static_cast<Letter>((y + int64_t(h) * step) % n), step, h));
        w = std::min(w, other);
      }
      words.push_back(std::move(w));
    }
  }
  std::sort(words.begin(), words.end());
  words.erase(std::unique(words.begin(), words.end()), words.end());
  return words;
}

}  // namespace

std::size_t neighbour_count(const Presentation &p) {
  const std::size_t m = 4 * std::size_t(p.genus()) - 1;
  return m * m;
}

Word neighbour_word(const Presentation &p, std::size_t id) {
  if (id >= neighbour_count(p))
    throw std::invalid_argument("translation id " + std::to_string(id) + " is not in N (|N| = " +
                                std::to_string(neighbour_count(p)) + ")");
  int length = 0;
  while (id >= elements_of_length(p, length)) id -= elements_of_length(p, length++);
  return elements_of_length_sorted(p, length)[id];
}

std::vector<Word> neighbour_words(const Presentation &p) {
  std::vector<Word> all;
  all.reserve(neighbour_count(p));
  for (int length = 0; length <= p.half_relator(); ++length) {
    std::vector<Word> words = elements_of_length_sorted(p, length);
    if (words.size() != elements_of_length(p, length))
      throw std::logic_error("neighbour set: wrong number of elements of length " + std::to_string(length));
    all.insert(all.end(), words.begin(), words.end());
  }
  return all;
}

}  // namespace hdt::group
