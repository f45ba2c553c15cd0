/* libhdt: Delaunay triangulations of the symmetric hyperbolic surfaces M_g.
 *
 * The one public header. C99, no C++ type crosses it. Conventions
 * (docs/design.md of the source tree explains them at length):
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
  HDT_EDOMAIN = -3,     /* a coordinate is NaN, infinite, or outside the open unit disk;
                           or a result is not representable (matrix entries beyond the double
                           range, an image that rounds onto the circle) */
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

/* The version of this header, MAJOR.MINOR.PATCH, and as one number. Symbol
   node HDT_0.N (lib/hdt.map) comes with version 0.N.0: a program that calls
   a later function can test at compile time, e.g. hdt_save (HDT_0.4) with
   #if HDT_VERSION >= 400. hdt_version() is the library's own at run time. */
#define HDT_VERSION_MAJOR 0
#define HDT_VERSION_MINOR 8
#define HDT_VERSION_PATCH 0
#define HDT_VERSION (HDT_VERSION_MAJOR * 10000 + HDT_VERSION_MINOR * 100 + HDT_VERSION_PATCH)

/* Library version as "MAJOR.MINOR.PATCH". */
HDT_API const char *hdt_version_string(void) HDT_NOEXCEPT;
/* Library version as the number MAJOR * 10000 + MINOR * 100 + PATCH. */
HDT_API int hdt_version(void) HDT_NOEXCEPT;
/* ABI version: equals the SONAME's number (libhdt.so.N). Bindings check it. */
HDT_API int hdt_abi_version(void) HDT_NOEXCEPT;

/* ---- Surface facts (no handle) ---- */

/* Largest genus the functions taking a genus accept (HDT_ENOTSUP above it;
   hdt_systole has no limit). May grow in later versions. Up to it each
   finishes in bounded time and memory, for every point of the open disk
   and every word up to HDT_WORD_MAX_LENGTH (the word functions' cost as
   HDT_WORD_MAX_LENGTH says): the first call of hdt_point_representative
   or a word function for a genus in a process builds that genus's tables,
   later calls reuse them. Times and memory measured at genus 1024:
   docs/benchmarks.md. hdt_create has a lower limit: */
#define HDT_GENUS_MAX 1024

/* Largest genus hdt_create accepts (HDT_ENOTSUP, naming this limit, above
   it), the largest at which a test builds and certifies the dummy points.
   The first triangulation of a genus in a process builds and certifies
   them (exact arithmetic; the costliest first call of the library at large
   genus); later ones copy them. Times and memory of both, per genus:
   docs/benchmarks.md. May grow in later versions. */
#define HDT_CREATE_GENUS_MAX 256

/* The systole of M_g: 2 arccosh(1 + 2 cos(pi / 2g)), correctly rounded (the
   nearest double). NaN when genus < 2. */
HDT_API double hdt_systole(int genus) HDT_NOEXCEPT;

/* Vertex v_k of F_g (angle (2k+1) pi / 4g, Euclidean radius
   sqrt(cos(pi / 2g))), k taken mod 4g; x and y are each correctly rounded.
   The rounded point is a different point of the disk from v_k: inserting it
   makes a new vertex near v_0, not the dummy vertex at v_0. */
HDT_API hdt_status hdt_polygon_vertex(int genus, int k, double *x, double *y) HDT_NOEXCEPT;

/* Midpoint m_k of side s_k of F_g (angle k pi / 2g, Euclidean radius
   sqrt((A - 1) / (A + 1)) with A = cot(pi / 4g)), k taken mod 4g; x and y are
   each correctly rounded (a coordinate on an axis is +0).
   Side s_k joins v_{k-1} and v_k and is paired with s_{k+2g} by g_k. */
HDT_API hdt_status hdt_polygon_side_midpoint(int genus, int k, double *x, double *y) HDT_NOEXCEPT;

/* The canonical representative of the disk point (x, y): the element h of
   Gamma_g with h(x + iy) in the half-open fundamental domain, which holds
   the interior of F_g, the open sides s_0 .. s_{2g-1} and the one vertex
   v_0 (decided with exact predicates; a point on s_{k+2g} goes to s_k, every
   vertex to v_0). (*rx, *ry) receives h(x + iy) rounded to double (may be
   NULL); the canonical word of h uses the two-call pattern of
   hdt_word_reduce (word may be NULL when capacity is 0); every point of the
   open disk gets its word, however long (the two-call pattern sizes it;
   the longest words met are listed in docs/benchmarks.md). HDT_EDOMAIN
   when (x, y) is not a finite point of the open unit disk. */
HDT_API hdt_status hdt_point_representative(int genus, double x, double y, double *rx, double *ry,
                                            int32_t *word, size_t capacity, size_t *length) HDT_NOEXCEPT;

/* ---- Words in the group Gamma_g (no handle) ----
   A word is an array of int32_t letters, each in 0..4g-1 (else HDT_EINVAL).
   length may be 0 (the identity; word may then be NULL). */

/* Longest word the word functions accept, in letters. hdt_word_matrix,
   hdt_word_lorentz and hdt_word_apply take time linear in the length for
   Dehn's algorithm and one pass in double. When the result fits in double
   they add a multiprecision product of the reduced word, which is then
   short at small genus (g_0^n at genus 2 overflows from n = 465); only at
   large genus can a long reduced word (a chain of half relators) still
   fit, and its product costs more per letter than the first pass. The first call
   for a genus also builds its tables. Times: docs/benchmarks.md. */
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
   does the whole reduction). Long reduced words whose points stay near O
   (the words of hdt_point_representative) are certified at a few hundred
   bits; the others take a precision that grows with the length, so their
   time grows faster than the length (docs/large_genus.md; times in
   docs/benchmarks.md). HDT_ENOTSUP, nothing written, when such a word's
   reduced form has more than 2048 letters. */
HDT_API hdt_status hdt_word_reduce(int genus, const int32_t *word, size_t length,
                                   int32_t *out, size_t capacity, size_t *out_length) HDT_NOEXCEPT;

/* The SU(1,1) matrix [[a, b], [conj b, conj a]] of the word, in double
   precision: m[0] = Re a, m[1] = Im a, m[2] = Re b, m[3] = Im b. The word is
   first shortened with Dehn's algorithm, which keeps the matrix itself (the
   relator's product is the identity matrix, not its negative): any word of
   the identity gives exactly a = 1, b = 0. The shortened word's product is
   computed in multiprecision within 2^-72 (|a| + |b|) and rounded once.
   HDT_EDOMAIN, nothing written, when an entry rounds to +-infinity ("the
   matrix entries exceed the double range"; decided on the accurate value,
   or, for results far beyond the range, by a certified lower bound without
   the product): g_0^n at genus 2 from n = 465. HDT_ENOTSUP as a safety net
   never met: a product even the top precision cannot certify. */
HDT_API hdt_status hdt_word_matrix(int genus, const int32_t *word, size_t length, double m[4]) HDT_NOEXCEPT;

