// The dual outputs of one triangulation as the C API hands them out, and
// what is kept from call to call for them: the circumcentre cache, the rows
// of every star, scratch. Each function does what may fail (new translation
// ids and matrices, memory, the check of a broken invariant) before it
// writes to the caller's buffers, so a failure writes nothing. What is
// kept is tagged with the triangulation's revision it was made at, and
// serves while that is current. One thread at a time, as for the
// triangulation (hdt.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "dual/adjacency.hpp"
#include "dual/all_stars.hpp"
#include "dual/constructions.hpp"
#include "mesh/triangulation.hpp"

namespace hdt::dual {

class Outputs {
 public:
  // The star of live vertex v (vertex_star), in scratch kept here.
  template <class Tri>
  const std::vector<StarEntry> &star(const Tri &tri, uint32_t v);
  // The Voronoi cell of the vertex of the last star(): the circumcentre of
  // each face of that star, in the vertex's frame (the centres kept in the
  // cache for the other Voronoi outputs).
  template <class Tri>
  const std::vector<Point> &cell_of_star(const Tri &tri);

  // hdt_edges (count = 3F/2); each output may be null.
  template <class Tri>
  static void edges(const Tri &tri, std::size_t count, uint32_t *vertices, int32_t *translations,
                    uint32_t *faces, double *lengths);
  // hdt_voronoi_vertices: 2 and 1 per face, either null.
  template <class Tri>
  void voronoi_vertices(const Tri &tri, double *xy, double *radii);
  // hdt_voronoi_edges: 4 per edge, in hdt_edges' order (count = 3F/2).
  template <class Tri>
  void voronoi_edges(const Tri &tri, std::size_t count, double *xy);
  // hdt_vertex_stars and hdt_voronoi_cells (AllStars::write, write_cells).
  template <class Tri>
  void vertex_stars(const Tri &tri, std::size_t *offsets, uint32_t *faces, uint8_t *corners,
                    int32_t *translations);
  template <class Tri>
  void voronoi_cells(const Tri &tri, std::size_t *offsets, double *xy);

 private:
  // Entries check themselves against the faces, so it needs no revision.
  CentreCache centres_;
  std::vector<StarEntry> star_;
  // cell_of_star's result, and hdt_voronoi_edges' centres without a cache
  // (16 bytes a face): kept, so later calls allocate nothing.
  std::vector<Point> cell_;
  // The rows of every star (about 92 bytes a vertex), kept: while the
  // triangulation is unchanged a later call writes them again without
  // building them, and otherwise into pages already mapped.
  AllStars rows_;
  static constexpr uint64_t kNever = ~uint64_t(0);  // none, or a build that did not finish
  uint64_t rows_revision_ = kNever;                 // the rows (translations; no matrices)
  uint64_t cells_revision_ = kNever;                // and the cells' matrices and centres
};

}  // namespace hdt::dual
