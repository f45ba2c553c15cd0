/* Points along the curves a user samples on M_g, for the curves benchmark
 * and tests/test_curves.c. Sampling a curve puts many points on one
 * Euclidean line or circle of the disk: exactly cocircular in-circle tests
 * and vertices (the dummies) of very high degree, the worst case of removal.
 *
 * Header-only, C99. The same (shape, n, seed) gives the same points.
 */
#ifndef HDT_BENCH_CURVE_POINTS_H
#define HDT_BENCH_CURVE_POINTS_H

#include "uniform_points.h"

typedef enum curve_shape {
  CURVE_RANDOM,        /* uniform for hyperbolic area in F_g (the reference) */
  CURVE_SEGMENT,       /* the Euclidean segment y = x/4 + 0.1 (a hypercycle) */
  CURVE_CIRCLE,        /* the circle |z| = 1/2 about 0 */
  CURVE_GEODESIC,      /* a geodesic not through 0: |z - 5/4| = 3/4 */
  CURVE_HOROCYCLE,     /* the horocycle |z - 0.6| = 0.4, tangent at 1 */
  CURVE_HYPERCYCLE,    /* |z - 1/2|^2 = 0.45, through the geodesic's ends */
  CURVE_AXIS_SIDES,    /* the polygon's axis through m_0 and m_2g: y = 0 */
  CURVE_AXIS_VERTICES, /* the polygon's axis through v_0: angle pi/4g */
  CURVE_SHAPES
} curve_shape;

static const char *const curve_shape_names[CURVE_SHAPES] = {
    "random", "segment", "circle", "geodesic", "horocycle", "hypercycle", "axis-sides", "axis-vertices"};

/* n points of the shape (random order along the curve) into xy. */
static inline void curve_points(curve_shape shape, int g, size_t n, uint64_t seed, double *xy) {
  if (shape == CURVE_RANDOM) {
    bench_points_in_polygon(g, n, seed, xy);
    return;
  }
  bench_rng r = bench_rng_seed(seed);
  for (size_t i = 0; i < n; ++i) {
    const double u = bench_uniform01(&r), s = 2 * u - 1;
    double x = 0, y = 0, a;
    switch (shape) {
      case CURVE_SEGMENT: x = 0.8 * s, y = x / 4 + 0.1; break;
      case CURVE_CIRCLE: a = 2 * M_PI * u, x = 0.5 * cos(a), y = 0.5 * sin(a); break;
      case CURVE_GEODESIC: a = M_PI + 0.92 * s, x = 1.25 + 0.75 * cos(a), y = 0.75 * sin(a); break;
      case CURVE_HOROCYCLE: a = 0.05 + (2 * M_PI - 0.1) * u, x = 0.6 + 0.4 * cos(a), y = 0.4 * sin(a); break;
      case CURVE_HYPERCYCLE:
        a = M_PI + 2.0 * s, x = 0.5 + sqrt(0.45) * cos(a), y = sqrt(0.45) * sin(a);
        break;
      case CURVE_AXIS_SIDES: x = 0.95 * s; break;
      case CURVE_AXIS_VERTICES: a = M_PI / (4 * g), x = 0.95 * s * cos(a), y = 0.95 * s * sin(a); break;
      default: break;
    }
    xy[2 * i] = x, xy[2 * i + 1] = y;
  }
}

#endif
