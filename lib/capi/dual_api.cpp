// Adjacency, edges, corner points and the Voronoi diagram (symbol version
// HDT_0.4). The combinatorics and the constructions live in
// lib/dual (adjacency, constructions); these functions check the
// arguments and copy the results out. Each does what may fail (new
// translation ids and matrices, memory) before it writes to the caller's
// buffers, so that a failure (HDT_ENOMEM above all) writes nothing but the
// count.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "capi/guard.hpp"
#include "capi/handle.hpp"
#include "hdt.h"
#include "dual/adjacency.hpp"
#include "dual/all_stars.hpp"
#include "dual/constructions.hpp"

using hdt::capi::ApiError;
using hdt::capi::guarded;
using hdt::capi::list_fits;
using hdt::capi::of;
using hdt::mesh::Face;
using hdt::dual::Point;
using hdt::mesh::Triangulation;

extern "C" {

HDT_API hdt_status hdt_face_neighbours(const hdt_triangulation *t, uint32_t *faces, int32_t *translations,
                                       size_t capacity, size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_face_neighbours", [&] {
    const Triangulation &tri = of(t);
    const auto &all = tri.faces();
    if (!list_fits(all.size(), capacity, count, "faces")) return HDT_OK;
    // Nothing to compute: the canonical copies and the translations between
    // them are hdt_faces' as stored.
    for (std::size_t f = 0; f < all.size(); ++f)
      for (int i = 0; i < 3; ++i) {
        if (faces) faces[3 * f + i] = all[f].n[i];
        if (translations) translations[3 * f + i] = all[f].nt[i];
      }
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_vertex_star(const hdt_triangulation *t, uint32_t v, uint32_t *faces, uint8_t *corners,
                                   int32_t *translations, size_t capacity, size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_vertex_star", [&] {
    const Triangulation &tri = of(t);
    if (!count) throw ApiError(HDT_EINVAL, "count must not be NULL");
    tri.check_live(v);
    std::vector<hdt::dual::StarEntry> &star = t->star;
    hdt::dual::vertex_star(tri, v, &star);
    if (!list_fits(star.size(), capacity, count, "faces")) return HDT_OK;
    // A caller walking every vertex pays this per call: one loop when all
    // three outputs are asked, else one per output.
    const std::size_t n = star.size();
    if (faces && corners && translations) {
      for (std::size_t k = 0; k < n; ++k)
        faces[k] = star[k].face, corners[k] = uint8_t(star[k].corner), translations[k] = star[k].translation;
      return HDT_OK;
    }
    if (faces)
      for (std::size_t k = 0; k < n; ++k) faces[k] = star[k].face;
    if (corners)
      for (std::size_t k = 0; k < n; ++k) corners[k] = uint8_t(star[k].corner);
    if (translations)
      for (std::size_t k = 0; k < n; ++k) translations[k] = star[k].translation;
    return HDT_OK;
  });
}

HDT_API size_t hdt_edge_count(const hdt_triangulation *t) HDT_NOEXCEPT {
  return t ? t->tri.faces().size() / 2 * 3 : 0;
}

