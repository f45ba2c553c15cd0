// A smaller dummy set, chosen in double precision (dummy_relaxation.cpp).
//
// The thinning's certified moves stop in a local optimum: no two neighbours
// fit into one point while the others stay where they are. This pass works
// on a double-precision copy of the triangulation, where a merge may leave
// circles too large for a while: it merges two neighbours, then moves the
// points around them until every circle is below the limit again, or undoes
// the merge. It only CHOOSES points: the caller inserts them as dummies and
// removes the old ones through the certified removal.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace hdt::mesh {
template <class Geometry>
class BasicTriangulation;
class MgGeometry;
using Triangulation = BasicTriangulation<MgGeometry>;
}

namespace hdt::dummies {

struct RelaxedDummies {
  std::vector<uint32_t> removed;                 // old dummies not in the relaxed set
  std::vector<std::array<double, 2>> added;      // its new points, in the disk
  std::vector<uint32_t> near;                    // per added point, an old dummy near it
};

// t: a triangulation of dummies only that meets the invariant. The relaxed
// set keeps vertex 0 and the sites; it is empty (nothing to change) when the
// pass found no merge.
RelaxedDummies relax_dummy_points(mesh::Triangulation &t);

}  // namespace hdt::dummies
