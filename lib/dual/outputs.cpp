#include "dual/outputs.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>
#include "mesh/polygon_triangulation.hpp"

namespace hdt::dual {

template <class Tri>
const std::vector<StarEntry> &Outputs::star(const Tri &tri, uint32_t v) {
  vertex_star(tri, v, &star_);
  return star_;
}

template <class Tri>
const std::vector<Point> &Outputs::cell_of_star(const Tri &tri) {
  centres_.reserve(tri);
  cell_.clear();
  for (const StarEntry &s : star_) {
    const Point c = centres_.centre(tri, s.face);
    cell_.push_back(s.translation == 0 ? c : tri.table().moebius(s.translation).apply(c));
  }
  return cell_;
}

template <class Tri>
void Outputs::edges(const Tri &tri, std::size_t count, uint32_t *vertices, int32_t *translations,
                    uint32_t *faces, double *lengths) {
  const auto &all = tri.faces();
  // What may fail (new translation ids and matrices, memory) first. An
  // edge between corners at the identity (most, inside F_g) has the
  // identity; the others are few, kept as (edge, translation) in order.
  // A corner is at the identity when its translation and its vertex's
  // home are: with no home other than the identity (points given in F_g)
  // the faces alone tell. With lengths, the corner translations' matrices
  // too, in the same pass over the faces (not a pass of their own).
  std::vector<std::pair<std::size_t, int32_t>> moved;
  if (translations || lengths) {
    auto &T = tri.table();
    bool homes = false;
    if (translations)
      for (const auto &u : tri.vertices()) homes |= u.alive() && u.home != 0;
    std::size_t k = 0;
    for (uint32_t f = 0; f < all.size(); ++f) {
      const mesh::Face &A = all[f];
      if (lengths && (A.t[0] | A.t[1] | A.t[2]) != 0)
        for (int i = 0; i < 3; ++i)
          if (A.t[i] != 0) T.moebius(A.t[i]);
      if (!translations) continue;
      for (int i = 0; i < 3; ++i) {
        if (!edge_listed_with(A, f, i)) continue;
        const int a = mesh::next(i), b = mesh::prev(i);
        if (A.t[a] != 0 || A.t[b] != 0 || (homes && (public_corner(tri, A, a) != 0 || public_corner(tri, A, b) != 0))) {
          const int32_t h = edge_translation(tri, A, i);
          if (h != 0) moved.push_back({k, h});
        }
        ++k;
      }
    }
    if (translations && k != count) throw std::logic_error("edges: the edge count is not 3F/2");
  }
  // Then the writing, which cannot fail.
  if (vertices || faces || lengths) write_edges(tri, count, vertices, faces, lengths);
  if (translations) {
    std::fill(translations, translations + count, 0);
    for (const auto &m : moved) translations[m.first] = m.second;
  }
}

template <class Tri>
void Outputs::voronoi_vertices(const Tri &tri, double *xy, double *radii) {
  // The matrices first; then nothing allocates, and the results go
  // straight to the caller's buffers (only a broken invariant, a logic
  // error, could stop it part way). Through the centre cache when
  // cell_of_star or voronoi_cells made one (hits read, misses computed and
  // kept); else computed directly: making the cache here (48 bytes a face,
  // written once to fresh pages) would cost a single call about as much as
  // the centres themselves.
  warm_corner_matrices(tri, false);
  if (xy || radii) dual::voronoi_vertices(tri, xy, radii, centres_.ready(tri) ? &centres_ : nullptr);
}

template <class Tri>
void Outputs::voronoi_edges(const Tri &tri, std::size_t count, double *xy) {
  const auto &all = tri.faces();
  // Every centre first, with the matrices the writing needs (the neighbour
  // translations'; the corners' the centres make): nothing is written
  // before they are made. Where the cache is made, into it (its misses
  // computed and kept), read from its centres (16 bytes a face: the writing
  // reads the neighbours' centres in no order); else into cell_.
  const Point *centre;
  if (centres_.ready(tri)) {
    face_centres(tri, nullptr, &centres_, true);
    centre = centres_.centres();
  } else {
    cell_.resize(all.size());
    face_centres(tri, cell_.data(), nullptr, true);
    centre = cell_.data();
  }
  // hdt_edges' order: edge i of face f when f < its neighbour there (k
  // stops at the count: a broken invariant must not write past it).
  std::size_t k = 0;
  for (uint32_t f = 0; f < all.size(); ++f) {
    const mesh::Face &A = all[f];
    // The neighbours' centres are read scattered: fetched some faces ahead.
    if (f + 32 < all.size())
      for (int i = 0; i < 3; ++i) __builtin_prefetch(&centre[all[f + 32].n[i]]);
    if (!(A.n[0] > f || A.n[1] > f || A.n[2] > f)) continue;
    const Point c = centre[f];
    for (int i = 0; i < 3; ++i) {
      if (!edge_listed_with(A, f, i) || k == count) continue;
      const Point q = translate(tri, A.nt[i], centre[A.n[i]]);
      xy[4 * k] = c.re, xy[4 * k + 1] = c.im, xy[4 * k + 2] = q.re, xy[4 * k + 3] = q.im;
      ++k;
    }
  }
  if (k != count) throw std::logic_error("voronoi_edges: the edge count is not 3F/2");
}

template <class Tri>
void Outputs::vertex_stars(const Tri &tri, std::size_t *offsets, uint32_t *faces, uint8_t *corners,
                           int32_t *translations) {
  if (rows_revision_ != tri.revision()) {
    rows_revision_ = cells_revision_ = kNever;
    rows_.build(tri, false);
    rows_revision_ = tri.revision();
  }
  rows_.write(tri, offsets, faces, corners, translations);
}

template <class Tri>
void Outputs::voronoi_cells(const Tri &tri, std::size_t *offsets, double *xy) {
  // The rows (with every matrix the centres and the cells need) and, in
  // the same pass over the faces, every face's centre in the cache (the
  // same bits as cell_of_star's; kept for the next call and the other
  // Voronoi outputs); the writing last, once nothing can fail. Rows of
  // vertex_stars at this revision serve: only what the cells add is made.
  if (cells_revision_ != tri.revision()) {
    const bool rows_ready = rows_revision_ == tri.revision();
    rows_revision_ = cells_revision_ = kNever;
    if (rows_ready) rows_.prepare_cells(tri, centres_);
    else rows_.build_cells(tri, centres_);
    rows_revision_ = cells_revision_ = tri.revision();
  }
  rows_.write_cells(tri, offsets, xy, centres_.centres());
}

// Both kinds of triangulation: M_g's and a polygon surface's.
#define HDT_DUAL_INSTANTIATE(Tri) \
  template const std::vector<StarEntry> &Outputs::star(const Tri &, uint32_t);                            \
  template const std::vector<Point> &Outputs::cell_of_star(const Tri &);                                  \
  template void Outputs::edges(const Tri &, std::size_t, uint32_t *, int32_t *, uint32_t *, double *);    \
  template void Outputs::voronoi_vertices(const Tri &, double *, double *);                               \
  template void Outputs::voronoi_edges(const Tri &, std::size_t, double *);                               \
  template void Outputs::vertex_stars(const Tri &, std::size_t *, uint32_t *, uint8_t *, int32_t *);      \
  template void Outputs::voronoi_cells(const Tri &, std::size_t *, double *);
HDT_DUAL_INSTANTIATE(mesh::Triangulation)
HDT_DUAL_INSTANTIATE(mesh::PolygonTriangulation)
#undef HDT_DUAL_INSTANTIATE

}  // namespace hdt::dual
