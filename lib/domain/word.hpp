// Words in the side pairings: the letter k stands for g_k = P.pairing(k), and
// the word (w_0, ..., w_{m-1}) for the product g_{w_0} g_{w_1} ... g_{w_{m-1}}
// (g_{w_{m-1}} applied first). The inverse of g_k is g_{paired(k)} (each sends
// one side of the pair onto the other, with opposite orientations), so the
// pairings alone, without inverse letters, generate the group.
#pragma once

#include <vector>

#include "domain/element.hpp"
#include "domain/fundamental_polygon.hpp"

namespace hdt::domain {

struct Word {
  std::vector<int> letters;
  Element element;
};

// g_0 .. g_{n-1} as elements.
std::vector<Element> pairing_elements(const FundamentalPolygon &P);
Element word_element(const FundamentalPolygon &P, const std::vector<int> &letters);

}  // namespace hdt::domain
