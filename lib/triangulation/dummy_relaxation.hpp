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

namespace hdt::triangulation {

class Triangulation;

struct RelaxedDummies {
  std::vector<uint32_t> removed;                 // old dummies not in the relaxed set
  std::vector<std::array<double, 2>> added;      // its new points, in the disk
  std::vector<uint32_t> near;                    // per added point, an old dummy near it
};

// t: a triangulation of dummies only that meets the invariant. The relaxed
// set keeps vertex 0 and the sites; it is empty (nothing to change) when the
// pass found no merge.
RelaxedDummies relax_dummy_points(Triangulation &t);

// The largest genus relaxed (1.42 times the area bound there; the first
// hdt_create 0.65 s of CPU). Beyond it the double computations fail near
// F_g's corners, whose coordinates grow like cot(pi/4g)^2 (2.6e4 at genus
// 128): a corner lorentz(t) P_v with entries near 1e8 keeps only about 1e-4
// of absolute accuracy, and a circle cancels four times the bits of its
// coordinates. The ratio then climbs (1.46 to 1.56 at genus 52 to 63, 1.63
// at 128) and the time passes 1 s: genus 49 .. 128 keep the local thinning.
constexpr int kRelaxationGenusMax = 48;

}  // namespace hdt::triangulation
