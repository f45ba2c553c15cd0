/* Threads: several threads, each with its own triangulations, run at the
 * same time and get exactly the results of the same work done on one
 * thread; errors are thread-local; the handle-free functions (surface
 * facts, words) give the same answers from all threads at once.
 *
 * The library promises (include/hdt.h): one handle is used by one thread at
 * a time, distinct handles are independent, hdt_last_error_message() is
 * per thread. The shared state behind that promise is the per-genus data
 * built lazily on first use (the dummy template of hdt_create, the group's
 * tables, the exact field, the representative's kernels): each test makes
 * the threads race on the first use of genera not used before in the
 * process, starting them together at a barrier. The single-threaded
 * reference therefore runs after the threads (before, it would warm every
 * cache and leave nothing to race on); the order does not matter for the
 * comparison. With CK_FORK=no (as under ThreadSanitizer, .ci/tsan) all tests
 * share one process, so each test uses genera no earlier test has touched.
 *
 * Check's assertions must run on the test's own thread (a failure longjmps
 * or exits from there), so worker threads record their first failure as
 * text and the main thread asserts on it after pthread_join. */
#define _POSIX_C_SOURCE 200809L /* pthread_barrier_t, clock_gettime */
#include <pthread.h>
#include <stdarg.h>
#include <time.h>

#include "hdt_test.h"

enum { THREADS = 4 };

/* Uniform (by Euclidean area) in the disk of radius 0.9 about 0; the library
   maps each point to its representative in F_g. */
static void disk_points(uint64_t seed, size_t n, double *xy) {
  uint64_t rng = seed;
  for (size_t i = 0; i < n; ++i) {
    const double r = 0.9 * sqrt(uniform01(&rng)), a = 6.283185307179586 * uniform01(&rng);
    xy[2 * i] = r * cos(a), xy[2 * i + 1] = r * sin(a);
  }
}

/* ---- Failures recorded on a worker thread ---- */

typedef struct failure_t {
  char text[768];
} failure_t;

