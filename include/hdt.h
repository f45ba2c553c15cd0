/* libhdt: Delaunay triangulations of the symmetric hyperbolic surfaces M_g.
 *
 * The one public header. C99, no C++ type crosses it. Conventions
 * (see README.md and DESIGN.md):
 *   - every fallible function returns an hdt_status and writes its results
 *     through pointers; on failure nothing is written to the outputs unless
 *     the function says otherwise;
 *   - hdt_last_error_message() gives a thread-local detail of the last failure;
 *   - indices are 0-based and taken mod 4g.
 *
 * Group elements are words over the letters 0..4g-1: letter k is the generator
 * g_k, the translation that maps side s_{k+2g} of the fundamental 4g-gon F_g
 * onto side s_k, and g_{k+2g} = g_k^{-1}. The word [k1, ..., km] is the
 * product g_k1 g_k2 ... g_km (applied to a point: g_km first).
 */
#ifndef HDT_H
#define HDT_H

#include <stddef.h>
#include <stdint.h>

#if defined(_WIN32) && defined(HDT_BUILDING_LIBRARY)
#define HDT_API __declspec(dllexport)
#elif defined(_WIN32)
#define HDT_API
#elif defined(__GNUC__) && (__GNUC__ >= 4)
#define HDT_API __attribute__((visibility("default")))
#else
#define HDT_API
#endif

/* C++ callers see that no function throws. */
#ifdef __cplusplus
#define HDT_NOEXCEPT noexcept
#else
#define HDT_NOEXCEPT
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Status codes: values are pinned forever. ---- */
typedef enum hdt_status {
  HDT_OK = 0,           /* success */
  HDT_ERROR = -1,       /* unspecified failure */
  HDT_EINVAL = -2,      /* invalid argument: NULL pointer, genus < 2, bad letter, ... */
  HDT_EDOMAIN = -3,     /* a coordinate is NaN, infinite, or outside the open unit disk */
  HDT_EEXISTS = -4,     /* the point is already a vertex */
  HDT_ENOMEM = -5,      /* out of memory */
  HDT_EBUFS = -6,       /* an output buffer is too small; the needed size is reported */
  HDT_ENOTSUP = -7,     /* valid request beyond what this build supports */
  HDT_EINTERNAL = -99   /* a broken invariant: a bug in libhdt, please report it */
} hdt_status;

/* Static English text for a status code; never NULL ("unknown status" for
   values outside the enum). */
HDT_API const char *hdt_status_string(int status) HDT_NOEXCEPT;

/* Detail of the last failure of an hdt_* call on the calling thread ("" when
   none). The pointer stays valid until the next hdt_* call on this thread. */
HDT_API const char *hdt_last_error_message(void) HDT_NOEXCEPT;

/* ---- Versions ---- */

/* Library version as "MAJOR.MINOR.PATCH". */
HDT_API const char *hdt_version_string(void) HDT_NOEXCEPT;
/* Library version as the number MAJOR * 10000 + MINOR * 100 + PATCH. */
HDT_API int hdt_version(void) HDT_NOEXCEPT;
/* ABI version: equals the SONAME's number (libhdt.so.N). Bindings check it. */
HDT_API int hdt_abi_version(void) HDT_NOEXCEPT;

/* ---- Surface facts (no handle) ---- */

/* Largest genus the functions taking a genus accept (HDT_ENOTSUP above it;
   hdt_systole has no limit). May grow in later versions. */
#define HDT_GENUS_MAX 1024

/* The systole of M_g: 2 arccosh(1 + 2 cos(pi / 2g)). NaN when genus < 2. */
HDT_API double hdt_systole(int genus) HDT_NOEXCEPT;

/* Vertex v_k of F_g (angle (2k+1) pi / 4g), k taken mod 4g. */
HDT_API hdt_status hdt_polygon_vertex(int genus, int k, double *x, double *y) HDT_NOEXCEPT;

/* Midpoint m_k of side s_k of F_g (angle k pi / 2g), k taken mod 4g.
   Side s_k joins v_{k-1} and v_k and is paired with s_{k+2g} by g_k. */
