/* Allocation failure: under a tight address-space limit (in a forked child,
 * so the limit never reaches the test runner), insertions fail with
 * HDT_ENOMEM and leave a valid triangulation, one that the failing call did
 * not change; once memory is back, work goes on.
 *
 * Skipped under AddressSanitizer, ThreadSanitizer and valgrind: they reserve
 * address space of their own, so RLIMIT_AS means nothing there.
 */
#define _DEFAULT_SOURCE

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "hdt_test.h"
#include "limited_child.h"

static int under_valgrind(void) {
  const char *preload = getenv("LD_PRELOAD");
  return preload && strstr(preload, "vgpreload");
}

/* n random points of the disk of radius 0.95. */
static double *random_points(uint64_t *rng, size_t n) {
  double *xy = malloc(2 * n * sizeof *xy);
  for (size_t i = 0; i < n;) {
    const double x = 2.0 * (double)(rng_next(rng) >> 11) * 0x1.0p-53 - 1.0;
    const double y = 2.0 * (double)(rng_next(rng) >> 11) * 0x1.0p-53 - 1.0;
    if (x * x + y * y >= 0.95 * 0.95) continue;
    xy[2 * i] = x, xy[2 * i + 1] = y;
    ++i;
  }
  return xy;
}

typedef struct {
  size_t vertices, faces, dummies, id_bound;
} counts_t;

static counts_t counts(const hdt_triangulation *t) {
  counts_t c = {hdt_vertex_count(t), hdt_face_count(t), hdt_dummy_count(t), hdt_vertex_id_bound(t)};
  return c;
}

static int same_counts(counts_t a, counts_t b) {
  return a.vertices == b.vertices && a.faces == b.faces && a.dummies == b.dummies && a.id_bound == b.id_bound;
}

static void expect_out_of_memory(hdt_status s, const char *function) {
  const char *msg = hdt_last_error_message();
  require(s == HDT_ENOMEM, "%s returned %s, expected HDT_ENOMEM", function, hdt_status_string(s));
  require(strstr(msg, function) && strstr(msg, "memory"), "message \"%s\"", msg);
}

/* The child: grows a triangulation until memory runs out, three ways. */
static void child(int genus) {
  const size_t start = 2000, many = 1000000;
  uint64_t rng = 0xE40E3 + (uint64_t)genus;
  double *first = random_points(&rng, start);
  double *rest = random_points(&rng, many); /* allocated before the limit */
  require(first && rest, "no memory for the points");
  hdt_triangulation *t = NULL;
  require(hdt_create(&t, genus) == HDT_OK, "hdt_create: %s", hdt_last_error_message());
  require(hdt_insert_many(t, first, start, NULL) == HDT_OK, "hdt_insert_many: %s", hdt_last_error_message());
  require(hdt_remove_dummies(t, NULL) == HDT_OK, "hdt_remove_dummies: %s", hdt_last_error_message());

  struct rlimit old;
  require(getrlimit(RLIMIT_AS, &old) == 0, "getrlimit: %s", strerror(errno));
  const size_t headroom = (size_t)4 << 20;
  struct rlimit tight = {(rlim_t)(address_space_bytes() + headroom), old.rlim_max};
  require(old.rlim_cur == RLIM_INFINITY || tight.rlim_cur < old.rlim_cur, "the limit is already tight");
  require(setrlimit(RLIMIT_AS, &tight) == 0, "setrlimit: %s", strerror(errno));

  /* 1. A batch too large to reserve for: refused whole, nothing changed. */
  counts_t before = counts(t);
  expect_out_of_memory(hdt_insert_many(t, rest, many, NULL), "hdt_insert_many");
  require(same_counts(before, counts(t)), "a refused hdt_insert_many changed the counts");

  /* 2. One by one until the face array cannot grow: the failing insertion
     changes nothing. */
  size_t i = 0, inserted = 0;
  hdt_status s = HDT_OK;
  for (; i < many; ++i) {
    before = counts(t);
    s = hdt_insert(t, rest[2 * i], rest[2 * i + 1], NULL);
    if (s != HDT_OK) break;
    ++inserted;
  }
  require(i < many, "%zu insertions under a %zu MiB headroom never ran out of memory", inserted, headroom >> 20);
  expect_out_of_memory(s, "hdt_insert");
  require(same_counts(before, counts(t)), "a failed hdt_insert changed the counts");

  /* 3. Memory back: the triangulation is valid, and the point that failed
     goes in (it was not half inserted). */
  require(setrlimit(RLIMIT_AS, &old) == 0, "setrlimit back: %s", strerror(errno));
  require(hdt_validate(t) == HDT_OK, "after ENOMEM: %s", hdt_last_error_message());
  uint32_t v = 0;
  require(hdt_insert(t, rest[2 * i], rest[2 * i + 1], &v) == HDT_OK, "the failed point, again: %s",
          hdt_last_error_message());
  require(hdt_vertex_count(t) == before.vertices + 1, "one more vertex after the retry");
  require(hdt_validate(t) == HDT_OK, "after the retry: %s", hdt_last_error_message());
  printf("enomem g=%d: %zu vertices at the limit (%zu inserted one by one), then the failed point went in\n", genus,
         before.vertices, inserted);
  fflush(stdout);
  hdt_destroy(t);
  free(first);
  free(rest);
  _exit(0);
}

