// Adjacency, edges, corner points and the Voronoi diagram (symbol version
// HDT_0.4). The combinatorics, the constructions and the caches kept
// between calls live in lib/dual (dual::Outputs); these functions check the
// arguments, call once and copy the results out. What may fail (new
// translation ids and matrices, memory) comes before anything is written
// to the caller's buffers, so that a failure (HDT_ENOMEM above all) writes
// nothing but the count.
#include <vector>

#include "capi/guard.hpp"
#include "capi/handle.hpp"
#include "hdt.h"
#include "dual/constructions.hpp"
#include "dual/outputs.hpp"

using hdt::capi::ApiError;
using hdt::capi::guarded;
using hdt::capi::list_fits;
using hdt::dual::Point;

extern "C" {

HDT_API hdt_status hdt_face_neighbours(const hdt_triangulation *t, uint32_t *faces, int32_t *translations,
                                       size_t capacity, size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_face_neighbours", [&] {
    return hdt::capi::visit(t, [&](const auto &tri) {
      const auto &all = tri.faces();
      if (!list_fits(all.size(), capacity, count, "faces")) return HDT_OK;
      // Nothing to compute: the canonical copies and the translations
      // between them are hdt_faces' as stored.
      for (std::size_t f = 0; f < all.size(); ++f)
        for (int i = 0; i < 3; ++i) {
          if (faces) faces[3 * f + i] = all[f].n[i];
          if (translations) translations[3 * f + i] = all[f].nt[i];
        }
      return HDT_OK;
    });
  });
}

HDT_API hdt_status hdt_vertex_star(const hdt_triangulation *t, uint32_t v, uint32_t *faces, uint8_t *corners,
                                   int32_t *translations, size_t capacity, size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_vertex_star", [&] {
    return hdt::capi::visit(t, [&](const auto &tri) {
      if (!count) throw ApiError(HDT_EINVAL, "count must not be NULL");
      const std::vector<hdt::dual::StarEntry> &star = t->outputs.star(tri, v);
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
  });
}

HDT_API size_t hdt_edge_count(const hdt_triangulation *t) HDT_NOEXCEPT {
  return hdt::capi::count(t, [](const auto &tri) { return tri.faces().size() / 2 * 3; });
}

HDT_API hdt_status hdt_edges(const hdt_triangulation *t, uint32_t *vertices, int32_t *translations, uint32_t *faces,
                             double *lengths, size_t capacity, size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_edges", [&] {
    return hdt::capi::visit(t, [&](const auto &tri) {
      if (!list_fits(tri.faces().size() / 2 * 3, capacity, count, "edges")) return HDT_OK;
      hdt::dual::Outputs::edges(tri, *count, vertices, translations, faces, lengths);
      return HDT_OK;
    });
  });
}

HDT_API hdt_status hdt_face_points(const hdt_triangulation *t, double *xy, size_t capacity,
                                   size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_face_points", [&] {
    return hdt::capi::visit(t, [&](const auto &tri) {
      if (!list_fits(tri.faces().size(), capacity, count, "faces")) return HDT_OK;
      if (!xy) throw ApiError(HDT_EINVAL, "xy must not be NULL when capacity > 0");
      hdt::dual::warm_corner_matrices(tri, false);
      hdt::dual::face_points(tri, xy);
      return HDT_OK;
    });
  });
}

HDT_API hdt_status hdt_voronoi_vertices(const hdt_triangulation *t, double *xy, double *radii, size_t capacity,
                                        size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_voronoi_vertices", [&] {
    return hdt::capi::visit(t, [&](const auto &tri) {
      if (!list_fits(tri.faces().size(), capacity, count, "faces")) return HDT_OK;
      t->outputs.voronoi_vertices(tri, xy, radii);
      return HDT_OK;
    });
  });
}

HDT_API hdt_status hdt_voronoi_edges(const hdt_triangulation *t, double *xy, size_t capacity,
                                     size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_voronoi_edges", [&] {
    return hdt::capi::visit(t, [&](const auto &tri) {
      if (!list_fits(tri.faces().size() / 2 * 3, capacity, count, "edges")) return HDT_OK;
      if (!xy) throw ApiError(HDT_EINVAL, "xy must not be NULL when capacity > 0");
      t->outputs.voronoi_edges(tri, *count, xy);
      return HDT_OK;
    });
  });
}

HDT_API hdt_status hdt_voronoi_cell(const hdt_triangulation *t, uint32_t v, double *xy, size_t capacity,
                                    size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_voronoi_cell", [&] {
    return hdt::capi::visit(t, [&](const auto &tri) {
      if (!count) throw ApiError(HDT_EINVAL, "count must not be NULL");
      if (!list_fits(t->outputs.star(tri, v).size(), capacity, count, "corners")) return HDT_OK;
      if (!xy) throw ApiError(HDT_EINVAL, "xy must not be NULL when capacity > 0");
      const std::vector<Point> &cell = t->outputs.cell_of_star(tri);
      for (std::size_t k = 0; k < cell.size(); ++k) xy[2 * k] = cell[k].re, xy[2 * k + 1] = cell[k].im;
      return HDT_OK;
    });
  });
}

HDT_API hdt_status hdt_vertex_stars(const hdt_triangulation *t, size_t *offsets, uint32_t *faces, uint8_t *corners,
                                    int32_t *translations, size_t capacity, size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_vertex_stars", [&] {
    return hdt::capi::visit(t, [&](const auto &tri) {
      if (!list_fits(3 * tri.faces().size(), capacity, count, "star entries")) return HDT_OK;
      t->outputs.vertex_stars(tri, offsets, faces, corners, translations);
      return HDT_OK;
    });
  });
}

HDT_API hdt_status hdt_voronoi_cells(const hdt_triangulation *t, size_t *offsets, double *xy, size_t capacity,
                                     size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_voronoi_cells", [&] {
    return hdt::capi::visit(t, [&](const auto &tri) {
      if (!list_fits(3 * tri.faces().size(), capacity, count, "cell corners")) return HDT_OK;
      if (!xy) throw ApiError(HDT_EINVAL, "xy must not be NULL when capacity > 0");
      t->outputs.voronoi_cells(tri, offsets, xy);
      return HDT_OK;
    });
  });
}

}  // extern "C"