HDT_API hdt_status hdt_polygon_side_midpoint(int genus, int k, double *x, double *y) HDT_NOEXCEPT;

/* The canonical representative of the disk point (x, y): the element h of
   Gamma_g with h(x + iy) in the half-open fundamental domain, which holds
   the interior of F_g, the open sides s_0 .. s_{2g-1} and the one vertex
   v_0 (decided with exact predicates; a point on s_{k+2g} goes to s_k, every
   vertex to v_0). (*rx, *ry) receives h(x + iy) rounded to double (may be
   NULL); the canonical word of h uses the two-call pattern of
   hdt_word_reduce (word may be NULL when capacity is 0). HDT_EDOMAIN when
   (x, y) is not a finite point of the open unit disk. */
HDT_API hdt_status hdt_point_representative(int genus, double x, double y, double *rx, double *ry,
                                            int32_t *word, size_t capacity, size_t *length) HDT_NOEXCEPT;

/* ---- Words in the group Gamma_g (no handle) ----
   A word is an array of int32_t letters, each in 0..4g-1 (else HDT_EINVAL).
   length may be 0 (the identity; word may then be NULL). */

/* Longest word the word functions accept, in letters. */
#define HDT_WORD_MAX_LENGTH 1000000

/* The canonical word of the element: the shortlex-least geodesic word
   (fewest letters; among those, lexicographically least by letter value).
   Two words of the same element give the same canonical word; the identity
   gives the empty word. Dehn's algorithm shortens the word first; the
   canonical choice among geodesic words is then made with certified
   multiprecision geometry. Two-call pattern: capacity 0 (out may be NULL)
   asks for *out_length; HDT_EBUFS (with *out_length set) when capacity is
   too small. The canonical word is never longer than the input, so
   capacity >= length always suffices and saves the second call (each call
   does the whole reduction). HDT_ENOTSUP when the reduced word is too long
   for the built-in precision (hundreds of letters; see README). */
HDT_API hdt_status hdt_word_reduce(int genus, const int32_t *word, size_t length,
                                   int32_t *out, size_t capacity, size_t *out_length) HDT_NOEXCEPT;

/* The SU(1,1) matrix [[a, b], [conj b, conj a]] of the word, in double
   precision: m[0] = Re a, m[1] = Im a, m[2] = Re b, m[3] = Im b. The product
   is taken as written (not reduced first). */
HDT_API hdt_status hdt_word_matrix(int genus, const int32_t *word, size_t length, double m[4]) HDT_NOEXCEPT;

/* The 3x3 Lorentz matrix of the word acting on the hyperboloid
   t^2 - u^2 - v^2 = 1 (rows t, u, v), row-major in m[9]. A disk point
   z = x + iy is the hyperboloid point ((1 + |z|^2), 2x, 2y) / (1 - |z|^2). */
HDT_API hdt_status hdt_word_lorentz(int genus, const int32_t *word, size_t length, double m[9]) HDT_NOEXCEPT;

/* The image (*ox, *oy) of the disk point (x, y) under the word's element,
   computed in multiprecision and rounded (accurate near the unit circle too).
   HDT_EDOMAIN when (x, y) is not a finite point of the open unit disk. */
HDT_API hdt_status hdt_word_apply(int genus, const int32_t *word, size_t length,
                                  double x, double y, double *ox, double *oy) HDT_NOEXCEPT;

/* The neighbour set N = { h in Gamma_g : h(F_g) meets F_g }, identity
   included; |N| = (4g-1)^2. Its elements carry the translation ids
   0..|N|-1, fixed for each genus: id 0 is the identity, the others follow
   in shortlex order of their canonical words. */
HDT_API hdt_status hdt_neighbour_count(int genus, size_t *count) HDT_NOEXCEPT;

/* The canonical word of the element of N with translation id `id`
   (two-call pattern as in hdt_word_reduce). HDT_EINVAL when id >= |N|. */
HDT_API hdt_status hdt_neighbour_word(int genus, size_t id, int32_t *out,
                                      size_t capacity, size_t *out_length) HDT_NOEXCEPT;

#ifdef __cplusplus
}
#endif

#endif /* HDT_H */
