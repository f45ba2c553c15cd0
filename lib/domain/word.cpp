#include "domain/word.hpp"

namespace hdt::domain {

std::vector<Element> pairing_elements(const FundamentalPolygon &P) {
  std::vector<Element> g;
  for (int k = 0; k < P.side_count(); ++k) g.emplace_back(P.pairing(k));
  return g;
}

Element word_element(const FundamentalPolygon &P, const std::vector<int> &letters) {
  Element product = identity_element(P.vertex(0).re);
  for (const int k : letters) product = product * Element(P.pairing(k));
  return product;
}

}  // namespace hdt::domain
