#include "domain/neighbours.hpp"

#include <stdexcept>
#include <unordered_set>

namespace hdt::domain {

std::vector<Word> tiles_around_vertex(const FundamentalPolygon &P, int k) {
  const int n = P.side_count();
  std::vector<Word> tiles;
  Word w{{}, identity_element(P.vertex(0).re)};
  int side = k;
  do {
    w.letters.push_back(side);
    w.element = w.element * Element(P.pairing(side));
    tiles.push_back(w);
    side = (P.paired(side) + 1) % n;
  } while (side != k);
  if (!tiles.back().element.is_identity())
    throw std::logic_error("domain::tiles_around_vertex: the walk around a vertex does not close");
  return tiles;
}

std::vector<Word> neighbours(const FundamentalPolygon &P) {
  std::vector<Word> all{{{}, identity_element(P.vertex(0).re)}};
  std::unordered_set<Element, ElementHash> seen{all.front().element};
  for (int k = 0; k < P.side_count(); ++k)
    for (Word &w : tiles_around_vertex(P, k))
      if (seen.insert(w.element).second) all.push_back(std::move(w));
  return all;
}

}  // namespace hdt::domain
