// The neighbour set N = { h in Gamma_g : h(F_g) meets F_g }, |N| = (4g-1)^2.
//
// The tiles meeting F_g are those around its 4g vertices. Going around a
// vertex from F_g through L tiles is a relator run of L letters, so
// N \ {1} is the set of runs of length 1..2g (a longer run is the shorter way
// round the other side). Runs of length < 2g are the unique geodesic words of
// their elements (they stay in a dihedral parabolic subgroup of the
// reflection group of F_g, where such words are unique); each element at
// length 2g has two geodesic words, the run and its complement, and the
// shortlex-least is canonical. So N is built without any arithmetic.
//
// Order (= translation id): shortlex of the canonical words, identity first.
// Word length L holds 1 element for L = 0, 4g for L = 1, 8g for
// L = 2..2g-1 and 4g for L = 2g.
#pragma once

#include <cstdint>

#include "group/presentation.hpp"

namespace hdt::group {

// (4g-1)^2, without enumerating.
std::size_t neighbour_count(const Presentation &p);

// The canonical word of the element with translation id `id` < |N|, in
// time linear in its length (the order within a length is known in closed
// form, below). Throws std::invalid_argument when id >= |N|.
Word neighbour_word(const Presentation &p, std::size_t id);

// The translation id of w when w is the canonical word of an element of N,
// else -1; linear in |w|, no arithmetic.
int64_t neighbour_id(const Presentation &p, const Word &w);

// All of N in id order, by enumerating and sorting each length's elements:
// the reference the closed forms are tested against.
std::vector<Word> neighbour_words(const Presentation &p);

}  // namespace hdt::group
