/* Shared helpers of the Check tests of libhdt (public header only). */
#ifndef HDT_TEST_H
#define HDT_TEST_H

#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hdt.h"

/* ck_assert_msg without Check's bookkeeping of passed assertions (a write
   to the parent process for each one), which dominates hot loops. */
#define expect(cond, ...)                   \
  do {                                      \
    if (!(cond)) ck_abort_msg(__VA_ARGS__); \
  } while (0)

/* Longest word the tests hold in a word_t. */
#define TW_MAX 256

typedef struct word_t {
  size_t n;
  int32_t a[TW_MAX];
} word_t;

/* ---- A small deterministic PRNG (xorshift64*) ---- */
static inline uint64_t rng_next(uint64_t *s) {
  *s ^= *s >> 12;
  *s ^= *s << 25;
  *s ^= *s >> 27;
  return *s * UINT64_C(2685821657736338717);
}
/* Uniform in 0..n-1 (n > 0; the bias is irrelevant here). */
static inline int rng_below(uint64_t *s, int n) { return (int)(rng_next(s) % (uint64_t)n); }
/* Uniform in [0, 1), 53 random bits. */
static inline double uniform01(uint64_t *s) { return (double)(rng_next(s) >> 11) * 0x1p-53; }

/* A call that must succeed. */
#define OK(call) expect((call) == HDT_OK, "%s: %s", #call, hdt_last_error_message())

/* A new triangulation of genus g, or the test fails. */
static inline hdt_triangulation *new_triangulation(int g) {
  hdt_triangulation *t = NULL;
  const hdt_status s = hdt_create(&t, g);
  expect(s == HDT_OK && t != NULL, "hdt_create(%d): %s (%s)", g, hdt_status_string(s), hdt_last_error_message());
  expect(hdt_genus(t) == g, "hdt_genus gives %d for a genus-%d handle", hdt_genus(t), g);
  return t;
}

/* The surface of a polygon text, or the test fails. */
static inline hdt_surface *surface_from_text(const char *text) {
  hdt_surface *s = NULL;
  const hdt_status st = hdt_surface_from_polygon(&s, text, strlen(text));
  expect(st == HDT_OK && s, "hdt_surface_from_polygon: %s (%s)", hdt_status_string(st), hdt_last_error_message());
  return s;
}

/* n points uniform in the disk of radius r about 0 (malloc'd, 2n doubles). */
static inline double *uniform_disk_points(size_t n, uint64_t seed, double r) {
  double *xy = (double *)malloc((2 * n + 1) * sizeof *xy);
  ck_assert_ptr_nonnull(xy);
  for (size_t i = 0; i < n;) {
    const double x = 2 * r * uniform01(&seed) - r, y = 2 * r * uniform01(&seed) - r;
    if (x * x + y * y >= r * r) continue;
    xy[2 * i] = x, xy[2 * i + 1] = y;
    ++i;
  }
  return xy;
}

/* n random points (x, y pairs, malloc'ed) of the disk of radius 0.4:
   inside F_g for every genus (the sides' midpoints are at radius > 0.64),
   so no point is on F_g's boundary and each is its own representative
   (hdt_vertex_point gives it back bit for bit). */
static inline double *small_disk_points(size_t n, uint64_t seed) { return uniform_disk_points(n, seed, 0.4); }

/* A triangulation of uniform_disk_points(n, seed, r), dummies removed or kept. */
static inline hdt_triangulation *disk_triangulation(int genus, size_t n, uint64_t seed, double r, int remove_dummies) {
  hdt_triangulation *t = new_triangulation(genus);
  double *xy = uniform_disk_points(n, seed, r);
  expect(hdt_insert_many(t, xy, n, NULL) == HDT_OK, "hdt_insert_many: %s", hdt_last_error_message());
  if (remove_dummies) expect(hdt_remove_dummies(t, NULL) == HDT_OK, "hdt_remove_dummies: %s", hdt_last_error_message());
  free(xy);
  return t;
}
/* Of small_disk_points. */
static inline hdt_triangulation *small_disk_triangulation(int genus, size_t n, uint64_t seed, int remove_dummies) {
  return disk_triangulation(genus, n, seed, 0.4, remove_dummies);
}
/* Of points in the disk of radius 0.95: many outside F_g, so that vertices
   have homes other than the identity. */
static inline hdt_triangulation *wide_disk_triangulation(int genus, size_t n, uint64_t seed, int remove_dummies) {
  return disk_triangulation(genus, n, seed, 0.95, remove_dummies);
}

#if defined(_POSIX_C_SOURCE) && _POSIX_C_SOURCE >= 199309L
#include <time.h>
/* Monotonic seconds, for the timings a test prints (never asserts). */
static inline double seconds(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}
#endif

/* Sign of x^2 + y^2 - 1 computed exactly, for x and y multiples of 2^-60
   below 2 in magnitude (each is then m 2^-60 with |m| < 2^61, and the sum of
   squares fits 128 bits); 2 when that does not apply. */
