// The canonical word of an element of Gamma_g: its shortlex-least geodesic
// word (fewest letters, then lexicographically least letter values).
//
// Why geometry: the tiles h(F_g) of the plane are the chambers of the
// reflection group of F_g (its angles pi/2g are submultiples of pi), so the
// length of h is the number of tessellation lines separating F_g from
// h(F_g), and a geodesic word of h may start with k exactly when the line of
// side s_k separates them. The greedy choice of the least such k, repeated,
// yields the shortlex-least geodesic word. Each separation test is the sign of
// <P, O - g_k(O)> for the hyperboloid point P = h(O), whose magnitude is at
// least 2 (A^2 - 1) because tile centres keep the inradius from every line;
// multiprecision arithmetic with a precision chosen from the word length
// makes the computed sign certain (and it is checked against that margin):
// the compile-time ladder's rungs, and past its top (412 letters at genus
// 256) MPFR at a precision chosen at run time from the same bound.
#pragma once

#include "group/presentation.hpp"

namespace hdt::group {

// Longest Dehn-reduced word the compile-time precision ladder canonicalises
// for genus g (depends on g through the generators' size); longer words
// take a run-time precision (slower: bits grow linearly with the length).
std::size_t canonical_ladder_length(const Presentation &p);

// Words of any length. Throws std::invalid_argument for invalid letters;
// exact::Unsupported only for a word that needs a run-time precision (past
// the ladder's reach and the tracked bound's at 160 digits) and whose
// Dehn-reduced rest then has more than max_runtime_length letters: the cost
// grows about as the cube of the length there.
Word canonical_word(const Presentation &p, const Letter *w, std::size_t length,
                    std::size_t max_runtime_length = std::size_t(-1));
inline Word canonical_word(const Presentation &p, const Word &w) { return canonical_word(p, w.data(), w.size()); }

// Whether a word is the canonical word of its element, decided without
// computing that word: w is canonical exactly when, for every suffix
// h_i = w_i w_{i+1} ... of it, w_i is the least letter whose side line
// separates O from h_i(O) (the greedy choice canonical_word makes). The
// suffixes' points are built from the right, one product a letter, in
// double precision, then if a test is left open at 40 and at 160 digits
// with the tracked error bound; it stops at the first letter that is not
// the least. So the cost is linear in the length at a fixed precision: a
// word that would need more (its points farther from O than that precision
// certifies, cosh d around 2^150; a double point of the disk is within
// cosh d = 2^54 of O) is left open, never computed at length. Letters must be
// valid (Presentation::check_word).
enum class CanonicalCheck { kCanonical, kNotCanonical, kOpen };
CanonicalCheck check_canonical(const Presentation &p, const Letter *w, std::size_t length);

// The walk of a point of the disk into F_g, with a point tracked at 40
// digits and an error bound: letters k_1, k_2, ... (appended) such that
// g_{k_1}^-1, then g_{k_2}^-1, ... take x + iy across the side line each
// is beyond, each sign certified, until no side line separates it from O.
// True when it got there; false when a sign was left open (near a line)
// or after max_steps letters: the letters then go part of the way. Its
// signs are certified, but the caller need not trust them: the point's
// representative is still decided by exact tests from where it ends.
bool walk_into_domain(const Presentation &p, double x, double y, Word &letters, std::size_t max_steps);

}  // namespace hdt::group
