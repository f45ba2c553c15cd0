#include "domain/systole.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <stdexcept>
#include <string>
#include <unordered_set>

#include "domain/base_point.hpp"
#include "domain/distance.hpp"
#include "exact/unsupported.hpp"

namespace hdt::domain {

namespace {

struct Shortest {
  Word word;
  Number cosh2;
};

// Keeps w when it translates less than the best so far (exact comparison;
// on a tie the first met stays).
void keep_if_shorter(Shortest &best, const Word &w) {
  if (w.element.is_identity()) return;
  const Number c2 = cosh2_half_translation(w.element);
  if (c2 < best.cosh2) best = {w, c2};
}

// The starting upper bound: the pairings and their products of two.
Shortest shortest_of_length_two(const std::vector<Element> &g) {
  Shortest best{{{0}, g[0]}, cosh2_half_translation(g[0])};
  for (int k = 0; k < int(g.size()); ++k) {
    keep_if_shorter(best, {{k}, g[std::size_t(k)]});
    for (int m = 0; m < int(g.size()); ++m) keep_if_shorter(best, {{k, m}, g[std::size_t(k)] * g[std::size_t(m)]});
  }
  return best;
}

double radius_above(const FundamentalPolygon &P, const Complex &c) {
  double R = 0;
  for (int k = 0; k < P.side_count(); ++k) R = std::max(R, arccosh_above(cosh_distance(c, P.vertex(k))));
  return R;
}

Word extended(const Word &h, int k, const Element &g_k) {
  Word w{h.letters, h.element * g_k};
  w.letters.push_back(k);
  return w;
}

// The breadth-first walk of systole.hpp; returns the count of tiles accepted.
std::size_t walk(const std::vector<Element> &g, const Complex &c, const Number &bound, std::size_t tile_limit,
                 Shortest &best) {
  const Element one = identity_element(c.re);
  std::unordered_set<Element, ElementHash> seen{one};
  std::deque<Word> accepted{{{}, one}};
  std::size_t count = 0;
  for (; !accepted.empty(); accepted.pop_front(), ++count) {
    if (count == tile_limit)
      throw exact::Unsupported("the certified systole's walk exceeds " + std::to_string(tile_limit) + " tiles");
    const Word &h = accepted.front();
    keep_if_shorter(best, h);
    for (int k = 0; k < int(g.size()); ++k) {
      Word next = extended(h, k, g[std::size_t(k)]);
      if (seen.insert(next.element).second && cosh_displacement(next.element, c) <= bound)
        accepted.push_back(std::move(next));
    }
  }
  return count;
}

// The walk accepts about the area of the ball B(c, L + 2R) over P's, 4 pi (g - 1):
// a walk estimated past the limit is refused before it starts.
void refuse_long_walks(const FundamentalPolygon &P, double L, double R, std::size_t tile_limit) {
  const double estimate = (std::cosh(L + 2 * R) - 1) / (2.0 * (P.genus() - 1));
  if (!(estimate <= double(tile_limit)))
    throw exact::Unsupported("the certified systole would walk about " + std::to_string(std::llround(estimate)) +
                             " tiles (a vertex " + std::to_string(R) +
                             " from the base point: a thin polygon), more than the limit " +
                             std::to_string(tile_limit));
}

}  // namespace

Systole systole(const FundamentalPolygon &P, std::size_t tile_limit) {
  const std::vector<Element> g = pairing_elements(P);
  const Complex c = base_point(P);
  Shortest best = shortest_of_length_two(g);
  const double L = length_from_cosh2_half(best.cosh2).hi, R = radius_above(P, c);
  refuse_long_walks(P, L, R, tile_limit);
  const Number bound(c.re.parent(), cosh_above(sum_above(L, sum_above(R, R))));
  const std::size_t walked = walk(g, c, bound, tile_limit, best);
  return {best.word, best.cosh2, length_from_cosh2_half(best.cosh2), walked};
}

}  // namespace hdt::domain
