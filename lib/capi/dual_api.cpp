// Adjacency, edges, corner points and the Voronoi diagram (symbol version
// HDT_0.4). The combinatorics and the constructions live in
// lib/triangulation (adjacency, constructions); these functions check the
// arguments and copy the results out. Each does what may fail (new
// translation ids and matrices, memory) before it writes to the caller's
// buffers, so that a failure (HDT_ENOMEM above all) writes nothing but the
// count.
#include <stdexcept>
#include <string>
#include <vector>

#include "capi/guard.hpp"
#include "capi/handle.hpp"
#include "hdt.h"
#include "triangulation/adjacency.hpp"
#include "triangulation/constructions.hpp"

using hdt::capi::ApiError;
using hdt::capi::guarded;
using hdt::capi::list_fits;
using hdt::capi::of;
using hdt::triangulation::Circle;
using hdt::triangulation::Face;
using hdt::triangulation::Point;
using hdt::triangulation::Triangulation;

namespace {

Circle face_circle(const Triangulation &tri, const Face &f) {
  using hdt::triangulation::face_corner;
  const Point p[3] = {face_corner(tri, f, 0), face_corner(tri, f, 1), face_corner(tri, f, 2)};
  return hdt::triangulation::circumcircle(tri, f, p);
}

// The matrices of every corner translation (and, with `across`, of every
// translation between neighbours) computed now: what follows only applies
// them and cannot fail half way through the caller's buffer.
void warm_matrices(const Triangulation &tri, bool across) {
  hdt::group::TranslationTable &T = tri.table();
  for (const Face &f : tri.faces())
    for (int i = 0; i < 3; ++i) {
      if (f.t[i] != 0) T.moebius(f.t[i]);
      if (across && f.nt[i] != 0) T.moebius(f.nt[i]);
    }
}

// The per-vertex functions' scratch, reused from call to call on a thread:
// a caller walking every vertex would otherwise pay an allocation per call.
std::vector<hdt::triangulation::StarEntry> &star_scratch() {
  thread_local std::vector<hdt::triangulation::StarEntry> star;
  return star;
}

void check_vertex(const Triangulation &tri, uint32_t v) {
  if (v >= tri.vertices().size() || !tri.vertices()[v].alive())
    throw ApiError(HDT_EINVAL, "vertex " + std::to_string(v) + " is not a live vertex");
}

}  // namespace

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
    check_vertex(tri, v);
    std::vector<hdt::triangulation::StarEntry> &star = star_scratch();
    hdt::triangulation::vertex_star(tri, v, &star);
    if (!list_fits(star.size(), capacity, count, "faces")) return HDT_OK;
    for (std::size_t k = 0; k < star.size(); ++k) {
      if (faces) faces[k] = star[k].face;
      if (corners) corners[k] = uint8_t(star[k].corner);
      if (translations) translations[k] = star[k].translation;
    }
    return HDT_OK;
  });
}

HDT_API size_t hdt_edge_count(const hdt_triangulation *t) HDT_NOEXCEPT {
  return t ? t->tri.faces().size() / 2 * 3 : 0;
}

