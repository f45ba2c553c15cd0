// Every live vertex's star at once, in compressed rows by vertex id: the
// entries of vertex v are [offset(v), offset(v + 1)), each exactly what
// vertex_star(v) gives (same first face, same order, same translations).
// Built in face order, not by walking each star: a walk jumps through
// memory (a cache miss per face at 10^6 vertices), while counting the
// corners per vertex, scattering them into their vertex's row and ordering
// each row (a handful of entries, in cache) reads the faces in order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "triangulation/constructions.hpp"
#include "triangulation/triangulation.hpp"

namespace hdt::triangulation {

class AllStars {
 public:
  // Everything that may fail: memory, and the translation ids (and, with
  // matrices, their matrices) the stars need. Throws std::bad_alloc, or
  // std::logic_error on a broken invariant; the triangulation is unchanged
  // (its table may have gained ids, as with any query). For the cells,
  // centre[f] the circumcentre of face f's canonical copy (built with
  // matrices) and xy (2 per entry) the cells' output: build writes it (a
  // face's centre at each of its corners' places) once nothing can fail,
  // and write_cells puts it in order.
  void build(const Triangulation &tri, bool matrices, const Point *centre = nullptr, double *xy = nullptr);
  std::size_t entries() const { return entries_; }  // 3F
  // Then the outputs, which cannot fail. offsets: id bound + 1 entries
  // (may be null); the others 1 per entry, each may be null.
  void write(const Triangulation &tri, std::size_t *offsets, uint32_t *faces, uint8_t *corners,
             int32_t *translations) const;
  // xy as build(centre, xy) left it.
  void write_cells(const Triangulation &tri, std::size_t *offsets, double *xy) const;

 private:
  template <class U>
  struct Rows;
  template <class U>
  void build_rows(const Triangulation &tri, bool matrices, const Point *centre, double *xy, Rows<U> &rows);
  // For each live vertex by id: begin(row start, degree), then emit(entry,
  // index in the row, face, corner, translation) in star order.
  template <class U, class Begin, class Emit>
  void each(const Triangulation &tri, const Rows<U> &rows, std::size_t *offsets, Begin &&begin, Emit &&emit) const;
  template <class Begin, class Emit>
  void dispatch(const Triangulation &tri, std::size_t *offsets, Begin &&begin, Emit &&emit) const;

  // Corner k = 3f + c of each entry and the next face about the vertex
  // (counterclockwise), in the vertex's row in face order; the top bit of k marks a corner whose translation is not the
  // vertex's home, listed in moved_ (by k). 32-bit while 3F < 2^31.
  template <class U>
  struct Rows {
    struct Entry {
      U k, next;
    };
    std::vector<U> start;            // id bound + 1
    std::unique_ptr<Entry[]> entry;  // 3F used, uninitialised until scattered
    std::size_t capacity = 0;        // entries allocated
  };
  Rows<uint32_t> small_;
  Rows<uint64_t> large_;
  bool wide_ = false;
  std::size_t entries_ = 0;
  std::vector<std::pair<uint64_t, TranslationId>> moved_;
  mutable std::vector<Point> row_;  // the largest row's centres, for write_cells
};

}  // namespace hdt::triangulation
