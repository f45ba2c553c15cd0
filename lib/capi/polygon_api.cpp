// Surfaces given by a fundamental polygon (symbol version HDT_0.7): read from
// text or drawn at random, checked exactly (lib/domain), and described.
#include <complex>
#include <cstring>
#include <string>
#include <string_view>

#include "capi/guard.hpp"
#include "capi/surface_handle.hpp"
#include "domain/field_lock.hpp"
#include "domain/fundamental_polygon.hpp"
#include "domain/neighbours.hpp"
#include "domain/polygon_text.hpp"
#include "domain/random_octagon.hpp"
#include "hdt.h"

using hdt::capi::ApiError;
using hdt::capi::guarded;
using hdt::domain::Complex;
using hdt::domain::FieldLock;
using hdt::domain::FundamentalPolygon;

namespace {

const FundamentalPolygon &polygon_of(const hdt_surface *s) {
  if (!s) throw ApiError(HDT_EINVAL, "the surface handle is NULL");
  return s->polygon;
}

// Whether calls on the surface do number-field arithmetic (field_lock.hpp).
bool in_field(const FundamentalPolygon &p) { return bool(p.field()); }

// *out gets the surface make() returns; NULL when it throws. make() runs
// under the field lock when lock_field is true.
template <class Make>
hdt_status new_surface(const char *function, hdt_surface **out, bool lock_field, Make &&make) {
  return guarded(function, [&] {
    if (!out) throw ApiError(HDT_EINVAL, "out must not be NULL");
    *out = nullptr;
    try {
      const FieldLock lock(lock_field);
      *out = new hdt_surface(make());
    } catch (const hdt::domain::ParseError &e) {
      throw ApiError(HDT_EINVAL, e.what());
    }
    return HDT_OK;
  });
}

// The SU(1,1) form (a, b) of a projective matrix [[A, B], [C, D]] of a disk
// isometry: [[A, B], [C, D]] = lambda [[a, b], [conj b, conj a]] with
// |a|^2 - |b|^2 = 1 and lambda^2 = AD - BC. a^2 = A^2 / det and ab = AB / det
// are exact in K(i); only their roundings are taken, then a = sqrt(a^2)
// (principal root, Re a >= 0) and b = ab / a (|a| >= 1: no cancellation).
void su11(const hdt::domain::Moebius &M, double m[4]) {
  const Complex det = M.a * M.d - M.b * M.c;
  const Complex a2 = M.a * M.a / det, ab = M.a * M.b / det;
  const auto rounded = [](const Complex &z) {
    return std::complex<double>(static_cast<double>(z.re), static_cast<double>(z.im));
  };
  const std::complex<double> a = std::sqrt(rounded(a2)), b = rounded(ab) / a;
  m[0] = a.real(), m[1] = a.imag(), m[2] = b.real(), m[3] = b.imag();
}

}  // namespace

