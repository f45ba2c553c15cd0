/* Points the fuzz targets build: exact disk membership, ulp steps, points on
   the sides of the fundamental polygon F_g. */
#ifndef HDT_FUZZ_POINTS_H
#define HDT_FUZZ_POINTS_H

#include <gmp.h>
#include <math.h>

#include "hdt.h"

#define HDT_FUZZ_PI 3.14159265358979323846

typedef struct point {
  double x, y;
} point;

/* 1 when (x, y) is a finite point of the open unit disk, decided exactly. */
static inline int in_open_disk(double x, double y) {
  if (!isfinite(x) || !isfinite(y)) return 0;
  if (fabs(x) >= 1 || fabs(y) >= 1) return 0;
  mpq_t a, b;
  mpq_inits(a, b, NULL);
  mpq_set_d(a, x);
  mpq_mul(a, a, a);
  mpq_set_d(b, y);
  mpq_mul(b, b, b);
  mpq_add(a, a, b);
  const int inside = mpq_cmp_ui(a, 1, 1) < 0;
  mpq_clears(a, b, NULL);
  return inside;
}

/* x moved by `steps` ulps (toward +inf for steps > 0). */
static inline double ulps(double x, int steps) {
  for (; steps > 0; --steps) x = nextafter(x, INFINITY);
  for (; steps < 0; ++steps) x = nextafter(x, -INFINITY);
  return x;
}

/* A point on side s_k of F_g at parameter u in [0, 1] (ends at v_{k-1}, v_k),
   rounded; 0 when the polygon functions refuse g or k. The side is the arc of
   the circle orthogonal to the unit circle through m_k, centred on the ray of
   m_k. */
static inline int side_point(int g, int k, double u, point *p) {
  double mx, my, ax, ay, bx, by;
  if (hdt_polygon_side_midpoint(g, k, &mx, &my) != HDT_OK || hdt_polygon_vertex(g, k - 1, &ax, &ay) != HDT_OK ||
      hdt_polygon_vertex(g, k, &bx, &by) != HDT_OK)
    return 0;
  const double rm = hypot(mx, my), c = (1 + rm * rm) / (2 * rm), rad = c - rm;
  const double cx = c * mx / rm, cy = c * my / rm;
  const double a0 = atan2(ay - cy, ax - cx), a1 = atan2(by - cy, bx - cx);
  double da = a1 - a0;
  while (da > HDT_FUZZ_PI) da -= 2 * HDT_FUZZ_PI;
  while (da < -HDT_FUZZ_PI) da += 2 * HDT_FUZZ_PI;
  const double a = a0 + u * da;
  p->x = cx + rad * cos(a);
  p->y = cy + rad * sin(a);
  return 1;
}

#endif /* HDT_FUZZ_POINTS_H */
