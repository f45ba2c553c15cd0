/* Points near the unit circle, for the benchmarks: 1 - |z| uniform in
 * [1e-15, 2e-15] and the angle uniform in [0, 2 pi), from a seed (splitmix64
 * of uniform_points.h): the same (n, seed) gives the same points. Their
 * representatives' words are the longest the library meets (issue 33). */
#ifndef HDT_BENCH_NEAR_CIRCLE_POINTS_H
#define HDT_BENCH_NEAR_CIRCLE_POINTS_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "uniform_points.h"

static inline void bench_points_near_circle(size_t n, uint64_t seed, double *xy) {
  bench_rng r = bench_rng_seed(seed);
  for (size_t i = 0; i < n; ++i) {
    const double angle = 2 * M_PI * bench_uniform01(&r);
    const double gap = 1e-15 * (1 + bench_uniform01(&r));
    xy[2 * i] = (1 - gap) * cos(angle), xy[2 * i + 1] = (1 - gap) * sin(angle);
  }
}

#endif