/* The second child: the outputs of HDT_0.4 that need memory of their own
   (hdt_voronoi_edges: the circumcentres; hdt_voronoi_cell: the handle's
   cache of them) fail with HDT_ENOMEM under a limit their scratch exceeds,
   and write nothing to the caller's buffers but the count; with memory back
   they answer. hdt_voronoi_vertices allocates nothing: it answers under the
   limit, the same bytes as later. hdt_edges keeps only the translations
   other than the identity: it may answer or refuse, and a refusal writes
   nothing. */
static void dual_child(int genus) {
  const size_t n = 200000;
  uint64_t rng = 0xD0A1 + (uint64_t)genus;
  double *xy = random_points(&rng, n);
  hdt_triangulation *t = NULL;
  require(xy && hdt_create(&t, genus) == HDT_OK, "hdt_create: %s", hdt_last_error_message());
  require(hdt_insert_many(t, xy, n, NULL) == HDT_OK, "hdt_insert_many: %s", hdt_last_error_message());
  const size_t F = hdt_face_count(t), E = hdt_edge_count(t);
  double *out = malloc(4 * E * sizeof *out), *radii = malloc(F * sizeof *radii);
  double *centres = malloc(2 * F * sizeof *centres), *radii_later = malloc(F * sizeof *radii_later);
  int32_t *translations = malloc(E * sizeof *translations);
  require(out && radii && centres && radii_later && translations, "no memory for the buffers");
  memset(out, 0x5a, 4 * E * sizeof *out), memset(radii, 0x5a, F * sizeof *radii);
  memset(translations, 0x5a, E * sizeof *translations);
  size_t count = 0;
  /* A live vertex (a size query fills no cache). */
  uint32_t v = 0;
  while (hdt_voronoi_cell(t, v, NULL, 0, &count) != HDT_OK) ++v;
  struct rlimit old;
  require(getrlimit(RLIMIT_AS, &old) == 0, "getrlimit: %s", strerror(errno));
  /* Less than any of the scratch vectors (3.2 MB and more here). */
  const size_t headroom = (size_t)1 << 20;
  struct rlimit tight = {(rlim_t)(address_space_bytes() + headroom), old.rlim_max};
  require(setrlimit(RLIMIT_AS, &tight) == 0, "setrlimit: %s", strerror(errno));
  require(hdt_voronoi_vertices(t, centres, radii, F, &count) == HDT_OK,
          "hdt_voronoi_vertices under the limit: %s", hdt_last_error_message());
  require(count == F, "hdt_voronoi_vertices: count %zu, F %zu", count, F);
  expect_out_of_memory(hdt_voronoi_edges(t, out, E, &count), "hdt_voronoi_edges");
  require(count == E, "hdt_voronoi_edges: count %zu, E %zu", count, E);
  expect_out_of_memory(hdt_voronoi_cell(t, v, out, E, &count), "hdt_voronoi_cell");
  const hdt_status edges_status = hdt_edges(t, NULL, translations, NULL, NULL, E, &count);
  require(count == E, "hdt_edges: count %zu, E %zu", count, E);
  if (edges_status != HDT_OK) expect_out_of_memory(edges_status, "hdt_edges");
  const unsigned char *bytes = (const unsigned char *)out;
  for (size_t i = 0; i < 4 * E * sizeof *out; ++i) require(bytes[i] == 0x5a, "a failed call wrote byte %zu", i);
  bytes = (const unsigned char *)translations;
  if (edges_status != HDT_OK)
    for (size_t i = 0; i < E * sizeof *translations; ++i) require(bytes[i] == 0x5a, "a failed call wrote byte %zu", i);
  require(setrlimit(RLIMIT_AS, &old) == 0, "setrlimit back: %s", strerror(errno));
  require(hdt_voronoi_vertices(t, out, radii_later, F, &count) == HDT_OK && hdt_voronoi_edges(t, out, E, &count) == HDT_OK &&
              hdt_voronoi_cell(t, v, out, E, &count) == HDT_OK &&
              hdt_edges(t, NULL, translations, NULL, NULL, E, &count) == HDT_OK,
          "with memory back: %s", hdt_last_error_message());
  require(hdt_voronoi_vertices(t, out, radii_later, F, &count) == HDT_OK, "hdt_voronoi_vertices: %s",
          hdt_last_error_message());
  require(memcmp(out, centres, 2 * F * sizeof *out) == 0 && memcmp(radii, radii_later, F * sizeof *radii) == 0,
          "hdt_voronoi_vertices under the limit and later differ");
  printf("enomem g=%d: the HDT_0.4 outputs of %zu faces refused under a 1 MiB headroom (hdt_edges %s), then answered\n",
         genus, F, edges_status == HDT_OK ? "answered" : "refused");
  fflush(stdout);
  hdt_destroy(t);
  free(xy), free(out), free(radii), free(centres), free(radii_later), free(translations);
  _exit(0);
}

