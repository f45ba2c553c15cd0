// The triangulation handle: lifecycle, insertion, removal, queries, output.
#include <algorithm>
#include <string>
#include <vector>

#include "capi/guard.hpp"
#include "capi/handle.hpp"
#include "capi/surface_handle.hpp"
#include "dummies/dummy_points.hpp"
#include "hdt.h"
#include "mesh/polygon_triangulation.hpp"
#include "mesh/triangulation.hpp"

using hdt::capi::ApiError;
using hdt::capi::fail;
using hdt::capi::guarded;
using hdt::mesh::Triangulation;

using hdt::capi::count;
using hdt::capi::visit;
using hdt::mesh::PolygonTriangulation;

namespace {

template <class Tri>
void check_translation(const Tri &tri, int32_t id) {
  if (id < 0 || std::size_t(id) >= tri.table().size())
    throw ApiError(HDT_EINVAL, "unknown translation id " + std::to_string(id));
}

// Whether the mesh is M_g's, for the calls whose answer differs by kind.
template <class Tri>
constexpr bool is_mg = std::is_same_v<Tri, Triangulation>;

}  // namespace

extern "C" {

HDT_API hdt_status hdt_create(hdt_triangulation **out, int genus) HDT_NOEXCEPT {
  return guarded("hdt_create", [&] {
    if (!out) throw ApiError(HDT_EINVAL, "out must not be NULL");
    *out = nullptr;
    hdt::capi::check_genus(genus);
    *out = new hdt_triangulation(genus);
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_create_on_surface(hdt_triangulation **out, const hdt_surface *s) HDT_NOEXCEPT {
  return guarded("hdt_create_on_surface", [&] {
    if (!out) throw ApiError(HDT_EINVAL, "out must not be NULL");
    *out = nullptr;
    if (!s) throw ApiError(HDT_EINVAL, "the surface handle is NULL");
    const bool in_field = bool(s->polygon.field());
    const hdt::domain::FieldLock lock(in_field);
    *out = new hdt_triangulation(hdt::dummies::new_polygon_triangulation(s->polygon), in_field);
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_triangulation_surface(const hdt_triangulation *t, hdt_surface **out) HDT_NOEXCEPT {
  return guarded("hdt_triangulation_surface", [&] {
    if (!out) throw ApiError(HDT_EINVAL, "out must not be NULL");
    *out = nullptr;
    return visit(t, [&](const auto &tri) {
      if constexpr (!is_mg<std::decay_t<decltype(tri)>>) *out = new hdt_surface(tri.surface().polygon());
      return HDT_OK;
    });
  });
}

HDT_API void hdt_destroy(hdt_triangulation *t) HDT_NOEXCEPT {
  // From the progress function of a call running on t (re-entry): that
  // call frees t as it returns (hdt::capi::LongCall).
  if (t && t->busy) {
    t->destroy_pending = true;
    return;
  }
  if (t) hdt::capi::destroy(t);
}

HDT_API int hdt_genus(const hdt_triangulation *t) HDT_NOEXCEPT {
  return count(t, [](const auto &tri) { return tri.genus(); });
}

HDT_API hdt_status hdt_insert(hdt_triangulation *t, double x, double y, uint32_t *vertex) HDT_NOEXCEPT {
  return guarded("hdt_insert", [&] {
    return visit(t, [&](auto &tri) {
      hdt::capi::check_disk_point(x, y);
      const auto r = tri.insert(x, y);
      if (vertex) *vertex = r.vertex;
      if (r.existed) return fail(HDT_EEXISTS, "hdt_insert", "the point is already vertex " + std::to_string(r.vertex));
      return HDT_OK;
    });
  });
}

HDT_API hdt_status hdt_insert_many(hdt_triangulation *t, const double *xy, size_t n, uint32_t *vertices) HDT_NOEXCEPT {
  return guarded("hdt_insert_many", [&] {
    const hdt::capi::LongCall call(t, "hdt_insert_many");
    if (n > 0 && !xy) throw ApiError(HDT_EINVAL, "xy is NULL but n is " + std::to_string(n));
    call.visit([&](auto &tri) { tri.insert_many(xy, n, vertices, call.progress()); });
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_remove_vertex(hdt_triangulation *t, uint32_t v) HDT_NOEXCEPT {
  return guarded("hdt_remove_vertex", [&] {
    if (!visit(t, [&](auto &tri) { return tri.remove(v); }))
      return fail(HDT_ENOTSUP, "hdt_remove_vertex",
                  "removing vertex " + std::to_string(v) +
                      " would leave a face of circumdiameter >= sys/2 (the triangulation could stop being simplicial)");
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_remove_dummies(hdt_triangulation *t, size_t *remaining) HDT_NOEXCEPT {
  return guarded("hdt_remove_dummies", [&] {
    const std::size_t left = visit(t, [](auto &tri) { return tri.remove_dummies(); });
    if (remaining) *remaining = left;
    return HDT_OK;
  });
}

HDT_API size_t hdt_vertex_count(const hdt_triangulation *t) HDT_NOEXCEPT {
  return count(t, [](const auto &tri) { return tri.vertex_count(); });
}
HDT_API size_t hdt_dummy_count(const hdt_triangulation *t) HDT_NOEXCEPT {
  return count(t, [](const auto &tri) { return tri.dummy_count(); });
}
HDT_API size_t hdt_vertex_id_bound(const hdt_triangulation *t) HDT_NOEXCEPT {
  return count(t, [](const auto &tri) { return tri.vertices().size(); });
}
HDT_API size_t hdt_face_count(const hdt_triangulation *t) HDT_NOEXCEPT {
  return count(t, [](const auto &tri) { return tri.faces().size(); });
}

HDT_API hdt_status hdt_vertex_point(const hdt_triangulation *t, uint32_t v, double *x, double *y) HDT_NOEXCEPT {
  return guarded("hdt_vertex_point", [&] {
    return visit(t, [&](const auto &tri) {
      if (!x || !y) throw ApiError(HDT_EINVAL, "x and y must not be NULL");
      double px, py;
      tri.vertex_point(v, &px, &py);
      *x = px, *y = py;
      return HDT_OK;
    });
  });
}

HDT_API int hdt_vertex_is_dummy(const hdt_triangulation *t, uint32_t v) HDT_NOEXCEPT {
  if (!t) return -1;
  return std::visit([v](const auto &tri) { return tri.is_live(v) ? tri.is_dummy(v) ? 1 : 0 : -1; }, t->tri);
}

HDT_API hdt_status hdt_vertices(const hdt_triangulation *t, uint32_t *ids, double *xy, uint8_t *dummy, size_t capacity,
                                size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_vertices", [&] {
    return visit(t, [&](const auto &tri) {
      const std::size_t V = tri.vertex_count();
      if (!hdt::capi::list_fits(V, capacity, count, "vertices")) return HDT_OK;
      tri.write_vertices(ids, xy, dummy);
      return HDT_OK;
    });
  });
}

HDT_API hdt_status hdt_faces(const hdt_triangulation *t, uint32_t *vertices, int32_t *translations, size_t capacity,
                             size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_faces", [&] {
    return visit(t, [&](const auto &tri) {
      const auto &faces = tri.faces();
      const std::size_t F = faces.size();
      if (!hdt::capi::list_fits(F, capacity, count, "faces")) return HDT_OK;
      if (!vertices) throw ApiError(HDT_EINVAL, "vertices must not be NULL when capacity > 0");
      // The corners whose translation is not the face's own (their vertex's
      // home is not the identity: few, often none), computed before anything
      // is written: they may allocate (and fail). A copy of every corner's
      // into scratch would cost a first call 12 bytes a face of fresh pages,
      // whose faults outweigh the copy itself.
      std::vector<std::pair<std::size_t, int32_t>> moved;
      if (translations) tri.corner_translations(&moved);
      if (translations)
        for (std::size_t f = 0; f < F; ++f)
          for (int i = 0; i < 3; ++i) vertices[3 * f + i] = faces[f].v[i], translations[3 * f + i] = faces[f].t[i];
      else
        for (std::size_t f = 0; f < F; ++f)
          for (int i = 0; i < 3; ++i) vertices[3 * f + i] = faces[f].v[i];
      for (const auto &m : moved) translations[m.first] = m.second;
      *count = F;
      return HDT_OK;
    });
  });
}

HDT_API hdt_status hdt_translation_word(const hdt_triangulation *t, int32_t id, int32_t *out, size_t capacity,
                                        size_t *out_length) HDT_NOEXCEPT {
  return guarded("hdt_translation_word", [&] {
    return visit(t, [&](const auto &tri) {
      if (!out_length) throw ApiError(HDT_EINVAL, "out_length must not be NULL");
      check_translation(tri, id);
      if constexpr (is_mg<std::decay_t<decltype(tri)>>) {
        return hdt::capi::copy_word(tri.table().word(id), out, capacity, out_length);
      } else {
        const std::vector<int> letters = tri.surface().word(hdt::domain::ElementId(id));
        return hdt::capi::copy_word(hdt::group::Word(letters.begin(), letters.end()), out, capacity, out_length);
      }
    });
  });
}

HDT_API hdt_status hdt_translation_matrix(const hdt_triangulation *t, int32_t id, double m[4]) HDT_NOEXCEPT {
  return guarded("hdt_translation_matrix", [&] {
    return visit(t, [&](const auto &tri) {
      if (!m) throw ApiError(HDT_EINVAL, "m must not be NULL");
      check_translation(tri, id);
      if constexpr (is_mg<std::decay_t<decltype(tri)>>) {
        const auto &f = tri.table().moebius(id);
        m[0] = f.a.re, m[1] = f.a.im, m[2] = f.b.re, m[3] = f.b.im;
      } else {
        // The sign of (a, b) as hdt_surface_pairing gives it: Re a >= 0.
        auto [a, b] = tri.surface().rounded(hdt::domain::ElementId(id));
        if (a.real() < 0 || (a.real() == 0 && a.imag() < 0)) a = -a, b = -b;
        m[0] = a.real(), m[1] = a.imag(), m[2] = b.real(), m[3] = b.imag();
      }
      return HDT_OK;
    });
  });
}

HDT_API hdt_status hdt_locate(const hdt_triangulation *t, double x, double y, size_t *face,
                              int32_t *translation) HDT_NOEXCEPT {
  return guarded("hdt_locate", [&] {
    return visit(t, [&](const auto &tri) {
      hdt::capi::check_disk_point(x, y);
      const auto r = tri.locate(x, y);
      if (face) *face = r.face;
      if (translation) *translation = r.translation;
      return HDT_OK;
    });
  });
}

HDT_API hdt_status hdt_nearest_vertex(const hdt_triangulation *t, double x, double y, uint32_t *vertex) HDT_NOEXCEPT {
  return guarded("hdt_nearest_vertex", [&] {
    return visit(t, [&](const auto &tri) {
      if (!vertex) throw ApiError(HDT_EINVAL, "vertex must not be NULL");
      hdt::capi::check_disk_point(x, y);
      *vertex = tri.nearest_vertex(x, y);
      return HDT_OK;
    });
  });
}

HDT_API hdt_status hdt_validate(const hdt_triangulation *t) HDT_NOEXCEPT {
  return guarded("hdt_validate", [&] {
    visit(t, [](const auto &tri) { tri.validate(); });
    return HDT_OK;
  });
}

}  // extern "C"
