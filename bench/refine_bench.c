/* Refinement and epsilon-nets from the dummy set alone (docs/refinement.md
 * quotes it): one line per run, the genus, the bounds, the vertices and
 * faces of the result, the points added, the wall and CPU times (on a
 * shared machine the CPU time varies less), and the result's
 * quality (hdt_quality).
 *
 *   refine_bench [--genus 2] [--radius R] [--ratio B] [--epsilon E]
 *
 * Without --radius or --epsilon: epsilon-nets for eps = 0.1, 0.05, 0.02,
 * 0.01 at the genus given. */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_common.h"
#include "hdt.h"

static void check(hdt_status s, const char *what) {
  if (s != HDT_OK) {
    fprintf(stderr, "%s: %s: %s\n", what, hdt_status_string(s), hdt_last_error_message());
    exit(1);
  }
}

/* radius finite and ratio INFINITY with net set: hdt_epsilon_net. */
static void run(int g, double radius, double ratio, int net) {
  hdt_triangulation *t;
  check(hdt_create(&t, g), "hdt_create");
  size_t added, unmet;
  const double t0 = bench_now_ms(), c0 = bench_cpu_ms();
  if (net)
    check(hdt_epsilon_net(t, radius, SIZE_MAX, &added, &unmet), "hdt_epsilon_net");
  else
    check(hdt_refine(t, radius, ratio, SIZE_MAX, &added, &unmet), "hdt_refine");
  const double ms = bench_now_ms() - t0, cpu = bench_cpu_ms() - c0;
  double angle, max_ratio, max_radius, min_edge;
  check(hdt_quality(t, &angle, &max_ratio, &max_radius, &min_edge), "hdt_quality");
  printf("%s g=%d radius=%g ratio=%g V=%zu F=%zu added=%zu unmet=%zu ms=%.1f cpu_ms=%.1f min_angle_deg=%.2f max_ratio=%.4f "
         "max_radius=%.6f min_edge=%.6f\n",
         net ? "epsilon_net" : "refine", g, radius, ratio, hdt_vertex_count(t), hdt_face_count(t), added, unmet, ms, cpu,
         angle * 180 / 3.14159265358979323846, max_ratio, max_radius, min_edge);
  hdt_destroy(t);
}

int main(int argc, char **argv) {
  int g = 2;
  double radius = 0, ratio = INFINITY, eps = 0;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (strcmp(argv[i], "--genus") == 0) g = atoi(argv[i + 1]);
    else if (strcmp(argv[i], "--radius") == 0) radius = atof(argv[i + 1]);
    else if (strcmp(argv[i], "--ratio") == 0) ratio = atof(argv[i + 1]);
    else if (strcmp(argv[i], "--epsilon") == 0) eps = atof(argv[i + 1]);
    else {
      fprintf(stderr, "usage: refine_bench [--genus G] [--radius R] [--ratio B] [--epsilon E]\n");
      return 2;
    }
  }
  if (radius > 0) run(g, radius, ratio, 0);
  else if (eps > 0) run(g, eps, INFINITY, 1);
  else {
    const double table[] = {0.1, 0.05, 0.02, 0.01};
    for (int k = 0; k < 4; ++k) run(g, table[k], INFINITY, 1);
  }
  return 0;
}