/* The 3x3 Lorentz matrix of the word acting on the hyperboloid
   t^2 - u^2 - v^2 = 1 (rows t, u, v), row-major in m[9]. A disk point
   z = x + iy is the hyperboloid point ((1 + |z|^2), 2x, 2y) / (1 - |z|^2).
   Computed from the matrix of hdt_word_matrix (the identity gives the
   identity matrix exactly; HDT_ENOTSUP likewise), each entry within
   2^-66 m[0] before rounding.
   HDT_EDOMAIN, nothing written, when m[0] = |a|^2 + |b|^2, the largest
   entry, rounds to infinity: g_0^n at genus 2 from n = 233. */
HDT_API hdt_status hdt_word_lorentz(int genus, const int32_t *word, size_t length, double m[9]) HDT_NOEXCEPT;

/* The image (*ox, *oy) of the disk point (x, y) under the word's element,
   computed in multiprecision within about 2^-75 and rounded (accurate near
   the unit circle too); Dehn's algorithm first, so a word of the identity
   returns (x, y) bit for bit. HDT_EDOMAIN, nothing written, when (x, y) is
   not a finite point of the open unit disk, and when the image is not:
   its rounding to double is on or outside the unit circle ("the image
   rounds to the unit circle"). An image shown to lie within 2^-100 of the
   circle (double coordinates cannot tell it from the circle) may be refused
   so without being computed ("the image lies within 2^-100 of the unit
   circle"). HDT_ENOTSUP as in hdt_word_matrix. */
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

/* ---- Triangulations ----
   A triangulation of genus g holds a finite point set on M_g and its
   Delaunay triangulation, always a simplicial complex whose faces have
   hyperbolic circumdiameter < sys(M_g) / 2 (so every face is a proper
   triangle of the surface, with three distinct vertices).

   A new triangulation holds the dummy points of its genus (a certified set
   Q with sys(M_g) > 2 delta_Q; see docs/design.md). User points are inserted,
   dummies removed where the result keeps the guarantee.

   Vertices: ids are dense and stable. The dummy vertices take ids 0..d-1
   at creation, each new distinct point the next id; a removed id is never
   reused. A vertex stores the point as given; hdt_vertex_point gives its
   representative in the half-open fundamental domain (see
   hdt_point_representative).

   Faces: 3 vertex ids counterclockwise and, per corner, a translation id:
   the group element applied to that vertex's representative point to place
   it in the face's canonical copy. The canonical copy is the one in which the
   face's smallest vertex id sits at its representative (translation 0, the
   identity), so it meets F_g. Face indices are positions in the order of
   hdt_faces; they hold until the next change of the triangulation.

   Translation ids 0..|N|-1 are the neighbour set N (hdt_neighbour_word);
   larger ids are given by a triangulation as it meets new elements and are
   valid for that handle only (hdt_translation_word, hdt_translation_matrix).

   Memory is linear in V: at least 121 bytes a vertex (its record and
   its two faces: F = 2 (V + 2g - 2)), more for the translation table,
   the point-location grid and the caches some queries below keep (each
   named there). Measured peaks per vertex: docs/benchmarks.md.

   Every function below that takes a handle and returns an hdt_status may
   return, beside the statuses its comment names, HDT_EINVAL for t NULL or
   busy (below) and HDT_ENOMEM when memory runs out; these are not repeated
   at each function. A call that fails leaves the triangulation exactly as
   it was, with one exception: memory running out (HDT_ENOMEM) part way
   through hdt_insert_many, hdt_remove_dummies, hdt_refine or
   hdt_epsilon_net, which then keep the work done so far, in a valid
   triangulation (their outputs, or hdt_dummy_count, tell what was kept).
   One handle is used by one thread at a time; distinct handles are
   independent. While hdt_insert_many,
   hdt_refine or hdt_epsilon_net runs, its progress function may not use
   the handle: such calls fail with HDT_EINVAL, nothing changed (see
   "Progress and cancellation" below). */
typedef struct hdt_triangulation hdt_triangulation; /* opaque */

/* "No vertex": in hdt_insert_many's output, a point not inserted. */
#define HDT_NO_VERTEX UINT32_MAX

/* A new triangulation of M_genus holding its dummy points. *out is NULL on
   failure. HDT_EINVAL for genus < 2 or out NULL, HDT_ENOTSUP above
   HDT_CREATE_GENUS_MAX. */
HDT_API hdt_status hdt_create(hdt_triangulation **out, int genus) HDT_NOEXCEPT;
/* Frees the triangulation; NULL is a no-op. Called from the progress
   function of a call running on t, it only marks t: the call stops at that
   report, as if the function had returned non-zero, and frees t as it
   returns. */
HDT_API void hdt_destroy(hdt_triangulation *t) HDT_NOEXCEPT;
/* The genus, or 0 when t is NULL. */
HDT_API int hdt_genus(const hdt_triangulation *t) HDT_NOEXCEPT;

/* Inserts the point (x, y) of the open unit disk (its representative on
   M_g). A point already present as a user vertex: HDT_EEXISTS, and *vertex
   receives that vertex. A point equal to a dummy vertex turns it into a user
   vertex (HDT_OK, *vertex is the dummy's id). vertex may be NULL.
   HDT_EDOMAIN for NaN, infinities or |z| >= 1 (decided exactly). */
HDT_API hdt_status hdt_insert(hdt_triangulation *t, double x, double y, uint32_t *vertex) HDT_NOEXCEPT;
/* Inserts n points xy[2i], xy[2i+1] in a biased randomized order: rounds
   of growing size (half the points in the last, a quarter before, ...,
   chosen by a fixed hash of i; one round up to 1024 points), each round
   along a Hilbert curve on the representatives, each point located from
   the previous one (a round's first point from the nearest of a random
   sample of vertices; in a call of fewer than V/8 points among V
   vertices, every point from a vertex near it, as hdt_insert). For n
   points uniform on M_g the expected cost is O(log n) a point (randomized
   incremental construction: O(1) expected faces changed a point, short
   walks along the curve), and the order is computed in linear time. Points
   along a curve, or given in many small calls, cost more per point (the
   walks are longer and the order is sorted per call): the figures are in
   docs/benchmarks.md
   (bench/curves_bench.c, bench/batch_bench.c). New vertices get their ids
   in that order, not in input order (the same call gives the same ids).
   vertices (may be NULL)
   receives n ids: vertices[i] answers point i (a duplicate gets the
   existing vertex; that is not an error here, and a dummy met this way
   becomes a user vertex). Every point is checked first:
   a bad point rejects the whole call (HDT_EDOMAIN naming its index) and
   nothing is inserted. The memory for all n points is reserved before the
   first insertion, growing at least twofold so that a series of calls does
   not copy the triangulation each time (HDT_ENOMEM, nothing inserted, when
   that fails); should an
   allocation still fail later, the call returns HDT_ENOMEM with the points
   inserted so far in place, and vertices[i] is HDT_NO_VERTEX for each
   point i not inserted. */