/* Records the first failure; returns -1 so callers can `return FAIL(...)`. */
static int record_failure(failure_t *f, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static int record_failure(failure_t *f, const char *fmt, ...) {
  if (f->text[0] == '\0') {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(f->text, sizeof f->text, fmt, ap);
    va_end(ap);
  }
  return -1;
}

#define TCHECK(f, cond, ...)                                 \
  do {                                                       \
    if (!(cond)) return record_failure((f), __VA_ARGS__);    \
  } while (0)

/* ---- The work on one triangulation, and its result ---- */

/* Everything compared between runs: per vertex id, liveness, dummy flag and
   the bits of hdt_vertex_point (so the assumption that ids are assigned
   deterministically is checked, not presumed); the statuses of the
   removals; the faces, each as text "v0 v1 v2 [word] [word] [word]" rotated
   to start at its smallest vertex id (orientation kept), with translation
   ids replaced by their canonical words (ids past the neighbour set are
   interned per handle; words mean the same in every handle), sorted. */
typedef struct result_t {
  size_t bound, vertices, dummies_left, faces;
  int *is_dummy;     /* bound entries: -1 removed, 0 user, 1 dummy */
  uint64_t *bits;    /* 2 * bound: the bits of x and y of live vertices */
  char *removals;    /* one letter per removal attempt: 'r' removed, 'n' refused */
  char **face_text;  /* faces entries, sorted */
} result_t;

static void result_free(result_t *r) {
  free(r->is_dummy);
  free(r->bits);
  free(r->removals);
  if (r->face_text)
    for (size_t i = 0; i < r->faces; ++i) free(r->face_text[i]);
  free(r->face_text);
  memset(r, 0, sizeof *r);
}

static int cmp_text(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

/* "[0 5 2]" of translation id `id`, cached in words[id]. */
static int translation_text(const hdt_triangulation *t, int32_t id, char ***words, size_t *nwords, failure_t *f,
                            const char **out) {
  TCHECK(f, id >= 0, "negative translation id %d", id);
  if ((size_t)id >= *nwords) {
    size_t n = *nwords ? *nwords : 64;
    while (n <= (size_t)id) n *= 2;
    char **grown = realloc(*words, n * sizeof *grown);
    TCHECK(f, grown != NULL, "out of memory");
    for (size_t i = *nwords; i < n; ++i) grown[i] = NULL;
    *words = grown, *nwords = n;
  }
  if (!(*words)[id]) {
    word_t w = {0};
    const hdt_status s = hdt_translation_word(t, id, w.a, TW_MAX, &w.n);
    TCHECK(f, s == HDT_OK, "hdt_translation_word(%d): %s (%s)", id, hdt_status_string(s), hdt_last_error_message());
    char buf[4 * TW_MAX + 4];
    buf[0] = '[';
    word_str(&w, buf + 1, sizeof buf - 2);
    strcat(buf, "]");
    (*words)[id] = strdup(buf);
    TCHECK(f, (*words)[id] != NULL, "out of memory");
  }
  *out = (*words)[id];
  return 0;
}

static int read_result(const hdt_triangulation *t, result_t *r, failure_t *f) {
  r->bound = hdt_vertex_id_bound(t);
  r->vertices = hdt_vertex_count(t);
  r->is_dummy = malloc(r->bound * sizeof *r->is_dummy + 1);
  r->bits = calloc(2 * r->bound + 1, sizeof *r->bits);
  TCHECK(f, r->is_dummy && r->bits, "out of memory");
  for (uint32_t v = 0; v < r->bound; ++v) {
    r->is_dummy[v] = hdt_vertex_is_dummy(t, v);
    if (r->is_dummy[v] < 0) continue;
    double x, y;
    const hdt_status s = hdt_vertex_point(t, v, &x, &y);
    TCHECK(f, s == HDT_OK, "hdt_vertex_point(%u): %s (%s)", v, hdt_status_string(s), hdt_last_error_message());
    memcpy(&r->bits[2 * v], &x, sizeof x);
    memcpy(&r->bits[2 * v + 1], &y, sizeof y);
  }
  size_t count = 0;
  hdt_status s = hdt_faces(t, NULL, NULL, 0, &count);
  TCHECK(f, s == HDT_OK, "hdt_faces(count): %s (%s)", hdt_status_string(s), hdt_last_error_message());
  uint32_t *fv = malloc(3 * count * sizeof *fv + 1);
  int32_t *ft = malloc(3 * count * sizeof *ft + 1);
  r->face_text = calloc(count + 1, sizeof *r->face_text);
  TCHECK(f, fv && ft && r->face_text, "out of memory");
  r->faces = count;
  size_t got = 0;
  s = hdt_faces(t, fv, ft, count, &got);
  int status = 0;
  char **words = NULL;
  size_t nwords = 0;
  if (s != HDT_OK || got != count) {
    status = record_failure(f, "hdt_faces: %s, %zu of %zu faces (%s)", hdt_status_string(s), got, count,
                            hdt_last_error_message());
  }
  for (size_t i = 0; status == 0 && i < count; ++i) {
    const uint32_t *v = &fv[3 * i];
    const int32_t *tr = &ft[3 * i];
    const int k = v[0] < v[1] ? (v[0] < v[2] ? 0 : 2) : (v[1] < v[2] ? 1 : 2);
    const char *w[3];
    for (int c = 0; c < 3 && status == 0; ++c) status = translation_text(t, tr[(k + c) % 3], &words, &nwords, f, &w[c]);
    if (status) break;
    char buf[64 + 3 * (4 * TW_MAX + 4)];
    snprintf(buf, sizeof buf, "%u %u %u %s %s %s", v[k], v[(k + 1) % 3], v[(k + 2) % 3], w[0], w[1], w[2]);
    r->face_text[i] = strdup(buf);
    if (!r->face_text[i]) status = record_failure(f, "out of memory");
  }
  for (size_t i = 0; i < nwords; ++i) free(words[i]);
  free(words);
  free(fv);
  free(ft);
  if (status == 0) qsort(r->face_text, count, sizeof *r->face_text, cmp_text);
  return status;
}

/* Points per run: the threaded test stays well under 30 s in the normal
   build on two cores. */
static size_t points_for(int g) { return g == 2 ? 6000 : g == 3 ? 5000 : 4000; }

/* One run: create (the caller may have waited at a barrier just before),
   insert n seeded points (the first 60% by hdt_insert_many, the rest one by
   one), remove the dummies, try to remove every 4th user vertex (refusal
   allowed), validate, read the result. */
static int run_work(int g, uint64_t seed, pthread_barrier_t *before_create, result_t *r, failure_t *f) {
  if (before_create) pthread_barrier_wait(before_create); /* first, so no failure skips it */
  const size_t n = points_for(g);
  double *xy = malloc(2 * n * sizeof *xy);
  uint32_t *ids = malloc(n * sizeof *ids);
  TCHECK(f, xy && ids, "out of memory");
  disk_points(seed, n, xy);
  hdt_triangulation *t = NULL;
  hdt_status s = hdt_create(&t, g);
  int status = 0;
  if (s != HDT_OK)
    status = record_failure(f, "hdt_create(%d): %s (%s)", g, hdt_status_string(s), hdt_last_error_message());
  const size_t bulk = n * 3 / 5;
  if (!status && (s = hdt_insert_many(t, xy, bulk, ids)) != HDT_OK)
    status = record_failure(f, "g=%d: hdt_insert_many(%zu): %s (%s)", g, bulk, hdt_status_string(s),
                            hdt_last_error_message());
  for (size_t i = bulk; !status && i < n; ++i)
    if ((s = hdt_insert(t, xy[2 * i], xy[2 * i + 1], &ids[i])) != HDT_OK)
      status = record_failure(f, "g=%d: hdt_insert(%.17g, %.17g): %s (%s)", g, xy[2 * i], xy[2 * i + 1],
                              hdt_status_string(s), hdt_last_error_message());
  size_t remaining = 0;
  if (!status && (s = hdt_remove_dummies(t, &remaining)) != HDT_OK)
    status = record_failure(f, "g=%d: hdt_remove_dummies: %s (%s)", g, hdt_status_string(s), hdt_last_error_message());
  if (!status) {
    r->dummies_left = remaining;
    const size_t bound = hdt_vertex_id_bound(t);
    r->removals = calloc(bound + 1, 1);
    if (!r->removals) status = record_failure(f, "out of memory");
    size_t attempts = 0, users = 0;
    for (uint32_t v = 0; !status && v < bound; ++v) {
      if (hdt_vertex_is_dummy(t, v) != 0 || users++ % 4 != 0) continue;
      s = hdt_remove_vertex(t, v);
      if (s == HDT_OK) r->removals[attempts++] = 'r';
      else if (s == HDT_ENOTSUP) r->removals[attempts++] = 'n';
      else status = record_failure(f, "g=%d: hdt_remove_vertex(%u): %s (%s)", g, v, hdt_status_string(s),
                                   hdt_last_error_message());
    }
  }
  if (!status && (s = hdt_validate(t)) != HDT_OK)
    status = record_failure(f, "g=%d: hdt_validate: %s (%s)", g, hdt_status_string(s), hdt_last_error_message());
  if (!status) status = read_result(t, r, f);
  hdt_destroy(t);
  free(xy);
  free(ids);
  return status;
}

/* "" when equal, else the first difference into `diff`. */
static const char *compare_results(const result_t *a, const result_t *b, char *diff, size_t size) {
  diff[0] = '\0';
  if (a->bound != b->bound || a->vertices != b->vertices || a->dummies_left != b->dummies_left ||
      a->faces != b->faces) {
    snprintf(diff, size, "id bound %zu vs %zu, vertices %zu vs %zu, dummies left %zu vs %zu, faces %zu vs %zu",
             a->bound, b->bound, a->vertices, b->vertices, a->dummies_left, b->dummies_left, a->faces, b->faces);
    return diff;
  }
  for (size_t v = 0; v < a->bound; ++v)
    if (a->is_dummy[v] != b->is_dummy[v] || a->bits[2 * v] != b->bits[2 * v] ||
        a->bits[2 * v + 1] != b->bits[2 * v + 1]) {
      snprintf(diff, size, "vertex %zu differs (state %d vs %d, point bits %016llx %016llx vs %016llx %016llx)", v,
               a->is_dummy[v], b->is_dummy[v], (unsigned long long)a->bits[2 * v],
               (unsigned long long)a->bits[2 * v + 1], (unsigned long long)b->bits[2 * v],
               (unsigned long long)b->bits[2 * v + 1]);
      return diff;
    }
  if (strcmp(a->removals ? a->removals : "", b->removals ? b->removals : "") != 0) {
    snprintf(diff, size, "removal outcomes differ: %.80s vs %.80s", a->removals, b->removals);
    return diff;
  }
  for (size_t i = 0; i < a->faces; ++i)
    if (strcmp(a->face_text[i], b->face_text[i]) != 0) {
      snprintf(diff, size, "sorted face %zu: \"%.200s\" vs \"%.200s\"", i, a->face_text[i], b->face_text[i]);
      return diff;
    }
  return diff;
}

/* ---- Test 1: concurrent triangulations equal the single-threaded ones ---- */

static const int work_genera[] = {2, 3, 5};
enum { NGENERA = sizeof work_genera / sizeof work_genera[0], SEEDS = 2 };

static uint64_t work_seed(int thread) { return UINT64_C(0x5EED0000) + (uint64_t)(thread % SEEDS) * 7919; }

typedef struct work_ctx {
  int thread;
  pthread_barrier_t *barrier;
  result_t results[NGENERA];
  failure_t failure;
  int failed_genus;
} work_ctx;

static void *work_thread(void *arg) {
  work_ctx *c = arg;
  for (int k = 0; k < NGENERA; ++k) {
    /* Every thread calls the barrier once per genus even after a failure, so
       the others are not left waiting. */
    result_t *r = &c->results[k];
    if (c->failure.text[0]) {
      pthread_barrier_wait(c->barrier);
      continue;
    }
    if (run_work(work_genera[k], work_seed(c->thread), c->barrier, r, &c->failure) != 0)
      c->failed_genus = work_genera[k];
  }
  return NULL;
}

START_TEST(concurrent_triangulations_match_sequential) {
  const double t0 = seconds();
  pthread_barrier_t barrier;
  ck_assert_int_eq(pthread_barrier_init(&barrier, NULL, THREADS), 0);
  static work_ctx ctx[THREADS];
  memset(ctx, 0, sizeof ctx);
  pthread_t th[THREADS];
  for (int i = 0; i < THREADS; ++i) {
    ctx[i].thread = i, ctx[i].barrier = &barrier;
    ck_assert_int_eq(pthread_create(&th[i], NULL, work_thread, &ctx[i]), 0);
  }
  for (int i = 0; i < THREADS; ++i) ck_assert_int_eq(pthread_join(th[i], NULL), 0);
  pthread_barrier_destroy(&barrier);
  const double t1 = seconds();
  for (int i = 0; i < THREADS; ++i)
    expect(ctx[i].failure.text[0] == '\0', "thread %d, genus %d: %s", i, ctx[i].failed_genus, ctx[i].failure.text);

  /* The same work on this thread, once per (genus, seed); then twice the
     same sequential run must agree with itself too (through the threads
     sharing a seed). */
  for (int k = 0; k < NGENERA; ++k)
    for (int s = 0; s < SEEDS; ++s) {
      result_t ref = {0};
      failure_t f = {{0}};
      const int st = run_work(work_genera[k], work_seed(s), NULL, &ref, &f);
      expect(st == 0, "single-threaded, genus %d: %s", work_genera[k], f.text);
      for (int i = 0; i < THREADS; ++i) {
        if (i % SEEDS != s) continue;
        char diff[640];
        compare_results(&ctx[i].results[k], &ref, diff, sizeof diff);
        expect(diff[0] == '\0', "genus %d, thread %d vs single-threaded: %s", work_genera[k], i, diff);
      }
      printf("threads: genus %d seed %d: %zu vertices (%zu dummies left), %zu faces, %zu removal attempts, equal\n",
             work_genera[k], s, ref.vertices, ref.dummies_left, ref.faces, strlen(ref.removals));
      result_free(&ref);
    }
  for (int i = 0; i < THREADS; ++i)
    for (int k = 0; k < NGENERA; ++k) result_free(&ctx[i].results[k]);
  printf("threads: %d threads x %d genera in %.2f s, single-threaded reference in %.2f s\n", THREADS, NGENERA,
         t1 - t0, seconds() - t1);
  fflush(stdout);
}
END_TEST

/* ---- Test 2: errors are thread-local ---- */

/* Each thread provokes its own error at the same moment (behind a barrier),
   waits until all have, then reads its message: it must name its own
   function and problem and none of the others'. Repeated so the calls
   overlap in many interleavings. */
enum { ERROR_ROUNDS = 300 };

static const char *const error_function[THREADS] = {"hdt_insert", "hdt_remove_vertex", "hdt_word_reduce",
                                                    "hdt_faces"};

typedef struct error_ctx {
  int thread;
  pthread_barrier_t *barrier;
  hdt_triangulation *t;
  failure_t failure;
} error_ctx;

/* Provokes thread c->thread's error of round `round`; *detail receives a text
   the message must contain, specific to the thread and the round. */
static int provoke(error_ctx *c, int round, char *detail, size_t size) {
  failure_t *f = &c->failure;
  hdt_status s, want;
  switch (c->thread) {
    case 0: { /* HDT_EDOMAIN: NaN */
      uint32_t v = 4242;
      const double y = 0.25 + round / 1024.0;
      s = hdt_insert(c->t, nan(""), y, &v), want = HDT_EDOMAIN;
      snprintf(detail, size, "%.17g) is not finite", y);
      TCHECK(f, v == 4242, "hdt_insert wrote the vertex on failure");
      break;
    }
    case 1: { /* HDT_EINVAL: no such vertex */
      const uint32_t v = 1000000u + (uint32_t)round;
      s = hdt_remove_vertex(c->t, v), want = HDT_EINVAL;
      snprintf(detail, size, "vertex %u", v);
      break;
    }
    case 2: { /* HDT_EINVAL: a bad letter */
      const int32_t w[3] = {0, 99 + round, 1};
      int32_t out[3];
      size_t len = 0;
      s = hdt_word_reduce(2, w, 3, out, 3, &len), want = HDT_EINVAL;
      snprintf(detail, size, "letter %d", 99 + round);
      break;
    }
    default: { /* HDT_EBUFS: capacity too small */
      uint32_t fv[3 * 8];
      size_t count = 0;
      const size_t capacity = 1 + (size_t)round % 8;
      s = hdt_faces(c->t, fv, NULL, capacity, &count), want = HDT_EBUFS;
      snprintf(detail, size, "capacity %zu ", capacity);
      TCHECK(f, count == hdt_face_count(c->t), "hdt_faces reported %zu faces with HDT_EBUFS, not %zu", count,
             hdt_face_count(c->t));
      break;
    }
  }
  TCHECK(f, s == want, "round %d: %s returned %s, expected %s (%s)", round, error_function[c->thread],
         hdt_status_string(s), hdt_status_string(want), hdt_last_error_message());
  return 0;
}

/* The message names the thread's own function and detail, and no other
   thread's function. */
static int check_own_message(error_ctx *c, int round, const char *detail) {
  const char *msg = hdt_last_error_message();
  TCHECK(&c->failure, msg != NULL, "round %d: hdt_last_error_message() is NULL", round);
  const char *own = error_function[c->thread];
  char head[64];
  snprintf(head, sizeof head, "%s:", own); /* "function: detail" */
  TCHECK(&c->failure, strncmp(msg, head, strlen(head)) == 0 && strstr(msg, detail) != NULL,
         "round %d, thread %d: message \"%s\" is not %s's error \"%s\"", round, c->thread, msg, own, detail);
  for (int o = 0; o < THREADS; ++o) {
    if (o == c->thread) continue;
    char other[64];
    snprintf(other, sizeof other, "%s:", error_function[o]);
    TCHECK(&c->failure, strstr(msg, other) == NULL, "round %d, thread %d: message \"%s\" names %s", round, c->thread,
           msg, error_function[o]);
  }
  return 0;
}

static void *error_thread(void *arg) {
  error_ctx *c = arg;
  /* A new thread has no failure yet, whatever the main thread's is. */
  const char *first = hdt_last_error_message();
  if (!first || first[0] != '\0')
    record_failure(&c->failure, "a new thread's hdt_last_error_message() is \"%s\", not \"\"",
                   first ? first : "(NULL)");
  /* Each thread its own handle; genus 4, which the earlier test does not
     use: the threads race on its dummy template too. */
  pthread_barrier_wait(c->barrier);
  const hdt_status s = hdt_create(&c->t, 4);
  if (s != HDT_OK)
    record_failure(&c->failure, "hdt_create(4): %s (%s)", hdt_status_string(s), hdt_last_error_message());
  for (int round = 0; round < ERROR_ROUNDS; ++round) {
    char detail[128] = "";
    pthread_barrier_wait(c->barrier);
    if (!c->failure.text[0]) provoke(c, round, detail, sizeof detail); /* c->t is NULL after a failure */
    pthread_barrier_wait(c->barrier); /* every thread's error is set */
    if (!c->failure.text[0]) check_own_message(c, round, detail);
    /* A successful call between rounds: the next failure must replace the
       message, whatever a success does to it. */
    if (!c->failure.text[0] && hdt_face_count(c->t) == 0)
      record_failure(&c->failure, "round %d: no faces", round);
  }
  return NULL;
}

START_TEST(errors_are_thread_local) {
  pthread_barrier_t barrier;
  ck_assert_int_eq(pthread_barrier_init(&barrier, NULL, THREADS), 0);
  static error_ctx ctx[THREADS];
  memset(ctx, 0, sizeof ctx);
  pthread_t th[THREADS];
  for (int i = 0; i < THREADS; ++i) ctx[i].thread = i, ctx[i].barrier = &barrier;
  /* The main thread's own message is untouched by the workers. */
  hdt_triangulation *none = NULL;
  expect_failure(hdt_create(&none, 1), HDT_EINVAL, "hdt_create");
  char mine[512];
  snprintf(mine, sizeof mine, "%s", hdt_last_error_message());
  for (int i = 0; i < THREADS; ++i) ck_assert_int_eq(pthread_create(&th[i], NULL, error_thread, &ctx[i]), 0);
  for (int i = 0; i < THREADS; ++i) ck_assert_int_eq(pthread_join(th[i], NULL), 0);
  pthread_barrier_destroy(&barrier);
  expect(strcmp(hdt_last_error_message(), mine) == 0, "the main thread's message changed to \"%s\" (was \"%s\")",
         hdt_last_error_message(), mine);
  for (int i = 0; i < THREADS; ++i) {
    expect(ctx[i].failure.text[0] == '\0', "thread %d: %s", i, ctx[i].failure.text);
    hdt_destroy(ctx[i].t);
  }
}
END_TEST

/* ---- Test 3: the handle-free functions from all threads at once ---- */

/* Genera 6 and 7, first used here: the threads race on building their
   group tables, exact fields and representative kernels; threads 0 and 1
   also create genus-6 triangulations (the dummy template) while 2 and 3
   compute representatives of genus 6. Every answer is reduced to bits and
   folded into a checksum per (genus, thread kind); the main thread then
   recomputes each on its own. */
enum { SURFACE_POINTS = 150, SURFACE_WORDS = 60 };
static const int surface_genera[] = {6, 7};

static uint64_t fold(uint64_t h, uint64_t x) {
  h ^= x + UINT64_C(0x9E3779B97F4A7C15) + (h << 6) + (h >> 2);
  return h;
}
static uint64_t fold_double(uint64_t h, double x) {
  uint64_t b;
  memcpy(&b, &x, sizeof b);
  return fold(h, b);
}

/* The checksum of one genus's surface and word answers for one seed. */
static int surface_work(int g, uint64_t seed, uint64_t *sum, failure_t *f) {
  uint64_t rng = seed, h = 0;
  hdt_status s;
  h = fold_double(h, hdt_systole(g));
  for (int k = 0; k < 4 * g; ++k) {
    double x, y;
    s = hdt_polygon_vertex(g, k, &x, &y);
    TCHECK(f, s == HDT_OK, "hdt_polygon_vertex: %s", hdt_status_string(s));
    h = fold_double(fold_double(h, x), y);
    s = hdt_polygon_side_midpoint(g, k, &x, &y);
    TCHECK(f, s == HDT_OK, "hdt_polygon_side_midpoint: %s", hdt_status_string(s));
    h = fold_double(fold_double(h, x), y);
  }
  size_t nn = 0;
  s = hdt_neighbour_count(g, &nn);
  TCHECK(f, s == HDT_OK, "hdt_neighbour_count: %s", hdt_status_string(s));
  h = fold(h, nn);
  for (size_t id = 0; id < nn; id += 7) {
    word_t w = {0};
    s = hdt_neighbour_word(g, id, w.a, TW_MAX, &w.n);
    TCHECK(f, s == HDT_OK, "hdt_neighbour_word(%zu): %s (%s)", id, hdt_status_string(s), hdt_last_error_message());
    for (size_t i = 0; i < w.n; ++i) h = fold(h, (uint64_t)w.a[i]);
  }
  for (int i = 0; i < SURFACE_POINTS; ++i) {
    const double r = 0.995 * sqrt(uniform01(&rng)), a = 6.283185307179586 * uniform01(&rng);
    const double x = r * cos(a), y = r * sin(a);
    double rx, ry;
    word_t w = {0};
    s = hdt_point_representative(g, x, y, &rx, &ry, w.a, TW_MAX, &w.n);
    TCHECK(f, s == HDT_OK, "hdt_point_representative(%d, %.17g, %.17g): %s (%s)", g, x, y, hdt_status_string(s),
           hdt_last_error_message());
    h = fold_double(fold_double(h, rx), ry);
    for (size_t k = 0; k < w.n; ++k) h = fold(h, (uint64_t)w.a[k]);
    /* The word maps the point to its representative. */
    double ox, oy;
    s = hdt_word_apply(g, w.a, w.n, x, y, &ox, &oy);
    TCHECK(f, s == HDT_OK, "hdt_word_apply: %s (%s)", hdt_status_string(s), hdt_last_error_message());
    TCHECK(f, hypot(ox - rx, oy - ry) < 1e-12,
           "genus %d: (%.17g, %.17g) has the representative (%.17g, %.17g), but its word maps it to (%.17g, %.17g)", g,
           x, y, rx, ry, ox, oy);
    h = fold_double(fold_double(h, ox), oy);
  }
  for (int i = 0; i < SURFACE_WORDS; ++i) {
    const word_t w = random_word(&rng, g, 40);
    word_t out = {0};
    s = hdt_word_reduce(g, w.a, w.n, out.a, TW_MAX, &out.n);
    TCHECK(f, s == HDT_OK, "hdt_word_reduce: %s (%s)", hdt_status_string(s), hdt_last_error_message());
    for (size_t k = 0; k < out.n; ++k) h = fold(h, (uint64_t)out.a[k]);
    double m[4], l[9];
    s = hdt_word_matrix(g, w.a, w.n, m);
    TCHECK(f, s == HDT_OK, "hdt_word_matrix: %s", hdt_status_string(s));
    s = hdt_word_lorentz(g, out.a, out.n, l);
    TCHECK(f, s == HDT_OK, "hdt_word_lorentz: %s", hdt_status_string(s));
    for (int k = 0; k < 4; ++k) h = fold_double(h, m[k]);
    for (int k = 0; k < 9; ++k) h = fold_double(h, l[k]);
  }
  *sum = h;
  return 0;
}

typedef struct surface_ctx {
  int thread;
  pthread_barrier_t *barrier;
  uint64_t sums[2];
  size_t faces; /* of the genus-6 triangulation made by threads 0 and 1 */
  failure_t failure;
  int failed_genus;
} surface_ctx;

static void *surface_thread(void *arg) {
  surface_ctx *c = arg;
  for (int k = 0; k < 2; ++k) {
    const int g = surface_genera[k];
    pthread_barrier_wait(c->barrier);
    if (c->failure.text[0]) continue;
    if (g == 6 && c->thread < 2) {
      hdt_triangulation *t = NULL;
      const hdt_status s = hdt_create(&t, g);
      if (s != HDT_OK) {
        record_failure(&c->failure, "hdt_create(%d): %s (%s)", g, hdt_status_string(s), hdt_last_error_message());
        continue;
      }
      c->faces = hdt_face_count(t);
      hdt_destroy(t);
    }
    if (surface_work(g, UINT64_C(0xABC) + (uint64_t)(c->thread % 2), &c->sums[k], &c->failure) != 0)
      c->failed_genus = g;
  }
  return NULL;
}

START_TEST(surface_functions_concurrently) {
  pthread_barrier_t barrier;
  ck_assert_int_eq(pthread_barrier_init(&barrier, NULL, THREADS), 0);
  static surface_ctx ctx[THREADS];
  memset(ctx, 0, sizeof ctx);
  pthread_t th[THREADS];
  for (int i = 0; i < THREADS; ++i) {
    ctx[i].thread = i, ctx[i].barrier = &barrier;
    ck_assert_int_eq(pthread_create(&th[i], NULL, surface_thread, &ctx[i]), 0);
  }
  for (int i = 0; i < THREADS; ++i) ck_assert_int_eq(pthread_join(th[i], NULL), 0);
  pthread_barrier_destroy(&barrier);
  for (int i = 0; i < THREADS; ++i)
    expect(ctx[i].failure.text[0] == '\0', "thread %d, genus %d: %s", i, ctx[i].failed_genus, ctx[i].failure.text);
  for (int k = 0; k < 2; ++k)
    for (int seed = 0; seed < 2; ++seed) {
      uint64_t ref = 0;
      failure_t f = {{0}};
      expect(surface_work(surface_genera[k], UINT64_C(0xABC) + (uint64_t)seed, &ref, &f) == 0,
             "single-threaded, genus %d: %s", surface_genera[k], f.text);
      for (int i = seed; i < THREADS; i += 2)
        expect(ctx[i].sums[k] == ref, "genus %d: thread %d's answers differ from the single-threaded ones",
               surface_genera[k], i);
    }
  hdt_triangulation *t = NULL;
  ck_assert_int_eq(hdt_create(&t, 6), HDT_OK);
  for (int i = 0; i < 2; ++i)
    expect(ctx[i].faces == hdt_face_count(t), "thread %d: a new genus-6 triangulation had %zu faces, now %zu", i,
           ctx[i].faces, hdt_face_count(t));
  hdt_destroy(t);
}
END_TEST

/* ---- Surfaces from polygons, one per thread ---- */

/* The Bolza octagon in Q(g). e-antic keeps one field per polynomial, root and
   generator's name, shared by every surface read with it, and refines its
   embedding in place as numbers are compared: threads reading the octagon
   with one name share a field; a new name gives a new field, not yet
   refined, so each round below races on a fresh one. */
static const char bolza_template[] =
    "field g^4-2*g^2-1 g 1.5538+/-0.01\n8\n4 5 6 7 0 1 2 3\n"
    "1/2*g 1/2*g^3-g\n1/2*g^3-g 1/2*g\n-1/2*g^3+g 1/2*g\n-1/2*g 1/2*g^3-g\n"
    "-1/2*g -1/2*g^3+g\n-1/2*g^3+g -1/2*g\n1/2*g^3-g -1/2*g\n1/2*g -1/2*g^3+g\n";

/* The octagon's text with the generator named a<round> (two digits). */
static void bolza_polygon(int round, char *text, size_t capacity) {
  size_t n = 0;
  for (const char *c = bolza_template; *c && n + 4 < capacity; ++c)
    if (*c == 'g')
      n += (size_t)snprintf(text + n, capacity - n, "a%02d", round % 100);
    else
      text[n++] = *c;
  text[n] = '\0';
}

/* Makes a surface (the Bolza octagon of the round when which is 0, else the
   random decagon of seed which), reduces points into it and folds the
   answers (bits of the representatives, the words' letters, the text's
   length) into *sum. */
static int polygon_work(int round, int which, uint64_t *sum, failure_t *f) {
  hdt_surface *s = NULL;
  char text[1024];
  bolza_polygon(round, text, sizeof text);
  const hdt_status st = which == 0 ? hdt_surface_from_polygon(&s, text, strlen(text))
                                   : hdt_surface_random_symmetric(&s, 10, (uint64_t)which);
  TCHECK(f, st == HDT_OK, "surface %d: %s (%s)", which, hdt_status_string(st), hdt_last_error_message());
  double xy[2 * 20];
  disk_points(UINT64_C(0x5EED) + (uint64_t)which, 20, xy);
  uint64_t h = 0;
  for (int i = 0; i < 20; ++i) {
    double rx, ry;
    int32_t word[128];
    size_t length = 0;
    const hdt_status r = hdt_surface_representative(s, xy[2 * i], xy[2 * i + 1], &rx, &ry, word, 128, &length);
    if (r != HDT_OK) {
      hdt_surface_destroy(s);
      return record_failure(f, "surface %d, point %d: %s", which, i, hdt_last_error_message());
    }
    h = fold_double(fold_double(h, rx), ry);
    for (size_t k = 0; k < length; ++k) h = fold_double(h, (double)word[k]);
  }
  size_t length = 0;
  TCHECK(f, hdt_surface_polygon_text(s, NULL, 0, &length) == HDT_OK, "surface %d: no text", which);
  *sum = fold_double(h, (double)length);
  hdt_surface_destroy(s);
  return 0;
}

typedef struct polygon_ctx {
  int round, which;
  pthread_barrier_t *barrier;
  uint64_t sum;
  failure_t failure;
} polygon_ctx;

static void *polygon_thread(void *arg) {
  polygon_ctx *c = arg;
  pthread_barrier_wait(c->barrier);
  polygon_work(c->round, c->which, &c->sum, &c->failure);
  return NULL;
}

enum { POLYGON_ROUNDS = 8 };

/* In each round, threads read polygons at once (all but the last the same
   Bolza octagon, in one fresh e-antic field; the last a rational decagon)
   and get the answers of one thread. Without libhdt's field lock, e-antic
   1.3 aborts here now and then (two threads refining one embedding). */
START_TEST(polygon_surfaces_concurrently) {
  for (int round = 0; round < POLYGON_ROUNDS; ++round) {
    pthread_barrier_t barrier;
    ck_assert_int_eq(pthread_barrier_init(&barrier, NULL, THREADS), 0);
    static polygon_ctx ctx[THREADS];
    memset(ctx, 0, sizeof ctx);
    pthread_t th[THREADS];
    for (int i = 0; i < THREADS; ++i) {
      ctx[i].round = round, ctx[i].which = i == THREADS - 1 ? 1 + round : 0, ctx[i].barrier = &barrier;
      ck_assert_int_eq(pthread_create(&th[i], NULL, polygon_thread, &ctx[i]), 0);
    }
    for (int i = 0; i < THREADS; ++i) ck_assert_int_eq(pthread_join(th[i], NULL), 0);
    pthread_barrier_destroy(&barrier);
    for (int i = 0; i < THREADS; ++i) {
      expect(ctx[i].failure.text[0] == '\0', "round %d, thread %d: %s", round, i, ctx[i].failure.text);
      uint64_t ref = 0;
      failure_t f = {{0}};
      expect(polygon_work(round, ctx[i].which, &ref, &f) == 0, "single-threaded: %s", f.text);
      expect(ctx[i].sum == ref, "round %d, thread %d: its answers differ from the single-threaded ones", round, i);
    }
  }
}
END_TEST

int main(void) {
  const TTest *const tests[] = {
      concurrent_triangulations_match_sequential,
      errors_are_thread_local,
      surface_functions_concurrently,
      polygon_surfaces_concurrently,
  };
  return run_tests("threads", tests, sizeof tests / sizeof tests[0]);
}
