/* hdt-triangulate: random points uniform for hyperbolic area in F_g.
 *
 * F_g lies in the disk of hyperbolic radius R about 0, cosh R = cot^2(pi/4g)
 * (its vertices are at distance R). On that disk the area element is
 * sinh r dr dtheta, so cosh r uniform in [1, cosh R] and theta uniform in
 * [0, 2 pi) give the uniform distribution; a candidate is kept when it lies
 * in the half-open F_g, i.e. when its canonical representative is itself
 * (hdt_point_representative gives the empty word). The Poincare radius is
 * tanh(r/2) = sqrt((cosh r - 1) / (cosh r + 1)).
 *
 * Most rejected candidates lie far beyond a side, and the library call is
 * not free, so a double-precision test rejects those first: side s_k lies on
 * the circle of centre c_k = |c| e^{ik pi/2g}, |c| = (mu + 1/mu)/2 with mu the
 * midpoints' Euclidean radius, orthogonal to the unit circle, and z is beyond
 * it when its power |z - c_k|^2 - (|c|^2 - 1) = 1 + |z|^2 - 2 c_k.z is
 * negative. Only the side nearest in angle is tried (a candidate outside F_g
 * is mostly beyond that one); this is a filter, never the decision: every
 * candidate it lets through is decided by the library, exactly.
 */
#define _POSIX_C_SOURCE 200809L

#include "random_points.h"

#include "cli_util.h"

#include <hdt.h>

#include <math.h>

typedef struct {
  uint64_t state;
} splitmix64;

static uint64_t next_u64(splitmix64 *r) {
  uint64_t z = (r->state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/* Uniform in [0, 1), 53 random bits. */
static double next_uniform(splitmix64 *r) { return (double)(next_u64(r) >> 11) * 0x1.0p-53; }

/* A candidate uniform for hyperbolic area in the disk about 0 of
   hyperbolic radius R (cosh R given): cosh r uniform in [1, cosh R], the
   angle uniform; its Poincare radius and angle into *rho and *theta. */
static void draw_candidate(splitmix64 *rng, double cosh_R, double *x, double *y, double *rho, double *theta) {
  const double pi = acos(-1.0);
  const double ch = 1.0 + next_uniform(rng) * (cosh_R - 1.0);
  *rho = sqrt((ch - 1.0) / (ch + 1.0));
  *theta = 2.0 * pi * next_uniform(rng);
  *x = *rho * cos(*theta), *y = *rho * sin(*theta);
}

int random_points(int genus, uint64_t seed, size_t n, double *xy, size_t *tried) {
  const double pi = acos(-1.0);
  const double cot = 1.0 / tan(pi / (4.0 * genus));
  const double cosh_R = cot * cot;
  double mx, my;
  if (!cli_check(hdt_polygon_side_midpoint(genus, 0, &mx, &my), "hdt_polygon_side_midpoint")) return 0;
  const double mu = hypot(mx, my), c = (mu + 1.0 / mu) / 2.0, step = pi / (2.0 * genus);
  splitmix64 rng = {seed};
  size_t kept = 0, drawn = 0;
  while (kept < n) {
    double x, y, rho, theta;
    draw_candidate(&rng, cosh_R, &x, &y, &rho, &theta);
    ++drawn;
    const double side_angle = step * floor(theta / step + 0.5);
    if (1.0 + rho * rho - 2.0 * c * rho * cos(theta - side_angle) < -1e-9) continue; /* clearly outside */
    size_t length = 0;
    if (!cli_check(hdt_point_representative(genus, x, y, NULL, NULL, NULL, 0, &length),
                   "hdt_point_representative"))
      return 0;
    if (length != 0) continue; /* outside the half-open F_g */
    xy[2 * kept] = x;
    xy[2 * kept + 1] = y;
    ++kept;
  }
  if (tried) *tried = drawn;
  return 1;
}

/* The polygon is convex and the disk about 0 through its farthest vertex is
   a convex hyperbolic disk, so it holds the polygon; its hyperbolic radius R
   has cosh R = (1 + rho^2) / (1 - rho^2), rho that vertex's radius. */
int random_surface_points(const hdt_surface *s, uint64_t seed, size_t n, double *xy, size_t *tried) {
  double rho2 = 0;
  for (int k = 0; k < hdt_surface_side_count(s); ++k) {
    double x, y;
    if (!cli_check(hdt_surface_vertex(s, k, &x, &y), "hdt_surface_vertex")) return 0;
    rho2 = fmax(rho2, x * x + y * y);
  }
  const double cosh_R = (1 + rho2) / (1 - rho2);
  splitmix64 rng = {seed};
  size_t kept = 0, drawn = 0;
  while (kept < n) {
    double x, y, rho, theta;
    draw_candidate(&rng, cosh_R, &x, &y, &rho, &theta);
    ++drawn;
    size_t length = 0;
    if (!cli_check(hdt_surface_representative(s, x, y, NULL, NULL, NULL, 0, &length), "hdt_surface_representative"))
      return 0;
    if (length != 0) continue; /* outside the half-open fundamental set */
    xy[2 * kept] = x;
    xy[2 * kept + 1] = y;
    ++kept;
  }
  if (tried) *tried = drawn;
  return 1;
}
