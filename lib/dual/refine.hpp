// Delaunay refinement on M_g: Steiner points at the circumcentres of bad
// faces, roughly largest circumradius first (classes of ratio sqrt 2, the
// newest first within a class), until every face has circumradius
// <= max_radius and radius-edge ratio <= max_ratio, or a cap on the number
// of points is reached. docs/refinement.md proves that it terminates for
// max_ratio >= 1 (a packing argument on the closed surface).
#pragma once

#include <cstddef>

#include "dual/constructions.hpp"
#include "mesh/progress.hpp"
#include "mesh/triangulation.hpp"

namespace hdt::dual {

struct RefineBounds {
  double max_radius;  // > 0; +infinity: no bound
  double max_ratio;   // >= 1; +infinity: no bound
};

// The relative margin by which refine() tightens both bounds before it
// compares them with values computed in double, so that the bounds hold for
// the exact faces too: the constructions' relative error is below 1e-12 on
// faces of circumradius above 1e-3 (docs/refinement.md).
constexpr double kRefineMargin = 1e-9;

// Whether the face breaks the bounds, as refine() decides it.
template <class Tri>
bool is_bad(const Tri &tri, const mesh::Face &f, const RefineBounds &b, Circle *circle);

// Steiner points are doubles, so a bad face is refined only when its
// circumcircle's Euclidean radius in the disk (in its canonical copy) is at
// least kResolution: the rounded circumcentre is then within a relative
// 2^-11 of the exact one (the centre's error is at most a few ulps of its
// coordinates from exact corners, 4.3e-13 hyperbolic from translated ones:
// docs/refinement.md), so each Steiner point keeps its distance from
// every vertex up to that factor and the proof's packing argument holds.
// Smaller bad faces arise only next to points closer than about 1e-9 (a
// user's near-duplicates): they are left and counted as unmet.
constexpr double kResolution = 0x1p-30;
bool resolvable(const Circle &c);

struct Refined {
  std::size_t added;    // Steiner points inserted
  std::size_t unmet;    // faces still breaking the bounds: 0 unless the cap, progress or memory
                        // stopped it or some bad face is below the resolution (an upper bound
                        // when memory ran out)
  bool out_of_memory;   // memory ran out part way: the points added stay, the triangulation is valid
};
// A lower bound on the vertices that a refinement to max_radius leaves on
// M_g, whatever else it does: every point of M_g is then within max_radius
// of a vertex, so disks of that radius cover the area 4 pi (g - 1), each of
// area 2 pi (cosh r - 1) = 4 pi sinh^2(r / 2). 0 for max_radius infinite (no
// size bound: nothing is known ahead).
double vertices_needed(int genus, double max_radius);
// The least memory that many vertices occupy (their records and the faces
// of Euler's formula, about two a vertex), in bytes.
double bytes_needed(double vertices);

// Steiner points are ordinary user vertices, inserted through
// Triangulation::insert_in_circle (exact predicates; the triangulation stays exactly
// Delaunay); a face whose rounded circumcentre is not strictly inside its
// circle (decided exactly) is left, as one below kResolution is. Throws
// before changing anything only on bad bounds (std::invalid_argument);
// running out of memory is reported in the result, not thrown. progress
// (may be null) is told the points added (total 0: unknown) and can stop
// it like the cap.
template <class Tri>
Refined refine(Tri &tri, const RefineBounds &b, std::size_t max_points,
               const mesh::Progress *progress = nullptr);

}  // namespace hdt::dual
