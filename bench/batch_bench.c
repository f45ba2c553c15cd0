/* Points given a few at a time against all at once, side by side in one
 * process: N random points of F_g (bench/uniform_points.h) go into a fresh
 * triangulation by one hdt_insert_many call, by calls of k points each, and
 * by hdt_insert one at a time; then hdt_locate and hdt_nearest_vertex of N
 * other random points one at a time. The CPU time, best of --repeat runs,
 * and its ratio to the one call. Every way of inserting must give the same
 * face count (checked). Prints a Markdown table.
 *
 *   batch_bench [--n 100000] [--genus 2] [--repeat 3] [--calls 10,100,1000]
 */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_common.h"
#include "hdt.h"
#include "uniform_points.h"

/* The best CPU time of `repeat` rounds of hdt_locate (nearest = 0) or
   hdt_nearest_vertex (1) of the n points q, one at a time, in t. */
static double queries(const hdt_triangulation *t, const double *q, size_t n, int nearest, int repeat) {
  double best = 1e300;
  for (int r = 0; r < repeat; ++r) {
    const double t0 = bench_cpu_ms();
    for (size_t i = 0; i < n; ++i) {
      size_t face;
      int32_t translation;
      uint32_t vertex;
      const hdt_status s = nearest ? hdt_nearest_vertex(t, q[2 * i], q[2 * i + 1], &vertex)
                                   : hdt_locate(t, q[2 * i], q[2 * i + 1], &face, &translation);
      if (s != HDT_OK) exit(1);
    }
    const double dt = bench_cpu_ms() - t0;
    if (dt < best) best = dt;
  }
  return best;
}

/* k = 0: hdt_insert one point at a time; else hdt_insert_many k at a time.
   The best CPU time of `repeat` runs; *faces the face count. */
static double run(int g, const double *xy, size_t n, size_t k, int repeat, size_t *faces) {
  double best = 1e300;
  for (int r = 0; r < repeat; ++r) {
    hdt_triangulation *t = NULL;
    if (hdt_create(&t, g) != HDT_OK) exit(1);
    const double t0 = bench_cpu_ms();
    for (size_t i = 0; i < n; i += k ? k : 1) {
      const size_t m = k == 0 ? 1 : (n - i < k ? n - i : k);
      const hdt_status s = k == 0 ? hdt_insert(t, xy[2 * i], xy[2 * i + 1], NULL)
                                  : hdt_insert_many(t, xy + 2 * i, m, NULL);
      if (s != HDT_OK) exit(1);
    }
    const double dt = bench_cpu_ms() - t0;
    if (dt < best) best = dt;
    *faces = hdt_face_count(t);
    hdt_destroy(t);
  }
  return best;
}

int main(int argc, char **argv) {
  size_t n = 100000;
  int genus = 2, repeat = 3;
  char calls[256] = "10,100,1000";
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!strcmp(argv[i], "--n")) n = (size_t)strtoull(argv[i + 1], NULL, 10);
    else if (!strcmp(argv[i], "--genus")) genus = atoi(argv[i + 1]);
    else if (!strcmp(argv[i], "--repeat")) repeat = atoi(argv[i + 1]);
    else if (!strcmp(argv[i], "--calls")) snprintf(calls, sizeof calls, "%s", argv[i + 1]);
    else {
      fprintf(stderr, "usage: batch_bench [--n N] [--genus G] [--repeat R] [--calls 10,100,1000]\n");
      return 2;
    }
  }
  double *xy = malloc(2 * n * sizeof *xy);
  if (!xy) return 1;
  bench_points_in_polygon(genus, n, 1, xy);
  printf("libhdt %s: genus %d, N = %zu random points of F_g, CPU time, best of %d (batch_bench)\n\n",
         hdt_version_string(), genus, n, repeat);
  printf("| how | ms | us per point | / one call |\n|---|---:|---:|---:|\n");
  size_t faces_one, faces;
  const double one = run(genus, xy, n, n, repeat, &faces_one);
  printf("| one hdt_insert_many call | %.1f | %.2f | 1 |\n", one, 1e3 * one / n);
  for (char *k = strtok(calls, ","); k; k = strtok(NULL, ",")) {
    const size_t size = (size_t)strtoull(k, NULL, 10);
    if (size == 0) continue;
    const double ms = run(genus, xy, n, size, repeat, &faces);
    if (faces != faces_one) return fprintf(stderr, "calls of %zu: %zu faces, not %zu\n", size, faces, faces_one), 1;
    printf("| hdt_insert_many, %zu points a call | %.1f | %.2f | %.2f |\n", size, ms, 1e3 * ms / n, ms / one);
  }
  const double each = run(genus, xy, n, 0, repeat, &faces);
  if (faces != faces_one) return fprintf(stderr, "hdt_insert: %zu faces, not %zu\n", faces, faces_one), 1;
  printf("| hdt_insert, one point a call | %.1f | %.2f | %.2f |\n", each, 1e3 * each / n, each / one);
  /* Queries at N other random points of F_g, on the triangulation of the
     first N (its dummies kept). */
  hdt_triangulation *t = NULL;
  if (hdt_create(&t, genus) != HDT_OK || hdt_insert_many(t, xy, n, NULL) != HDT_OK) return 1;
  bench_points_in_polygon(genus, n, 2, xy);
  const double locate = queries(t, xy, n, 0, repeat), nearest = queries(t, xy, n, 1, repeat);
  printf("| hdt_locate, N other points one at a time | %.1f | %.2f | %.2f |\n", locate, 1e3 * locate / n, locate / one);
  printf("| hdt_nearest_vertex, the same | %.1f | %.2f | %.2f |\n", nearest, 1e3 * nearest / n, nearest / one);
  hdt_destroy(t);
  free(xy);
  return 0;
}
