// The systole of the surface, certified: the least translation length l
// over the non-identity elements of the group, with an element realising it.
//
// The argument (docs/polygons.md has it whole). Every non-identity element
// is hyperbolic; a shortest closed geodesic lifts to the axis of an element
// g through a point of P, so g(P) meets the L-neighbourhood N of P for any
// L >= l. N is convex, and the tiles meeting a convex set are connected
// through sides, so a breadth-first walk through side neighbours that keeps
// a superset of the tiles meeting N reaches g(P). A tile h(P) is kept when
// some ball B(c_j, r_j) of a cover of P (polygon_cover.hpp) has h(c_j)
// within r_j + L of every side's half-plane. L is the least translation
// found so far (lowering it keeps the argument true).
//
// The walk runs on Arb's balls (ball_isometry.hpp): every test is decided
// by Arb or keeps the tile; two paths to one tile are told apart by the
// tile's centre (distinct centres are 2 rho apart, rho the base point's
// distance to the sides). The candidates for the least translation are
// then multiplied out exactly and compared by e-antic.
//
// Cost: about the area of P's (L + 2r)-neighbourhood over P's area. A walk
// estimated past tile_limit is refused with exact::Unsupported before it
// starts, and one that passes it anyway is stopped so.
#pragma once

#include <cstddef>

#include "domain/fundamental_polygon.hpp"
#include "domain/real_bounds.hpp"
#include "domain/word.hpp"

namespace hdt::domain {

struct Systole {
  Word shortest;             // a non-identity element of least translation length
  Number cosh2_half;         // its cosh^2(l/2), exact
  DoubleInterval length;     // lo <= l <= hi
  std::size_t tiles_walked;  // the tiles the walk accepted
};

Systole systole(const FundamentalPolygon &P, std::size_t tile_limit = 20000);

}  // namespace hdt::domain