HDT_API hdt_status hdt_insert_many(hdt_triangulation *t, const double *xy, size_t n,
                                   uint32_t *vertices) HDT_NOEXCEPT;
/* Removes vertex v (user or dummy). Refused with HDT_ENOTSUP, nothing
   changed, when the triangulation without v would break the guarantee
   (a new face of circumdiameter >= sys/2). HDT_EINVAL when v is not a live
   vertex. */
HDT_API hdt_status hdt_remove_vertex(hdt_triangulation *t, uint32_t v) HDT_NOEXCEPT;
/* Removes every dummy vertex that can go without breaking the guarantee;
   *remaining (may be NULL) receives how many dummies are left. */
HDT_API hdt_status hdt_remove_dummies(hdt_triangulation *t, size_t *remaining) HDT_NOEXCEPT;

/* Live vertices, dummies included (0 when t is NULL). */
HDT_API size_t hdt_vertex_count(const hdt_triangulation *t) HDT_NOEXCEPT;
/* Live dummy vertices (0 when t is NULL). */
HDT_API size_t hdt_dummy_count(const hdt_triangulation *t) HDT_NOEXCEPT;
/* One past the largest vertex id ever given: ids below it are live or
   removed (0 when t is NULL). */
HDT_API size_t hdt_vertex_id_bound(const hdt_triangulation *t) HDT_NOEXCEPT;
/* Faces: F = 2 (V + 2g - 2) (0 when t is NULL). */
HDT_API size_t hdt_face_count(const hdt_triangulation *t) HDT_NOEXCEPT;
/* The representative of vertex v in the half-open F_g, rounded to double.
   HDT_EINVAL when v is not a live vertex. */
HDT_API hdt_status hdt_vertex_point(const hdt_triangulation *t, uint32_t v, double *x, double *y) HDT_NOEXCEPT;
/* 1 for a dummy vertex, 0 for a user vertex, -1 for no live vertex v. */
HDT_API int hdt_vertex_is_dummy(const hdt_triangulation *t, uint32_t v) HDT_NOEXCEPT;
/* Every live vertex in one call, by increasing id (symbol version HDT_0.2).
   Two-call pattern as in hdt_faces, capacity in vertices: capacity 0 asks
   for *count (= hdt_vertex_count); HDT_EBUFS, with *count set and nothing
   written, when too small. Each output may be NULL: ids, xy (2 per vertex:
   the representative, as hdt_vertex_point), dummy (1 dummy, 0 user). */
HDT_API hdt_status hdt_vertices(const hdt_triangulation *t, uint32_t *ids, double *xy, uint8_t *dummy,
                                size_t capacity, size_t *count) HDT_NOEXCEPT;

/* The faces, two-call pattern: capacity (in faces) 0 asks for *count
   (vertices may then be NULL); HDT_EBUFS, with *count set, when too small.
   vertices: 3 per face, counterclockwise. translations (may be NULL): 3 per
   face, the translation id of each corner (see above). */
HDT_API hdt_status hdt_faces(const hdt_triangulation *t, uint32_t *vertices, int32_t *translations,
                             size_t capacity, size_t *count) HDT_NOEXCEPT;
/* The canonical word of a translation id of this triangulation (two-call
   pattern as in hdt_word_reduce). HDT_EINVAL for an unknown id. */
HDT_API hdt_status hdt_translation_word(const hdt_triangulation *t, int32_t id, int32_t *out,
                                        size_t capacity, size_t *out_length) HDT_NOEXCEPT;
/* The SU(1,1) matrix of a translation id (layout of hdt_word_matrix). */
HDT_API hdt_status hdt_translation_matrix(const hdt_triangulation *t, int32_t id, double m[4]) HDT_NOEXCEPT;
/* The class [h] in H_1(M_g; Z) = Z^{2g} of a translation id h (symbol
   version HDT_0.6): its abelianisation over the generators, out[k] for
   k = 0..2g-1 the number of letters k minus the number of letters k + 2g
   (g_k^-1) in its word. The relator counts 0 (each g_k and each g_k^-1
   occurs in it once), so this is a homomorphism: [h h'] = [h] + [h'],
   [h^-1] = -[h], the same for every word of h. Characters of Gamma_g into
   U(1), the twists of hyperbolic band theory, factor through it:
   chi_k(h) = exp(i k . [h]). Two-call pattern as in hdt_faces, capacity in
   entries: capacity 0 asks for *count (= 2g; out may then be NULL);
   HDT_EBUFS, with *count set and nothing written, when 0 < capacity < 2g.
   HDT_EINVAL, nothing written, for t or count NULL, an unknown id, out NULL
   with capacity > 0. On a surface given by a polygon (HDT_0.8): the class
   in a basis of its own H_1 (see hdt_create_on_surface). */
HDT_API hdt_status hdt_translation_homology(const hdt_triangulation *t, int32_t id, int32_t *out, size_t capacity,
                                            size_t *count) HDT_NOEXCEPT;

/* Point location: the face (index in hdt_faces order) whose copy contains
   the disk point (x, y), and the translation id h of that copy: (x, y) lies
   in the closed triangle h(canonical copy). A point on an edge or vertex gets
   one of the faces around it. face or translation may be NULL. Queries in
   no particular order start their walk from a vertex near the point (a
   grid over the representatives, rebuilt whenever the vertex count has
   doubled), so that for vertices spread over M_g a walk crosses about a
   grid cell's faces instead of the O(V^(1/2)) of a walk from afar; the
   grid takes O(V) memory. hdt_nearest_vertex walks likewise. Times per
   query: docs/benchmarks.md (bench/batch_bench.c). */
HDT_API hdt_status hdt_locate(const hdt_triangulation *t, double x, double y, size_t *face,
                              int32_t *translation) HDT_NOEXCEPT;
/* The vertex nearest to the disk point (x, y) on M_g (hyperbolic distance,
   decided exactly; ties go to the smaller id), dummies included. */
HDT_API hdt_status hdt_nearest_vertex(const hdt_triangulation *t, double x, double y,
                                      uint32_t *vertex) HDT_NOEXCEPT;

/* Full check of every invariant with exact predicates: each edge shared by
   two faces with consistent translations, canonical counterclockwise faces,
   F = 2 (V + 2g - 2), each vertex surrounded once, the empty-circle property
   across every edge, the simplicial condition (no loops, no double edges)
   and the circumdiameter guarantee. HDT_OK, or HDT_EINTERNAL with a message
   naming the broken invariant. */
HDT_API hdt_status hdt_validate(const hdt_triangulation *t) HDT_NOEXCEPT;

/* ---- Pictures ---- */

#define HDT_SVG_NEIGHBOURS 1u    /* also the 4g copies of F_g across its sides, and the faces, vertices and
                                    (with HDT_SVG_VORONOI) Voronoi edges in them, lighter */
