/* Insertion at large genus against genus 2, side by side in one process.
 *
 *   genus_ratio_bench [--n 1000000] [--genus 2,64,128] [--rounds 7] [--seed 1]
 *
 * Draws N points uniform for hyperbolic area in F_g for each genus (the
 * points of bench/triangulation_bench.c), creates each genus once (its
 * first-creation cost out of the way), then runs R rounds; a round times
 * hdt_insert_many of each genus's points into a fresh triangulation, in the
 * order given, and destroys it. CPU time per point. Prints each genus's best
 * and median over the rounds and their ratios to the first genus, and the
 * range of the ratio within a round (where the two share the machine's
 * state, the ratio is steadier than either time on a shared machine).
 */
#define _GNU_SOURCE
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_common.h"
#include "hdt.h"
#include "uniform_points.h"

enum { kMaxGenera = 16 };

static int cmp_double(const void *a, const void *b) {
  const double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

static void check(hdt_status s, const char *what) {
  if (s != HDT_OK) {
    fprintf(stderr, "%s: %s: %s\n", what, hdt_status_string(s), hdt_last_error_message());
    exit(1);
  }
}

int main(int argc, char **argv) {
  int genera[kMaxGenera] = {2, 64, 128}, ng = 3, rounds = 7;
  size_t n = 1000000;
  uint64_t seed = 1;
  for (int i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "--n") && i + 1 < argc) {
      n = strtoull(argv[++i], NULL, 10);
    } else if (!strcmp(argv[i], "--genus") && i + 1 < argc) {
      ng = 0;
      for (char *s = strtok(argv[++i], ","); s && ng < kMaxGenera; s = strtok(NULL, ",")) genera[ng++] = atoi(s);
    } else if (!strcmp(argv[i], "--rounds") && i + 1 < argc) {
      rounds = atoi(argv[++i]);
    } else if (!strcmp(argv[i], "--seed") && i + 1 < argc) {
      seed = strtoull(argv[++i], NULL, 10);
    } else {
      fprintf(stderr, "usage: %s [--n N] [--genus 2,64,128] [--rounds R] [--seed S]\n", argv[0]);
      return 2;
    }
  }
  if (n == 0 || ng == 0 || rounds < 1) return 2;

  double *xy[kMaxGenera];
  uint32_t *ids = malloc(n * sizeof *ids);
  double *us = malloc((size_t)ng * (size_t)rounds * sizeof *us);  // [genus][round], µs per point
  for (int k = 0; k < ng; ++k) {
    xy[k] = malloc(2 * n * sizeof *xy[k]);
    bench_points_in_polygon(genera[k], n, seed, xy[k]);
    hdt_triangulation *t;
    check(hdt_create(&t, genera[k]), "hdt_create");  // the first creation, untimed
    hdt_destroy(t);
  }
  for (int r = 0; r < rounds; ++r)
    for (int k = 0; k < ng; ++k) {
      hdt_triangulation *t;
      check(hdt_create(&t, genera[k]), "hdt_create");
      const double c0 = bench_cpu_ms();
      check(hdt_insert_many(t, xy[k], n, ids), "hdt_insert_many");
      us[k * rounds + r] = (bench_cpu_ms() - c0) * 1e3 / (double)n;
      hdt_destroy(t);
    }

  printf("libhdt %s: hdt_insert_many of %zu points uniform in F_g, %d interleaved rounds (CPU time, one process)\n",
         hdt_version_string(), n, rounds);
  printf("  genus  best us/pt  median us/pt  best / g%d  median / g%d  in a round / g%d\n", genera[0], genera[0],
         genera[0]);
  double *sorted = malloc((size_t)rounds * sizeof *sorted);
  double best0 = 0, median0 = 0;
  for (int k = 0; k < ng; ++k) {
    double lo = 1e300, hi = 0;
    for (int r = 0; r < rounds; ++r) {
      const double ratio = us[k * rounds + r] / us[r];
      lo = ratio < lo ? ratio : lo, hi = ratio > hi ? ratio : hi;
    }
    memcpy(sorted, us + k * rounds, (size_t)rounds * sizeof *sorted);
    qsort(sorted, (size_t)rounds, sizeof *sorted, cmp_double);
    const double best = sorted[0], median = sorted[rounds / 2];
    if (k == 0) best0 = best, median0 = median;
    printf("  %5d  %10.3f  %12.3f  %9.2f  %11.2f  %.2f to %.2f\n", genera[k], best, median, best / best0,
           median / median0, lo, hi);
  }
  for (int k = 0; k < ng; ++k) free(xy[k]);
  free(sorted);
  free(us);
  free(ids);
  return 0;
}
