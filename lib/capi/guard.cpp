#include "capi/guard.hpp"

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <cstring>

#include <flint/flint.h>
#include <mpfr.h>

#include <thread>

#include "exact/unit_disk.hpp"

namespace hdt::capi {

namespace {
// The detail of the last failure on this thread.
thread_local std::string last_error;
}  // namespace

const char *last_error_message() noexcept { return last_error.c_str(); }

namespace {
// The thread that loaded the library: the main thread, in practice.
const std::thread::id loading_thread = std::this_thread::get_id();

// MPFR keeps constants (pi, ...) and cos/sin tables per thread, and FLINT
// (under e-antic, lib/domain) its integers' memory pool; a thread that ends
// without freeing them leaks them. One of these per thread that called
// libhdt frees them at its exit. FLINT's are left to the loading thread's
// exit, when the numbers e-antic keeps for the process (its fields, in
// statics destroyed after this runs) would still need them.
struct CacheRelease {
  ~CacheRelease() {
    mpfr_free_cache2(MPFR_FREE_LOCAL_CACHE);
    if (std::this_thread::get_id() != loading_thread) flint_cleanup();
  }
};
}  // namespace

void release_caches_at_thread_exit() noexcept {
  static thread_local CacheRelease release;
  (void)release;
}

hdt_status fail(hdt_status status, const std::string &message) noexcept {
  try {
    last_error = message;
  } catch (...) {
    last_error.clear();  // keep the status even when the text cannot be stored
  }
  return status;
}

hdt_status fail(hdt_status status, const char *function, const std::string &message) noexcept {
  try {
    return fail(status, std::string(function) + ": " + message);
  } catch (...) {
    return fail(status, message);
  }
}

hdt_status fail(hdt_status status, const char *function, const char *message) noexcept {
  try {
    last_error.assign(function).append(": ").append(message);
  } catch (...) {
    last_error.clear();
  }
  return status;
}

void check_genus(int genus) {
  if (genus < 2) throw ApiError(HDT_EINVAL, "genus must be at least 2, got " + std::to_string(genus));
  if (genus > HDT_GENUS_MAX)
    throw ApiError(HDT_ENOTSUP,
                   "genus " + std::to_string(genus) + " exceeds HDT_GENUS_MAX = " + std::to_string(HDT_GENUS_MAX));
}

bool list_fits(std::size_t size, size_t capacity, size_t *count, const char *items) {
  if (!count) throw ApiError(HDT_EINVAL, "count must not be NULL");
  *count = size;
  if (capacity == 0) return false;
  if (capacity < size)
    throw ApiError(HDT_EBUFS, "capacity " + std::to_string(capacity) + " is too small for " + std::to_string(size) +
                                  " " + items);
  return true;
}

hdt_status copy_word(const group::Word &w, int32_t *out, size_t capacity, size_t *out_length) {
  if (capacity > 0 && !out) throw ApiError(HDT_EINVAL, "out is NULL but capacity is " + std::to_string(capacity));
  *out_length = w.size();
  if (capacity == 0) return HDT_OK;
  if (capacity < w.size())
    throw ApiError(HDT_EBUFS, "the word has " + std::to_string(w.size()) + " letters, capacity is " +
                                  std::to_string(capacity));
  std::copy(w.begin(), w.end(), out);
  return HDT_OK;
}

hdt_status copy_text(const std::string &s, const char *what, char *text, size_t capacity, size_t *length) {
  if (capacity > 0 && !text) throw ApiError(HDT_EINVAL, "text is NULL but capacity is " + std::to_string(capacity));
  *length = s.size();
  if (capacity == 0) return HDT_OK;
  if (capacity < s.size() + 1)
    throw ApiError(HDT_EBUFS, std::string(what) + " has " + std::to_string(s.size()) + " bytes and its NUL, capacity is " +
                                  std::to_string(capacity));
  std::memcpy(text, s.c_str(), s.size() + 1);
  return HDT_OK;
}

void check_disk_point(double x, double y) {
  char text[96];
  if (!std::isfinite(x) || !std::isfinite(y)) {
    std::snprintf(text, sizeof text, "the point (%.17g, %.17g) is not finite", x, y);
    throw ApiError(HDT_EDOMAIN, text);
  }
  if (!exact::inside_unit_disk(x, y)) {
    std::snprintf(text, sizeof text, "the point (%.17g, %.17g) is not inside the open unit disk", x, y);
    throw ApiError(HDT_EDOMAIN, text);
  }
}

}  // namespace hdt::capi
