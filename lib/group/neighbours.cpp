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

// Where each length's elements start in the id order, and their order.
// Every element of N other than 1 is a run (y, s, L): first letter y, step
// s in {s1 = 2g+1, s2 = 2g-1}, L letters. Shortlex orders runs of one length
// by y, then by the second letter y + s: the s2 run first, except for
// y = 2g-1 and 2g, where y + s1 wraps round past 0. At L = 2g the run
// (y, s1) and the run (y - 1, s2) spell one element (the two halves of a
// relator, one inverted), and the canonical one of the pair has the smaller
// first letter: the set is (0, s2), (0, s1), (1, s2) .. (4g-2, s2), in that
// order.
namespace {

std::size_t length_offset(const Presentation &p, int length) {
  const std::size_t n = p.letter_count();
  if (length <= 1) return std::size_t(length);
  return 1 + n + 2 * n * std::size_t(length - 2);
}

bool s1_first(const Presentation &p, Letter y) { return y == p.half_relator() - 1 || y == p.half_relator(); }

}  // namespace

Word neighbour_word(const Presentation &p, std::size_t id) {
  if (id >= neighbour_count(p))
    throw std::invalid_argument("translation id " + std::to_string(id) + " is not in N (|N| = " +
                                std::to_string(neighbour_count(p)) + ")");
  const int h = p.half_relator(), s1 = p.relator_step(), s2 = p.inverse_relator_step();
  if (id == 0) return Word{};
  if (id < length_offset(p, 2)) return Word{static_cast<Letter>(id - 1)};
  if (id >= length_offset(p, h)) {
    const std::size_t i = id - length_offset(p, h);
    if (i <= 1) return run(p, 0, i == 0 ? s2 : s1, h);
    return run(p, static_cast<Letter>(i - 1), s2, h);
  }
  const int length = 2 + int((id - length_offset(p, 2)) / (2 * std::size_t(p.letter_count())));
  const std::size_t i = id - length_offset(p, length);
  const auto y = static_cast<Letter>(i / 2);
  const bool first = i % 2 == 0;
  return run(p, y, first == s1_first(p, y) ? s1 : s2, length);
}

int64_t neighbour_id(const Presentation &p, const Word &w) {
  const int n = p.letter_count(), h = p.half_relator(), s2 = p.inverse_relator_step();
  const int length = int(w.size());
  if (length > h) return -1;
  for (Letter k : w)
    if (!p.is_letter(k)) return -1;
  if (length == 0) return 0;
  if (length == 1) return 1 + w[0];
  const int s = p.step(w[0], w[1]);
  if (!p.is_run_step(s)) return -1;
  for (int i = 2; i < length; ++i)
    if (p.step(w[i - 1], w[i]) != s) return -1;
  const Letter y = w[0];
  if (length == h) {
    if (y == 0) return int64_t(length_offset(p, h)) + (s == s2 ? 0 : 1);
    if (s != s2 || y > n - 2) return -1;  // the other spelling is canonical
    return int64_t(length_offset(p, h)) + 1 + y;
  }
  const bool is_s1 = s != s2;
  return int64_t(length_offset(p, length)) + 2 * int64_t(y) + (is_s1 == s1_first(p, y) ? 0 : 1);
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
