// The image of a double point under a long word, with a certified bound:
// what a point near the unit circle needs to be known in F_g.
//
// The word's matrix would need about m log2(2A) extra bits for m letters
// (its entries grow with the word); applying the letters one by one to the
// point needs only those that the point's own nearness to the circle costs.
// Each letter is an isometry of the hyperbolic metric, so an error made at
// one step is carried, not magnified, by the later ones: measured
// hyperbolically, the errors of the steps add. The analysis is in
// certified_image.cpp.
#pragma once

#include "exact/multiprecision.hpp"
#include "group/moebius.hpp"
#include "group/presentation.hpp"

namespace hdt::group {

// h(x + iy) for the element h spelled by w (letters valid, the last one
// acting first), |x + iy| < 1, within 2^-128 in each coordinate. False,
// with nothing written, when even the top multiprecision rung cannot
// certify that (not met: the bits needed grow with log2 of the word length
// and of 1 / (1 - |z|), a few hundred at most for double input).
bool certified_image(const Presentation &p, const Word &w, double x, double y,
                     Complex<exact::mp_real<40>> *image);

}  // namespace hdt::group
