// Dehn's algorithm for Gamma_g.
//
// The relator has length 4g and its pieces have length 1, so Dehn's algorithm
// solves the word problem: a freely reduced word with no subword of more than
// half a cyclic rotation of the relator (or its inverse) is the identity only
// if it is empty. dehn_reduce returns such a word for the same element.
//
// Dehn-reduced words are not canonical and not always geodesic: a chain of
// half relators can hide a shorter word (g = 2: [0 5 2 7 5 2 7 4] equals the
// six-letter [7 2 5 7 2 5]). canonical.hpp finishes the job.
#pragma once

#include "group/presentation.hpp"

namespace hdt::group {

// Freely reduced and free of runs longer than 2g; linear time in the length
// for fixed genus. Letters must be valid (Presentation::check_word).
Word dehn_reduce(const Presentation &p, const Letter *w, std::size_t length);
inline Word dehn_reduce(const Presentation &p, const Word &w) { return dehn_reduce(p, w.data(), w.size()); }

// True when the word is freely reduced and has no relator run longer than 2g.
bool is_dehn_reduced(const Presentation &p, const Word &w);

}  // namespace hdt::group