HDT_API hdt_status hdt_edges(const hdt_triangulation *t, uint32_t *vertices, int32_t *translations, uint32_t *faces,
                             double *lengths, size_t capacity, size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_edges", [&] {
    using hdt::dual::edge_listed_with;
    using hdt::dual::public_corner;
    const Triangulation &tri = of(t);
    const auto &all = tri.faces();
    if (!list_fits(all.size() / 2 * 3, capacity, count, "edges")) return HDT_OK;
    // What may fail (new translation ids and matrices, memory) first. An
    // edge between corners at the identity (most, inside F_g) has the
    // identity; the others are few, kept as (edge, translation) in order.
    // A corner is at the identity when its translation and its vertex's
    // home are: with no home other than the identity (points given in F_g)
    // the faces alone tell.
    // With lengths, the corner translations' matrices too, in the same
    // pass over the faces (not a pass of their own).
    std::vector<std::pair<std::size_t, int32_t>> moved;
    if (translations || lengths) {
      hdt::group::TranslationTable &T = tri.table();
      bool homes = false;
      if (translations)
        for (const auto &u : tri.vertices()) homes |= u.alive() && u.home != 0;
      std::size_t k = 0;
      for (uint32_t f = 0; f < all.size(); ++f) {
        const Face &A = all[f];
        if (lengths && (A.t[0] | A.t[1] | A.t[2]) != 0)
          for (int i = 0; i < 3; ++i)
            if (A.t[i] != 0) T.moebius(A.t[i]);
        if (!translations) continue;
        for (int i = 0; i < 3; ++i) {
          if (!edge_listed_with(A, f, i)) continue;
          const int a = hdt::mesh::next(i), b = hdt::mesh::prev(i);
          if (A.t[a] != 0 || A.t[b] != 0 || (homes && (public_corner(tri, A, a) != 0 || public_corner(tri, A, b) != 0))) {
            const int32_t h = hdt::dual::edge_translation(tri, A, i);
            if (h != 0) moved.push_back({k, h});
          }
          ++k;
        }
      }
      if (translations && k != *count) throw std::logic_error("hdt_edges: the edge count is not 3F/2");
    }
    // Then the writing, which cannot fail.
    if (vertices || faces || lengths) hdt::dual::write_edges(tri, *count, vertices, faces, lengths);
    if (translations) {
      std::fill(translations, translations + *count, 0);
      for (const auto &m : moved) translations[m.first] = m.second;
    }
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_face_points(const hdt_triangulation *t, double *xy, size_t capacity,
                                   size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_face_points", [&] {
    const Triangulation &tri = of(t);
    if (!list_fits(tri.faces().size(), capacity, count, "faces")) return HDT_OK;
    if (!xy) throw ApiError(HDT_EINVAL, "xy must not be NULL when capacity > 0");
    hdt::dual::warm_corner_matrices(tri, false);
    hdt::dual::face_points(tri, xy);
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_voronoi_vertices(const hdt_triangulation *t, double *xy, double *radii, size_t capacity,
                                        size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_voronoi_vertices", [&] {
    const Triangulation &tri = of(t);
    if (!list_fits(tri.faces().size(), capacity, count, "faces")) return HDT_OK;
    // The matrices first; then nothing allocates, and the results go
    // straight to the caller's buffers (only a broken invariant, a logic
    // error, could stop it part way). Through the handle's centre cache
    // when hdt_voronoi_cell or hdt_voronoi_edges made one (hits read, misses
    // computed and kept); else computed directly: making the cache here
    // (48 bytes a face, written once to fresh pages) would cost a single
    // call about as much as the centres themselves.
    hdt::dual::warm_corner_matrices(tri, false);
    hdt::dual::CentreCache &cache = t->centres;
    if (xy || radii) hdt::dual::voronoi_vertices(tri, xy, radii, cache.ready(tri) ? &cache : nullptr);
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_voronoi_edges(const hdt_triangulation *t, double *xy, size_t capacity,
                                     size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_voronoi_edges", [&] {
    const Triangulation &tri = of(t);
    const auto &all = tri.faces();
    if (!list_fits(all.size() / 2 * 3, capacity, count, "edges")) return HDT_OK;
    if (!xy) throw ApiError(HDT_EINVAL, "xy must not be NULL when capacity > 0");
    // Every centre into scratch first, with the matrices the writing needs
    // (the neighbour translations'; the corners' the centres make): nothing
    // is written before they are made. Then the writing.
    // Where hdt_voronoi_cell made the handle's cache, into the cache (its
    // misses computed and kept), and read from its centres (16 bytes a
    // face: the writing reads the neighbours' centres in no order); else
    // into the handle's scratch (kept: no allocation, no fresh pages on
    // later calls).
    hdt::dual::CentreCache &cache = t->centres;
    const Point *centre;
    if (cache.ready(tri)) {
      hdt::dual::face_centres(tri, nullptr, &cache, true);
      centre = cache.centres();
    } else {
      std::vector<Point> &scratch = t->cell;
      scratch.resize(all.size());
      hdt::dual::face_centres(tri, scratch.data(), nullptr, true);
      centre = scratch.data();
    }
    // hdt_edges' order: edge i of face f when f < its neighbour there (k
    // stops at the count: a broken invariant must not write past it).
    std::size_t k = 0;
    for (uint32_t f = 0; f < all.size(); ++f) {
      const Face &A = all[f];
      // The neighbours' centres are read scattered: fetched some faces ahead.
      if (f + 32 < all.size())
        for (int i = 0; i < 3; ++i) __builtin_prefetch(&centre[all[f + 32].n[i]]);
      if (!(A.n[0] > f || A.n[1] > f || A.n[2] > f)) continue;
      const Point c = centre[f];
      for (int i = 0; i < 3; ++i) {
        if (!hdt::dual::edge_listed_with(A, f, i) || k == *count) continue;
        const Point q = hdt::dual::translate(tri, A.nt[i], centre[A.n[i]]);
        xy[4 * k] = c.re, xy[4 * k + 1] = c.im, xy[4 * k + 2] = q.re, xy[4 * k + 3] = q.im;
        ++k;
      }
    }
    if (k != *count) throw std::logic_error("hdt_voronoi_edges: the edge count is not 3F/2");
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_voronoi_cell(const hdt_triangulation *t, uint32_t v, double *xy, size_t capacity,
                                    size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_voronoi_cell", [&] {
    const Triangulation &tri = of(t);
    if (!count) throw ApiError(HDT_EINVAL, "count must not be NULL");
    tri.check_live(v);
    std::vector<hdt::dual::StarEntry> &star = t->star;
    hdt::dual::vertex_star(tri, v, &star);
    if (!list_fits(star.size(), capacity, count, "corners")) return HDT_OK;
    if (!xy) throw ApiError(HDT_EINVAL, "xy must not be NULL when capacity > 0");
    // Into scratch first: a face's centre (cached on the handle, computed
    // on first request) may need new matrices, and a failure must leave the
    // caller's buffer untouched.
    hdt::dual::CentreCache &cache = t->centres;
    cache.reserve(tri);
    std::vector<Point> &cell = t->cell;
    cell.clear();
    for (const auto &s : star) {
      const Point c = cache.centre(tri, s.face);
      cell.push_back(s.translation == 0 ? c : tri.table().moebius(s.translation).apply(c));
    }
    for (std::size_t k = 0; k < cell.size(); ++k) xy[2 * k] = cell[k].re, xy[2 * k + 1] = cell[k].im;
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_vertex_stars(const hdt_triangulation *t, size_t *offsets, uint32_t *faces, uint8_t *corners,
                                    int32_t *translations, size_t capacity, size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_vertex_stars", [&] {
    const Triangulation &tri = of(t);
    if (!list_fits(3 * tri.faces().size(), capacity, count, "star entries")) return HDT_OK;
    // What may fail (memory, translation ids) into the handle's scratch
    // first (unless the rows are those of this triangulation already),
    // then the writing.
    hdt::dual::AllStars &rows = t->rows;
    if (t->rows_generation != t->generation) {
      t->rows_generation = t->cells_generation = hdt_triangulation::kNever;
      rows.build(tri, false);
      t->rows_generation = t->generation;
    }
    rows.write(tri, offsets, faces, corners, translations);
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_voronoi_cells(const hdt_triangulation *t, size_t *offsets, double *xy, size_t capacity,
                                     size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_voronoi_cells", [&] {
    const Triangulation &tri = of(t);
    if (!list_fits(3 * tri.faces().size(), capacity, count, "cell corners")) return HDT_OK;
    if (!xy) throw ApiError(HDT_EINVAL, "xy must not be NULL when capacity > 0");
    // The rows (with every matrix the centres and the cells need) and,
    // in the same pass over the faces, every face's centre in the handle's
    // centre cache as hdt_voronoi_cell (the same bits; kept for the next
    // call and the other Voronoi outputs); the writing last, once nothing
    // can fail, reading the centres from the cache.
    // While the triangulation is unchanged, the rows (of
    // hdt_vertex_stars or of an earlier call) serve again: only what the
    // cells add is made, or nothing.
    if (t->cells_generation != t->generation) {
      const bool rows_ready = t->rows_generation == t->generation;
      t->rows_generation = t->cells_generation = hdt_triangulation::kNever;
      if (rows_ready) t->rows.prepare_cells(tri, t->centres);
      else t->rows.build_cells(tri, t->centres);
      t->rows_generation = t->cells_generation = t->generation;
    }
    const hdt::dual::AllStars &rows = t->rows;
    rows.write_cells(tri, offsets, xy, t->centres.centres());
    return HDT_OK;
  });
}

}  // extern "C"
