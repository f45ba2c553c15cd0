/* Shared point generator of the benchmarks: the same (genus, n, seed) gives
 * the same points, bit for bit, in every program (C and C++; libhdt and the
 * CGAL peers), so the triangulations can be compared vertex by vertex.
 *
 * Header-only, static functions, C99 and C++. Only IEEE double arithmetic
 * and libm's tanh, acosh, cos, sin, tan, sqrt: the same on both sides since
 * both link the same libm.
 */
#ifndef HDT_BENCH_UNIFORM_POINTS_H
#define HDT_BENCH_UNIFORM_POINTS_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* splitmix64 (Steele, Lea, Flood 2014). */
typedef struct bench_rng {
  uint64_t state;
} bench_rng;

static inline bench_rng bench_rng_seed(uint64_t seed) {
  bench_rng r;
  r.state = seed;
  return r;
}

static inline uint64_t bench_rng_next(bench_rng *r) {
  uint64_t z = (r->state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/* Uniform in [0, 1), 53 random bits. */
static inline double bench_uniform01(bench_rng *r) { return (double)(bench_rng_next(r) >> 11) * 0x1p-53; }

/* n points uniform for hyperbolic area in the fundamental 4g-gon F_g (its
   vertex v_k at angle (2k+1) pi / 4g, the midpoint of side s_k at angle
   k pi / 2g; for g = 2 the same octagon as CGAL's Bolza domain): uniform in
   the hyperbolic disk of F_g's circumradius R (cosh r uniform in
   [1, cosh R]), kept when every side's line leaves them on the side of 0.
   The double test keeps a margin of 1e-9 (relative, in the hyperboloid
   coordinates) from every side, so that no point lies on or within rounding
   of the boundary of F_g: every point is then strictly inside F_g for any
   exact test too (CGAL's Bolza triangulation requires its points in its
   half-open octagon). xy receives x0, y0, x1, y1, ... */
static inline void bench_points_in_polygon(int g, size_t n, uint64_t seed, double *xy) {
  bench_rng r = bench_rng_seed(seed);
  const double A = 1.0 / tan(M_PI / (4.0 * g));
  const double cosh_R = A * A, cosh_l = 2 * A * A - 1, sinh_l = sqrt(cosh_l * cosh_l - 1);
  /* The sides' directions, once: 4g sines and cosines per sample made the
     points cost more than their triangulation from genus 32 on. */
  /* Cast for the C++ programs that include this header too. */
  double *cos_th = (double *)malloc(4 * (size_t)g * sizeof *cos_th);
  double *sin_th = (double *)malloc(4 * (size_t)g * sizeof *sin_th);
  if (!cos_th || !sin_th) abort();
  for (int k = 0; k < 4 * g; ++k) {
    const double th = k * M_PI / (2.0 * g);
    cos_th[k] = cos(th), sin_th[k] = sin(th);
  }
  for (size_t i = 0; i < n;) {
    const double c = 1 + (cosh_R - 1) * bench_uniform01(&r), a = 2 * M_PI * bench_uniform01(&r);
    const double rho = tanh(acosh(c) / 2), x = rho * cos(a), y = rho * sin(a);
    const double w = 1 - x * x - y * y, t = (1 + x * x + y * y) / w, u = 2 * x / w, v = 2 * y / w;
    int inside = rho < 1.0;
    /* Only the side nearest in direction and its two neighbours can reject
       P: s below is cosh r (1 - cosh l) + sinh l sinh r cos(th - a), which
       vanishes on the circumcircle (r = R) at |th - a| = pi/4g, and the
       other sides, at |th - a| >= 3 pi/4g, leave it below -1e-6 t cosh l
       (genus <= 1024), far beyond the margin and rounding: the same points
       as testing all 4g sides. */
    const int n_sides = 4 * g, nearest = (int)lround(a / (M_PI / (2.0 * g)));
    for (int d = -1; d <= 1 && inside; ++d) {
      const int k = ((nearest + d) % n_sides + n_sides) % n_sides;
      /* <P, O> - <P, g_k O> with g_k O = (cosh l, sinh l cos th, sinh l sin th),
         th = k pi / 2g: negative when P is nearer to O than to its image
         across side s_k. */
      const double s = t - (t * cosh_l - u * sinh_l * cos_th[k] - v * sinh_l * sin_th[k]);
      if (s > -1e-9 * t * cosh_l) inside = 0;
    }
    if (inside) xy[2 * i] = x, xy[2 * i + 1] = y, ++i;
  }
  free(cos_th);
  free(sin_th);
}

/* n points uniform in the unit square [0, 1)^2 (the Euclidean reference). */
static inline void bench_points_in_square(size_t n, uint64_t seed, double *xy) {
  bench_rng r = bench_rng_seed(seed);
  for (size_t i = 0; i < 2 * n; ++i) xy[i] = bench_uniform01(&r);
}

#endif