extern "C" {

HDT_API hdt_status hdt_surface_from_polygon(hdt_surface **out, const char *text, size_t length) HDT_NOEXCEPT {
  const bool field = text && hdt::domain::names_field(std::string_view(text, length));
  return new_surface("hdt_surface_from_polygon", out, field, [&] {
    if (!text && length > 0) throw ApiError(HDT_EINVAL, "text is NULL but length is " + std::to_string(length));
    return FundamentalPolygon(hdt::domain::parse_polygon_text(std::string(text ? text : "", length)));
  });
}

HDT_API hdt_status hdt_surface_random_symmetric(hdt_surface **out, int sides, uint64_t seed) HDT_NOEXCEPT {
  return new_surface("hdt_surface_random_symmetric", out, false, [&] {
    if (sides != 8 && sides != 10)
      throw ApiError(HDT_EINVAL, "sides must be 8 or 10, not " + std::to_string(sides));
    return hdt::domain::random_symmetric_polygon(sides / 2, seed);
  });
}

HDT_API void hdt_surface_destroy(hdt_surface *s) HDT_NOEXCEPT {
  if (!s) return;
  const FieldLock lock(in_field(s->polygon));
  delete s;
}

HDT_API int hdt_surface_genus(const hdt_surface *s) HDT_NOEXCEPT { return s ? s->polygon.genus() : 0; }

HDT_API int hdt_surface_side_count(const hdt_surface *s) HDT_NOEXCEPT { return s ? s->polygon.side_count() : 0; }

HDT_API hdt_status hdt_surface_vertex(const hdt_surface *s, int k, double *x, double *y) HDT_NOEXCEPT {
  return guarded("hdt_surface_vertex", [&] {
    const FundamentalPolygon &p = polygon_of(s);
    const FieldLock lock(in_field(p));
    if (!x || !y) throw ApiError(HDT_EINVAL, "x and y must not be NULL");
    const std::complex<double> z = p.vertex_double(k);
    *x = z.real(), *y = z.imag();
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_surface_pairing(const hdt_surface *s, int k, int *paired_side, double m[4]) HDT_NOEXCEPT {
  return guarded("hdt_surface_pairing", [&] {
    const FundamentalPolygon &p = polygon_of(s);
    const FieldLock lock(in_field(p));
    double out[4];
    if (m) su11(p.pairing(k), out);
    if (paired_side) *paired_side = p.paired(k);
    if (m) std::memcpy(m, out, sizeof out);
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_surface_vertex_cycles(const hdt_surface *s, int *cycle, size_t capacity,
                                             size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_surface_vertex_cycles", [&] {
    const FundamentalPolygon &p = polygon_of(s);
    if (!count) throw ApiError(HDT_EINVAL, "count must not be NULL");
    if (capacity > 0 && !cycle) throw ApiError(HDT_EINVAL, "cycle is NULL but capacity is " + std::to_string(capacity));
    const std::size_t n = std::size_t(p.side_count());
    *count = p.cycles().size();
    if (capacity == 0) return HDT_OK;
    if (capacity < n)
      throw ApiError(HDT_EBUFS, "the polygon has " + std::to_string(n) + " vertices, capacity is " +
                                    std::to_string(capacity));
    const auto &cycles = p.cycles();
    for (std::size_t c = 0; c < cycles.size(); ++c)
      for (int v : cycles[c]) cycle[v] = int(c);
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_surface_polygon_text(const hdt_surface *s, char *text, size_t capacity,
                                            size_t *length) HDT_NOEXCEPT {
  return guarded("hdt_surface_polygon_text", [&] {
    const FundamentalPolygon &p = polygon_of(s);
    const FieldLock lock(in_field(p));
    if (!length) throw ApiError(HDT_EINVAL, "length must not be NULL");
    return hdt::capi::copy_text(hdt::domain::polygon_text(p.text()), "the polygon's text", text, capacity, length);
  });
}

HDT_API hdt_status hdt_surface_systole(const hdt_surface *s, double *lo, double *hi) HDT_NOEXCEPT {
  return guarded("hdt_surface_systole", [&] {
    const FundamentalPolygon &p = polygon_of(s);
    const FieldLock lock(in_field(p));
    if (!lo || !hi) throw ApiError(HDT_EINVAL, "lo and hi must not be NULL");
    if (!s->systole) s->systole = hdt::domain::systole(p);
    *lo = s->systole->length.lo, *hi = s->systole->length.hi;
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_surface_neighbour_count(const hdt_surface *s, size_t *count) HDT_NOEXCEPT {
  return guarded("hdt_surface_neighbour_count", [&] {
    const FundamentalPolygon &p = polygon_of(s);
    const FieldLock lock(in_field(p));
    if (!count) throw ApiError(HDT_EINVAL, "count must not be NULL");
    if (!s->neighbours) s->neighbours = hdt::domain::neighbours(p);
    *count = s->neighbours->size();
    return HDT_OK;
  });
}

HDT_API hdt_status hdt_surface_neighbour_word(const hdt_surface *s, size_t id, int32_t *word, size_t capacity,
                                              size_t *length) HDT_NOEXCEPT {
  return guarded("hdt_surface_neighbour_word", [&] {
    const FundamentalPolygon &p = polygon_of(s);
    const FieldLock lock(in_field(p));
    if (!length) throw ApiError(HDT_EINVAL, "length must not be NULL");
    if (!s->neighbours) s->neighbours = hdt::domain::neighbours(p);
    if (id >= s->neighbours->size())
      throw ApiError(HDT_EINVAL, "id " + std::to_string(id) + " is not below |N| = " +
                                     std::to_string(s->neighbours->size()));
    const auto &letters = (*s->neighbours)[id].letters;
    return hdt::capi::copy_word(hdt::group::Word(letters.begin(), letters.end()), word, capacity, length);
  });
}

HDT_API hdt_status hdt_surface_representative(const hdt_surface *s, double x, double y, double *rx, double *ry,
                                              int32_t *word, size_t capacity, size_t *length) HDT_NOEXCEPT {
  return guarded("hdt_surface_representative", [&] {
    const FundamentalPolygon &p = polygon_of(s);
    const FieldLock lock(in_field(p));
    if (!length) throw ApiError(HDT_EINVAL, "length must not be NULL");
    hdt::capi::check_disk_point(x, y);
    if (!s->reduction) s->reduction = std::make_unique<hdt::domain::Reduction>(p);
    const hdt::domain::Representative r = (*s->reduction)(x, y);
    const hdt::group::Word letters(r.word.letters.begin(), r.word.letters.end());
    const hdt_status status = hdt::capi::copy_word(letters, word, capacity, length);
    if (rx) *rx = static_cast<double>(r.point.re);
    if (ry) *ry = static_cast<double>(r.point.im);
    return status;
  });
}

}  // extern "C"