#define HDT_SVG_HIDE_DUMMIES 2u  /* do not mark the dummy vertices (the faces around them are drawn either way) */
#define HDT_SVG_VORONOI 4u       /* also the Voronoi diagram, cut at the sides like the faces (HDT_0.4 on) */
#define HDT_SVG_SIDE_LABELS 8u   /* label the sides of F_g beside their midpoints: s_k with g_k (which maps
                                    s_{k+2g} onto it) and s_{k+2g} with g_k^-1, k < 2g (from version 0.6.0;
                                    earlier libraries refuse it with HDT_EINVAL) */
/* Largest picture width hdt_svg accepts, in pixels. */
#define HDT_SVG_SIZE_MAX 100000.0

/* The triangulation drawn in the Poincare disk, as the text of an SVG
   document (UTF-8; symbol version HDT_0.3). The picture shows M_g as F_g
   (a surface given by a polygon, HDT_0.8: as that polygon) with its sides
   paired: every copy of a face that meets F_g, with
   geodesic edges, cut at F_g's sides, so that F_g is tiled exactly; F_g
   filled lightly and outlined; user vertices dark dots, dummy vertices
   larger red ones (a vertex on F_g's boundary gets a dot at each of its
   places there: 2 on a side, 4g at the corners); above them a caption of
   two parts, the title and what the picture shows, each wrapped at spaces
   where an estimate of its width (generous: DejaVu Sans's advance widths
   and 5%) would not fit the picture's width.
   Coordinates are rounded to 0.01 px. The triangulation is not changed.
   size: the width in pixels, finite, > 0 and <= HDT_SVG_SIZE_MAX (the
   height adds a caption band of 0.07 size, and 0.025 size for each further
   title line and 0.02125 size for each further line of the second part
   when they wrap; hdt-triangulate uses 800).
   title: the caption's first line, plain UTF-8 text (markup is escaped;
   control characters and bytes that are not UTF-8 show as '?'); NULL for
   "Delaunay triangulation of N points on M_g" (N user vertices), or, with
   no user vertex, "The dummy point set of M_g and its Delaunay
   triangulation" (", before any insertion," after M_g while no vertex was
   ever inserted or removed). flags: HDT_SVG_* bits; others are HDT_EINVAL.
   Two-call pattern as in hdt_faces, in bytes: *length receives the length
   of the text without its terminating NUL; capacity 0 asks for it (text
   may then be NULL); HDT_EBUFS, with *length set and nothing written, when
   0 < capacity < *length + 1; otherwise the text and a NUL are written.
   Each call draws the whole picture. HDT_EINVAL (nothing written, *length
   included) for t or length NULL, a bad size or flags, text NULL with
   capacity > 0; HDT_ENOMEM when memory runs out. Time: faces x (4g-1)^2
   (each face's copies under the neighbour set N are tried), 4g + 1 times
   that with HDT_SVG_NEIGHBOURS. */
HDT_API hdt_status hdt_svg(const hdt_triangulation *t, double size, const char *title, unsigned flags,
                           char *text, size_t capacity, size_t *length) HDT_NOEXCEPT;

/* ---- Saving and loading (symbol version HDT_0.4) ----
   A triangulation as bytes, in a versioned binary format with a checksum
   (docs/format.md): the genus, every vertex's point exactly as given, the
   ids with the gaps removals left, the dummy flags, the faces in their
   slots, and the translation ids the triangulation has given. A loaded
   triangulation is the saved one: the same ids, hdt_faces and hdt_vertices
   give the same bytes, and the same later calls on both give the same
   results (a query made on one only may give it new translation ids the
   other gives to other elements later). A triangulation of a surface given
   by a polygon (HDT_0.8) is saved in format version 2, which stores the
   polygon's text exactly and the translations as words in its pairings;
   hdt_load reads both versions, and checks a version 2 file's polygon as
   hdt_surface_from_polygon does. */

/* Writes t's saved form into bytes (capacity bytes). Two-call pattern in
   bytes: capacity 0 asks for *size (bytes may then be NULL); HDT_EBUFS,
   with *size set and nothing written, when capacity < *size. The
   triangulation is not changed. HDT_EINVAL for t or size NULL, bytes NULL
   with capacity > 0. HDT_ENOTSUP, as a safety net never met, when a
   translation word is longer than the format holds (32g + 64 letters; the
   longest met: 28 at genus 2, 46 at genus 5, 189 at genus 64 with points
   1e-15 from the circle), or when its element lies too far from O for
   hdt_load to certify its word (docs/format.md, check 5: far beyond the
   translation of any point of the disk). Time and size are linear:
   25 bytes a vertex id and 48 a face, about 121 bytes a vertex; each
   translation word beyond N is checked once, a product a letter. */
HDT_API hdt_status hdt_save(const hdt_triangulation *t, void *bytes, size_t capacity, size_t *size) HDT_NOEXCEPT;

/* A new triangulation from the size bytes hdt_save wrote (*out receives it;
   hdt_destroy frees it). Every field is checked and the result validated
   as hdt_validate does (exact predicates) before it is returned: bytes that
   are truncated, corrupted or crafted give HDT_EINVAL, with
   hdt_last_error_message naming the byte offset at fault ("byte 136:
   vertex 3 is not a point of the open unit disk"), and never a triangulation
   that breaks an invariant. Memory: a small multiple of size (every count
   is checked against size before anything is allocated) plus the surface
   of the file's genus, which a file that passes the checks needing no
   surface gets built whatever its size (its exact sites, generators and
   tables; measured peaks per genus: docs/format.md). Time: linear in
   size with constants set by the genus, whatever the bytes: each
   translation word is checked to be canonical with one product a letter at
   a fixed precision (at most 160 digits), never canonicalised; a word
   whose element lies too far from O for that (far beyond any point's
   translation, docs/format.md) is refused. The validation (hdt_validate's
   exact predicates on every edge) dominates: of the order of
   hdt_insert_many of the same points (measured ratio: docs/benchmarks.md,
   docs/format.md). *out is not written on failure. HDT_EINVAL also for out
   NULL or bytes NULL with size > 0; HDT_ENOMEM when memory runs out. */
HDT_API hdt_status hdt_load(hdt_triangulation **out, const void *bytes, size_t size) HDT_NOEXCEPT;

