/* What a polygon surface costs before any point is inserted: for each random
 * genus-2 polygon of hdt_surface_random_symmetric (octagons and decagons,
 * seeds 0 to S - 1), the CPU time of making it (every exact check on entry)
 * and of its certified systole (the first hdt_surface_systole call), the
 * systole's bounds and |N|.
 *
 *   surface_bench [--seeds S] [--sides 8,10]
 *
 * One line per polygon, starting with "SURFACE ", then one "SUMMARY " line
 * per number of sides (the least, median and largest systole time). */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_common.h"
#include "hdt.h"

static int by_value(const void *a, const void *b) {
  const double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* One polygon; its systole's CPU time in ms, or -1 on failure. */
static double measure(int sides, unsigned seed) {
  hdt_surface *s = NULL;
  const double t0 = bench_cpu_ms();
  if (hdt_surface_random_symmetric(&s, sides, seed) != HDT_OK) {
    fprintf(stderr, "surface_bench: %s\n", hdt_last_error_message());
    return -1;
  }
  const double t1 = bench_cpu_ms();
  double lo = 0, hi = 0;
  const hdt_status st = hdt_surface_systole(s, &lo, &hi);
  const double t2 = bench_cpu_ms();
  size_t neighbours = 0;
  hdt_surface_neighbour_count(s, &neighbours);
  printf("SURFACE sides=%d seed=%u create_cpu_ms=%.2f systole_cpu_ms=%.2f status=%d lo=%.17g hi=%.17g neighbours=%zu\n",
         sides, seed, t1 - t0, t2 - t1, (int)st, lo, hi, neighbours);
  fflush(stdout);
  hdt_surface_destroy(s);
  return st == HDT_OK ? t2 - t1 : -1;
}

int main(int argc, char **argv) {
  unsigned seeds = 8;
  char sides_list[64] = "8,10";
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!strcmp(argv[i], "--seeds")) seeds = (unsigned)strtoul(argv[i + 1], NULL, 10);
    else if (!strcmp(argv[i], "--sides")) snprintf(sides_list, sizeof sides_list, "%s", argv[i + 1]);
    else {
      fprintf(stderr, "surface_bench: unknown option %s\n", argv[i]);
      return 2;
    }
  }
  if (seeds == 0 || seeds > 1000) return 2;
  double *ms = malloc(seeds * sizeof *ms);
  if (!ms) return 1;
  int failed = 0;
  for (char *tok = strtok(sides_list, ","); tok; tok = strtok(NULL, ",")) {
    const int sides = atoi(tok);
    for (unsigned seed = 0; seed < seeds; ++seed) {
      ms[seed] = measure(sides, seed);
      failed |= ms[seed] < 0;
    }
    qsort(ms, seeds, sizeof *ms, by_value);
    printf("SUMMARY sides=%d seeds=%u systole_cpu_ms_min=%.2f median=%.2f max=%.2f\n", sides, seeds, ms[0],
           ms[seeds / 2], ms[seeds - 1]);
  }
  free(ms);
  return failed;
}