static inline int exact_norm_vs_one(double x, double y) {
  __extension__ typedef unsigned __int128 u128;
  const double sx = ldexp(fabs(x), 60), sy = ldexp(fabs(y), 60);
  if (!(fabs(x) < 2 && fabs(y) < 2) || sx != floor(sx) || sy != floor(sy)) return 2;
  const u128 mx = (u128)(uint64_t)sx, my = (u128)(uint64_t)sy;
  const u128 sum = mx * mx + my * my, one = (u128)1 << 120;
  return sum < one ? -1 : sum > one;
}

/* ---- Words ---- */
static inline int inv_letter(int g, int k) { return (k + 2 * g) % (4 * g); }

static inline void word_push(word_t *w, int32_t k) {
  expect(w->n < TW_MAX, "test word longer than %d letters", TW_MAX);
  w->a[w->n++] = k;
}

static inline void word_append(word_t *w, const word_t *tail) {
  for (size_t i = 0; i < tail->n; ++i) word_push(w, tail->a[i]);
}

/* A random word of 0..max_len letters. */
static inline word_t random_word(uint64_t *rng, int g, size_t max_len) {
  word_t w = {0};
  const size_t len = (size_t)rng_below(rng, (int)max_len + 1);
  for (size_t i = 0; i < len; ++i) word_push(&w, rng_below(rng, 4 * g));
  return w;
}

/* The relator: letters j (2g+1) mod 4g, j = 0..4g-1. */
static inline word_t relator(int g) {
  word_t r = {0};
  for (int j = 0; j < 4 * g; ++j) word_push(&r, (int32_t)((j * (2 * g + 1)) % (4 * g)));
  return r;
}

static inline word_t word_inverse(int g, const word_t *w) {
  word_t r = {0};
  for (size_t i = w->n; i-- > 0;) word_push(&r, inv_letter(g, w->a[i]));
  return r;
}

/* The cyclic rotation starting at position s. */
static inline word_t word_rotate(const word_t *w, size_t s) {
  word_t r = {0};
  for (size_t i = 0; i < w->n; ++i) word_push(&r, w->a[(s + i) % w->n]);
  return r;
}

static inline int word_eq(const word_t *x, const word_t *y) {
  return x->n == y->n && (x->n == 0 || memcmp(x->a, y->a, x->n * sizeof x->a[0]) == 0);
}

/* Shortlex order: shorter first, then lexicographic by letter value. */
static inline int shortlex_cmp(const word_t *x, const word_t *y) {
  if (x->n != y->n) return x->n < y->n ? -1 : 1;
  for (size_t i = 0; i < x->n; ++i)
    if (x->a[i] != y->a[i]) return x->a[i] < y->a[i] ? -1 : 1;
  return 0;
}

/* "[0 5 2]" into buf, for messages. */
static inline const char *word_str(const word_t *w, char *buf, size_t size) {
  size_t used = 0;
  buf[0] = '\0';
  for (size_t i = 0; i < w->n && used + 16 < size; ++i)
    used += (size_t)snprintf(buf + used, size - used, i ? " %d" : "%d", (int)w->a[i]);
  return buf;
}

/* Canonical word through hdt_word_reduce (asserts success). */
static inline word_t reduce_word(int g, const word_t *w) {
  word_t r = {0};
  size_t len = 0;
  hdt_status s = hdt_word_reduce(g, w->a, w->n, r.a, TW_MAX, &len);
  expect(s == HDT_OK, "hdt_word_reduce(genus %d, %zu letters): %s (%s)", g, w->n, hdt_status_string(s),
         hdt_last_error_message());
  expect(len <= TW_MAX, "canonical word of %zu letters", len);
  r.n = len;
  return r;
}

static inline void word_matrix(int g, const word_t *w, double m[4]) {
  hdt_status s = hdt_word_matrix(g, w->a, w->n, m);
  expect(s == HDT_OK, "hdt_word_matrix(genus %d): %s (%s)", g, hdt_status_string(s), hdt_last_error_message());
}

/* Distance of two SU(1,1) matrices up to sign, relative to the larger entry
   (at least 1). */
static inline double matrix_gap(const double x[4], const double y[4]) {
  double plus = 0, minus = 0, size = 1;
  for (int i = 0; i < 4; ++i) {
    plus = fmax(plus, fabs(x[i] - y[i]));
    minus = fmax(minus, fabs(x[i] + y[i]));
    size = fmax(size, fmax(fabs(x[i]), fabs(y[i])));
  }
  return fmin(plus, minus) / size;
}

/* Translation length 2 arccosh |Re a| of a matrix. */
static inline double translation_length(const double m[4]) { return 2 * acosh(fabs(m[0])); }

/* Image of the disk point (x, y) under the word (asserts success). */
static inline void apply_word(int g, const word_t *w, double x, double y, double *ox, double *oy) {
  hdt_status s = hdt_word_apply(g, w->a, w->n, x, y, ox, oy);
  expect(s == HDT_OK, "hdt_word_apply(genus %d, (%.17g, %.17g)): %s (%s)", g, x, y, hdt_status_string(s),
         hdt_last_error_message());
}