/* ---- Adjacency, edges, corner points and the Voronoi diagram ----
   Symbol version HDT_0.4. All are queries on a const handle (they may add
   translation ids to the handle's table, as hdt_faces does). Faces are
   indices in hdt_faces order (until the next change of the triangulation,
   as there; so are edge indices), and translations are ids of this
   triangulation in hdt_faces' convention: h applied to a vertex's
   representative, or to a face's canonical copy (hdt_translation_word,
   hdt_translation_matrix). Lists use the two-call pattern of hdt_faces:
   capacity 0 asks for *count, HDT_EBUFS with *count set when too small,
   HDT_EINVAL for a NULL t or count; each output may be NULL unless said.

   Points (corners, circumcentres), radii and lengths are computed in
   double from the stored points and the translations' matrices: rounded
   values, not exact ones. Lengths, radii and angles (hdt_quality's too)
   are read from a face's sides, and where rounded corners (translated,
   dummy sites) could put a side off by more than 2^-46 of the face's
   smallest altitude, the sides come from the exact data in double-double
   or at 200 bits: they keep their relative accuracy however short (two
   distinct vertices 1e-16 apart have an edge of about that length, never
   0). Accuracy, measured (not proved) against a 256-bit MPFR evaluation
   by tests/test_dual.c (random sets of genus 2, 3 and 5, dummy sets of
   genus 2 and 4, and edges of 4e-18 to 1e-16 between a point and the
   rounded image of a nearby one; the worst values in docs/dual.md):
   radii, edge lengths and hdt_quality's figures within a relative 1e-14;
   corners within 5e-15 of the exact ones in the disk
   (hyperbolic distance 1.1e-13, growing with the genus, with the entries
   of the translations' matrices), circumcentres within 1.3e-14
   (docs/dual.md). A face double cannot resolve (corners nearly collinear,
   or at the scale of 1e-300) has its circle computed with 200-bit
   arithmetic from the exact data instead; hdt_face_points' corners are
   rounded values. */

/* Per face f and corner i, faces[3f + i]: the face across the edge opposite
   corner i (from corner i+1 to corner i+2), and translations[3f + i]: the
   id h such that h(canonical copy of that face) shares that edge with f's
   canonical copy. Across an edge and back the translations are inverse.
   Capacity in faces (3 entries each). */
HDT_API hdt_status hdt_face_neighbours(const hdt_triangulation *t, uint32_t *faces, int32_t *translations,
                                       size_t capacity, size_t *count) HDT_NOEXCEPT;

/* The star of vertex v: the faces around it, counterclockwise, starting
   at one of them (no particular one). For the k-th: faces[k] its index,
   corners[k] v's corner in it (0..2), translations[k] the id h such that
   h(canonical copy) has v at its representative, so the copies tile a
   neighbourhood of hdt_vertex_point(v). A face appears once (the
   triangulation is a simplicial complex); the star of v has its degree's
   number of faces. Capacity in faces. HDT_EINVAL when v is not a live
   vertex. */
HDT_API hdt_status hdt_vertex_star(const hdt_triangulation *t, uint32_t v, uint32_t *faces, uint8_t *corners,
                                   int32_t *translations, size_t capacity, size_t *count) HDT_NOEXCEPT;

/* Edges: E = 3F/2 = 3 (V + 2g - 2) (0 when t is NULL). */
HDT_API size_t hdt_edge_count(const hdt_triangulation *t) HDT_NOEXCEPT;

/* Every edge once, in a fixed order: the edge of face f opposite corner i
   is listed with f when f is the smaller of its two faces, by increasing f
   then i. Edge e runs from the representative of vertices[2e] to h(the
   representative of vertices[2e + 1]), h = translations[e]; it is the edge
   of faces[2e]'s canonical copy mapped by the inverse of vertices[2e]'s
   corner translation there. faces[2e] lies on its left, faces[2e + 1] on
   its right. lengths[e]: its hyperbolic length (curvature -1, in double).
   Capacity in edges (2, 1, 2 and 1 entries). */
HDT_API hdt_status hdt_edges(const hdt_triangulation *t, uint32_t *vertices, int32_t *translations,
                             uint32_t *faces, double *lengths, size_t capacity, size_t *count) HDT_NOEXCEPT;

/* The three corners of each face's canonical copy in the disk, in
   hdt_faces order: xy[6f + 2i], xy[6f + 2i + 1] is corner i of face f (the
   translation of hdt_faces applied to the vertex's point, in double). xy
   must not be NULL when capacity > 0. Capacity in faces. */
HDT_API hdt_status hdt_face_points(const hdt_triangulation *t, double *xy, size_t capacity,
                                   size_t *count) HDT_NOEXCEPT;

/* The Voronoi vertices, one per face (hdt_faces order): xy[2f], xy[2f + 1]
   the hyperbolic circumcentre of face f's canonical copy, radii[f] its
   hyperbolic circumradius (below sys(M_g)/4 by the triangulation's
   guarantee). The disk of that circle holds no vertex copy in its interior.
   Capacity in faces. */
HDT_API hdt_status hdt_voronoi_vertices(const hdt_triangulation *t, double *xy, double *radii, size_t capacity,
                                        size_t *count) HDT_NOEXCEPT;

/* The Voronoi edges, one per Delaunay edge in hdt_edges order: the
   geodesic segment from xy[4e], xy[4e + 1] (the circumcentre of the left
   face faces[2e], as in hdt_voronoi_vertices) to xy[4e + 2], xy[4e + 3]
   (the circumcentre of the right face's copy that shares the edge with the
   left face's canonical copy). It is perpendicular to the Delaunay edge's
   copy there; cocircular faces give a segment of length 0. xy must not be
   NULL when capacity > 0. Capacity in edges (4 entries each). */
HDT_API hdt_status hdt_voronoi_edges(const hdt_triangulation *t, double *xy, size_t capacity,
                                     size_t *count) HDT_NOEXCEPT;

/* The Voronoi cell of vertex v: the circumcentres of the faces of its star
   (hdt_vertex_star, same order), each of the copy around v's
   representative: a polygon, counterclockwise about hdt_vertex_point(v),
   whose geodesic sides are v's Voronoi edges. xy must not be NULL when
   capacity > 0. Capacity in points. HDT_EINVAL when v is not a live vertex.
   The handle keeps the circumcentres it computes for the cells (48 bytes a
   face, until hdt_destroy; a change of the triangulation makes the entries
   of the faces it changed stale, never wrong), so that the cells of every
   vertex compute each circumcentre once; hdt_voronoi_vertices and
   hdt_voronoi_edges then read them too (the same bits). */
HDT_API hdt_status hdt_voronoi_cell(const hdt_triangulation *t, uint32_t v, double *xy, size_t capacity,
                                    size_t *count) HDT_NOEXCEPT;

/* Every live vertex's star in one call (symbol version HDT_0.5), in rows
   by vertex id: the star of vertex v is entries offsets[v] to
   offsets[v + 1] - 1 of faces, corners and translations, exactly what
   hdt_vertex_star(v) gives (same first face, same order, same ids).
   offsets has hdt_vertex_id_bound(t) + 1 entries (offsets[0] = 0, the last
   3F); indexed by id so that v's row needs no search, a removed id having
   an empty row. Every face corner is in its vertex's row once: *count =
   3F entries. Capacity in entries; each output may be NULL. Time linear
   in V, in one pass over the faces in memory order (hdt_vertex_star for
   every vertex walks each star instead, out of order: several times
   slower at large V). The handle keeps the call's scratch (about 92 bytes
   a vertex) until hdt_destroy, and with it the rows: until the next call
   on a non-const handle, a later hdt_vertex_stars or hdt_voronoi_cells
   writes from them, a copy with no pass over the faces. Times:
   docs/benchmarks.md (bench/dual_bench.c). HDT_ENOMEM, nothing written but
   *count, when the scratch cannot be had (and nothing either on
   HDT_EINTERNAL: every star is checked before the writing). */
