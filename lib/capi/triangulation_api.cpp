// The triangulation handle: lifecycle, insertion, removal, queries, output.
#include <algorithm>
#include <string>
#include <vector>

#include "capi/guard.hpp"
#include "capi/handle.hpp"
#include "hdt.h"
#include "mesh/triangulation.hpp"

using hdt::capi::ApiError;
using hdt::capi::fail;
using hdt::capi::guarded;
using hdt::mesh::Triangulation;

using hdt::capi::of;

namespace {

void check_translation(const Triangulation &tri, int32_t id) {
  if (id < 0 || std::size_t(id) >= tri.table().size())
    throw ApiError(HDT_EINVAL, "unknown translation id " + std::to_string(id));
}

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

HDT_API void hdt_destroy(hdt_triangulation *t) HDT_NOEXCEPT {
  // From the progress function of a call running on t (re-entry): that
  // call frees t as it returns (hdt::capi::LongCall).
  if (t && t->busy) {
    t->destroy_pending = true;
    return;
  }
  delete t;
}

HDT_API int hdt_genus(const hdt_triangulation *t) HDT_NOEXCEPT { return t ? t->tri.genus() : 0; }

HDT_API hdt_status hdt_insert(hdt_triangulation *t, double x, double y, uint32_t *vertex) HDT_NOEXCEPT {
  return guarded("hdt_insert", [&] {
    Triangulation &tri = of(t);
    hdt::capi::check_disk_point(x, y);
    const Triangulation::Inserted r = tri.insert(x, y);
    if (vertex) *vertex = r.vertex;
    if (r.existed) return fail(HDT_EEXISTS, "hdt_insert", "the point is already vertex " + std::to_string(r.vertex));
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_insert_many(hdt_triangulation *t, const double *xy, size_t n, uint32_t *vertices) HDT_NOEXCEPT {
  return guarded("hdt_insert_many", [&] {
    const hdt::capi::LongCall call(t, "hdt_insert_many");
    if (n > 0 && !xy) throw ApiError(HDT_EINVAL, "xy is NULL but n is " + std::to_string(n));
    call.tri().insert_many(xy, n, vertices, call.progress());
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_remove_vertex(hdt_triangulation *t, uint32_t v) HDT_NOEXCEPT {
  return guarded("hdt_remove_vertex", [&] {
    Triangulation &tri = of(t);
    if (!tri.remove(v))
      return fail(HDT_ENOTSUP, "hdt_remove_vertex",
                  "removing vertex " + std::to_string(v) +
                      " would leave a face of circumdiameter >= sys/2 (the triangulation could stop being simplicial)");
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_remove_dummies(hdt_triangulation *t, size_t *remaining) HDT_NOEXCEPT {
  return guarded("hdt_remove_dummies", [&] {
    const std::size_t left = of(t).remove_dummies();
    if (remaining) *remaining = left;
    return HDT_OK;
  });
}

HDT_API size_t hdt_vertex_count(const hdt_triangulation *t) HDT_NOEXCEPT { return t ? t->tri.vertex_count() : 0; }
HDT_API size_t hdt_dummy_count(const hdt_triangulation *t) HDT_NOEXCEPT { return t ? t->tri.dummy_count() : 0; }
HDT_API size_t hdt_vertex_id_bound(const hdt_triangulation *t) HDT_NOEXCEPT {
  return t ? t->tri.vertices().size() : 0;
}
HDT_API size_t hdt_face_count(const hdt_triangulation *t) HDT_NOEXCEPT { return t ? t->tri.faces().size() : 0; }

HDT_API hdt_status hdt_vertex_point(const hdt_triangulation *t, uint32_t v, double *x, double *y) HDT_NOEXCEPT {
  return guarded("hdt_vertex_point", [&] {
    const Triangulation &tri = of(t);
    if (!x || !y) throw ApiError(HDT_EINVAL, "x and y must not be NULL");
    double px, py;
    tri.vertex_point(v, &px, &py);
    *x = px, *y = py;
    return HDT_OK;
  });
}

HDT_API int hdt_vertex_is_dummy(const hdt_triangulation *t, uint32_t v) HDT_NOEXCEPT {
  if (!t || !t->tri.is_live(v)) return -1;
  return t->tri.is_dummy(v) ? 1 : 0;
}

HDT_API hdt_status hdt_vertices(const hdt_triangulation *t, uint32_t *ids, double *xy, uint8_t *dummy, size_t capacity,
                                size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_vertices", [&] {
    const Triangulation &tri = of(t);
    const std::size_t V = tri.vertex_count();
    if (!hdt::capi::list_fits(V, capacity, count, "vertices")) return HDT_OK;
    tri.write_vertices(ids, xy, dummy);
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_faces(const hdt_triangulation *t, uint32_t *vertices, int32_t *translations, size_t capacity,
                             size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_faces", [&] {
    const Triangulation &tri = of(t);
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
}

HDT_API hdt_status hdt_translation_word(const hdt_triangulation *t, int32_t id, int32_t *out, size_t capacity,
                                        size_t *out_length) HDT_NOEXCEPT {
  return guarded("hdt_translation_word", [&] {
    const Triangulation &tri = of(t);
    if (!out_length) throw ApiError(HDT_EINVAL, "out_length must not be NULL");
    check_translation(tri, id);
    return hdt::capi::copy_word(tri.table().word(id), out, capacity, out_length);
  });
}

HDT_API hdt_status hdt_translation_matrix(const hdt_triangulation *t, int32_t id, double m[4]) HDT_NOEXCEPT {
  return guarded("hdt_translation_matrix", [&] {
    const Triangulation &tri = of(t);
    if (!m) throw ApiError(HDT_EINVAL, "m must not be NULL");
    check_translation(tri, id);
    const auto &f = tri.table().moebius(id);
    m[0] = f.a.re, m[1] = f.a.im, m[2] = f.b.re, m[3] = f.b.im;
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_locate(const hdt_triangulation *t, double x, double y, size_t *face,
                              int32_t *translation) HDT_NOEXCEPT {
  return guarded("hdt_locate", [&] {
    const Triangulation &tri = of(t);
    hdt::capi::check_disk_point(x, y);
    const Triangulation::Located r = tri.locate(x, y);
    if (face) *face = r.face;
    if (translation) *translation = r.translation;
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_nearest_vertex(const hdt_triangulation *t, double x, double y, uint32_t *vertex) HDT_NOEXCEPT {
  return guarded("hdt_nearest_vertex", [&] {
    const Triangulation &tri = of(t);
    if (!vertex) throw ApiError(HDT_EINVAL, "vertex must not be NULL");
    hdt::capi::check_disk_point(x, y);
    *vertex = tri.nearest_vertex(x, y);
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_validate(const hdt_triangulation *t) HDT_NOEXCEPT {
  return guarded("hdt_validate", [&] {
    of(t).validate();
    return HDT_OK;
  });
}

}  // extern "C"