/* UNDER_SANITIZER: 1 in an AddressSanitizer or ThreadSanitizer build, where
   an address-space limit (RLIMIT_AS) means nothing (they reserve address
   space of their own): the tests that limit memory skip themselves. */
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define UNDER_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define UNDER_SANITIZER 1
#endif
#endif
#ifndef UNDER_SANITIZER
#define UNDER_SANITIZER 0
#endif

/* ---- The observable state of a triangulation ---- */

/* hdt_faces whole: n faces, 3 vertex ids and 3 translation ids each
   (malloc'ed; faces_free). */
typedef struct faces_t {
  size_t n;
  uint32_t *v;
  int32_t *tr;
} faces_t;

static inline faces_t read_faces(const hdt_triangulation *t) {
  faces_t f = {0, NULL, NULL};
  expect(hdt_faces(t, NULL, NULL, 0, &f.n) == HDT_OK, "hdt_faces: %s", hdt_last_error_message());
  f.v = malloc(3 * f.n * sizeof *f.v + 1);
  f.tr = malloc(3 * f.n * sizeof *f.tr + 1);
  ck_assert(f.v && f.tr);
  size_t got = 0;
  const hdt_status s = hdt_faces(t, f.v, f.tr, f.n, &got);
  expect(s == HDT_OK && got == f.n, "hdt_faces: %s, %zu of %zu (%s)", hdt_status_string(s), got, f.n,
         hdt_last_error_message());
  return f;
}

static inline void faces_free(faces_t *f) {
  free(f->v);
  free(f->tr);
}

/* Everything hdt_faces and hdt_vertices say (ids, translations, points,
   dummy flags) as one byte string of *size bytes (malloc'ed): equal strings
   mean equal triangulations, down to the ids. */
static inline unsigned char *observable_bytes(const hdt_triangulation *t, size_t *size) {
  faces_t f = read_faces(t);
  size_t V = 0;
  expect(hdt_vertices(t, NULL, NULL, NULL, 0, &V) == HDT_OK, "hdt_vertices: %s", hdt_last_error_message());
  const size_t face_bytes = 3 * f.n * (sizeof *f.v + sizeof *f.tr);
  *size = face_bytes + V * (sizeof(uint32_t) + 2 * sizeof(double) + 1);
  unsigned char *out = malloc(*size + 1);
  uint32_t *ids = malloc(V * sizeof *ids + 1);
  double *xy = malloc(2 * V * sizeof *xy + 1);
  uint8_t *dummy = malloc(V + 1);
  ck_assert(out && ids && xy && dummy);
  expect(hdt_vertices(t, ids, xy, dummy, V, &V) == HDT_OK, "hdt_vertices: %s", hdt_last_error_message());
  unsigned char *at = out;
  memcpy(at, f.v, 3 * f.n * sizeof *f.v), at += 3 * f.n * sizeof *f.v;
  memcpy(at, f.tr, 3 * f.n * sizeof *f.tr), at += 3 * f.n * sizeof *f.tr;
  memcpy(at, ids, V * sizeof *ids), at += V * sizeof *ids;
  memcpy(at, xy, 2 * V * sizeof *xy), at += 2 * V * sizeof *xy;
  memcpy(at, dummy, V);
  faces_free(&f);
  free(ids), free(xy), free(dummy);
  return out;
}

/* Asserts that a call failed with `expected` and that the thread's error
   message names `function`. */
static inline void expect_failure(hdt_status got, hdt_status expected, const char *function) {
  const char *msg = hdt_last_error_message();
  expect(got == expected, "%s returned %d (%s), expected %d (%s)", function, (int)got, hdt_status_string(got),
         (int)expected, hdt_status_string(expected));
  expect(msg != NULL && strstr(msg, function) != NULL, "error message \"%s\" does not name %s", msg, function);
}

/* Runs the tests as one suite, each in its own case with a generous timeout
   (the heavier tests need more than Check's default of 4 s on a slow
   machine); prints Check's summary line and gives the exit status. */
/* Whether the environment variable HDT_SKIP_CASES (names separated by
   spaces) lists this test case: the slow builds (sanitizers, valgrind) leave
   out the cases that take minutes natively. */
static inline int case_skipped(const char *name) {
  const char *list = getenv("HDT_SKIP_CASES");
  const size_t n = strlen(name);
  for (const char *p = list; p && (p = strstr(p, name)) != NULL; p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == '\0' || p[n] == ' ')) return 1;
  return 0;
}

static inline int run_tests(const char *suite_name, const TTest *const *tests, size_t count) {
  Suite *suite = suite_create(suite_name);
  for (size_t i = 0; i < count; ++i) {
    if (case_skipped(tests[i]->name)) {
      printf("%s: case %s skipped (HDT_SKIP_CASES)\n", suite_name, tests[i]->name);
      continue;
    }
    TCase *tc = tcase_create(tests[i]->name);
    tcase_set_timeout(tc, 900);
    tcase_add_test(tc, tests[i]);
    suite_add_tcase(suite, tc);
  }
  SRunner *runner = srunner_create(suite);
  srunner_run_all(runner, CK_NORMAL);
  const int failed = srunner_ntests_failed(runner);
  srunner_free(runner);
  return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

#endif /* HDT_TEST_H */
