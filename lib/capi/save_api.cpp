// Saving and loading a triangulation (symbol version HDT_0.4): the handle
// to bytes and back, in the format of save_format.cpp.
#include <memory>

#include "capi/guard.hpp"
#include "capi/handle.hpp"
#include "capi/save_format.hpp"
#include "hdt.h"

using hdt::capi::ApiError;
using hdt::capi::guarded;

extern "C" {

HDT_API hdt_status hdt_save(const hdt_triangulation *t, void *bytes, size_t capacity, size_t *size) HDT_NOEXCEPT {
  return guarded("hdt_save", [&] {
    return hdt::capi::visit(t, [&](const auto &tri) {
      if (!size) throw ApiError(HDT_EINVAL, "size must not be NULL");
      if (capacity > 0 && !bytes)
        throw ApiError(HDT_EINVAL, "bytes is NULL but capacity is " + std::to_string(capacity));
      const std::size_t n = hdt::capi::saved_size(tri);
      if (capacity == 0) {
        *size = n;
        return HDT_OK;
      }
      if (capacity < n) {
        *size = n;
        throw ApiError(HDT_EBUFS, "the saved triangulation needs " + std::to_string(n) + " bytes, the buffer holds " +
                                      std::to_string(capacity));
      }
      hdt::capi::write_saved(tri, static_cast<unsigned char *>(bytes));
      *size = n;
      return HDT_OK;
    });
  });
}

HDT_API hdt_status hdt_load(hdt_triangulation **out, const void *bytes, size_t size) HDT_NOEXCEPT {
  return guarded("hdt_load", [&] {
    if (!out) throw ApiError(HDT_EINVAL, "out must not be NULL");
    if (size > 0 && !bytes) throw ApiError(HDT_EINVAL, "bytes is NULL but size is " + std::to_string(size));
    *out = hdt::capi::read_saved(static_cast<const unsigned char *>(bytes), size).release();
    return HDT_OK;
  });
}

}  // extern "C"
