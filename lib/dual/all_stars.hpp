// Every live vertex's star at once, in compressed rows by vertex id: the
// entries of vertex v are [offset(v), offset(v + 1)), each exactly what
// vertex_star(v) gives (same first face, same order, same translations).
// Built in face order, not by walking each star: a walk jumps through
// memory (a cache miss per face at 10^6 vertices), while scattering the
// corners into fixed slots per vertex and ordering each row (a handful of
// entries, in cache) reads the faces once, in order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "dual/constructions.hpp"
#include "mesh/triangulation.hpp"

namespace hdt::dual {

class AllStars {
 public:
  // Everything that may fail: memory, the translation ids (and, with
  // matrices, their matrices and the corners' matrices, as
  // warm_corner_matrices(tri, false)) the stars need, and the check of
  // every star (each row ordered here, so that a broken one is found
  // before anything is written). Throws std::bad_alloc, or
  // std::logic_error on a broken invariant; the triangulation is unchanged
  // (its table may have gained ids, as with any query). wide: 64-bit
  // entries even when 32 bits hold them (for the tests of that path).
  template <class Tri>
  void build(const Tri &tri, bool matrices, bool wide = false);
  // The same with matrices, for the cells, and every entry of the cache
  // made to hold its face's circumcentre, in the same pass over the faces
  // (reserved here; its misses computed and kept, as hdt_voronoi_cell
  // does): write_cells then reads cache.centres().
  template <class Tri>
  void build_cells(const Tri &tri, CentreCache &cache, bool wide = false);
  // What build_cells adds to build(tri, false) of the same triangulation
  // (the matrices, the cache's centres), for rows built that way.
  template <class Tri>
  void prepare_cells(const Tri &tri, CentreCache &cache);
  std::size_t entries() const { return entries_; }  // 3F
  // Then the outputs, which cannot fail. offsets: id bound + 1 entries
  // (may be null); the others 1 per entry, each may be null.
  template <class Tri>
  void write(const Tri &tri, std::size_t *offsets, uint32_t *faces, uint8_t *corners,
             int32_t *translations) const;
  // xy: 2 per entry; centre[f] the circumcentre of face f's canonical copy
  // (built with matrices).
  template <class Tri>
  void write_cells(const Tri &tri, std::size_t *offsets, double *xy, const Point *centre) const;

 private:
  template <class U>
  struct Rows;
  template <class Tri>
  void build(const Tri &tri, bool matrices, CentreCache *cache, bool wide);
  template <class U, class Tri>
  void build_rows(const Tri &tri, bool matrices, CentreCache *cache, Rows<U> &rows);
  template <class U, class Tri>
  void order_rows(const Tri &tri, Rows<U> &rows);
  // For each live vertex by id, in star order: emit(entry, face, corner,
  // translation); offsets written when not null. prefetch (may be null):
  // per-face data emit reads, fetched some entries ahead.
  template <class U, class Emit, class Tri>
  void each(const Tri &tri, const Rows<U> &rows, std::size_t *offsets, const Point *prefetch,
            Emit &&emit) const;
  template <class Emit, class Tri>
  void dispatch(const Tri &tri, std::size_t *offsets, const Point *prefetch, Emit &&emit) const;

  // The scatter puts each corner, in face order, into its vertex's next
  // slot: its corner index k = 4f + c (the top bit set when its translation
  // is not the vertex's home, listed in moved_ by k) and the next face about
  // the vertex (counterclockwise). kSlots slots a vertex (one cache line
  // for 32 bits; most vertices have 4 to 8 faces), the entries beyond in
  // overflow. Ordering the rows then puts each row's corners, in star
  // order, at order[start(v)] .., and turns count into the starts. 32-bit
  // while F < 2^29.
  static constexpr std::size_t kSlots = 8;
  template <class U>
  struct Overflow {
    uint32_t v;
    U k, next;
  };
  template <class U>
  struct Rows {
    std::vector<U> count;             // id bound + 1: degrees, then where each row starts
    std::unique_ptr<U[]> slot_store;  // 2 kSlots per vertex, uninitialised until scattered
    U *slots = nullptr;               // slot_store aligned to a cache line
    std::size_t slot_capacity = 0;    // vertices allocated
    std::vector<Overflow<U>> overflow;
    std::unique_ptr<U[]> order;  // 1 per entry
    std::size_t order_capacity = 0;
    std::vector<U> long_row;  // a row of more than kSlots entries, gathered to be ordered
    std::vector<uint8_t> met;  // the entries of a row ordered one by one, met so far
  };
  Rows<uint32_t> small_;
  Rows<uint64_t> large_;
  bool wide_ = false;
  std::size_t entries_ = 0;
  std::vector<std::pair<uint64_t, mesh::TranslationId>> moved_;
};

}  // namespace hdt::dual
