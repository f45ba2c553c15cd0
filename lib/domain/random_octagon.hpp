// Random fundamental polygons of genus 2 with rational vertices, built the
// way CGAL's Hyperbolic_fundamental_domain_factory_2 builds its octagons:
// a centrally symmetric polygon z_0 .. z_{m-1}, -z_0 .. -z_{m-1} with side k
// paired with the opposite side k + m, z_0 real positive, its angle
// condition made exact by moving the last vertex z_{m-1} along a geodesic
// (docs/polygons.md derives each formula).
//
// m = 4: the octagon, one vertex cycle of 8 vertices, angle sum 2 pi.
// m = 5: a decagon, two vertex cycles of 5 vertices, each 2 pi; genus 2 too.
//
// Deterministic from the seed on every platform: std::mt19937_64(seed), each
// uniform number (x >> 11) 2^-53 in [0, 1) from one draw x. Per attempt, for
// k = 1 .. m-1: u, v, a point (2u - 1, v) of the square kept when inside the
// upper half disk (else both drawn again); the points are then sorted by
// argument. An attempt that fails is followed by the next from the same
// generator.
#pragma once

#include <cstdint>

#include "domain/fundamental_polygon.hpp"

namespace hdt::domain {

FundamentalPolygon random_octagon(std::uint64_t seed);
// half = m, 4 or 5 (std::invalid_argument otherwise).
FundamentalPolygon random_symmetric_polygon(int half, std::uint64_t seed);

}  // namespace hdt::domain
