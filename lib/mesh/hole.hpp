// The Delaunay triangulation of the hole that removing a vertex leaves.
//
// The hole is the star of the removed vertex v: its boundary (the link of
// v) is a polygon, star-shaped from v, whose Delaunay triangulation (with the
// kernel's symbolic perturbation) is what replaces the star. Two methods:
//
//   - fill_hole: lowers v's lifting coordinate until v leaves the
//     triangulation. Each time the lowered v crosses the plane of an ear
//     (a, b, c) of the link, the edge v-b flips to a-c and (a, b, c) is a
//     final face; the ears are taken in the order of their crossing, the
//     ratio of the in-circle and orientation determinants (the power of v
//     with respect to the ear's circle), estimated in double from a heap:
//     O(k log k) for a vertex of degree k. Estimates can misorder nearly
//     tied ears, so Lawson flips with the exact predicates then make every
//     edge locally Delaunay, which makes the result exact; with good
//     estimates they find nothing to flip.
//   - fill_hole_by_wrapping: the face on each new edge is the one whose
//     circle holds no other vertex of its part of the polygon, found by a
//     scan: O(k^2) tests. Simple, the fallback of fill_hole.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "predicates/kernel.hpp"

namespace hdt::mesh {

struct HoleVertex {
  predicates::TranslatedPoint point;  // in the common frame of the hole
  uint32_t vertex;                    // its vertex id, for the perturbation
  // The hyperboloid vector of point in double, computed once per hole, and
  // a certified bound on each coordinate's error (infinite when unknown):
  // fill_hole's ear order and remove()'s early refusal read them.
  std::array<double, 3> lift;
  double lift_error;

  // The lift as the double stage's certified point (Kernel's overloads that
  // take one).
  predicates::FilteredPoint certified() const { return {{lift[0], lift[1], lift[2]}, lift_error}; }
};

// The hole's vertex at p (vertex id `vertex`) with its lift: the double
// filter's point where that is within 1e-9 N_0 (with its own error bound),
// else the kernel's more precise one (Kernel::hyperboloid: within 1e-9 N_0
// when accurate, else an unknown error).
HoleVertex lifted_hole_vertex(predicates::Kernel &kernel, const predicates::TranslatedPoint &p, uint32_t vertex);

// Faces as counterclockwise triples of indices into the polygon.
using HoleFace = std::array<int, 3>;

// polygon: the link of `removed`, counterclockwise, at least 3 distinct
// vertices. Writes the faces of the polygon's Delaunay triangulation to
// *faces (k - 2 of them). Returns false when an invariant of the method
// fails (not expected for a star-shaped polygon; the caller falls back).
bool fill_hole(predicates::Kernel &kernel, const std::vector<HoleVertex> &polygon, const HoleVertex &removed,
               std::vector<HoleFace> *faces);

// The same faces by wrapping. Throws std::logic_error when a part of the
// polygon has no Delaunay triangle on its closing edge. Any kernel with
// orientation and in_circle_perturbed (M_g's, a polygon surface's).
template <class Kernel>
void fill_hole_by_wrapping(Kernel &kernel, const std::vector<HoleVertex> &polygon, std::vector<HoleFace> *faces);

}  // namespace hdt::mesh