HDT_API hdt_status hdt_vertex_stars(const hdt_triangulation *t, size_t *offsets, uint32_t *faces, uint8_t *corners,
                                    int32_t *translations, size_t capacity, size_t *count) HDT_NOEXCEPT;

/* Every live vertex's Voronoi cell in one call (symbol version HDT_0.5),
   in the rows of hdt_vertex_stars (offsets the same, hdt_vertex_id_bound(t)
   + 1 entries, may be NULL): xy[2k], xy[2k + 1] for k from offsets[v] to
   offsets[v + 1] - 1 is the cell of v, the same bits as hdt_voronoi_cell(v).
   *count = 3F points; xy must not be NULL when capacity > 0. Capacity in
   points. Keeps the circumcentres on the handle as hdt_voronoi_cell does,
   and reuses the rows as hdt_vertex_stars does; time linear in V (times:
   docs/benchmarks.md). */
HDT_API hdt_status hdt_voronoi_cells(const hdt_triangulation *t, size_t *offsets, double *xy, size_t capacity,
                                     size_t *count) HDT_NOEXCEPT;

/* ---- Refinement, epsilon-nets and quality (symbol version HDT_0.4) ----
   Meshes of controlled size and shape (docs/refinement.md, with the proof
   that the refinement terminates and how many points it can add).
   Sizes are hyperbolic (curvature -1) and computed in double from the
   stored points, like hdt_voronoi_vertices' radii and hdt_edges' lengths. */

/* Delaunay refinement: inserts Steiner points, the circumcentres of the
   faces that break a bound (the largest first, up to a factor sqrt 2), until every face
   has hyperbolic circumradius <= max_radius and radius-edge ratio
   (circumradius / shortest edge) <= max_ratio, or max_points points were
   added in this call. A Steiner point is the circumcentre rounded to
   double, inserted as hdt_insert would (a user vertex, the next id): the
   result is exactly the Delaunay triangulation of its vertices. The bounds
   are decided in double with both tightened by a relative 1e-9, more than
   the computation's error on faces of circumradius above 1e-3, so that
   there they also hold for the exact faces.
   Dummy vertices take part like any vertex and stay (hdt_remove_dummies
   afterwards may break the bounds around the ones it removes); on a new
   triangulation the call meshes M_g uniformly from its dummies alone.
   max_radius: > 0, +INFINITY for no bound on the size (every face's is
   below sys(M_g)/4 anyway); max_ratio: >= 1, +INFINITY for no bound on
   the shape (the proof needs >= 1). *added (may be NULL) receives the
   number of points inserted, *unmet (may be NULL) the number of faces that
   still break a bound, both written on every return with a usable handle
   (nothing is written for t NULL or busy). *unmet is 0 when the
   call completed; > 0 when the cap stopped it, the triangulation then
   valid and Delaunay with the points added so far (HDT_OK: check *unmet),
   or when a bad face is below what a double Steiner point can refine:
   its circumcircle's Euclidean radius in the disk is under 2^-30, or its
   rounded circumcentre is not strictly inside the circle (decided
   exactly). Such faces arise only next to vertices closer than about
   1e-9 (a user's near-duplicates); they are left as they are, with every
   other face refined (HDT_OK). HDT_EINVAL, nothing changed, *added and
   *unmet 0, for t NULL, max_radius NaN or <= 0, max_ratio NaN or < 1.
   HDT_ENOMEM, nothing changed, *added and *unmet 0, before any work when
   the radius bound certainly needs more vertices (disks of radius
   max_radius cover M_g: at least (g - 1) / sinh^2(max_radius / 2), up to
   max_points more than there are) than the memory this process can have
   holds (physical memory, or RLIMIT_AS / RLIMIT_DATA; about 121 bytes a
   vertex at the least); the message gives the count. Later
   HDT_ENOMEM when memory runs out: the *added points inserted so far stay,
   in a valid triangulation, and *unmet counts the faces still breaking a
   bound (an upper bound). Time: each Steiner point goes straight into the
   cavity of the face it refines (no point location), so the cost grows
   with the points added, times the logarithm of the queue's size; a
   packing argument bounds how many are added (docs/refinement.md; times
   in docs/benchmarks.md). */
HDT_API hdt_status hdt_refine(hdt_triangulation *t, double max_radius, double max_ratio, size_t max_points,
                              size_t *added, size_t *unmet) HDT_NOEXCEPT;

/* An epsilon-net of M_g: hdt_refine(t, epsilon, INFINITY, ...), so that
   every point of M_g is within epsilon of a vertex (covering). Each point
   it adds is at distance >= epsilon (within a relative 1e-9) from every
   other vertex, so the vertices are pairwise epsilon apart (packing) when
   those present before were: on a new triangulation, for epsilon up to
   the dummies' spacing (docs/refinement.md). hdt_quality checks both.
   HDT_EINVAL, nothing changed, for epsilon NaN, infinite or <= 0; the
   rest as hdt_refine. */
HDT_API hdt_status hdt_epsilon_net(hdt_triangulation *t, double epsilon, size_t max_points, size_t *added,
                                   size_t *unmet) HDT_NOEXCEPT;

/* Quality statistics over all faces, each output may be NULL:
   *min_angle the smallest hyperbolic angle (radians), *max_ratio the
   largest radius-edge ratio, *max_radius the largest circumradius (the
   covering radius: every point of M_g is within it of a vertex),
   *min_edge the shortest edge (the packing distance: the distance on M_g
   of the two closest vertices). The triangulation is an epsilon-net when
   *max_radius <= epsilon <= *min_edge. HDT_EINVAL for t NULL. Time:
   linear in the faces. */
HDT_API hdt_status hdt_quality(const hdt_triangulation *t, double *min_angle, double *max_ratio,
                               double *max_radius, double *min_edge) HDT_NOEXCEPT;

/* ---- Progress and cancellation (symbol version HDT_0.5) ---- */

/* A caller's progress function: done items of total so far (hdt_insert_many:
   points handled, duplicates included, of n; hdt_refine, hdt_epsilon_net:
   points added, total 0 as the count is not known in advance). done only
   grows; a call that runs to the end reports last with done == total (then
   the return value is ignored). A non-zero return stops the call. It runs
   on the calling thread inside the call, between two points, the
   triangulation valid.

   The handle is busy meanwhile. A call on it from the function (re-entry)
   is refused: HDT_EINVAL, nothing changed, hdt_last_error_message "the
   triangulation is busy in hdt_insert_many" (the running call's name);
   hdt_set_progress included, so the running call keeps the function it
   began with. Allowed, as they have no status to refuse with and read
   only counts: hdt_genus, hdt_vertex_count, hdt_dummy_count,
   hdt_vertex_id_bound, hdt_face_count, hdt_edge_count and
   hdt_vertex_is_dummy. hdt_destroy(t) is deferred: the running call stops
   at that report and frees t as it returns (its outputs are still
   written); use t no more. Other handles are not busy. */
