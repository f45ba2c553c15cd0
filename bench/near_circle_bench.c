/* Points near the unit circle against points uniform in F_g (issue 33):
 * for each genus, n points of each kind (bench/near_circle_points.h,
 * bench/uniform_points.h) timed through hdt_insert one by one (mean and
 * max a point), hdt_insert_many into a fresh handle, hdt_validate, and
 * hdt_save + hdt_load of the result; one line per genus and kind, then the
 * ratios near / uniform. hdt_create's first call of a genus (building its
 * dummy points) is made before any timing.
 *
 *   near_circle_bench [--genus 16,64,256] [--n 100,100,20] [--seed S]
 *
 * Lines start with "NEAR " (key=value fields, times in ms). */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_common.h"
#include "hdt.h"
#include "near_circle_points.h"
#include "uniform_points.h"

typedef struct row_t {
  double one_mean, one_max, many, validate, save, load;
} row_t;

static int fail(const char *what) {
  fprintf(stderr, "near_circle_bench: %s: %s\n", what, hdt_last_error_message());
  return 1;
}

static int measure(int genus, const double *xy, size_t n, row_t *r) {
  hdt_triangulation *t = NULL;
  if (hdt_create(&t, genus) != HDT_OK) return fail("hdt_create");
  r->one_mean = 0, r->one_max = 0;
  for (size_t i = 0; i < n; ++i) {
    const double t0 = bench_now_ms();
    if (hdt_insert(t, xy[2 * i], xy[2 * i + 1], NULL) != HDT_OK) return fail("hdt_insert");
    const double ms = bench_now_ms() - t0;
    r->one_mean += ms / (double)n;
    if (ms > r->one_max) r->one_max = ms;
  }
  hdt_destroy(t);
  if (hdt_create(&t, genus) != HDT_OK) return fail("hdt_create");
  double t0 = bench_now_ms();
  if (hdt_insert_many(t, xy, n, NULL) != HDT_OK) return fail("hdt_insert_many");
  r->many = bench_now_ms() - t0;
  t0 = bench_now_ms();
  if (hdt_validate(t) != HDT_OK) return fail("hdt_validate");
  r->validate = bench_now_ms() - t0;
  size_t size = 0;
  t0 = bench_now_ms();
  if (hdt_save(t, NULL, 0, &size) != HDT_OK) return fail("hdt_save");
  unsigned char *bytes = malloc(size);
  if (!bytes || hdt_save(t, bytes, size, &size) != HDT_OK) return fail("hdt_save");
  r->save = bench_now_ms() - t0;
  hdt_triangulation *u = NULL;
  t0 = bench_now_ms();
  if (hdt_load(&u, bytes, size) != HDT_OK) return fail("hdt_load");
  r->load = bench_now_ms() - t0;
  free(bytes);
  hdt_destroy(u);
  hdt_destroy(t);
  return 0;
}

static void print_row(const char *kind, int genus, size_t n, const row_t *r) {
  printf("NEAR points=%s g=%d n=%zu insert_mean_ms=%.3f insert_max_ms=%.3f insert_many_ms=%.3f validate_ms=%.3f "
         "save_ms=%.3f load_ms=%.3f\n",
         kind, genus, n, r->one_mean, r->one_max, r->many, r->validate, r->save, r->load);
}

static size_t parse_list(char *s, long *out, size_t max) {
  size_t k = 0;
  for (char *p = strtok(s, ","); p && k < max; p = strtok(NULL, ",")) out[k++] = atol(p);
  return k;
}

int main(int argc, char **argv) {
  long genera[16] = {16, 64, 256}, counts[16] = {100, 100, 20};
  size_t ng = 3, nc = 3;
  uint64_t seed = 1;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!strcmp(argv[i], "--genus")) ng = parse_list(argv[i + 1], genera, 16);
    else if (!strcmp(argv[i], "--n")) nc = parse_list(argv[i + 1], counts, 16);
    else if (!strcmp(argv[i], "--seed")) seed = strtoull(argv[i + 1], NULL, 10);
    else {
      fprintf(stderr, "usage: %s [--genus 16,64,256] [--n 100,100,20] [--seed S]\n", argv[0]);
      return 2;
    }
  }
  for (size_t k = 0; k < ng; ++k) {
    const int genus = (int)genera[k];
    const size_t n = (size_t)counts[k < nc ? k : nc - 1];
    hdt_triangulation *warm = NULL; /* the genus's dummy points, built once a process */
    if (hdt_create(&warm, genus) != HDT_OK) return fail("hdt_create");
    hdt_destroy(warm);
    double *near = malloc(2 * n * sizeof *near + 16), *uniform = malloc(2 * n * sizeof *uniform + 16);
    if (!near || !uniform) return 1;
    bench_points_near_circle(n, seed, near);
    bench_points_in_polygon(genus, n, seed, uniform);
    row_t a, b;
    if (measure(genus, uniform, n, &b) || measure(genus, near, n, &a)) return 1;
    print_row("uniform", genus, n, &b);
    print_row("near-circle", genus, n, &a);
    printf("NEAR ratio g=%d n=%zu insert_mean=%.1f insert_max=%.1f insert_many=%.1f validate=%.1f save=%.1f load=%.1f\n",
           genus, n, a.one_mean / b.one_mean, a.one_max / b.one_max, a.many / b.many, a.validate / b.validate,
           a.save / b.save, a.load / b.load);
    fflush(stdout);
    free(near);
    free(uniform);
  }
  return 0;
}
