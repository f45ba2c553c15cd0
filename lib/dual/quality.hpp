// The shape of the faces of a triangulation: circumradius, shortest edge,
// angles, and their extremes over the surface. Computed in double from the
// stored points (constructions.hpp), so rounded values: the refinement
// (refine.hpp) decides with them behind a relative margin, and the C API
// reports them (hdt_quality).
#pragma once

#include <cstdint>

#include "dual/constructions.hpp"
#include "mesh/triangulation.hpp"

namespace hdt::dual {

struct FaceShape {
  Circle circle;        // of the canonical copy: centre in the disk, hyperbolic radius
  double shortest_edge; // hyperbolic length
};
template <class Tri>
FaceShape face_shape(const Tri &tri, const mesh::Face &f);
// The hyperbolic length of the shortest side of the triangle p[0..2].
double shortest_edge(const Point p[3]);

// The smallest of the face's three hyperbolic angles, in radians.
template <class Tri>
double smallest_angle(const Tri &tri, const mesh::Face &f);

struct Quality {
  double min_angle;     // radians, over all faces
  double max_ratio;     // circumradius / shortest edge, over all faces
  double max_radius;    // the covering radius: every point of M_g is that close to a vertex
  double min_edge;      // the packing distance: the closest two vertices of M_g
};
template <class Tri>
Quality quality(const Tri &tri);

}  // namespace hdt::dual
