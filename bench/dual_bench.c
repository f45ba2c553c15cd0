/* The cost of the adjacency, edge, corner and Voronoi outputs (HDT_0.4)
 * next to hdt_faces on the same triangulation: N points uniform for area in
 * F_g, dummies removed; each output fetched whole (the stars and cells in
 * one call, hdt_vertex_stars and hdt_voronoi_cells, and one vertex at a
 * time, every vertex): the first call, then the best of
 * `calls - 1` more. Then the cost of saving and loading that triangulation
 * next to hdt_insert_many of its points.
 *
 *   dual_bench [--n 1000000] [--genus 2] [--calls 4] [--rounds 0] [--load-rounds 0]
 *
 * Prints one line per output: milliseconds and the ratio to hdt_faces
 * (vertex ids and translations), first call and best later call; then
 * hdt_voronoi_vertices, hdt_voronoi_edges and hdt_voronoi_cells again, now that
 * hdt_voronoi_cell has filled the handle's centre cache (not with
 * --calls 1); then, with --rounds R, R rounds of hdt_faces,
 * hdt_vertex_stars and hdt_voronoi_cells (after a change) and both again
 * (unchanged: the rows reused) in turn (best and median of each; --calls 0
 * leaves out everything else); then
 * hdt_insert_many, hdt_save and hdt_load (first and best) in ms; then,
 * with --load-rounds R, R rounds of hdt_insert_many of the points into a
 * fresh handle followed by hdt_load of the saved bytes (CPU time; best and
 * median of each and the median of the rounds' ratios load / insert). With
 * --calls 1 each function runs once, for callgrind --toggle-collect;
 * --calls 0 with --rounds or --load-rounds runs only the rounds.
 * docs/dual.md and docs/format.md quote it. */
#define _POSIX_C_SOURCE 200809L

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_common.h"
#include "hdt.h"
#include "uniform_points.h"

static void check(hdt_status s, const char *what) {
  if (s != HDT_OK) {
    fprintf(stderr, "%s: %s: %s\n", what, hdt_status_string(s), hdt_last_error_message());
    exit(1);
  }
}

typedef struct buffers {
  size_t V, F, E, bound;
  size_t *offsets;
  uint32_t *ids, *u32a, *u32b;
  int32_t *i32a;
  uint8_t *u8;
  double *d1, *d2;
} buffers;

static hdt_triangulation *T;
static buffers B;

static void faces(void) { size_t n; check(hdt_faces(T, B.u32a, B.i32a, B.F, &n), "hdt_faces"); }
static void neighbours(void) { size_t n; check(hdt_face_neighbours(T, B.u32a, B.i32a, B.F, &n), "hdt_face_neighbours"); }
static void edges(void) { size_t n; check(hdt_edges(T, B.u32a, B.i32a, B.u32b, B.d1, B.E, &n), "hdt_edges"); }
static void face_points(void) { size_t n; check(hdt_face_points(T, B.d1, B.F, &n), "hdt_face_points"); }
static void voronoi_vertices(void) {
  size_t n;
  check(hdt_voronoi_vertices(T, B.d1, B.d2, B.F, &n), "hdt_voronoi_vertices");
}
static void voronoi_edges(void) { size_t n; check(hdt_voronoi_edges(T, B.d1, B.E, &n), "hdt_voronoi_edges"); }
static void stars(void) {
  for (size_t i = 0; i < B.V; ++i) {
    size_t n;
    check(hdt_vertex_star(T, B.ids[i], B.u32a, B.u8, B.i32a, B.F, &n), "hdt_vertex_star");
  }
}
static void cells(void) {
  for (size_t i = 0; i < B.V; ++i) {
    size_t n;
    check(hdt_voronoi_cell(T, B.ids[i], B.d1, B.F, &n), "hdt_voronoi_cell");
  }
}

/* The handle reuses the rows of hdt_vertex_stars and hdt_voronoi_cells
   while the triangulation is unchanged; a call on a non-const handle
   (here hdt_set_progress, which changes nothing else) counts as a change,
   so that all_stars and all_cells time the whole work, as after an
   insertion. The "again" forms time the reuse. */
