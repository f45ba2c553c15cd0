// The one funnel between the C ABI and the C++ core.
//
// Every extern "C" body runs inside guarded(): an exception never crosses the
// ABI (it would kill a ctypes caller); it becomes a status code, and its text
// becomes the thread-local last error message. Plain argument checks use
// fail() and never throw.
#pragma once

#include <new>
#include <stdexcept>
#include <string>

#include "exact/unsupported.hpp"
#include "group/presentation.hpp"
#include "hdt.h"

namespace hdt::capi {

// The thread-local text behind hdt_last_error_message.
const char *last_error_message() noexcept;

// Records a failure for hdt_last_error_message and returns its status.
hdt_status fail(hdt_status status, const std::string &message) noexcept;
hdt_status fail(hdt_status status, const char *function, const std::string &message) noexcept;
// The same without building a std::string first: safe when memory is short.
hdt_status fail(hdt_status status, const char *function, const char *message) noexcept;

// An argument error found inside the core's call tree, with its status.
struct ApiError : std::runtime_error {
  ApiError(hdt_status s, const std::string &what) : std::runtime_error(what), status(s) {}
  hdt_status status;
};

// Makes sure this thread frees MPFR's per-thread caches when it exits.
void release_caches_at_thread_exit() noexcept;

template <class Body>
hdt_status guarded(const char *function, Body &&body) noexcept {
  release_caches_at_thread_exit();
  try {
    return body();
  } catch (const ApiError &e) {
    return fail(e.status, function, e.what());
  } catch (const std::bad_alloc &) {
    return fail(HDT_ENOMEM, function, "out of memory");
  } catch (const std::invalid_argument &e) {
    return fail(HDT_EINVAL, function, e.what());
  } catch (const std::domain_error &e) {
    return fail(HDT_EDOMAIN, function, e.what());
  } catch (const exact::Unsupported &e) {
    return fail(HDT_ENOTSUP, function, e.what());
  } catch (const std::length_error &e) {  // a container asked past its max_size
    return fail(HDT_ENOMEM, function, std::string("out of memory: ") + e.what());
  } catch (const std::logic_error &e) {
    try {
      return fail(HDT_EINTERNAL, function, std::string("internal error: ") + e.what());
    } catch (...) {
      return fail(HDT_EINTERNAL, function, e.what());
    }
  } catch (const std::exception &e) {
    return fail(HDT_ERROR, function, e.what());
  } catch (...) {
    return fail(HDT_ERROR, function, "unknown exception");
  }
}

// Checks shared by the functions that take a genus; throws ApiError.
void check_genus(int genus);
// Two-call pattern for a word output: capacity 0 asks for the length
// (out may then be NULL); HDT_EBUFS, with *out_length set, when it is too
// small. Throws ApiError.
hdt_status copy_word(const group::Word &w, int32_t *out, size_t capacity, size_t *out_length);
// Two-call pattern for a text output (hdt_svg): *length gets the text's
// length without its NUL; capacity 0 asks for it only (text may then be
// NULL); HDT_EBUFS, nothing written, when capacity < length + 1; else the
// text and a NUL are written. `what` names the text in the message. Throws
// ApiError.
hdt_status copy_text(const std::string &s, const char *what, char *text, size_t capacity, size_t *length);
// Two-call pattern for a list output (hdt_faces, hdt_vertices): sets *count
// to the list's size, and tells whether to fill the caller's buffers of
// `capacity` items: false for capacity 0 (a size query). Throws ApiError:
// HDT_EINVAL for a NULL count, HDT_EBUFS (with *count set, nothing else
// written) when the buffers are too small; `items` names them in the message.
bool list_fits(std::size_t size, size_t capacity, size_t *count, const char *items);
// A finite point of the open unit disk (decided exactly); else HDT_EDOMAIN.
void check_disk_point(double x, double y);

}  // namespace hdt::capi
