// Surface facts: systole, the polygon's vertices and side midpoints.
#include "capi/guard.hpp"
#include "group/presentation.hpp"
#include "hdt.h"
#include "predicates/representative.hpp"
#include "surface/polygon.hpp"
#include "surface/systole.hpp"
#include "dummies/dummy_points.hpp"

// hdt_create's limit is the dummy construction's, which refuses beyond it.
static_assert(HDT_CREATE_GENUS_MAX == hdt::dummies::kDummyGenusMax);
static_assert(HDT_CREATE_GENUS_MAX <= HDT_GENUS_MAX);

using hdt::capi::ApiError;
using hdt::capi::guarded;

namespace {

template <class PointOf>
hdt_status polygon_point(const char *function, int genus, int k, double *x, double *y, PointOf point_of) {
  return guarded(function, [&] {
    hdt::capi::check_genus(genus);
    if (!x || !y) throw ApiError(HDT_EINVAL, "x and y must not be NULL");
    const hdt::group::Presentation p(genus);
    const auto z = point_of(p, k);
    *x = z.re;
    *y = z.im;
    return HDT_OK;
  });
}

}  // namespace

extern "C" {

HDT_API double hdt_systole(int genus) HDT_NOEXCEPT {
  hdt::capi::release_caches_at_thread_exit();
  return hdt::surface::systole_or_nan(genus);
}

HDT_API hdt_status hdt_polygon_vertex(int genus, int k, double *x, double *y) HDT_NOEXCEPT {
  return polygon_point("hdt_polygon_vertex", genus, k, x, y,
                       [](const hdt::group::Presentation &p, int i) { return hdt::surface::vertex(p, i); });
}

HDT_API hdt_status hdt_polygon_side_midpoint(int genus, int k, double *x, double *y) HDT_NOEXCEPT {
  return polygon_point("hdt_polygon_side_midpoint", genus, k, x, y,
                       [](const hdt::group::Presentation &p, int i) { return hdt::surface::side_midpoint(p, i); });
}

HDT_API hdt_status hdt_point_representative(int genus, double x, double y, double *rx, double *ry, int32_t *word,
                                            size_t capacity, size_t *length) HDT_NOEXCEPT {
  return guarded("hdt_point_representative", [&] {
    hdt::capi::check_genus(genus);
    if (!length) throw ApiError(HDT_EINVAL, "length must not be NULL");
    hdt::capi::check_disk_point(x, y);
    const hdt::predicates::RepresentativeImage r = hdt::predicates::representative_image(genus, x, y, rx || ry);
    const hdt_status status = hdt::capi::copy_word(r.word, word, capacity, length);
    if (rx) *rx = r.image.re;
    if (ry) *ry = r.image.im;
    return status;
  });
}

}  // extern "C"