static void changed(void) { check(hdt_set_progress(T, NULL, NULL, 0), "hdt_set_progress"); }
static void stars_again(void) {
  size_t n;
  check(hdt_vertex_stars(T, B.offsets, B.u32a, B.u8, B.i32a, 3 * B.F, &n), "hdt_vertex_stars");
}
static void cells_again(void) { size_t n; check(hdt_voronoi_cells(T, B.offsets, B.d1, 3 * B.F, &n), "hdt_voronoi_cells"); }
static void all_stars(void) { changed(), stars_again(); }
static void all_cells(void) { changed(), cells_again(); }

static int calls = 4;

static int cmp_double(const void *a, const void *b) {
  const double x = *(const double *)a, y = *(const double *)b;
  return x < y ? -1 : x > y;
}

/* --rounds R: R rounds of hdt_faces, hdt_vertex_stars and hdt_voronoi_cells
   (after a change), then both again (unchanged), one after the other, so
   that they see the same load (on a shared
   machine the load moves between the separate timings above); the best
   and the median round of each, and their ratios to hdt_faces'. */
enum { kInterleaved = 5 };
static void interleaved(int rounds) {
  void (*f[kInterleaved])(void) = {faces, all_stars, all_cells, stars_again, cells_again};
  const char *name[kInterleaved] = {"hdt_faces", "hdt_vertex_stars", "hdt_voronoi_cells", "hdt_vertex_stars again",
                                    "hdt_voronoi_cells again"};
  double *ms = malloc(kInterleaved * (size_t)rounds * sizeof *ms);
  for (int r = 0; r < rounds; ++r)
    for (int k = 0; k < kInterleaved; ++k) {
      const double t0 = bench_now_ms();
      f[k]();
      ms[k * rounds + r] = bench_now_ms() - t0;
    }
  double best[kInterleaved], median[kInterleaved];
  for (int k = 0; k < kInterleaved; ++k) {
    qsort(ms + k * rounds, (size_t)rounds, sizeof *ms, cmp_double);
    best[k] = ms[k * rounds], median[k] = ms[k * rounds + rounds / 2];
  }
  printf("  %d interleaved rounds (best, median):\n", rounds);
  for (int k = 0; k < kInterleaved; ++k)
    printf("  %-32s best %9.1f ms %5.2f x hdt_faces   median %9.1f ms %5.2f x hdt_faces\n", name[k], best[k],
           best[k] / best[0], median[k], median[k] / median[0]);
  free(ms);
}

/* --load-rounds R: hdt_insert_many into a fresh handle, then hdt_load of
   the saved bytes, R times in turn, so that both see the same load of a
   shared machine; CPU time of the process, the handles' creation and
   destruction not counted. The median of the per-round ratios is the
   figure docs/format.md quotes (issue 18: load at most the insertion). */
static void load_rounds(int rounds, int genus, const double *xy, size_t n, const void *bytes, size_t size) {
  double *ms = malloc(3 * (size_t)rounds * sizeof *ms);
  double *insert_ms = ms, *load_ms = ms + rounds, *ratio = ms + 2 * rounds;
  for (int r = 0; r < rounds; ++r) {
    hdt_triangulation *t, *l;
    check(hdt_create(&t, genus), "hdt_create");
    double t0 = bench_cpu_ms();
    check(hdt_insert_many(t, xy, n, NULL), "hdt_insert_many");
    insert_ms[r] = bench_cpu_ms() - t0;
    hdt_destroy(t);
    t0 = bench_cpu_ms();
    check(hdt_load(&l, bytes, size), "hdt_load");
    load_ms[r] = bench_cpu_ms() - t0;
    hdt_destroy(l);
    ratio[r] = load_ms[r] / insert_ms[r];
    printf("  round %d: hdt_insert_many %.1f ms, hdt_load %.1f ms, load / insert %.3f\n", r + 1, insert_ms[r],
           load_ms[r], ratio[r]);
  }
  for (int k = 0; k < 3; ++k) qsort(ms + k * rounds, (size_t)rounds, sizeof *ms, cmp_double);
  printf("  %d interleaved load rounds (CPU time): hdt_insert_many best %.1f ms median %.1f ms; hdt_load best %.1f ms "
         "median %.1f ms; load / insert median %.3f (best / best %.3f)\n",
         rounds, insert_ms[0], insert_ms[rounds / 2], load_ms[0], load_ms[rounds / 2], ratio[rounds / 2],
         load_ms[0] / insert_ms[0]);
  free(ms);
}