HDT_API hdt_status hdt_edges(const hdt_triangulation *t, uint32_t *vertices, int32_t *translations, uint32_t *faces,
                             double *lengths, size_t capacity, size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_edges", [&] {
    using hdt::triangulation::edge_listed_with;
    const Triangulation &tri = of(t);
    const auto &all = tri.faces();
    if (!list_fits(all.size() / 2 * 3, capacity, count, "edges")) return HDT_OK;
    // What may fail (new translation ids and matrices) first, then one pass
    // that writes every output.
    std::vector<int32_t> h;
    if (translations) {
      h.reserve(*count);
      for (uint32_t f = 0; f < all.size(); ++f)
        for (int i = 0; i < 3; ++i)
          if (edge_listed_with(all[f], f, i)) h.push_back(hdt::triangulation::edge_translation(tri, all[f], i));
      if (h.size() != *count) throw std::logic_error("hdt_edges: the edge count is not 3F/2");
    }
    if (lengths) warm_matrices(tri, false);
    std::size_t k = 0;
    for (uint32_t f = 0; f < all.size(); ++f)
      for (int i = 0; i < 3; ++i) {
        if (!edge_listed_with(all[f], f, i) || k == *count) continue;
        const int a = (i + 1) % 3, b = (i + 2) % 3;
        if (vertices) vertices[2 * k] = all[f].v[a], vertices[2 * k + 1] = all[f].v[b];
        if (translations) translations[k] = h[k];
        if (faces) faces[2 * k] = f, faces[2 * k + 1] = all[f].n[i];
        if (lengths)
          lengths[k] = hdt::triangulation::distance(hdt::triangulation::face_corner(tri, all[f], a),
                                                    hdt::triangulation::face_corner(tri, all[f], b));
        ++k;
      }
    if (k != *count) throw std::logic_error("hdt_edges: the edge count is not 3F/2");
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_face_points(const hdt_triangulation *t, double *xy, size_t capacity,
                                   size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_face_points", [&] {
    const Triangulation &tri = of(t);
    const auto &all = tri.faces();
    if (!list_fits(all.size(), capacity, count, "faces")) return HDT_OK;
    if (!xy) throw ApiError(HDT_EINVAL, "xy must not be NULL when capacity > 0");
    warm_matrices(tri, false);
    for (std::size_t f = 0; f < all.size(); ++f)
      for (int i = 0; i < 3; ++i) {
        const Point p = hdt::triangulation::face_corner(tri, all[f], i);
        xy[6 * f + 2 * i] = p.re, xy[6 * f + 2 * i + 1] = p.im;
      }
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_voronoi_vertices(const hdt_triangulation *t, double *xy, double *radii, size_t capacity,
                                        size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_voronoi_vertices", [&] {
    const Triangulation &tri = of(t);
    const auto &all = tri.faces();
    if (!list_fits(all.size(), capacity, count, "faces")) return HDT_OK;
    std::vector<Circle> circles;
    circles.reserve(all.size());
    for (const Face &f : all) circles.push_back(face_circle(tri, f));
    for (std::size_t f = 0; f < all.size(); ++f) {
      if (xy) xy[2 * f] = circles[f].centre.re, xy[2 * f + 1] = circles[f].centre.im;
      if (radii) radii[f] = circles[f].radius;
    }
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
    warm_matrices(tri, true);
    std::vector<Point> centre(all.size());
    for (std::size_t f = 0; f < all.size(); ++f) centre[f] = face_circle(tri, all[f]).centre;
    // hdt_edges' order: edge i of face f when f < its neighbour there (k
    // stops at the count: a broken invariant must not write past it).
    std::size_t k = 0;
    for (uint32_t f = 0; f < all.size(); ++f)
      for (int i = 0; i < 3; ++i) {
        if (!hdt::triangulation::edge_listed_with(all[f], f, i) || k == *count) continue;
        const Point q = hdt::triangulation::translate(tri, all[f].nt[i], centre[all[f].n[i]]);
        xy[4 * k] = centre[f].re, xy[4 * k + 1] = centre[f].im, xy[4 * k + 2] = q.re, xy[4 * k + 3] = q.im;
        ++k;
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
    check_vertex(tri, v);
    std::vector<hdt::triangulation::StarEntry> &star = star_scratch();
    hdt::triangulation::vertex_star(tri, v, &star);
    if (!list_fits(star.size(), capacity, count, "corners")) return HDT_OK;
    if (!xy) throw ApiError(HDT_EINVAL, "xy must not be NULL when capacity > 0");
    // Matrices first: the loop below then cannot fail half way.
    for (const auto &s : star)
      if (s.translation != 0) tri.table().moebius(s.translation);
    for (std::size_t k = 0; k < star.size(); ++k) {
      const Point p =
          hdt::triangulation::translate(tri, star[k].translation, face_circle(tri, tri.faces()[star[k].face]).centre);
      xy[2 * k] = p.re, xy[2 * k + 1] = p.im;
    }
    return HDT_OK;
  });
}

}  // extern "C"
