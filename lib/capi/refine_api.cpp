// Refinement, epsilon-nets and quality statistics (symbol version HDT_0.4).
// The algorithm is lib/triangulation/refine.cpp; here the arguments are
// checked before anything changes, and the results copied out.
#include <cmath>

#include "capi/guard.hpp"
#include "capi/handle.hpp"
#include "hdt.h"
#include "triangulation/quality.hpp"
#include "triangulation/refine.hpp"

using hdt::capi::ApiError;
using hdt::capi::guarded;
using hdt::capi::of;

namespace {

hdt_status run(const char *function, hdt_triangulation *t, double max_radius, double max_ratio, size_t max_points,
               size_t *added, size_t *unmet) {
  const hdt::capi::LongCall call(t, function);
  if (!(max_radius > 0)) throw ApiError(HDT_EINVAL, "the radius bound must be > 0 (and not NaN)");
  if (!(max_ratio >= 1)) throw ApiError(HDT_EINVAL, "max_ratio must be >= 1 (and not NaN)");
  const hdt::triangulation::Refined r =
      hdt::triangulation::refine(call.tri(), {max_radius, max_ratio}, max_points, call.progress());
  if (added) *added = r.added;
  if (unmet) *unmet = r.unmet;
  return HDT_OK;
}

}  // namespace

extern "C" {

HDT_API hdt_status hdt_refine(hdt_triangulation *t, double max_radius, double max_ratio, size_t max_points,
                              size_t *added, size_t *unmet) HDT_NOEXCEPT {
  return guarded("hdt_refine", [&] { return run("hdt_refine", t, max_radius, max_ratio, max_points, added, unmet); });
}

HDT_API hdt_status hdt_epsilon_net(hdt_triangulation *t, double epsilon, size_t max_points, size_t *added,
                                   size_t *unmet) HDT_NOEXCEPT {
  return guarded("hdt_epsilon_net", [&] {
    if (!(epsilon > 0) || std::isinf(epsilon)) throw ApiError(HDT_EINVAL, "epsilon must be finite and > 0");
    return run("hdt_epsilon_net", t, epsilon, INFINITY, max_points, added, unmet);
  });
}

HDT_API hdt_status hdt_quality(const hdt_triangulation *t, double *min_angle, double *max_ratio, double *max_radius,
                               double *min_edge) HDT_NOEXCEPT {
  return guarded("hdt_quality", [&] {
    const hdt::triangulation::Quality q = hdt::triangulation::quality(of(t));
    if (min_angle) *min_angle = q.min_angle;
    if (max_ratio) *max_ratio = q.max_ratio;
    if (max_radius) *max_radius = q.max_radius;
    if (min_edge) *min_edge = q.min_edge;
    return HDT_OK;
  });
}

}  // extern "C"
