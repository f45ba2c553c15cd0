// The systole of the surface, certified: the least translation length l
// over the non-identity elements of the group, with an element realising it.
//
// The argument. Every non-identity element is hyperbolic (the surface is
// closed), and the systole is the length of a shortest closed geodesic. Lift
// it to an axis in the disk; the axis meets some tile h(P), so the conjugate
// g of the lifted element by h has its axis through a point p of P, and
// d(p, g p) = l. Let L >= l be any upper bound (the least translation length
// among the pairings and their products of two, rounded up), c an interior
// base point (base_point.hpp) and R >= d(c, v) for every vertex v (rounded
// up); P lies in the ball B(c, R), which is convex and holds the vertices.
//   * g(P) meets the closed L-neighbourhood N of P, through g p.
//   * N is convex (the distance to a convex set is a convex function), and the
//     tiles meeting a convex set are connected through sides: join points of
//     two of them by a segment inside the set; along it consecutive tiles
//     share a side, or a vertex x, and then all tiles around x contain x,
//     meet the set, and follow one another through sides around x.
//   * A tile h(P) meeting N has a point q with d(q, P) <= L, so
//     d(c, h c) <= R + L + R.
// So a breadth-first walk from P through side neighbours (from h(P), the
// tiles h g_k(P)) that keeps the tiles with cosh d(c, h c) <= cosh(L + 2R)
// (a superset of the tiles meeting N, containing P) reaches every tile
// meeting N, g(P) among them. The systole is the least cosh^2(l/2) =
// tr^2 / (4 det) over the non-identity elements walked, compared exactly.
// L + 2R and its cosh are rounded upward (real_bounds.hpp), which only makes
// the walk accept more tiles.
//
// Cost. The walk accepts about (cosh(L + 2R) - 1) / (2 (g - 1)) tiles (the
// ball's area over P's), so it grows like e^{2R}: quick for polygons that are
// round about c (the Bolza octagon: R = 2.45, 761 tiles), out of reach for
// thin ones with vertices near the circle (R = 5.8: some 10^6 tiles and
// more). A walk whose estimate (that area ratio) passes tile_limit is refused
// with exact::Unsupported before it starts, and one that passes it anyway is
// stopped so; a tighter acceptance test (several base points) would be the
// cure and is not done.
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
