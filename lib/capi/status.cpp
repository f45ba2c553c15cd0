// Status texts, the last error message, versions.
#include "capi/guard.hpp"
#include "hdt.h"
#include "version.hpp"

extern "C" {

HDT_API const char *hdt_status_string(int status) HDT_NOEXCEPT {
  switch (status) {
    case HDT_OK: return "success";
    case HDT_ERROR: return "unspecified error";
    case HDT_EINVAL: return "invalid argument";
    case HDT_EDOMAIN: return "point outside the open unit disk or not finite";
    case HDT_EEXISTS: return "the point is already a vertex";
    case HDT_ENOMEM: return "out of memory";
    case HDT_EBUFS: return "output buffer too small";
    case HDT_ENOTSUP: return "not supported";
    case HDT_EINTERNAL: return "internal error (a bug in libhdt)";
    default: return "unknown status";
  }
}

HDT_API const char *hdt_last_error_message(void) HDT_NOEXCEPT { return hdt::capi::last_error_message(); }

HDT_API const char *hdt_version_string(void) HDT_NOEXCEPT { return HDT_VERSION_STRING_VALUE; }

HDT_API int hdt_version(void) HDT_NOEXCEPT {
  return HDT_VERSION_MAJOR_VALUE * 10000 + HDT_VERSION_MINOR_VALUE * 100 + HDT_VERSION_PATCH_VALUE;
}

HDT_API int hdt_abi_version(void) HDT_NOEXCEPT { return HDT_ABI_VERSION_VALUE; }

}  // extern "C"
