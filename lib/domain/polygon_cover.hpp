// Finitely many hyperbolic balls whose union holds the polygon P, each of
// radius at most a target: the systole's walk (systole.hpp) measures how far
// a tile is from P through the images of their centres.
//
// The construction. In the Klein model P is a Euclidean convex polygon and
// every Euclidean square is a hyperbolic convex quadrilateral (geodesics are
// chords). A quadtree over P's bounding square drops the squares certainly
// outside one side's line (all four corners beyond it, decided on balls: a
// square is convex, so it lies beyond too) and splits the others until each
// lies inside the unit disk with radius r <= target about its centre: r is
// an upper bound of the hyperbolic distance from the centre to the corners,
// and a ball holding a square's corners holds the square (balls are
// convex). The kept squares cover P; their corners and centres are exact
// doubles, so nothing depends on where a rounding fell.
//
// The whole quadtree is kept: a node holds its square's ball too (when the
// square is inside the disk), so that a test "is some point of P's image
// near X" can drop a subtree at once when the node's ball is far enough.
#pragma once

#include <cmath>

#include <vector>

#include "domain/ball.hpp"
#include "domain/fundamental_polygon.hpp"

namespace hdt::domain {

struct CoverBall {
  ComplexBall centre;       // a disk point (an enclosure of the square's exact centre)
  double radius = INFINITY;  // >= the distance from the centre to every point of its square
  std::vector<int> children;  // none: a leaf, of radius <= the target
};

// Throws exact::Unsupported when a square must be split more than 50 times
// (a vertex within about 2^-50 of the circle in the Klein model).
// The nodes, the root first; the leaves cover P.
std::vector<CoverBall> polygon_cover(const FundamentalPolygon &P, double target_radius);

}  // namespace hdt::domain
