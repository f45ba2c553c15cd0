// The opaque handle behind hdt_triangulation: a core triangulation, made
// by hdt_create (a genus) or hdt_load (a restored triangulation), shared by
// the files of lib/capi that take one.
#pragma once

#include <cstdint>
#include <utility>

#include "capi/guard.hpp"
#include "hdt.h"
#include "triangulation/adjacency.hpp"
#include "triangulation/all_stars.hpp"
#include "triangulation/constructions.hpp"
#include "triangulation/progress.hpp"
#include "triangulation/triangulation.hpp"

struct hdt_triangulation {
  explicit hdt_triangulation(int genus) : tri(genus) {}
  explicit hdt_triangulation(hdt::triangulation::Triangulation &&t) : tri(std::move(t)) {}
  hdt::triangulation::Triangulation tri;
  hdt::triangulation::Progress progress;  // hdt_set_progress; none by default
  // hdt_voronoi_cell's circumcentres, kept from call to call (the other
  // Voronoi outputs read them when present); entries check themselves
  // against the faces, so changes need not clear it. And scratch reused from
  // call to call: the per-vertex functions' (a caller walking every vertex
  // would otherwise pay an allocation per call), and cell also holds
  // hdt_voronoi_edges' centres (16 bytes a face). Const queries may use
  // them: one thread uses a handle at a time (hdt.h).
  mutable hdt::triangulation::CentreCache centres;
  mutable std::vector<hdt::triangulation::StarEntry> star;
  mutable std::vector<hdt::triangulation::Point> cell;
  // hdt_vertex_stars' and hdt_voronoi_cells' rows (about 92 bytes a
  // vertex), kept: a later call writes into pages already mapped, and
  // while the triangulation is unchanged it writes them without building
  // them again.
  mutable hdt::triangulation::AllStars rows;
  // Bumped by every call that may change the triangulation (hdt::capi::of
  // on a non-const handle, the only way to one): the rows serve while it
  // is the generation they were built for. kNever: no rows, or a build
  // that did not finish.
  static constexpr uint64_t kNever = ~uint64_t(0);
  uint64_t generation = 0;
  mutable uint64_t rows_generation = kNever;   // the rows (translations; no matrices)
  mutable uint64_t cells_generation = kNever;  // and the cells' matrices and centres (every cache entry holds)
};

namespace hdt::capi {

// The triangulation behind a handle: const for a const handle (queries fill
// only the core's documented caches).
// A non-const handle may be changed: what the handle derived from the
// faces is stale from now on (the generation moves on).
inline triangulation::Triangulation &of(hdt_triangulation *t) {
  if (!t) throw ApiError(HDT_EINVAL, "the triangulation handle is NULL");
  ++t->generation;
  return t->tri;
}
inline const triangulation::Triangulation &of(const hdt_triangulation *t) {
  if (!t) throw ApiError(HDT_EINVAL, "the triangulation handle is NULL");
  return t->tri;
}

}  // namespace hdt::capi