typedef int (*hdt_progress_fn)(void *user, size_t done, size_t total);

/* Has t's next hdt_insert_many, hdt_refine and hdt_epsilon_net calls report
   to fn(user, ...), at most once per interval_seconds (0: as often as it
   looks, which is once per 256 points; +INFINITY: only the final report),
   until replaced; fn NULL turns reports off (the default). The clock is
   read once per 256 points, so a call without fn runs as fast as before.
   A call that fn stops returns HDT_OK with the work done so far, in a
   valid Delaunay triangulation (the same contract as HDT_ENOMEM part way):
   hdt_insert_many's vertices[i] is HDT_NO_VERTEX for each point i not
   inserted; hdt_refine's *unmet > 0 tells that bounds are still broken.
   HDT_EINVAL, nothing changed, for t NULL or interval_seconds NaN or < 0,
   and from a progress function of t's (t is busy: the running call goes on
   with the function it began with). */
HDT_API hdt_status hdt_set_progress(hdt_triangulation *t, hdt_progress_fn fn, void *user,
                                    double interval_seconds) HDT_NOEXCEPT;

/* ---- Surfaces given by a fundamental polygon (symbol version HDT_0.7) ----
   Any closed orientable hyperbolic surface, given as CGAL's
   Triangulation_on_hyperbolic_surface_2 takes it: a convex geodesic polygon
   of the Poincare disk with n vertices v_0 .. v_{n-1} (counterclockwise,
   n even) and a pairing of its sides; side k runs from v_k to v_{k+1}
   (indices mod n), and the pairing of side k is the isometry that sends
   side j = paired(k), taken from v_{j+1} to v_j, onto side k from v_k to
   v_{k+1}. Coordinates are exact: rationals, or elements of one real number
   field (docs/polygons.md). Everything is checked exactly as the surface
   is made (no tolerance): n even and at least 4, the pairing a matching of
   distinct sides, every vertex inside the open unit disk, the polygon
   strictly convex and counterclockwise, paired sides of equal length, and
   around every vertex cycle the pairings compose to the identity with angle
   sum exactly 2 pi; the genus comes from Euler's formula and must be >= 2.
   A polygon that fails is refused with HDT_EINVAL and a
   hdt_last_error_message that names the token, side, vertex or cycle at
   fault. A surface is not changed after it is made (its systole, |N| and
   reduction are computed on first use and kept): one thread at a time uses
   it, and distinct surfaces may be used from different threads at once;
   calls on surfaces with coordinates in a number field (and reading a text
   with a field line) are serialized by one process-wide lock, since the
   number-field library refines a shared embedding; rational surfaces run in
   parallel. These calls read, check,
   describe and draw such surfaces, with their systole, neighbour count
   and representatives; hdt_create_on_surface (HDT_0.8, below) triangulates
   them. */
typedef struct hdt_surface hdt_surface; /* opaque */

/* A surface from the text of its fundamental polygon (length bytes, no NUL
   needed): CGAL's Hyperbolic_fundamental_domain_2 text format (n, the n
   paired sides, then the n vertices as exact rationals "p/q" or decimals
   "0.125"), optionally after a line "field MINPOLY GEN MID+/-RAD" naming a
   real number field whose elements the coordinates may then be
   (polynomials in GEN); docs/polygons.md. *out is NULL on failure:
   HDT_EINVAL for out NULL, text NULL with length > 0, malformed text or a
   polygon that fails a check; HDT_ENOMEM. Limits, refused up front with
   HDT_EINVAL: n <= 2^20, a field of degree <= 256, powers of the generator
   written <= 1024. Time: polynomial in n and in the size of the numbers
   (exact arithmetic). */
HDT_API hdt_status hdt_surface_from_polygon(hdt_surface **out, const char *text, size_t length) HDT_NOEXCEPT;
/* A random genus-2 surface, built as CGAL's
   Hyperbolic_fundamental_domain_factory_2 builds them: a centrally
   symmetric polygon with rational vertices, side k paired with side
   k + sides/2, its last vertex computed exactly so that the angle
   condition holds. sides: 8 (one vertex cycle) or 10 (two cycles of five).
   The same seed gives the same polygon on every platform. *out is NULL on
   failure: HDT_EINVAL for out NULL or another number of sides. */
HDT_API hdt_status hdt_surface_random_symmetric(hdt_surface **out, int sides, uint64_t seed) HDT_NOEXCEPT;
/* Frees the surface; NULL is a no-op. */
HDT_API void hdt_surface_destroy(hdt_surface *s) HDT_NOEXCEPT;
/* The genus, or 0 when s is NULL. */
HDT_API int hdt_surface_genus(const hdt_surface *s) HDT_NOEXCEPT;
/* n, the number of sides (= vertices) of the polygon, or 0 when s is NULL. */
HDT_API int hdt_surface_side_count(const hdt_surface *s) HDT_NOEXCEPT;
/* Vertex v_k (k taken mod n), each coordinate rounded to double.
   HDT_EINVAL for s, x or y NULL. */
HDT_API hdt_status hdt_surface_vertex(const hdt_surface *s, int k, double *x, double *y) HDT_NOEXCEPT;
/* The side paired with side k (k taken mod n) into *paired_side, and the
   pairing isometry of side k as hdt_word_matrix gives an element:
   z -> (a z + b) / (conj(b) z + conj(a)), |a|^2 - |b|^2 = 1, Re a >= 0,
   m = (Re a, Im a, Re b, Im b). a^2 and a b are computed exactly and
   rounded, then a and b taken from them in double: a few units in the
   last place. Either output may be NULL. HDT_EINVAL for s NULL. */
HDT_API hdt_status hdt_surface_pairing(const hdt_surface *s, int k, int *paired_side, double m[4]) HDT_NOEXCEPT;
/* The vertex cycles (the sets of polygon vertices that are one point of
   the surface): *count receives their number; cycle[k] (n entries, for
   k = 0 .. n-1) the index of vertex k's cycle, the cycles numbered in the
   order of their smallest vertex. capacity 0 asks for *count only (cycle
   may then be NULL); HDT_EBUFS, with *count set and nothing else written,
   when 0 < capacity < n. HDT_EINVAL for s or count NULL, cycle NULL with
   capacity > 0. */
HDT_API hdt_status hdt_surface_vertex_cycles(const hdt_surface *s, int *cycle, size_t capacity,
                                             size_t *count) HDT_NOEXCEPT;
/* The polygon as text that hdt_surface_from_polygon reads back as the same
   surface (the same pairing and exactly the same coordinates): CGAL's format
   for a rational polygon, which CGAL's from_stream reads; with the field
   line first otherwise. Two-call pattern as in hdt_svg: *length receives
   the text's length without its NUL; capacity 0 asks for it (text may then
   be NULL); HDT_EBUFS, with *length set and nothing written, when
   0 < capacity < *length + 1; otherwise the text and a NUL are written.
   HDT_EINVAL for s or length NULL, text NULL with capacity > 0. */
