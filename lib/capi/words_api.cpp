// Words in Gamma_g: canonical reduction, matrices, images, the set N.
#include <cmath>

#include "capi/guard.hpp"
#include "group/canonical.hpp"
#include "group/neighbours.hpp"
#include "group/presentation.hpp"
#include "group/word_matrix.hpp"
#include "hdt.h"

using hdt::capi::ApiError;
using hdt::capi::guarded;
using hdt::group::Letter;
using hdt::group::Presentation;

namespace {

// The presentation of a checked genus, and a checked word of it.
Presentation checked_word(int genus, const int32_t *word, size_t length) {
  hdt::capi::check_genus(genus);
  if (length > 0 && !word) throw ApiError(HDT_EINVAL, "word is NULL but length is " + std::to_string(length));
  if (length > HDT_WORD_MAX_LENGTH)
    throw ApiError(HDT_EINVAL, "word length " + std::to_string(length) + " exceeds HDT_WORD_MAX_LENGTH");
  Presentation p(genus);
  p.check_word(word, length);
  return p;
}

}  // namespace

extern "C" {

HDT_API hdt_status hdt_word_reduce(int genus, const int32_t *word, size_t length, int32_t *out, size_t capacity,
                                   size_t *out_length) HDT_NOEXCEPT {
  return guarded("hdt_word_reduce", [&] {
    const Presentation p = checked_word(genus, word, length);
    if (!out_length) throw ApiError(HDT_EINVAL, "out_length must not be NULL");
    // hdt.h: HDT_ENOTSUP past 2048 letters, only for the words that need a
    // run-time precision.
    return hdt::capi::copy_word(hdt::group::canonical_word(p, word, length, 2048), out, capacity, out_length);
  });
}

HDT_API hdt_status hdt_word_matrix(int genus, const int32_t *word, size_t length, double m[4]) HDT_NOEXCEPT {
  return guarded("hdt_word_matrix", [&] {
    const Presentation p = checked_word(genus, word, length);
    if (!m) throw ApiError(HDT_EINVAL, "m must not be NULL");
    const auto f = hdt::group::element_moebius(p, word, length);
    m[0] = f.a.re;
    m[1] = f.a.im;
    m[2] = f.b.re;
    m[3] = f.b.im;
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_word_lorentz(int genus, const int32_t *word, size_t length, double m[9]) HDT_NOEXCEPT {
  return guarded("hdt_word_lorentz", [&] {
    const Presentation p = checked_word(genus, word, length);
    if (!m) throw ApiError(HDT_EINVAL, "m must not be NULL");
    const auto L = hdt::group::element_lorentz(p, word, length);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m[3 * i + j] = L.m[i][j];
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_word_apply(int genus, const int32_t *word, size_t length, double x, double y, double *ox,
                                  double *oy) HDT_NOEXCEPT {
  return guarded("hdt_word_apply", [&] {
    const Presentation p = checked_word(genus, word, length);
    if (!ox || !oy) throw ApiError(HDT_EINVAL, "ox and oy must not be NULL");
    hdt::capi::check_disk_point(x, y);
    const auto z = hdt::group::element_image(p, word, length, {x, y});
    *ox = z.re;
    *oy = z.im;
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_neighbour_count(int genus, size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_neighbour_count", [&] {
    hdt::capi::check_genus(genus);
    if (!count) throw ApiError(HDT_EINVAL, "count must not be NULL");
    *count = hdt::group::neighbour_count(Presentation(genus));
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_neighbour_word(int genus, size_t id, int32_t *out, size_t capacity,
                                      size_t *out_length) HDT_NOEXCEPT {
  return guarded("hdt_neighbour_word", [&] {
    hdt::capi::check_genus(genus);
    if (!out_length) throw ApiError(HDT_EINVAL, "out_length must not be NULL");
    return hdt::capi::copy_word(hdt::group::neighbour_word(Presentation(genus), id), out, capacity, out_length);
  });
}

}  // extern "C"
