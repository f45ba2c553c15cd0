// Surface facts: systole, the polygon's vertices and side midpoints.
#include <memory>

#include "capi/guard.hpp"
#include "group/presentation.hpp"
#include "hdt.h"
#include "group/word_matrix.hpp"
#include "predicates/kernel.hpp"
#include "surface/polygon.hpp"
#include "surface/representative.hpp"
#include "surface/systole.hpp"

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

// The kernel of the genus last asked for on this thread: building one costs
// far more than a representative (the table of N), and a caller usually asks
// many times in a row for one genus.
hdt::predicates::Kernel &thread_kernel(int genus) {
  thread_local std::unique_ptr<hdt::predicates::Kernel> kernel;
  if (!kernel || kernel->presentation().genus() != genus)
    kernel = std::make_unique<hdt::predicates::Kernel>(hdt::group::Presentation(genus));
  return *kernel;
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
    const hdt::group::Presentation p(genus);
    hdt::predicates::Kernel &kernel = thread_kernel(genus);
    const hdt::surface::Representative r = hdt::surface::representative(kernel, x, y);
    const hdt::group::Word &w = kernel.table().word(r.translation);
    const hdt_status status = hdt::capi::copy_word(w, word, capacity, length);
    if (rx || ry) {
      const auto image = r.translation == 0 ? hdt::group::Complex<double>{x, y}
                                            : hdt::group::accurate_image(p, w, {x, y});
      if (rx) *rx = image.re;
      if (ry) *ry = image.im;
    }
    return status;
  });
}

}  // extern "C"