HDT_API hdt_status hdt_surface_polygon_text(const hdt_surface *s, char *text, size_t capacity,
                                            size_t *length) HDT_NOEXCEPT;
/* The systole of s, certified: *lo <= sys <= *hi, the two within a few
   units in the last place. It is the least translation length over the
   group, found exactly (docs/polygons.md): a walk over the tiles that may
   come within L of the polygon (L the least length met), tested on
   certified balls, then the shortest candidates compared exactly. The walk
   keeps about the area of the polygon's (L + 0.7)-neighbourhood over the
   polygon's, for round and thin polygons alike; one estimated at more than
   20000 tiles is refused at once with HDT_ENOTSUP naming the estimate.
   Computed on the first call, kept for the next (docs/polygons.md gives the
   measured times). HDT_EINVAL for s, lo or hi NULL. */
HDT_API hdt_status hdt_surface_systole(const hdt_surface *s, double *lo, double *hi) HDT_NOEXCEPT;
/* |N|: the number of group elements h (the identity included) whose copy
   h(P) of the polygon meets it, found around the vertex cycles: 1 + the
   sum over cycles C of |C| (|C| - 1) - n. HDT_EINVAL for s or count NULL. */
HDT_API hdt_status hdt_surface_neighbour_count(const hdt_surface *s, size_t *count) HDT_NOEXCEPT;
/* The representative of the disk point (x, y): the element t, as its word
   in the pairings (letter k is the pairing of side k; t = g_{w_0} g_{w_1}
   ...), with t(x + iy) in the polygon's half-open fundamental set (its
   interior, the interior of the side of smaller index of each pair, the
   smallest vertex of each cycle), and t(x + iy) rounded into *rx, *ry
   (either may be NULL). Exact: the geodesic from a base point to (x, y),
   taken exactly, is walked through the tiling, which ends for every convex
   fundamental polygon, Dirichlet domain or not (docs/polygons.md). Two-call
   pattern for the word as in hdt_point_representative (capacity 0 asks for
   *length; HDT_EBUFS, with *length set and nothing else written).
   HDT_EDOMAIN for a point that is not finite or not inside the open unit
   disk; HDT_EINVAL for s or length NULL, word NULL with capacity > 0. */
HDT_API hdt_status hdt_surface_representative(const hdt_surface *s, double x, double y, double *rx, double *ry,
                                              int32_t *word, size_t capacity, size_t *length) HDT_NOEXCEPT;
/* The polygon drawn in the Poincare disk as an SVG document (UTF-8): its
   sides as geodesic arcs, the two sides of each glued pair in one colour,
   each labelled "k~j" (side k, glued to side j) near its midpoint, and the
   vertices as dots coloured by vertex cycle, under a caption. size: the
   width in pixels, as for hdt_svg. Two-call pattern as in hdt_svg.
   HDT_EINVAL (nothing written) for s or length NULL, a bad size, text NULL
   with capacity > 0; HDT_ENOMEM. */
HDT_API hdt_status hdt_surface_svg(const hdt_surface *s, double size, char *text, size_t capacity,
                                   size_t *length) HDT_NOEXCEPT;

/* ---- Triangulations of surfaces given by a polygon (symbol version HDT_0.8) ----
   A triangulation handle on a surface s from hdt_surface_from_polygon or
   hdt_surface_random_symmetric, made as hdt_create makes one for M_g: the
   paper's Algorithm 1 on s (dummy points in the polygon, each face's
   circumdiameter certified below sys/2), then the same Delaunay insertion
   and removal with exact predicates on s's group. Translation ids are s's
   group elements: 0 is the identity, equal elements have equal ids;
   hdt_translation_word gives an id's word in the pairings (letter k is the
   pairing of side k, as for hdt_surface_representative), and
   hdt_translation_matrix its SU(1,1) form as hdt_surface_pairing does (the
   midpoint of a certified enclosure: a few units in the last place).
   Vertex points are reported as the points inserted (the representative in
   the polygon of each, rounded, for a point given outside it).
   Every call that takes a triangulation works on such a handle as on an
   M_g one, with the same statuses and guarantees; where they differ:
   hdt_save writes format version 2 (the polygon's text stored exactly, the
   translations as words in its pairings; hdt_load reads it back); hdt_svg
   draws the surface in its polygon, cut at its sides (HDT_SVG_NEIGHBOURS:
   the tiles across each side; HDT_SVG_SIDE_LABELS: side k labelled g_k,
   its pairing); the dual's constructions (hdt_face_points, hdt_voronoi_*,
   hdt_edges' lengths, hdt_quality) come from the elements' certified
   matrices, their accuracy measured on M_g only; hdt_translation_homology
   gives classes in a basis of the surface's own H_1 = Z^{2g} (Z^{n/2}, one
   generator per pair of sides, modulo the vertex cycles' relations, in
   Smith normal form): a homomorphism as on M_g, but not M_g's coordinates
   on the Bolza octagon. On a surface over a number field, every call holds
   the process-wide field lock (see above). */

/* A triangulation of s holding only its dummy points. s is only read: the
   triangulation keeps its own copy of the polygon, and s may be destroyed
   at once. *out is NULL on failure: HDT_EINVAL for out or s NULL;
   HDT_ENOTSUP where the systole's computation refuses the polygon (as
   hdt_surface_systole does) or the systole is so small that the dummy set
   could exceed 10^6 points (refused before any is built); HDT_ENOMEM.
   Time: well under a second for octagons and decagons (docs/polygons.md). */
HDT_API hdt_status hdt_create_on_surface(hdt_triangulation **out, const hdt_surface *s) HDT_NOEXCEPT;
/* The word in the pairings (letters as in hdt_surface_representative) of
   the element of N with index id, 0 .. |N| - 1 (hdt_surface_neighbour_count;
   id 0 is the identity, the empty word): the elements h whose copy h(P)
   meets P, in a fixed order. Two-call pattern as in hdt_word_reduce.
   HDT_EINVAL for s or length NULL, word NULL with capacity > 0, id >= |N|. */
HDT_API hdt_status hdt_surface_neighbour_word(const hdt_surface *s, size_t id, int32_t *word, size_t capacity,
                                              size_t *length) HDT_NOEXCEPT;
/* The surface t triangulates: *out receives a new surface (the caller
   destroys it) with the same polygon, exactly, when t was made by
   hdt_create_on_surface, and NULL when t is on a built-in M_g (hdt_create,
   hdt_load). HDT_EINVAL for t or out NULL, or t busy; HDT_ENOMEM. */
HDT_API hdt_status hdt_triangulation_surface(const hdt_triangulation *t, hdt_surface **out) HDT_NOEXCEPT;

#ifdef __cplusplus
}
#endif

#endif /* HDT_H */
