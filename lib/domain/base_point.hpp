// A base point c in the interior of a fundamental polygon P, with exact
// coordinates in P's field: the centre of the systole's ball and the start
// of every representative walk.
//
// The origin when it is interior (every centrally symmetric polygon: the
// Bolza octagon, the regular 4g-gons, the random octagons and decagons).
// Otherwise a point near the one whose Klein image is the centroid m of the
// Klein vertices, which is interior to the convex Klein polygon: the Poincare
// point m / (1 + sqrt(1 - |m|^2)) is computed in double, its coordinates
// taken exactly as rationals, and its Klein image tested inside exactly. The
// double only proposes the point; the exact test decides. It can fail only
// for a polygon narrower than the rounding error near its centroid; then
// std::runtime_error says so.
#pragma once

#include "domain/fundamental_polygon.hpp"

namespace hdt::domain {

Complex base_point(const FundamentalPolygon &P);

}  // namespace hdt::domain
