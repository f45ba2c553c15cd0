// The exact disk stage: points given by double coordinates in one frame.
//
// The disk filters (stage_disk.hpp) evaluate small polynomials of the
// coordinates; a double is a dyadic rational, so the same polynomials are
// exact in integers once every coordinate is scaled by a common power of
// two. Here that is done with GMP, at a cost of a few hundred nanoseconds
// instead of the field K_g's tens of microseconds. It matters for points on
// one Euclidean line or circle, which users sample: many of their in-circle
// determinants are exactly zero, which no floating-point stage can decide.
//
// The same signs hold for points that share one translation h and no site:
// h acts on the hyperboloid by a Lorentz matrix of determinant 1, which
// leaves both determinants unchanged (see kernel.hpp).
#pragma once

#include "predicates/sign.hpp"

namespace hdt::predicates {

// Exact sign of the hyperbolic orientation of a, b, c (disk_orientation's
// determinant): +1 counterclockwise, 0 on one geodesic.
Sign disk_orientation_exact(double ax, double ay, double bx, double by, double cx, double cy);

// Exact sign of in_circle (disk_in_circle's determinant): +1 when e is inside
// the circle through a, b, c counterclockwise, 0 on it.
Sign disk_in_circle_exact(double ax, double ay, double bx, double by, double cx, double cy, double ex, double ey);

}  // namespace hdt::predicates
