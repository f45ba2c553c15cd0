// The circumcircle of a face in multiprecision, from the vertices' exact
// descriptions: the fallback of the double constructions (constructions.hpp)
// for the faces double cannot resolve. Those are faces of nearly coincident
// or nearly collinear points (a user's points an ulp apart, a point an ulp
// from a dummy's algebraic point, needles along a curve, points at 1e-300
// whose squares underflow): their corners rounded to double can be
// collinear, or bound a circle far from the face's.
#pragma once

#include "dual/circle.hpp"
#include "mesh/triangulation.hpp"

namespace hdt::dual {

// Face f's circumcentre in its canonical copy and its hyperbolic radius,
// each rounded once to double: computed with 200-bit arithmetic from the
// stored points (a user's double exactly, a dummy site's coordinates
// within 2^-128) under the corners' translations (their words' products at
// 200 bits). Throws std::logic_error only when even that finds no proper
// circle (a broken invariant: every face of a triangulation has one).
template <class Tri>
Circle precise_circumcircle(const Tri &tri, const mesh::Face &f);

// Face f's corners and sides (side[i] = p[i+2] - p[i+1]) from the same
// 200-bit corners, each rounded once to double: face_frame's last resort,
// for sides too short for double-double.
template <class Tri>
void precise_frame(const Tri &tri, const mesh::Face &f, Point p[3], Point side[3]);

}  // namespace hdt::dual
