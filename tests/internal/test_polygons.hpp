// Polygons the domain suites share (test_domain, test_tiling): the Bolza
// octagon in a number field, the regular 12-gons, and exact rationals.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>

#include "domain/fundamental_polygon.hpp"
#include "domain/polygon_text.hpp"
#include "domain/random_octagon.hpp"

namespace hdt::domain::test {

// The Bolza octagon: v_k = 2^{-1/4} e^{i (2k+1) pi/8} = x + i y and its
// images, x = sqrt(sqrt2 + 1)/2, y = sqrt(sqrt2 - 1)/2. With a = sqrt(sqrt2 + 1)
// (a^4 - 2a^2 - 1 = 0, a ~ 1.5538) x = a/2 and y = 1/(2a) = (a^3 - 2a)/2.
inline std::string bolza_text(const char *pairing) {
  const std::string x = "1/2*a", y = "1/2*a^3-a", mx = "-1/2*a", my = "-1/2*a^3+a";
  return std::string("field a^4-2*a^2-1 a 1.5538+/-0.01\n8\n") + pairing + "\n" + x + " " + y + "\n" + y + " " + x +
         "\n" + my + " " + x + "\n" + mx + " " + y + "\n" + mx + " " + my + "\n" + my + " " + mx + "\n" + y + " " +
         mx + "\n" + x + " " + my + "\n";
}

inline FundamentalPolygon bolza(const char *pairing = "4 5 6 7 0 1 2 3") {
  return FundamentalPolygon(parse_polygon_text(bolza_text(pairing)));
}

// A regular 12-gon v_k = r e^{i (2k+1) pi/12} with opposite sides paired,
// from x + i y = v_0 and h = Re v_1 = Im v_1 in the field of `minpoly`:
// v_2 = (y, x), v_3 = (-y, x), v_4 = (-h, h), v_5 = (-x, y), then the negatives.
inline PolygonText regular_12_gon(const char *minpoly, const char *gen, const char *ball, const char *xs,
                                  const char *ys, const char *hs) {
  PolygonText t;
  t.field = make_field(minpoly, gen, ball);
  const Number x = make_element(*t.field, xs), y = make_element(*t.field, ys), h = make_element(*t.field, hs);
  t.vertices = {{x, y}, {h, h}, {y, x}, {-y, x}, {-h, h}, {-x, y}};
  for (int k = 0; k < 6; ++k) t.vertices.push_back(-t.vertices[std::size_t(k)]);
  for (int k = 0; k < 12; ++k) t.paired.push_back((k + 6) % 12);
  return t;
}

// Genus 3: r^2 = cos(pi/6) = sqrt3/2, in Q(b), b = 3^{1/4}: r cos(pi/12) =
// 3^{1/4} (sqrt3 + 1)/4, so x = (b^3 + b)/4, y = (b^3 - b)/4, h = b/2.
inline PolygonText genus_3_12_gon() {
  return regular_12_gon("b^4-3", "b", "1.316+/-0.01", "1/4*b^3+1/4*b", "1/4*b^3-1/4*b", "1/2*b");
}

// The same 12-gon with the pairing a1 b1 a1^-1 b1^-1 a2 b2 a2^-1 b2^-1 a3 b3
// a3^-1 b3^-1 (side 4j <-> 4j + 2, 4j + 1 <-> 4j + 3): still one cycle of
// twelve vertices, whose angles pi/6 sum to 2 pi, so genus 3 again.
inline PolygonText genus_3_commutator_12_gon() {
  PolygonText t = genus_3_12_gon();
  t.paired = {2, 3, 0, 1, 6, 7, 4, 5, 10, 11, 8, 9};
  return t;
}

// p/d as a Number in lowest terms (e-antic needs them).
inline Number q(long p, long d) {
  mpq_class r(p, d);
  r.canonicalize();
  return Number(r);
}

// The first random rational octagon (random_octagon.hpp, seeds 1, 2, ...)
// with every vertex within Euclidean radius max_reach, and that radius: a
// bounded search, so that the tiles a brute force searches stay few.
struct CompactOctagon {
  FundamentalPolygon polygon;
  double reach;
  std::uint64_t seed;
};
// half: 4 for an octagon, 5 for a decagon (two vertex cycles).
inline CompactOctagon compact_random_octagon(double max_reach = 0.9, int half = 4) {
  for (std::uint64_t seed = 1; seed < 200; ++seed) {
    FundamentalPolygon P = random_symmetric_polygon(half, seed);
    double reach = 0;
    for (int k = 0; k < 2 * half; ++k) reach = std::max(reach, std::abs(P.vertex_double(k)));
    if (reach <= max_reach) return {std::move(P), reach, seed};
  }
  throw std::logic_error("compact_random_octagon: none among 200 seeds");
}

}  // namespace hdt::domain::test