static void run_in_child(void (*body)(int), int genus) {
  fflush(stdout);
  fflush(stderr);
  const pid_t pid = fork();
  ck_assert_msg(pid >= 0, "fork: %s", strerror(errno));
  if (pid == 0) body(genus);
  int status = 0;
  ck_assert_msg(waitpid(pid, &status, 0) == pid, "waitpid: %s", strerror(errno));
  ck_assert_msg(WIFEXITED(status), "the child died of signal %d", WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  ck_assert_msg(WEXITSTATUS(status) == 0, "the child failed (its message is on stderr)");
}

START_TEST(insert_out_of_memory_genus2) {
  if (UNDER_SANITIZER || under_valgrind()) {
    printf("enomem: skipped under a sanitizer or valgrind (RLIMIT_AS does not apply)\n");
    return;
  }
  run_in_child(child, 2);
}
END_TEST

START_TEST(insert_out_of_memory_genus4) {
  if (UNDER_SANITIZER || under_valgrind()) return;
  run_in_child(child, 4);
}
END_TEST

START_TEST(dual_outputs_out_of_memory) {
  if (UNDER_SANITIZER || under_valgrind()) return;
  run_in_child(dual_child, 2);
}
END_TEST

int main(void) {
  const TTest *const tests[] = {insert_out_of_memory_genus2, insert_out_of_memory_genus4,
                                dual_outputs_out_of_memory};
  return run_tests("enomem", tests, sizeof tests / sizeof tests[0]);
}