/* The first call (it may compute translation products, matrices or cached
   circumcentres), then the best of the others (0 with --calls 1). */
static void time_calls(void (*f)(void), double *first, double *best) {
  *best = 1e300;
  for (int k = 0; k < calls; ++k) {
    const double t0 = bench_now_ms();
    f();
    const double dt = bench_now_ms() - t0;
    if (k == 0) *first = dt;
    else if (dt < *best) *best = dt;
  }
  if (calls < 2) *best = 0;
}

static hdt_triangulation *loaded;
static void *saved;
static size_t saved_size;
static void load(void) {
  if (loaded) hdt_destroy(loaded);
  check(hdt_load(&loaded, saved, saved_size), "hdt_load");
}

int main(int argc, char **argv) {
  size_t n = 1000000;
  int genus = 2, rounds = 0, load_round_count = 0;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!strcmp(argv[i], "--n")) n = strtoull(argv[i + 1], NULL, 10);
    else if (!strcmp(argv[i], "--genus")) genus = atoi(argv[i + 1]);
    else if (!strcmp(argv[i], "--calls")) calls = atoi(argv[i + 1]);
    else if (!strcmp(argv[i], "--rounds")) rounds = atoi(argv[i + 1]);
    else if (!strcmp(argv[i], "--load-rounds")) load_round_count = atoi(argv[i + 1]);
  }
  const int only_rounds = calls == 0 && (rounds > 0 || load_round_count > 0);
  if (calls < 1) calls = 1;
  double *xy = malloc(2 * n * sizeof *xy);
  bench_points_in_polygon(genus, n, 1, xy);
  check(hdt_create(&T, genus), "hdt_create");
  const double insert_t0 = bench_now_ms();
  check(hdt_insert_many(T, xy, n, NULL), "hdt_insert_many");
  const double insert_ms = bench_now_ms() - insert_t0;
  check(hdt_remove_dummies(T, NULL), "hdt_remove_dummies");
  B.V = hdt_vertex_count(T), B.F = hdt_face_count(T), B.E = hdt_edge_count(T), B.bound = hdt_vertex_id_bound(T);
  B.offsets = malloc((B.bound + 1) * sizeof *B.offsets);
  B.ids = malloc(B.V * sizeof *B.ids);
  B.u32a = malloc(3 * B.F * sizeof *B.u32a);
  B.u32b = malloc(2 * B.E * sizeof *B.u32b);
  B.i32a = malloc(3 * B.F * sizeof *B.i32a);
  B.u8 = malloc(3 * B.F);
  B.d1 = malloc(6 * B.F * sizeof *B.d1);
  B.d2 = malloc(B.F * sizeof *B.d2);
  /* Touched once: the first call must not pay the buffers' page faults. */
  /* (Not with zeros: GCC makes malloc and a memset to 0 a calloc, whose
     fresh pages are not touched.) */
  memset(B.u32a, 1, 3 * B.F * sizeof *B.u32a), memset(B.u32b, 1, 2 * B.E * sizeof *B.u32b);
  memset(B.i32a, 1, 3 * B.F * sizeof *B.i32a), memset(B.u8, 1, 3 * B.F);
  memset(B.offsets, 1, (B.bound + 1) * sizeof *B.offsets);
  memset(B.d1, 1, 6 * B.F * sizeof *B.d1), memset(B.d2, 1, B.F * sizeof *B.d2);
  size_t count;
  check(hdt_vertices(T, B.ids, NULL, NULL, B.V, &count), "hdt_vertices");
  printf("libhdt %s: genus %d, %zu vertices, %zu faces, %zu edges (first call; best of %d later calls)\n",
         hdt_version_string(), genus, B.V, B.F, B.E, calls - 1);
  const struct {
    const char *name;
    void (*f)(void);
  } runs[] = {{"hdt_faces", faces},
              {"hdt_face_neighbours", neighbours},
              {"hdt_edges (all outputs)", edges},
              {"hdt_face_points", face_points},
              {"hdt_voronoi_vertices", voronoi_vertices},
              {"hdt_voronoi_edges", voronoi_edges},
              {"hdt_vertex_stars", all_stars},
              {"hdt_voronoi_cells", all_cells},
              {"hdt_vertex_stars again", stars_again},
              {"hdt_voronoi_cells again", cells_again},
              {"hdt_vertex_star, every vertex", stars},
              {"hdt_voronoi_cell, every vertex", cells}};
  double base_first = 0, base_best = 0;
  for (size_t k = 0; !only_rounds && k < sizeof runs / sizeof runs[0]; ++k) {
    double first, best;
    time_calls(runs[k].f, &first, &best);
    if (k == 0) base_first = first, base_best = best;
    printf("  %-32s first %9.1f ms %5.2f x hdt_faces   later %9.1f ms %5.2f x hdt_faces\n", runs[k].name, first,
           first / base_first, best, base_best > 0 ? best / base_best : 0.0);
  }
  /* hdt_voronoi_cell left the handle's centre cache full: the other two
     Voronoi outputs read it. (Not with --calls 1, which runs each function
     once for callgrind.) */
  const struct {
    const char *name;
    void (*f)(void);
  } cached[] = {{"hdt_voronoi_vertices, cache full", voronoi_vertices}, {"hdt_voronoi_edges, cache full", voronoi_edges},
              {"hdt_voronoi_cells, cache full", all_cells}};
  for (size_t k = 0; !only_rounds && calls > 1 && k < sizeof cached / sizeof cached[0]; ++k) {
    double first, best;
    time_calls(cached[k].f, &first, &best);
    printf("  %-32s first %9.1f ms %5.2f x hdt_faces   later %9.1f ms %5.2f x hdt_faces\n", cached[k].name, first,
           first / base_first, best, base_best > 0 ? best / base_best : 0.0);
  }
  if (rounds > 0) {
    faces(), all_stars(), all_cells(); /* later calls only (the centre cache full, as in the table) */
    interleaved(rounds);
  }
  if (only_rounds && load_round_count == 0) {
    free(xy);
    free(B.ids), free(B.offsets), free(B.u32a), free(B.u32b), free(B.i32a), free(B.u8), free(B.d1), free(B.d2);
    hdt_destroy(T);
    return 0;
  }
  check(hdt_save(T, NULL, 0, &saved_size), "hdt_save");
  saved = malloc(saved_size);
  const double save_t0 = bench_now_ms();
  check(hdt_save(T, saved, saved_size, &saved_size), "hdt_save");
  const double save_ms = bench_now_ms() - save_t0;
  if (load_round_count > 0) load_rounds(load_round_count, genus, xy, n, saved, saved_size);
  free(xy);
  double load_first, load_best;
  if (!only_rounds) time_calls(load, &load_first, &load_best);
  if (!only_rounds) printf("  hdt_insert_many %.1f ms; hdt_save %.1f ms (%zu bytes); hdt_load first %.1f ms (%.2f x insert), later %.1f ms (%.2f x insert)\n",
         insert_ms, save_ms, saved_size, load_first, load_first / insert_ms, load_best, load_best / insert_ms);
  if (loaded) hdt_destroy(loaded);
  free(saved);
  free(B.ids), free(B.offsets), free(B.u32a), free(B.u32b), free(B.i32a), free(B.u8), free(B.d1), free(B.d2);
  hdt_destroy(T);
  return 0;
}
