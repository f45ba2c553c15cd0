// Progress reports and cancellation (symbol version HDT_0.5): the handle
// keeps the caller's function; hdt_insert_many, hdt_refine and
// hdt_epsilon_net hand it to the core (mesh/progress.hpp).
#include <cmath>

#include "capi/guard.hpp"
#include "capi/handle.hpp"
#include "hdt.h"

using hdt::capi::ApiError;
using hdt::capi::guarded;

extern "C" {

HDT_API hdt_status hdt_set_progress(hdt_triangulation *t, hdt_progress_fn fn, void *user,
                                    double interval_seconds) HDT_NOEXCEPT {
  return guarded("hdt_set_progress", [&] {
    hdt::capi::check_usable(t);
    if (!(interval_seconds >= 0)) throw ApiError(HDT_EINVAL, "interval_seconds must be >= 0 (and not NaN)");
    t->progress = {fn, fn ? user : nullptr, interval_seconds};
    return HDT_OK;
  });
}

}  // extern "C"
