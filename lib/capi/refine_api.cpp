// Refinement, epsilon-nets and quality statistics (symbol version HDT_0.4).
// The algorithm is lib/dual/refine.cpp; here the arguments are
// checked before anything changes, and the results copied out.
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "capi/guard.hpp"
#include "capi/handle.hpp"
#include "hdt.h"
#include "dual/quality.hpp"
#include "dual/refine.hpp"

using hdt::capi::ApiError;
using hdt::capi::fail;
using hdt::capi::guarded;

namespace {

// The most memory this process can have: the machine's physical memory,
// or less where a resource limit says so.
double memory_limit() {
  double limit = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
  for (const int resource : {RLIMIT_AS, RLIMIT_DATA}) {
    struct rlimit r;
    if (getrlimit(resource, &r) == 0 && r.rlim_cur != RLIM_INFINITY) limit = std::min(limit, double(r.rlim_cur));
  }
  return limit;
}

// Work that cannot finish is refused before anything changes: the vertices
// that the radius bound certainly needs (up to the cap) would not fit in
// memory.
template <class Tri>
void check_room(const char *what, const Tri &tri, double max_radius, size_t max_points) {
  const double needed = hdt::dual::vertices_needed(tri.genus(), max_radius);
  const double live = double(tri.vertex_count());
  const double added = std::min(double(max_points), std::max(0.0, needed - live));
  const double bytes = hdt::dual::bytes_needed(double(tri.vertices().size()) + added);
  const double limit = memory_limit();
  if (bytes <= limit) return;
  char message[320];
  std::snprintf(message, sizeof message,
                "%s to radius %.3g on %s%d needs at least %.3g vertices (covering), %.3g GiB, more than the %.3g GiB "
                "this process can have; nothing changed (a larger radius or a cap on the points added fits)",
                what, max_radius, hdt::dual::kMg<Tri> ? "M_" : "a surface of genus ", tri.genus(), live + added, bytes / 0x1p30, limit / 0x1p30);
  throw ApiError(HDT_ENOMEM, message);
}

// *added and *unmet are written on every return past the handle's check:
// 0 and 0 when the arguments are refused (nothing was looked at). A NULL or
// busy handle writes nothing, as everywhere in the API.
// net: hdt_epsilon_net's call (max_radius is its epsilon, which must be finite).
hdt_status run(const char *function, bool net, hdt_triangulation *t, double max_radius, double max_ratio,
               size_t max_points, size_t *added, size_t *unmet) {
  const hdt::capi::LongCall call(t, function);
  if (added) *added = 0;
  if (unmet) *unmet = 0;
  if (net && !(max_radius > 0 && !std::isinf(max_radius))) throw ApiError(HDT_EINVAL, "epsilon must be finite and > 0");
  if (!(max_radius > 0)) throw ApiError(HDT_EINVAL, "the radius bound must be > 0 (and not NaN)");
  if (!(max_ratio >= 1)) throw ApiError(HDT_EINVAL, "max_ratio must be >= 1 (and not NaN)");
  const hdt::dual::Refined r = call.visit([&](auto &tri) {
    check_room(std::isinf(max_ratio) ? "an epsilon-net" : "a refinement", tri, max_radius, max_points);
    return hdt::dual::refine(tri, {max_radius, max_ratio}, max_points, call.progress());
  });
  if (added) *added = r.added;
  if (unmet) *unmet = r.unmet;
  if (r.out_of_memory)
    return fail(HDT_ENOMEM, function,
                "out of memory after " + std::to_string(r.added) +
                    " points were added (they stay, in a valid triangulation; *added and *unmet tell)");
  return HDT_OK;
}

}  // namespace

extern "C" {

HDT_API hdt_status hdt_refine(hdt_triangulation *t, double max_radius, double max_ratio, size_t max_points,
                              size_t *added, size_t *unmet) HDT_NOEXCEPT {
  return guarded("hdt_refine", [&] { return run("hdt_refine", false, t, max_radius, max_ratio, max_points, added, unmet); });
}

HDT_API hdt_status hdt_epsilon_net(hdt_triangulation *t, double epsilon, size_t max_points, size_t *added,
                                   size_t *unmet) HDT_NOEXCEPT {
  return guarded("hdt_epsilon_net",
                 [&] { return run("hdt_epsilon_net", true, t, epsilon, INFINITY, max_points, added, unmet); });
}

HDT_API hdt_status hdt_quality(const hdt_triangulation *t, double *min_angle, double *max_ratio, double *max_radius,
                               double *min_edge) HDT_NOEXCEPT {
  return guarded("hdt_quality", [&] {
    const hdt::dual::Quality q = hdt::capi::visit(t, [](const auto &tri) { return hdt::dual::quality(tri); });
    if (min_angle) *min_angle = q.min_angle;
    if (max_ratio) *max_ratio = q.max_ratio;
    if (max_radius) *max_radius = q.max_radius;
    if (min_edge) *min_edge = q.min_edge;
    return HDT_OK;
  });
}

}  // extern "C"
