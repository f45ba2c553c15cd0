/* Points along curves against random points, side by side in one process:
 * for each genus and shape (bench/curve_points.h), the CPU time of
 * hdt_insert_many of N points followed by hdt_remove_dummies, best of
 * --repeat runs, and its ratio to the same for N random points of F_g.
 * Prints a Markdown table.
 *
 *   curves_bench [--n 10000] [--genus 2,3] [--repeat 3] [--shape NAME]
 *
 * --shape runs the reference and that one shape only (for profiling).
 */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_common.h"
#include "curve_points.h"
#include "hdt.h"

typedef struct timing {
  double insert_ms, remove_ms;
  size_t left;
} timing;

static timing run(int g, curve_shape shape, size_t n, int repeat) {
  double *xy = malloc(2 * n * sizeof *xy);
  if (!xy) exit(1);
  curve_points(shape, g, n, 1, xy);
  timing best = {1e300, 1e300, 0};
  for (int r = 0; r < repeat; ++r) {
    hdt_triangulation *t = NULL;
    if (hdt_create(&t, g) != HDT_OK) exit(1);
    const double t0 = bench_cpu_ms();
    if (hdt_insert_many(t, xy, n, NULL) != HDT_OK) exit(1);
    const double t1 = bench_cpu_ms();
    if (hdt_remove_dummies(t, &best.left) != HDT_OK) exit(1);
    const double t2 = bench_cpu_ms();
    if (t2 - t0 < best.insert_ms + best.remove_ms) best.insert_ms = t1 - t0, best.remove_ms = t2 - t1;
    hdt_destroy(t);
  }
  free(xy);
  return best;
}

int main(int argc, char **argv) {
  size_t n = 10000;
  int repeat = 3;
  const char *genera = "2,3";
  const char *only = NULL;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!strcmp(argv[i], "--n")) n = (size_t)strtoull(argv[i + 1], NULL, 10);
    else if (!strcmp(argv[i], "--genus")) genera = argv[i + 1];
    else if (!strcmp(argv[i], "--repeat")) repeat = atoi(argv[i + 1]);
    else if (!strcmp(argv[i], "--shape")) only = argv[i + 1];
    else {
      fprintf(stderr, "usage: curves_bench [--n N] [--genus 2,3] [--repeat R] [--shape NAME]\n");
      return 2;
    }
  }
  printf("N = %zu points, CPU time, best of %d (curves_bench)\n\n", n, repeat);
  printf("| genus | shape | insert ms | remove dummies ms | total vs random | dummies left |\n");
  printf("|---:|---|---:|---:|---:|---:|\n");
  for (const char *p = genera; *p;) {
    const int g = atoi(p);
    const timing reference = run(g, CURVE_RANDOM, n, repeat);
    const double total = reference.insert_ms + reference.remove_ms;
    for (int s = CURVE_RANDOM; s < CURVE_SHAPES; ++s) {
      if (only && s != CURVE_RANDOM && strcmp(only, curve_shape_names[s])) continue;
      const timing t = s == CURVE_RANDOM ? reference : run(g, (curve_shape)s, n, repeat);
      printf("| %d | %s | %.1f | %.1f | %.2fx | %zu |\n", g, curve_shape_names[s], t.insert_ms, t.remove_ms,
             (t.insert_ms + t.remove_ms) / total, t.left);
    }
    while (*p && *p != ',') ++p;
    if (*p == ',') ++p;
  }
  return 0;
}
