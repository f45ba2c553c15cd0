/* Triangulations through the public header: random and degenerate input,
 * bad input, dummy removal, vertex removal, point location and nearest
 * vertex. hdt_validate (exact) is the oracle for the Delaunay property; the
 * tests add the combinatorial facts any caller can see (F = 2 (V + 2g - 2),
 * live ids, canonical corners) and geometric checks in double. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include <ctype.h>
#include <float.h>
#include <limits.h>
#include <time.h>

#include "hdt_test.h"

static const double PI = 3.14159265358979323846;

/* ---- Handles and snapshots ---- */

static void expect_valid(const hdt_triangulation *t, const char *what) {
  const hdt_status s = hdt_validate(t);
  expect(s == HDT_OK, "%s: hdt_validate: %s (%s)", what, hdt_status_string(s), hdt_last_error_message());
}

/* Everything a caller can read about a triangulation, to compare before and
   after a call that must change nothing. */
typedef struct snapshot_t {
  size_t faces, vertices, dummies, bound;
  uint32_t *v;
  int32_t *tr;
} snapshot_t;

static snapshot_t snapshot(const hdt_triangulation *t) {
  const faces_t f = read_faces(t);
  return (snapshot_t){f.n, hdt_vertex_count(t), hdt_dummy_count(t), hdt_vertex_id_bound(t), f.v, f.tr};
}

static void snapshot_free(snapshot_t *s) {
  free(s->v);
  free(s->tr);
}

static void expect_unchanged(const hdt_triangulation *t, const snapshot_t *before, const char *what) {
  snapshot_t now = snapshot(t);
  expect(now.faces == before->faces && now.vertices == before->vertices && now.dummies == before->dummies &&
             now.bound == before->bound,
         "%s changed the triangulation: faces %zu -> %zu, vertices %zu -> %zu, dummies %zu -> %zu, id bound %zu -> %zu",
         what, before->faces, now.faces, before->vertices, now.vertices, before->dummies, now.dummies, before->bound,
         now.bound);
  expect(memcmp(now.v, before->v, 3 * now.faces * sizeof *now.v) == 0, "%s changed the faces' vertices", what);
  expect(memcmp(now.tr, before->tr, 3 * now.faces * sizeof *now.tr) == 0, "%s changed the faces' translations", what);
  snapshot_free(&now);
}

/* The facts hdt_faces shows: F = 2 (V + 2g - 2) faces, three distinct live
   vertices each, the smallest id at translation 0, every live vertex used,
   live ids counted by hdt_vertex_count and hdt_dummy_count. */
static void expect_structure(const hdt_triangulation *t, const char *what) {
  const int g = hdt_genus(t);
  const size_t V = hdt_vertex_count(t), F = hdt_face_count(t), bound = hdt_vertex_id_bound(t);
  expect(F == 2 * (V + 2 * (size_t)g - 2), "%s: %zu faces for %zu vertices (genus %d)", what, F, V, g);
  snapshot_t s = snapshot(t);
  expect(s.faces == F, "%s: hdt_faces lists %zu faces, hdt_face_count says %zu", what, s.faces, F);
  unsigned char *used = calloc(bound + 1, 1);
  ck_assert_ptr_nonnull(used);
  for (size_t f = 0; f < s.faces; ++f) {
    const uint32_t *v = &s.v[3 * f];
    const int32_t *tr = &s.tr[3 * f];
    int smallest = 0;
    for (int i = 0; i < 3; ++i) {
      expect(v[i] < bound && hdt_vertex_is_dummy(t, v[i]) >= 0, "%s: face %zu uses vertex %u, not live", what, f,
             v[i]);
      expect(tr[i] >= 0, "%s: face %zu has translation id %d", what, f, tr[i]);
      used[v[i]] = 1;
      if (v[i] < v[smallest]) smallest = i;
    }
    expect(v[0] != v[1] && v[1] != v[2] && v[0] != v[2], "%s: face %zu has vertices %u %u %u", what, f, v[0], v[1],
           v[2]);
    expect(tr[smallest] == 0, "%s: face %zu (%u %u %u): translation %d at its smallest vertex", what, f, v[0], v[1],
           v[2], tr[smallest]);
  }
  size_t live = 0, dummies = 0;
  for (uint32_t v = 0; v < bound; ++v) {
    const int d = hdt_vertex_is_dummy(t, v);
    if (d < 0) continue;
    expect(d == 0 || d == 1, "%s: hdt_vertex_is_dummy(%u) = %d", what, v, d);
    ++live;
    dummies += (size_t)d;
    expect(used[v], "%s: live vertex %u is in no face", what, v);
  }
  expect(live == V, "%s: %zu live ids below the bound %zu, hdt_vertex_count says %zu", what, live, bound, V);
  expect(dummies == hdt_dummy_count(t), "%s: %zu dummies, hdt_dummy_count says %zu", what, dummies,
         hdt_dummy_count(t));
  expect(hdt_vertex_is_dummy(t, (uint32_t)bound) == -1, "%s: id %zu at the bound is live", what, bound);
  free(used);
  snapshot_free(&s);
}

/* ---- Points ---- */

static double inradius(int g) { /* Euclidean radius of the inscribed circle of F_g */
  double x, y;
  ck_assert_int_eq(hdt_polygon_side_midpoint(g, 0, &x, &y), HDT_OK);
  return hypot(x, y);
}

static double circumradius(int g) { /* Euclidean radius of F_g's vertices */
  double x, y;
  ck_assert_int_eq(hdt_polygon_vertex(g, 0, &x, &y), HDT_OK);
  return hypot(x, y);
}

/* Uniform for hyperbolic area in the hyperbolic disk about 0 of Euclidean
   radius rmax (area grows like cosh d - 1). */
static void hyperbolic_uniform(uint64_t *rng, double rmax, double *x, double *y) {
  const double cosh_max = (1 + rmax * rmax) / (1 - rmax * rmax);
  const double ch = 1 + uniform01(rng) * (cosh_max - 1);
  const double r = sqrt((ch - 1) / (ch + 1));
  const double a = 2 * PI * uniform01(rng);
  *x = r * cos(a), *y = r * sin(a);
}

/* A mix: half uniform in F's inscribed disk (Euclidean), a quarter uniform by
   area in the disk through F's vertices (mostly in F), a quarter anywhere in
   the open disk (mapped to their representatives). */
static void mixed_points(uint64_t *rng, int g, size_t n, double *xy) {
  const double rin = inradius(g), rout = circumradius(g);
  for (size_t i = 0; i < n; ++i) {
    double x, y;
    const int kind = rng_below(rng, 4);
    if (kind <= 1) {
      const double r = rin * sqrt(uniform01(rng)), a = 2 * PI * uniform01(rng);
      x = r * cos(a), y = r * sin(a);
    } else if (kind == 2) {
      hyperbolic_uniform(rng, rout, &x, &y);
    } else {
      const double r = 0.999999 * sqrt(uniform01(rng)), a = 2 * PI * uniform01(rng);
      x = r * cos(a), y = r * sin(a);
    }
    xy[2 * i] = x, xy[2 * i + 1] = y;
  }
}

/* Uniform by hyperbolic area in F_g: kept when their own representative. */
static void points_in_f(uint64_t *rng, int g, size_t n, double *xy) {
  const double rout = circumradius(g);
  for (size_t i = 0; i < n;) {
    double x, y;
    size_t len = 1;
    hyperbolic_uniform(rng, rout, &x, &y);
    if (hdt_point_representative(g, x, y, NULL, NULL, NULL, 0, &len) != HDT_OK || len != 0) continue;
    xy[2 * i] = x, xy[2 * i + 1] = y;
    ++i;
  }
}


/* Inserts one point that must be accepted (new vertex or an existing one). */
static uint32_t insert_ok(hdt_triangulation *t, double x, double y, int *existed) {
  uint32_t v = UINT32_MAX;
  const hdt_status s = hdt_insert(t, x, y, &v);
  expect(s == HDT_OK || s == HDT_EEXISTS, "hdt_insert(%a, %a) [%.17g, %.17g]: %s (%s)", x, y, x, y,
         hdt_status_string(s), hdt_last_error_message());
  expect(hdt_vertex_is_dummy(t, v) >= 0, "hdt_insert(%.17g, %.17g) answered vertex %u, not live", x, y, v);
  if (existed) *existed = s == HDT_EEXISTS;
  return v;
}

/* hdt_insert_many that must succeed; checks vertices[i] against point i. */
static void insert_many_ok(hdt_triangulation *t, const double *xy, size_t n, const char *what) {
  uint32_t *ids = malloc(n * sizeof *ids + 1);
  ck_assert_ptr_nonnull(ids);
  const size_t before = hdt_vertex_count(t);
  const hdt_status s = hdt_insert_many(t, xy, n, ids);
  expect(s == HDT_OK, "%s: hdt_insert_many(%zu points): %s (%s)", what, n, hdt_status_string(s),
         hdt_last_error_message());
  expect(hdt_vertex_count(t) <= before + n, "%s: %zu points added %zu vertices", what, n,
         hdt_vertex_count(t) - before);
  const int g = hdt_genus(t);
  for (size_t i = 0; i < n; ++i) {
    expect(hdt_vertex_is_dummy(t, ids[i]) >= 0, "%s: vertices[%zu] = %u is not live", what, i, ids[i]);
    /* Spot check that vertices[i] is point i's vertex: their representatives
       agree (loosely: the accuracy of hdt_vertex_point has its own test). */
    if (i % 7 != 0) continue;
    double vx, vy, rx, ry;
    size_t len = 0;
    ck_assert_int_eq(hdt_vertex_point(t, ids[i], &vx, &vy), HDT_OK);
    ck_assert_int_eq(hdt_point_representative(g, xy[2 * i], xy[2 * i + 1], &rx, &ry, NULL, 0, &len), HDT_OK);
    expect(hypot(vx - rx, vy - ry) < 1e-9, "%s: point %zu (%.17g, %.17g): representative (%.17g, %.17g), vertex %u at (%.17g, %.17g)",
           what, i, xy[2 * i], xy[2 * i + 1], rx, ry, ids[i], vx, vy);
  }
  free(ids);
}

/* ---- Random input ---- */

typedef struct size_plan {
  int g;
  size_t n;
} size_plan;

/* Sizes chosen so the test runs in well under a minute with the
   debug-optimised build. */
static const size_plan random_plan[] = {{2, 10000}, {3, 10000}, {4, 10000}, {5, 10000},
                                        {6, 10000}, {7, 10000}, {8, 10000}};

START_TEST(random_points) {
  for (size_t p = 0; p < sizeof random_plan / sizeof random_plan[0]; ++p) {
    const int g = random_plan[p].g;
    const size_t n = random_plan[p].n;
    const double t0 = seconds();
    uint64_t rng = 0xC0FFEE + (uint64_t)g;
    double *xy = malloc(2 * n * sizeof *xy);
    ck_assert_ptr_nonnull(xy);
    mixed_points(&rng, g, n, xy);
    hdt_triangulation *t = new_triangulation(g);
    expect_valid(t, "new triangulation");
    expect_structure(t, "new triangulation");
    /* Five batches: four through insert_many (growing), one point by point. */
    const size_t cuts[] = {0, n / 20, n / 5, n / 2, 3 * n / 4, n};
    for (size_t b = 0; b + 1 < sizeof cuts / sizeof cuts[0]; ++b) {
      char what[96];
      snprintf(what, sizeof what, "g=%d, after points %zu..%zu", g, cuts[b], cuts[b + 1]);
      if (b == 2) {
        for (size_t i = cuts[b]; i < cuts[b + 1]; ++i) insert_ok(t, xy[2 * i], xy[2 * i + 1], NULL);
      } else {
        insert_many_ok(t, xy + 2 * cuts[b], cuts[b + 1] - cuts[b], what);
      }
      expect_valid(t, what);
      expect_structure(t, what);
    }
    const size_t d0 = hdt_dummy_count(t);
    printf("random_points g=%d: %zu points, %zu vertices (%zu dummies), %zu faces, %.2f s\n", g, n,
           hdt_vertex_count(t), d0, hdt_face_count(t), seconds() - t0);
    fflush(stdout);
    hdt_destroy(t);
    free(xy);
  }
}
END_TEST

/* hdt_vertex_point gives the representative rounded to double: it agrees
   with hdt_point_representative (rounded from multiprecision) to an ulp or
   two, also for input far out near the unit circle. */
START_TEST(vertex_point_is_the_rounded_representative) {
  uint64_t rng = 0xACC;
  for (int g = 2; g <= 6; ++g) {
    hdt_triangulation *t = new_triangulation(g);
    double worst = 0;
    for (int i = 0; i < 150; ++i) {
      /* 1 - |z| from 0.5 down to 1e-12: representatives need longer words. */
      const double gap = pow(10.0, -0.3 - 11.7 * uniform01(&rng)), a = 2 * PI * uniform01(&rng);
      const double x = (1 - gap) * cos(a), y = (1 - gap) * sin(a);
      const uint32_t v = insert_ok(t, x, y, NULL);
      double vx, vy, rx, ry;
      size_t len = 0;
      ck_assert_int_eq(hdt_vertex_point(t, v, &vx, &vy), HDT_OK);
      ck_assert_int_eq(hdt_point_representative(g, x, y, &rx, &ry, NULL, 0, &len), HDT_OK);
      const double err = hypot(vx - rx, vy - ry);
      worst = fmax(worst, err);
      expect(err <= 1e-15, "g=%d: vertex %u of (%.17g, %.17g) (1 - |z| = %.2g, word of %zu letters): hdt_vertex_point "
             "(%.17g, %.17g), hdt_point_representative (%.17g, %.17g), %.3g apart",
             g, v, x, y, gap, len, vx, vy, rx, ry, err);
    }
    expect_valid(t, "points near the circle");
    hdt_destroy(t);
  }
}
END_TEST

/* ---- Degenerate input ---- */

/* (a) The orbit of (x, y) under z -> -z, i z, conj z: 8 exactly representable
   points on one circle about 0, several radii. */
START_TEST(symmetric_orbits) {
  static const double base[][2] = {{0.25, 0},     {0.125, 0.0625}, {0.25, 0.25},     {0.375, 0.125},
                                   {0.5, 0.25},   {0.0625, 0.5},   {0.3125, 0.3125}, {0.625, 0.3125},
                                   {0.75, 0.125}, {0.1, 0.2},      {0.4, 0.3},       {0, 0}};
  const size_t nb = sizeof base / sizeof base[0];
  for (int g = 2; g <= 4; ++g) {
    hdt_triangulation *all = new_triangulation(g);
    for (size_t b = 0; b < nb; ++b) {
      const double x = base[b][0], y = base[b][1];
      const double orbit[8][2] = {{x, y}, {-x, y}, {x, -y}, {-x, -y}, {y, x}, {-y, x}, {y, -x}, {-y, -x}};
      hdt_triangulation *one = new_triangulation(g);
      for (int i = 0; i < 8; ++i) {
        insert_ok(one, orbit[i][0], orbit[i][1], NULL);
        insert_ok(all, orbit[i][0], orbit[i][1], NULL);
      }
      char what[96];
      snprintf(what, sizeof what, "g=%d, orbit of (%g, %g)", g, x, y);
      expect_valid(one, what);
      expect_structure(one, what);
      expect_valid(all, what);
      hdt_destroy(one);
    }
    expect_structure(all, "all orbits");
    hdt_destroy(all);
  }
}
END_TEST

/* (b) Grids of dyadic points k/32: many cocircular quadruples and whole rows
   on the real and imaginary axes (geodesics). */
START_TEST(dyadic_grids) {
  for (int g = 2; g <= 3; ++g) {
    const int denom = g == 2 ? 32 : 16, K = g == 2 ? 20 : 15;
    size_t n = 0;
    double *xy = malloc(2 * (size_t)(2 * K + 1) * (size_t)(2 * K + 1) * sizeof *xy);
    ck_assert_ptr_nonnull(xy);
    for (int i = -K; i <= K; ++i)
      for (int j = -K; j <= K; ++j) {
        if (i * i + j * j >= denom * denom) continue; /* stay in the open disk */
        xy[2 * n] = (double)i / denom, xy[2 * n + 1] = (double)j / denom;
        ++n;
      }
    char what[64];
    snprintf(what, sizeof what, "g=%d, %zu grid points k/%d", g, n, denom);
    /* All at once, and point by point in row order in another handle. */
    hdt_triangulation *t = new_triangulation(g);
    insert_many_ok(t, xy, n, what);
    expect_valid(t, what);
    expect_structure(t, what);
    hdt_triangulation *u = new_triangulation(g);
    for (size_t i = 0; i < n; ++i) insert_ok(u, xy[2 * i], xy[2 * i + 1], NULL);
    expect_valid(u, what);
    expect_structure(u, what);
    expect(hdt_vertex_count(t) == hdt_vertex_count(u), "%s: %zu vertices by insert_many, %zu one by one", what,
           hdt_vertex_count(t), hdt_vertex_count(u));
    /* A finer grid near 0 on top. */
    for (int i = -8; i <= 8; ++i)
      for (int j = -8; j <= 8; ++j) insert_ok(t, i / 128.0, j / 128.0, NULL);
    expect_valid(t, "finer grid near 0");
    expect_structure(t, "finer grid near 0");
    hdt_destroy(t);
    hdt_destroy(u);
    free(xy);
  }
}
END_TEST

/* Moves x by k ulps (k may be negative). */
static double ulps(double x, int k) {
  for (; k > 0; --k) x = nextafter(x, INFINITY);
  for (; k < 0; ++k) x = nextafter(x, -INFINITY);
  return x;
}

/* (c) The rounded side midpoints and vertices of F_g, their neighbours a few
   ulps away, and their images under the side pairings: points on and next to
   the sides and corners of F_g, where the representative's choice between
   paired sides (and among the 4g corners) is made, and where exact
   predicates see translated copies of nearly the same point. Every vertex
   image lies in the orbit of v_0, so those pile up within rounding of one
   point of M_g where 4g copies of F meet: the slowest case for the exact
   predicates. Up to genus 3 the full set (offsets up to 2 ulps, images of
   1-ulp neighbours under all letters, point by point and at once); above, a
   lighter set at once (1 ulp; a vertex v_k only under the two letters that
   map it to other corners of F, and one more), to bound the time. */
START_TEST(polygon_points) {
  for (int g = 2; g <= 8; ++g) {
    const double t0 = seconds();
    const int n4 = 4 * g, full = g <= 3, reach = full ? 2 : 1, sources = full ? 4 : 1;
    size_t n = 0, cap = (size_t)2 * n4 * (25 + 4 * n4);
    double *xy = malloc(2 * cap * sizeof *xy);
    ck_assert_ptr_nonnull(xy);
    for (int k = 0; k < n4; ++k)
      for (int which = 0; which < 2; ++which) {
        double x, y;
        if (which == 0)
          ck_assert_int_eq(hdt_polygon_side_midpoint(g, k, &x, &y), HDT_OK);
        else
          ck_assert_int_eq(hdt_polygon_vertex(g, k, &x, &y), HDT_OK);
        /* The point and its neighbours up to `reach` ulps in x and y. */
        for (int dx = -reach; dx <= reach; ++dx)
          for (int dy = -reach; dy <= reach; ++dy) {
            xy[2 * n] = ulps(x, dx), xy[2 * n + 1] = ulps(y, dy);
            ++n;
          }
        /* Images under the side pairings, of the point (and 1-ulp neighbours).
           v_k lies on s_k and s_{k+1}, which g_{k+2g} and g_{k+1+2g} map to
           the paired sides. */
        for (int32_t letter = 0; letter < n4; ++letter) {
          if (!full && which == 1 && letter != (k + 2 * g) % n4 && letter != (k + 1 + 2 * g) % n4 && letter != k)
            continue;
          const double src[4][2] = {{x, y}, {ulps(x, 1), y}, {x, ulps(y, -1)}, {ulps(x, -1), ulps(y, 1)}};
          for (int s = 0; s < sources; ++s) {
            double ix, iy;
            ck_assert_int_eq(hdt_word_apply(g, &letter, 1, src[s][0], src[s][1], &ix, &iy), HDT_OK);
            xy[2 * n] = ix, xy[2 * n + 1] = iy;
            ++n;
          }
        }
      }
    ck_assert_uint_le(n, cap);
    char what[64];
    snprintf(what, sizeof what, "g=%d, %zu polygon points", g, n);
    hdt_triangulation *u = new_triangulation(g);
    insert_many_ok(u, xy, n, what);
    expect_valid(u, what);
    expect_structure(u, what);
    if (full) { /* point by point too (EEXISTS is fine for repeats) */
      hdt_triangulation *t = new_triangulation(g);
      for (size_t i = 0; i < n; ++i) insert_ok(t, xy[2 * i], xy[2 * i + 1], NULL);
      expect_valid(t, what);
      expect_structure(t, what);
      expect(hdt_vertex_count(t) == hdt_vertex_count(u), "%s: %zu vertices one by one, %zu by insert_many", what,
             hdt_vertex_count(t), hdt_vertex_count(u));
      hdt_destroy(t);
    }
    printf("polygon_points g=%d: %zu points, %zu vertices, %.2f s\n", g, n, hdt_vertex_count(u), seconds() - t0);
    fflush(stdout);
    hdt_destroy(u);
    free(xy);
  }
}
END_TEST

/* Euclidean distance from (x, y) to the nearest N-image of (px, py): small
   when the two points are close on the surface (a point rounded out of F has
   its representative near another corner or side of F). */
static double gap_on_surface(int g, double x, double y, double px, double py) {
  size_t nn = 0;
  ck_assert_int_eq(hdt_neighbour_count(g, &nn), HDT_OK);
  double best = INFINITY;
  for (size_t id = 0; id < nn; ++id) {
    word_t w = {0};
    double ix, iy;
    ck_assert_int_eq(hdt_neighbour_word(g, id, w.a, TW_MAX, &w.n), HDT_OK);
    apply_word(g, &w, px, py, &ix, &iy);
    best = fmin(best, hypot(ix - x, iy - y));
  }
  return best;
}

/* (d) Re-inserting the dummy points' coordinates. The header: a point equal
   to a dummy turns it into a user vertex (HDT_OK, same id). hdt_vertex_point
   rounds, and a dummy whose coordinates are not doubles (the side midpoints
   and v_0 of Q0 are irrational) comes back as a different point within
   rounding of it: a new vertex, within rounding of an image of the dummy.
   Only those may grow the vertex count. */
START_TEST(dummy_coordinates_reinserted) {
  for (int g = 2; g <= 8; ++g) {
    hdt_triangulation *t = new_triangulation(g);
    const size_t d = hdt_dummy_count(t), V0 = hdt_vertex_count(t);
    expect(d == V0 && d > 0, "g=%d: new triangulation has %zu vertices, %zu dummies", g, V0, d);
    size_t converted = 0, exists = 0, added = 0;
    for (uint32_t v = 0; v < d; ++v) {
      expect(hdt_vertex_is_dummy(t, v) == 1, "g=%d: id %u of a new triangulation is not a dummy", g, v);
      double x, y;
      ck_assert_int_eq(hdt_vertex_point(t, v, &x, &y), HDT_OK);
      uint32_t got = UINT32_MAX;
      const hdt_status s = hdt_insert(t, x, y, &got);
      if (s == HDT_OK && got == v) {
        ++converted;
        expect(hdt_vertex_is_dummy(t, v) == 0, "g=%d: dummy %u re-inserted, still a dummy", g, v);
        /* Now a user vertex: a third insertion reports it. */
        uint32_t again = UINT32_MAX;
        const hdt_status s2 = hdt_insert(t, x, y, &again);
        expect(s2 == HDT_EEXISTS && again == v, "g=%d: converted dummy %u inserted again: %s, vertex %u", g, v,
               hdt_status_string(s2), again);
      } else if (s == HDT_EEXISTS) {
        ++exists;
        expect(got == v, "g=%d: dummy %u re-inserted: HDT_EEXISTS with vertex %u", g, v, got);
      } else {
        expect(s == HDT_OK, "g=%d: dummy %u at (%.17g, %.17g) re-inserted: %s (%s)", g, v, x, y, hdt_status_string(s),
               hdt_last_error_message());
        ++added;
        double nx, ny;
        ck_assert_int_eq(hdt_vertex_point(t, got, &nx, &ny), HDT_OK);
        const double gap = gap_on_surface(g, x, y, nx, ny);
        expect(got >= d && gap < 1e-13 && hdt_vertex_is_dummy(t, v) == 1,
               "g=%d: dummy %u at (%a, %a) re-inserted as new vertex %u at (%a, %a), %g away", g, v, x, y, got, nx, ny,
               gap);
      }
    }
    printf("dummy_coordinates_reinserted g=%d: %zu dummies: %zu became user vertices (HDT_OK), %zu HDT_EEXISTS, "
           "%zu new vertices\n",
           g, d, converted, exists, added);
    fflush(stdout);
    expect_valid(t, "dummies re-inserted");
    expect_structure(t, "dummies re-inserted");
    expect(hdt_vertex_count(t) == V0 + added, "g=%d: re-inserting the %zu dummies' coordinates: %zu vertices, expected %zu",
           g, d, hdt_vertex_count(t), V0 + added);
    expect(hdt_dummy_count(t) == d - converted, "g=%d: %zu dummies left after %zu conversions of %zu", g,
           hdt_dummy_count(t), converted, d);
    hdt_destroy(t);
  }
}
END_TEST

/* (e) The same point twice, (f) two points one ulp apart. */
START_TEST(duplicates_and_close_points) {
  uint64_t rng = 99;
  for (int g = 2; g <= 3; ++g) {
    hdt_triangulation *t = new_triangulation(g);
    const double rin = inradius(g);
    for (int rep = 0; rep < 30; ++rep) {
      const double r = rin * sqrt(uniform01(&rng)), a = 2 * PI * uniform01(&rng);
      const double x = r * cos(a), y = r * sin(a);
      uint32_t first = UINT32_MAX, second = UINT32_MAX;
      hdt_status s = hdt_insert(t, x, y, &first);
      expect(s == HDT_OK, "g=%d: insert (%.17g, %.17g): %s (%s)", g, x, y, hdt_status_string(s),
             hdt_last_error_message());
      const size_t V = hdt_vertex_count(t);
      s = hdt_insert(t, x, y, &second);
      expect(s == HDT_EEXISTS && second == first, "g=%d: second insert of (%.17g, %.17g): %s, vertex %u (first %u)", g,
             x, y, hdt_status_string(s), second, first);
      expect(hdt_vertex_count(t) == V, "g=%d: a repeated point changed the vertex count", g);
      /* NULL vertex is allowed. */
      ck_assert_int_eq(hdt_insert(t, x, y, NULL), HDT_EEXISTS);
      /* One ulp away in x, in y, in both: distinct vertices. */
      const double nx[3] = {nextafter(x, 1), x, nextafter(x, -1)};
      const double ny[3] = {y, nextafter(y, -1), nextafter(y, 1)};
      uint32_t ids[3];
      for (int k = 0; k < 3; ++k) {
        s = hdt_insert(t, nx[k], ny[k], &ids[k]);
        expect(s == HDT_OK, "g=%d: (%a, %a), one ulp from (%a, %a): %s (%s)", g, nx[k], ny[k], x, y,
               hdt_status_string(s), hdt_last_error_message());
        expect(ids[k] != first, "g=%d: one ulp apart, same vertex %u", g, first);
      }
      expect(ids[0] != ids[1] && ids[1] != ids[2] && ids[0] != ids[2], "g=%d: close points share a vertex", g);
      expect(hdt_vertex_count(t) == V + 3, "g=%d: 3 close points added %zu vertices", g, hdt_vertex_count(t) - V);
      if (rep % 10 == 9) {
        expect_valid(t, "duplicates and ulp neighbours");
        expect_structure(t, "duplicates and ulp neighbours");
      }
    }
    /* insert_many: repeats inside one call and of existing points share ids. */
    const double xy[] = {0.1, 0.2, 0.3, -0.1, 0.1, 0.2, -0.25, 0.125, 0.3, -0.1, 0.1, 0.2};
    uint32_t ids[6];
    const size_t V = hdt_vertex_count(t);
    ck_assert_int_eq(hdt_insert_many(t, xy, 6, ids), HDT_OK);
    expect(ids[0] == ids[2] && ids[0] == ids[5] && ids[1] == ids[4], "g=%d: repeats in insert_many got ids %u %u %u / %u %u", g,
           ids[0], ids[2], ids[5], ids[1], ids[4]);
    expect(ids[0] != ids[1] && ids[1] != ids[3] && ids[0] != ids[3], "g=%d: distinct points share ids", g);
    ck_assert_uint_eq(hdt_vertex_count(t), V + 3);
    uint32_t again[6];
    ck_assert_int_eq(hdt_insert_many(t, xy, 6, again), HDT_OK);
    expect(memcmp(ids, again, sizeof ids) == 0, "g=%d: insert_many of present points gave other ids", g);
    ck_assert_uint_eq(hdt_vertex_count(t), V + 3);
    /* Ids are dense: the next new point takes the bound. */
    const size_t bound = hdt_vertex_id_bound(t);
    uint32_t fresh = 0;
    ck_assert_int_eq(hdt_insert(t, -0.123, 0.0456, &fresh), HDT_OK);
    ck_assert_uint_eq(fresh, bound);
    expect_valid(t, "after insert_many repeats");
    expect_structure(t, "after insert_many repeats");
    hdt_destroy(t);
  }
}
END_TEST

/* (g) Points very close to the unit circle, in several directions. */
START_TEST(points_near_the_circle) {
  const double gaps[] = {1e-12, 1e-15};
  for (int g = 2; g <= 4; ++g) {
    hdt_triangulation *t = new_triangulation(g);
    size_t inserted = 0, outside = 0;
    for (size_t gi = 0; gi < 2; ++gi)
      for (int k = 0; k < 24; ++k) {
        const double r = 1 - gaps[gi], a = 2 * PI * k / 24 + 0.01 * gi;
        double x = r * cos(a), y = r * sin(a);
        if (k == 0) x = r, y = 0; /* exactly on the axes too */
        if (k == 6) x = 0, y = -r;
        /* Multiples of 2^-60, so that exact_norm_vs_one decides. */
        x = ldexp(round(ldexp(x, 60)), -60), y = ldexp(round(ldexp(y, 60)), -60);
        const int cmp = exact_norm_vs_one(x, y);
        ck_assert_int_ne(cmp, 2);
        uint32_t v = UINT32_MAX;
        const hdt_status s = hdt_insert(t, x, y, &v);
        if (cmp < 0) {
          expect(s == HDT_OK, "g=%d: (%.17g, %.17g), 1 - |z| ~ %g: %s (%s)", g, x, y, gaps[gi], hdt_status_string(s),
                 hdt_last_error_message());
          ++inserted;
        } else {
          expect(s == HDT_EDOMAIN, "g=%d: (%.17g, %.17g) is not inside the disk, got %s", g, x, y,
                 hdt_status_string(s));
          ++outside;
        }
      }
    expect(inserted + outside == 48 && inserted >= 40, "g=%d: only %zu of 48 points fell inside the disk", g, inserted);
    expect_valid(t, "points near the circle");
    expect_structure(t, "points near the circle");
    hdt_destroy(t);
  }
}
END_TEST

/* (h) Extreme coordinates: subnormal and tiny ones beside the origin (their
 * squares underflow), and clusters of points a few ulps apart near the
 * circle, where the translated copies nearly coincide. The first two
 * sequences are the fuzzer's findings (tests/fuzz/crashes/): an in_circle
 * filter decided on an underflowed determinant, and hdt_validate summed
 * angles in double around vertices 4 ulps apart. */
START_TEST(extreme_coordinates) {
  {
    hdt_triangulation *t = new_triangulation(5);
    ck_assert_int_eq(hdt_insert(t, 0, 0, NULL), HDT_OK);
    ck_assert_int_eq(hdt_insert(t, 0x0.0000000000003p-1022, -0x0.0000000000004p-1022, NULL), HDT_OK);
    expect_valid(t, "g=5: the origin and a subnormal point");
    hdt_destroy(t);
  }
  {
    hdt_triangulation *t = new_triangulation(2);
    const double xy[][2] = {{0x1.fffffff768fa1p-2, 0},
                            {0x1.ff7ced916872bp-1, 0},
                            {0x1.d8f84e5e8a648p-2, 0x1.8823d20068ea9p-3},
                            {0x1.ff7ced9168727p-1, 0}};
    for (int i = 0; i < 4; ++i) ck_assert_int_eq(hdt_insert(t, xy[i][0], xy[i][1], NULL), HDT_OK);
    expect_valid(t, "g=2: two points 4 ulps apart at |z| = 0.999");
    hdt_destroy(t);
  }
  {
    /* Within 1e-16 of the circle: the double image that orders
     * hdt_insert_many's points was 0/0 (NaN) here, converted to an integer
     * (undefined; the sanitizer build catches it). Fuzzer finding. */
    hdt_triangulation *t = new_triangulation(2);
    const double xy[2] = {0x1.69d491f1dfa19p-1, 0x1.6a3f33041e288p-1};
    ck_assert_int_eq(hdt_insert_many(t, xy, 1, NULL), HDT_OK);
    expect_valid(t, "g=2: insert_many of a point 1e-16 from the circle");
    hdt_destroy(t);
  }
  const double tiny[] = {0x1p-1074, 0x3p-1074, 0x1p-1030, 0x1p-1022, 0x1p-700, 0x1p-511, 0x1p-300};
  for (int g = 2; g <= 4; ++g) {
    hdt_triangulation *t = new_triangulation(g);
    char what[96];
    ck_assert_int_eq(hdt_insert(t, 0, 0, NULL), HDT_OK);
    for (size_t i = 0; i < sizeof tiny / sizeof tiny[0]; ++i)
      for (int k = 0; k < 4; ++k) {
        const double x = (k & 1) ? -tiny[i] : tiny[i], y = (k & 2) ? tiny[i] / 2 : -tiny[i] * 3;
        const hdt_status s = hdt_insert(t, x, y, NULL);
        expect(s == HDT_OK, "g=%d: insert (%a, %a): %s (%s)", g, x, y, hdt_status_string(s), hdt_last_error_message());
      }
    /* Clusters a few ulps apart at 1 - |z| = 2^-10 and 2^-30, on an axis and
     * on a diagonal. */
    const double radius[] = {1 - 0x1p-10, 1 - 0x1p-30};
    for (int r = 0; r < 2; ++r)
      for (int d = 0; d < 2; ++d) {
        double x = d ? radius[r] * sqrt(0.5) : radius[r], y = d ? x : 0;
        for (int k = 0; k < 4; ++k) {
          const hdt_status s = hdt_insert(t, x, y, NULL);
          expect(s == HDT_OK, "g=%d: insert (%a, %a): %s (%s)", g, x, y, hdt_status_string(s),
                 hdt_last_error_message());
          x = nextafter(nextafter(x, 0), 0);
          if (k == 1) y = nextafter(y, 1);
        }
      }
    snprintf(what, sizeof what, "g=%d, tiny coordinates and ulp clusters near the circle", g);
    expect_valid(t, what);
    expect_structure(t, what);
    hdt_destroy(t);
  }
}
END_TEST

/* ---- Bad input ---- */

/* Case-insensitive: does msg contain one of the '|'-separated keywords? */
static int mentions(const char *msg, const char *keywords) {
  char low[1024];
  size_t i = 0;
  for (; msg[i] && i + 1 < sizeof low; ++i) low[i] = (char)tolower((unsigned char)msg[i]);
  low[i] = '\0';
  char kw[256];
  snprintf(kw, sizeof kw, "%s", keywords);
  for (char *k = strtok(kw, "|"); k; k = strtok(NULL, "|"))
    if (strstr(low, k)) return 1;
  return 0;
}

/* A failed call: its status, a message naming the function and the problem. */
static void expect_error(hdt_status got, hdt_status expected, const char *function, const char *keywords,
                         const char *what) {
  const char *msg = hdt_last_error_message();
  expect(got == expected, "%s (%s): returned %s, expected %s (%s)", function, what, hdt_status_string(got),
         hdt_status_string(expected), msg);
  expect(msg != NULL && msg[0] != '\0', "%s (%s): empty error message", function, what);
  expect(strstr(msg, function) != NULL, "%s (%s): message \"%s\" does not name the function", function, what, msg);
  expect(mentions(msg, keywords), "%s (%s): message \"%s\" names none of \"%s\"", function, what, msg, keywords);
}

/* The bad-input tests each call one kind of bad input on this handle:
   genus 2, 40 mixed points (PRNG seed 5, its state after them left in *rng);
   *before is its snapshot. */
static hdt_triangulation *bad_input_handle(uint64_t *rng, snapshot_t *before) {
  hdt_triangulation *t = new_triangulation(2);
  *rng = 5;
  double good[2 * 40];
  mixed_points(rng, 2, 40, good);
  insert_many_ok(t, good, 40, "setup");
  *before = snapshot(t);
  return t;
}

/* The bad input changed nothing and left the handle valid. */
static void bad_input_done(hdt_triangulation *t, snapshot_t *before, const char *what) {
  expect_unchanged(t, before, what);
  expect_valid(t, what);
  snapshot_free(before);
  hdt_destroy(t);
}

/* Not points of the open disk, and a keyword the message must contain. */
static const struct {
  double x, y;
  const char *kw;
} bad_points[] = {{NAN, 0, "nan|finite"},        {0.1, -NAN, "nan|finite"},       {INFINITY, 0, "inf|finite"},
                  {0.2, -INFINITY, "inf|finite"}, {-INFINITY, INFINITY, "inf|finite"}, {1, 0, "disk|unit|circle"},
                  {0, -1, "disk|unit|circle"},     {0.6, 0.8, "disk|unit|circle"},      {-0.8, 0.6, "disk|unit|circle"},
                  {2, 3, "disk|unit|circle"},      {DBL_MAX, 0, "disk|unit|circle"}};
static const size_t n_bad_points = sizeof bad_points / sizeof bad_points[0];

/* hdt_insert of NaN, an infinity or a point on or outside the unit circle:
   HDT_EDOMAIN, the vertex not written. */
START_TEST(bad_input_insert_point) {
  uint64_t rng;
  snapshot_t before;
  hdt_triangulation *t = bad_input_handle(&rng, &before);
  for (size_t i = 0; i < n_bad_points; ++i) {
    char what[96];
    snprintf(what, sizeof what, "point (%g, %g)", bad_points[i].x, bad_points[i].y);
    uint32_t v = 4242;
    expect_error(hdt_insert(t, bad_points[i].x, bad_points[i].y, &v), HDT_EDOMAIN, "hdt_insert", bad_points[i].kw,
                 what);
    expect(v == 4242, "hdt_insert wrote the vertex on failure");
    expect_unchanged(t, &before, what);
  }
  bad_input_done(t, &before, "hdt_insert of bad points");
}
END_TEST

/* hdt_insert_many with one bad point among 19 good ones: the whole call is
   rejected with HDT_EDOMAIN, the message names the index, no id written. */
START_TEST(bad_input_insert_many_point) {
  uint64_t rng;
  snapshot_t before;
  hdt_triangulation *t = bad_input_handle(&rng, &before);
  for (size_t i = 0; i < n_bad_points; ++i) {
    double xy[2 * 20];
    mixed_points(&rng, 2, 20, xy);
    const size_t at = (size_t)rng_below(&rng, 20);
    xy[2 * at] = bad_points[i].x, xy[2 * at + 1] = bad_points[i].y;
    uint32_t ids[20];
    for (int k = 0; k < 20; ++k) ids[k] = 4242;
    char what[96], index[32];
    snprintf(what, sizeof what, "point (%g, %g) at index %zu of 20", bad_points[i].x, bad_points[i].y, at);
    snprintf(index, sizeof index, "%zu", at);
    expect_error(hdt_insert_many(t, xy, 20, ids), HDT_EDOMAIN, "hdt_insert_many", bad_points[i].kw, what);
    expect(strstr(hdt_last_error_message(), index) != NULL, "hdt_insert_many: message \"%s\" does not name index %zu",
           hdt_last_error_message(), at);
    for (int k = 0; k < 20; ++k) expect(ids[k] == 4242, "hdt_insert_many wrote vertices[%d] on failure", k);
    expect_unchanged(t, &before, what);
  }
  bad_input_done(t, &before, "hdt_insert_many with a bad point");
}
END_TEST

/* A NULL handle: HDT_EINVAL from every function with a status, naming the
   handle, and no output written. */
START_TEST(bad_input_null_handle_status) {
  uint64_t rng;
  snapshot_t before;
  hdt_triangulation *t = bad_input_handle(&rng, &before);
  double x = 7, y = 7, m[4];
  uint32_t v = 4242, fv[3];
  size_t count = 4242, face = 4242;
  int32_t tr = 4242, word[8];
  const double xy2[4] = {0.1, 0.1, 0.2, 0.2};
  expect_error(hdt_insert(NULL, 0.1, 0.1, &v), HDT_EINVAL, "hdt_insert", "null|handle", "NULL handle");
  expect_error(hdt_insert_many(NULL, xy2, 2, NULL), HDT_EINVAL, "hdt_insert_many", "null|handle", "NULL handle");
  expect_error(hdt_remove_vertex(NULL, 0), HDT_EINVAL, "hdt_remove_vertex", "null|handle", "NULL handle");
  expect_error(hdt_remove_dummies(NULL, &count), HDT_EINVAL, "hdt_remove_dummies", "null|handle", "NULL handle");
  expect_error(hdt_vertex_point(NULL, 0, &x, &y), HDT_EINVAL, "hdt_vertex_point", "null|handle", "NULL handle");
  expect_error(hdt_faces(NULL, fv, NULL, 1, &count), HDT_EINVAL, "hdt_faces", "null|handle", "NULL handle");
  expect_error(hdt_translation_word(NULL, 0, word, 8, &count), HDT_EINVAL, "hdt_translation_word", "null|handle",
               "NULL handle");
  expect_error(hdt_translation_matrix(NULL, 0, m), HDT_EINVAL, "hdt_translation_matrix", "null|handle", "NULL handle");
  expect_error(hdt_locate(NULL, 0.1, 0.1, &face, &tr), HDT_EINVAL, "hdt_locate", "null|handle", "NULL handle");
  expect_error(hdt_nearest_vertex(NULL, 0.1, 0.1, &v), HDT_EINVAL, "hdt_nearest_vertex", "null|handle", "NULL handle");
  expect_error(hdt_validate(NULL), HDT_EINVAL, "hdt_validate", "null|handle", "NULL handle");
  expect(x == 7 && y == 7 && v == 4242 && count == 4242 && face == 4242 && tr == 4242, "a NULL-handle call wrote outputs");
  bad_input_done(t, &before, "NULL-handle calls");
}
END_TEST

/* A NULL handle: the functions without a status give neutral answers, and
   hdt_destroy(NULL) does nothing. */
START_TEST(bad_input_null_handle_answers) {
  uint64_t rng;
  snapshot_t before;
  hdt_triangulation *t = bad_input_handle(&rng, &before);
  ck_assert_int_eq(hdt_genus(NULL), 0);
  ck_assert_uint_eq(hdt_vertex_count(NULL), 0);
  ck_assert_uint_eq(hdt_dummy_count(NULL), 0);
  ck_assert_uint_eq(hdt_vertex_id_bound(NULL), 0);
  ck_assert_uint_eq(hdt_face_count(NULL), 0);
  ck_assert_int_eq(hdt_vertex_is_dummy(NULL, 0), -1);
  hdt_destroy(NULL);
  bad_input_done(t, &before, "NULL-handle queries");
}
END_TEST

/* NULL output pointers (and a NULL xy): HDT_EINVAL naming them. */
START_TEST(bad_input_null_outputs) {
  uint64_t rng;
  snapshot_t before;
  hdt_triangulation *t = bad_input_handle(&rng, &before);
  double x = 7, y = 7;
  uint32_t fv[3];
  expect_error(hdt_vertex_point(t, 0, NULL, &y), HDT_EINVAL, "hdt_vertex_point", "null", "x NULL");
  expect_error(hdt_vertex_point(t, 0, &x, NULL), HDT_EINVAL, "hdt_vertex_point", "null", "y NULL");
  expect_error(hdt_faces(t, fv, NULL, 1, NULL), HDT_EINVAL, "hdt_faces", "null", "count NULL");
  expect_error(hdt_translation_matrix(t, 0, NULL), HDT_EINVAL, "hdt_translation_matrix", "null", "m NULL");
  expect_error(hdt_insert_many(t, NULL, 3, NULL), HDT_EINVAL, "hdt_insert_many", "null", "xy NULL");
  bad_input_done(t, &before, "NULL outputs");
}
END_TEST

/* hdt_create(&u, genus) fails with `expected`, naming the genus, and sets
   *out to NULL. */
static void expect_create_refused(int genus, hdt_status expected) {
  static char sentinel;
  hdt_triangulation *u = (hdt_triangulation *)&sentinel; /* any non-NULL value */
  char what[32];
  snprintf(what, sizeof what, "genus %d", genus);
  expect_error(hdt_create(&u, genus), expected, "hdt_create", "genus", what);
  expect(u == NULL, "hdt_create(genus %d) failed without setting *out to NULL", genus);
}

/* hdt_create with a NULL out, or a genus below 2: HDT_EINVAL; above
   HDT_GENUS_MAX: HDT_ENOTSUP. Other handles are untouched. */
START_TEST(bad_input_create) {
  uint64_t rng;
  snapshot_t before;
  hdt_triangulation *t = bad_input_handle(&rng, &before);
  expect_error(hdt_create(NULL, 2), HDT_EINVAL, "hdt_create", "null|out", "out NULL");
  const int small[] = {1, 0, -5, INT_MIN};
  for (size_t i = 0; i < sizeof small / sizeof small[0]; ++i) expect_create_refused(small[i], HDT_EINVAL);
  const int large[] = {HDT_GENUS_MAX + 1, INT_MAX};
  for (size_t i = 0; i < sizeof large / sizeof large[0]; ++i) expect_create_refused(large[i], HDT_ENOTSUP);
  bad_input_done(t, &before, "hdt_create with bad arguments");
}
END_TEST

/* hdt_faces with too small a buffer: HDT_EBUFS, the count reported, the
   buffers not written. */
START_TEST(bad_input_faces_small_buffer) {
  uint64_t rng;
  snapshot_t before;
  hdt_triangulation *t = bad_input_handle(&rng, &before);
  const size_t F = before.faces;
  uint32_t *vb = malloc(3 * F * sizeof *vb);
  int32_t *tb = malloc(3 * F * sizeof *tb);
  ck_assert(vb && tb);
  const size_t caps[] = {1, F / 2, F - 1};
  for (size_t c = 0; c < 3; ++c) {
    for (size_t i = 0; i < 3 * F; ++i) vb[i] = 0xAAAAAAAAu, tb[i] = -5;
    size_t count = 4242;
    expect_error(hdt_faces(t, vb, tb, caps[c], &count), HDT_EBUFS, "hdt_faces", "capacity|buffer|small", "small buffer");
    expect(count == F, "hdt_faces with capacity %zu: count %zu, expected %zu", caps[c], count, F);
    for (size_t i = 0; i < 3 * F; ++i)
      expect(vb[i] == 0xAAAAAAAAu && tb[i] == -5, "hdt_faces with capacity %zu wrote the buffers", caps[c]);
    expect_unchanged(t, &before, "hdt_faces with a small buffer");
  }
  free(vb);
  free(tb);
  bad_input_done(t, &before, "hdt_faces with a small buffer");
}
END_TEST

/* hdt_faces with capacity 0 asks for the count; the translations may be
   NULL, and the vertices are then those of the full call. */
START_TEST(bad_input_faces_count_only) {
  uint64_t rng;
  snapshot_t before;
  hdt_triangulation *t = bad_input_handle(&rng, &before);
  const size_t F = before.faces;
  uint32_t *vb = malloc(3 * F * sizeof *vb);
  ck_assert_ptr_nonnull(vb);
  size_t count = 4242;
  ck_assert_int_eq(hdt_faces(t, NULL, NULL, 0, &count), HDT_OK);
  ck_assert_uint_eq(count, F);
  ck_assert_int_eq(hdt_faces(t, vb, NULL, F, &count), HDT_OK);
  expect(memcmp(vb, before.v, 3 * F * sizeof *vb) == 0, "hdt_faces without translations lists other vertices");
  free(vb);
  bad_input_done(t, &before, "hdt_faces for the count");
}
END_TEST

/* Vertex ids at the bound, beyond it and UINT32_MAX: HDT_EINVAL from
   hdt_remove_vertex and hdt_vertex_point (point not written), -1 from
   hdt_vertex_is_dummy. */
START_TEST(bad_input_vertex_ids) {
  uint64_t rng;
  snapshot_t before;
  hdt_triangulation *t = bad_input_handle(&rng, &before);
  const uint32_t bound = (uint32_t)hdt_vertex_id_bound(t);
  const uint32_t bad_ids[] = {bound, bound + 5, UINT32_MAX};
  for (size_t i = 0; i < 3; ++i) {
    char what[32];
    snprintf(what, sizeof what, "vertex %u", bad_ids[i]);
    double x = 7, y = 7;
    expect_error(hdt_remove_vertex(t, bad_ids[i]), HDT_EINVAL, "hdt_remove_vertex", "vertex", what);
    expect_unchanged(t, &before, what);
    expect_error(hdt_vertex_point(t, bad_ids[i], &x, &y), HDT_EINVAL, "hdt_vertex_point", "vertex", what);
    expect(x == 7 && y == 7, "hdt_vertex_point wrote the point on failure");
    ck_assert_int_eq(hdt_vertex_is_dummy(t, bad_ids[i]), -1);
  }
  bad_input_done(t, &before, "bad vertex ids");
}
END_TEST

/* Translation ids unknown to the handle: HDT_EINVAL. */
START_TEST(bad_input_translation_ids) {
  uint64_t rng;
  snapshot_t before;
  hdt_triangulation *t = bad_input_handle(&rng, &before);
  int32_t word[8];
  size_t count = 4242;
  double m[4];
  expect_error(hdt_translation_word(t, -1, word, 8, &count), HDT_EINVAL, "hdt_translation_word", "translation|id",
               "id -1");
  expect_error(hdt_translation_matrix(t, INT32_MAX, m), HDT_EINVAL, "hdt_translation_matrix", "translation|id",
               "id INT32_MAX");
  bad_input_done(t, &before, "bad translation ids");
}
END_TEST

/* hdt_locate and hdt_nearest_vertex of a point not in the open disk:
   HDT_EDOMAIN. */
START_TEST(bad_input_query_outside_disk) {
  uint64_t rng;
  snapshot_t before;
  hdt_triangulation *t = bad_input_handle(&rng, &before);
  size_t face = 4242;
  int32_t tr = 4242;
  uint32_t v = 4242;
  expect_error(hdt_locate(t, 1, 0, &face, &tr), HDT_EDOMAIN, "hdt_locate", "disk|unit|circle", "(1, 0)");
  expect_error(hdt_nearest_vertex(t, NAN, 0, &v), HDT_EDOMAIN, "hdt_nearest_vertex", "nan|finite", "NaN");
  bad_input_done(t, &before, "queries outside the disk");
}
END_TEST

/* A removed vertex id stays invalid (HDT_EINVAL, -1 from
   hdt_vertex_is_dummy, nothing changed) and is never reused: the same point
   inserted again gets the next id. */
START_TEST(bad_input_removed_id) {
  uint64_t rng;
  snapshot_t before;
  hdt_triangulation *t = bad_input_handle(&rng, &before);
  snapshot_free(&before);
  uint32_t victim = 0, next = 0;
  double x = 7, y = 7;
  ck_assert_int_eq(hdt_insert(t, 0.05, -0.07, &victim), HDT_OK);
  ck_assert_int_eq(hdt_remove_vertex(t, victim), HDT_OK);
  before = snapshot(t);
  expect_error(hdt_remove_vertex(t, victim), HDT_EINVAL, "hdt_remove_vertex", "vertex", "removed vertex");
  expect_error(hdt_vertex_point(t, victim, &x, &y), HDT_EINVAL, "hdt_vertex_point", "vertex", "removed vertex");
  ck_assert_int_eq(hdt_vertex_is_dummy(t, victim), -1);
  expect_unchanged(t, &before, "removed id");
  ck_assert_int_eq(hdt_insert(t, 0.05, -0.07, &next), HDT_OK);
  expect(next == before.bound, "re-inserting a removed point gave id %u, expected %zu", next, before.bound);
  expect_valid(t, "after bad input");
  snapshot_free(&before);
  hdt_destroy(t);
}
END_TEST

/* ---- Dummy removal ---- */

START_TEST(dummies_go_after_many_points) {
  for (int g = 2; g <= 8; ++g) {
    uint64_t rng = 0xD00D + (uint64_t)g;
    double *xy = malloc(2 * 1000 * sizeof *xy);
    ck_assert_ptr_nonnull(xy);
    points_in_f(&rng, g, 1000, xy);
    hdt_triangulation *t = new_triangulation(g);
    insert_many_ok(t, xy, 1000, "1000 random points");
    const size_t V = hdt_vertex_count(t), d = hdt_dummy_count(t);
    size_t remaining = 4242;
    const hdt_status s = hdt_remove_dummies(t, &remaining);
    expect(s == HDT_OK, "g=%d: hdt_remove_dummies: %s (%s)", g, hdt_status_string(s), hdt_last_error_message());
    expect(remaining == 0, "g=%d: %zu of %zu dummies remain after 1000 random points", g, remaining, d);
    expect(hdt_dummy_count(t) == remaining, "g=%d: remaining %zu, hdt_dummy_count %zu", g, remaining,
           hdt_dummy_count(t));
    expect(hdt_vertex_count(t) == V - d + remaining, "g=%d: vertex count %zu after removing %zu of %zu dummies", g,
           hdt_vertex_count(t), d - remaining, V);
    for (uint32_t v = 0; v < hdt_vertex_id_bound(t); ++v)
      expect(hdt_vertex_is_dummy(t, v) != 1, "g=%d: vertex %u still a dummy", g, v);
    expect_valid(t, "dummies removed");
    expect_structure(t, "dummies removed");
    /* Nothing more to remove; NULL remaining is allowed. */
    ck_assert_int_eq(hdt_remove_dummies(t, NULL), HDT_OK);
    expect_valid(t, "dummies removed twice");
    hdt_destroy(t);
    free(xy);
  }
}
END_TEST

/* Not an assertion: how many random points (uniform in F) it takes before
   hdt_remove_dummies leaves no dummy. For each size n = 25, 50, ... a fresh
   triangulation gets the first n points of the sequence and removes its
   dummies; the table gives the first such n. */
START_TEST(dummy_removal_statistics) {
  enum { STEP = 25, MAXN = 3000, SEEDS = 3 };
  printf("dummy_removal_statistics: smallest n (steps of %d) with no dummy left after hdt_remove_dummies\n", STEP);
  printf("  g  dummies  seed1  seed2  seed3   mean\n");
  double *xy = malloc(2 * MAXN * sizeof *xy);
  ck_assert_ptr_nonnull(xy);
  for (int g = 2; g <= 8; ++g) {
    size_t found[SEEDS], dummies = 0;
    double sum = 0;
    for (int seed = 0; seed < SEEDS; ++seed) {
      uint64_t rng = 0xABCDEF + 7919 * (uint64_t)(seed + 1) + (uint64_t)g;
      points_in_f(&rng, g, MAXN, xy);
      found[seed] = 0;
      /* Progressive search on one handle to find the neighbourhood, then the
         exact answer on fresh handles from a little before it. */
      hdt_triangulation *t = new_triangulation(g);
      dummies = hdt_dummy_count(t);
      size_t n = 0, first = 0;
      while (n < MAXN) {
        insert_many_ok(t, xy + 2 * n, STEP, "statistics");
        n += STEP;
        size_t remaining = 0;
        ck_assert_int_eq(hdt_remove_dummies(t, &remaining), HDT_OK);
        if (remaining == 0) {
          first = n;
          break;
        }
      }
      hdt_destroy(t);
      if (first == 0) continue;
      const size_t from = first > 8 * STEP ? first - 8 * STEP : STEP;
      for (size_t m = from; m <= first; m += STEP) {
        hdt_triangulation *u = new_triangulation(g);
        insert_many_ok(u, xy, m, "statistics");
        size_t remaining = 1;
        ck_assert_int_eq(hdt_remove_dummies(u, &remaining), HDT_OK);
        hdt_destroy(u);
        if (remaining == 0) {
          found[seed] = m;
          break;
        }
      }
      if (found[seed] == 0) found[seed] = first;
      sum += (double)found[seed];
    }
    printf("  %d  %7zu  %5zu  %5zu  %5zu  %6.1f\n", g, dummies, found[0], found[1], found[2], sum / SEEDS);
    fflush(stdout);
  }
  free(xy);
}
END_TEST

/* ---- Vertex removal ---- */

static void shuffle(uint64_t *rng, uint32_t *a, size_t n) {
  for (size_t i = n; i > 1; --i) {
    const size_t j = (size_t)rng_below(rng, (int)i);
    const uint32_t tmp = a[i - 1];
    a[i - 1] = a[j], a[j] = tmp;
  }
}

/* Removes v: on success the triangulation is valid and has one vertex less
   (with its structure checked when `structure`), else the call was refused
   with HDT_ENOTSUP and nothing changed. Returns whether v was removed. */
static int remove_or_refuse(hdt_triangulation *t, uint32_t v, const char *what, int structure) {
  snapshot_t before = snapshot(t);
  const hdt_status s = hdt_remove_vertex(t, v);
  if (s == HDT_OK) {
    expect(hdt_vertex_count(t) == before.vertices - 1, "%s: count %zu -> %zu", what, before.vertices,
           hdt_vertex_count(t));
    expect_valid(t, what);
    if (structure) expect_structure(t, what);
  } else {
    expect_error(s, HDT_ENOTSUP, "hdt_remove_vertex", "guarantee|systole|circum|diameter|simplicial|refuse", what);
    expect_unchanged(t, &before, "a refused removal");
  }
  snapshot_free(&before);
  return s == HDT_OK;
}

/* hdt_vertices gives, in one call, what hdt_vertex_is_dummy and
 * hdt_vertex_point give per id, for the live ids only; the two-call pattern
 * writes nothing when the buffer is short. */
/* hdt_vertices keeps what it computed for vertices away from F_g: after
   removals and new insertions every answer must still be the rounded
   representative of that vertex's own input point (checked against
   hdt_point_representative, which needs no handle). */
START_TEST(vertex_points_stay_true_through_changes) {
  uint64_t rng = 0xCAC4E;
  hdt_triangulation *t = new_triangulation(2);
  enum { N = 400, BATCH = 200 };
  double input[2 * N][2];
  size_t known = 0;
  for (int round = 0; round < 2; ++round) {
    double xy[2 * BATCH];
    uint32_t ids[BATCH];
    for (int i = 0; i < BATCH; ++i) {
      const double gap = pow(10.0, -1 - 7 * uniform01(&rng)), a = 2 * PI * uniform01(&rng);
      xy[2 * i] = (1 - gap) * cos(a), xy[2 * i + 1] = (1 - gap) * sin(a);
    }
    ck_assert_int_eq(hdt_insert_many(t, xy, BATCH, ids), HDT_OK);
    for (int i = 0; i < BATCH; ++i) {
      ck_assert_uint_lt(ids[i], 2 * N);
      input[ids[i]][0] = xy[2 * i], input[ids[i]][1] = xy[2 * i + 1];
      if (ids[i] + 1 > known) known = ids[i] + 1;
    }
    for (int k = 0; k < 2; ++k) { /* the second call reads what the first stored */
      size_t count = hdt_vertex_count(t), got = 0;
      uint32_t *vid = malloc(count * sizeof *vid);
      double *points = malloc(2 * count * sizeof *points);
      uint8_t *dummy = malloc(count);
      ck_assert(vid && points && dummy);
      ck_assert_int_eq(hdt_vertices(t, vid, points, dummy, count, &got), HDT_OK);
      for (size_t i = 0; i < got; ++i) {
        if (dummy[i]) continue;
        double rx, ry;
        size_t len = 0;
        ck_assert_int_eq(hdt_point_representative(2, input[vid[i]][0], input[vid[i]][1], &rx, &ry, NULL, 0, &len),
                         HDT_OK);
        expect(hypot(points[2 * i] - rx, points[2 * i + 1] - ry) <= 1e-15,
               "round %d, call %d: vertex %u at (%.17g, %.17g), its representative (%.17g, %.17g)", round, k, vid[i],
               points[2 * i], points[2 * i + 1], rx, ry);
      }
      free(vid), free(points), free(dummy);
    }
    /* Remove a quarter of the user vertices: their ids are not reused. */
    for (int k = 0; k < BATCH / 4; ++k) hdt_remove_vertex(t, (uint32_t)rng_below(&rng, (int)known));
  }
  expect_valid(t, "after the changes");
  hdt_destroy(t);
}
END_TEST

START_TEST(vertices_in_one_call) {
  uint64_t rng = 31;
  hdt_triangulation *t = new_triangulation(3);
  enum { N = 300 };
  double xy[2 * N];
  const double rin = inradius(3);
  for (int i = 0; i < N; ++i) {
    const double r = 1.3 * rin * sqrt(uniform01(&rng)), a = 2 * PI * uniform01(&rng);
    xy[2 * i] = r * cos(a), xy[2 * i + 1] = r * sin(a);
  }
  ck_assert_int_eq(hdt_insert_many(t, xy, N, NULL), HDT_OK);
  for (int k = 0; k < 40; ++k) hdt_remove_vertex(t, (uint32_t)rng_below(&rng, (int)hdt_vertex_id_bound(t)));
  size_t count = 0;
  ck_assert_int_eq(hdt_vertices(t, NULL, NULL, NULL, 0, &count), HDT_OK);
  ck_assert_uint_eq(count, hdt_vertex_count(t));
  uint32_t *ids = malloc(count * sizeof *ids);
  double *points = malloc(2 * count * sizeof *points);
  uint8_t *dummy = malloc(count);
  ck_assert(ids && points && dummy);
  /* Too small: HDT_EBUFS, the count, nothing written. */
  memset(ids, 0xAB, count * sizeof *ids);
  size_t got = 0;
  ck_assert_int_eq(hdt_vertices(t, ids, points, dummy, count - 1, &got), HDT_EBUFS);
  ck_assert_uint_eq(got, count);
  for (size_t i = 0; i < count; ++i) ck_assert_uint_eq(ids[i], 0xABABABABu);
  ck_assert_int_eq(hdt_vertices(t, ids, points, dummy, count, &got), HDT_OK);
  ck_assert_uint_eq(got, count);
  size_t i = 0;
  for (uint32_t v = 0; v < hdt_vertex_id_bound(t); ++v) {
    const int d = hdt_vertex_is_dummy(t, v);
    if (d < 0) continue;
    ck_assert_uint_lt(i, count);
    ck_assert_uint_eq(ids[i], v);
    ck_assert_int_eq(dummy[i], d);
    double x, y;
    ck_assert_int_eq(hdt_vertex_point(t, v, &x, &y), HDT_OK);
    ck_assert(x == points[2 * i] && y == points[2 * i + 1]);
    ++i;
  }
  ck_assert_uint_eq(i, count);
  /* Any output may be NULL. */
  uint32_t *again = malloc(count * sizeof *again);
  ck_assert(again != NULL);
  ck_assert_int_eq(hdt_vertices(t, again, NULL, NULL, count, &got), HDT_OK);
  ck_assert(memcmp(again, ids, count * sizeof *ids) == 0);
  /* Bad calls. */
  ck_assert_int_eq(hdt_vertices(t, ids, points, dummy, count, NULL), HDT_EINVAL);
  ck_assert_int_eq(hdt_vertices(NULL, ids, points, dummy, count, &got), HDT_EINVAL);
  free(again), free(ids), free(points), free(dummy);
  hdt_destroy(t);
}
END_TEST

START_TEST(vertex_removal) {
  for (int g = 2; g <= 3; ++g) {
    uint64_t rng = 0x12345 + (uint64_t)g;
    const size_t n = 200;
    double xy[2 * 200];
    points_in_f(&rng, g, n, xy);
    hdt_triangulation *t = new_triangulation(g);
    const size_t d = hdt_dummy_count(t);
    insert_many_ok(t, xy, n, "removal setup");
    /* With every dummy present the guarantee holds for any superset of the
       dummies: removing user vertices is never refused. */
    uint32_t users[200];
    size_t nu = 0;
    for (uint32_t v = 0; v < hdt_vertex_id_bound(t); ++v)
      if (hdt_vertex_is_dummy(t, v) == 0) users[nu++] = v;
    shuffle(&rng, users, nu);
    for (size_t i = 0; i < nu / 2; ++i) {
      const size_t V = hdt_vertex_count(t);
      const hdt_status s = hdt_remove_vertex(t, users[i]);
      expect(s == HDT_OK, "g=%d: removing user vertex %u with all dummies present: %s (%s)", g, users[i],
             hdt_status_string(s), hdt_last_error_message());
      expect(hdt_vertex_count(t) == V - 1 && hdt_vertex_is_dummy(t, users[i]) == -1,
             "g=%d: vertex %u removed, count %zu -> %zu", g, users[i], V, hdt_vertex_count(t));
      char what[64];
      snprintf(what, sizeof what, "g=%d, user vertex %u removed", g, users[i]);
      expect_valid(t, what);
      if (i % 10 == 0) expect_structure(t, what);
    }
    /* Dummies through hdt_remove_vertex: removed, or refused with nothing changed. */
    size_t dummy_ok = 0, dummy_refused = 0;
    for (uint32_t v = 0; v < d; ++v) {
      char what[64];
      snprintf(what, sizeof what, "g=%d, dummy %u removed", g, v);
      if (remove_or_refuse(t, v, what, 0)) ++dummy_ok;
      else ++dummy_refused;
    }
    expect_structure(t, "after dummy removals");
    /* Without dummies (those left go through hdt_remove_dummies), remove the
       remaining user vertices in random order until refused. */
    size_t remaining = 0;
    ck_assert_int_eq(hdt_remove_dummies(t, &remaining), HDT_OK);
    expect_valid(t, "remove_dummies");
    size_t removed = 0, refused = 0;
    for (size_t i = nu / 2; i < nu; ++i) {
      char what[64];
      snprintf(what, sizeof what, "g=%d, user vertex %u", g, users[i]);
      if (remove_or_refuse(t, users[i], what, 1)) ++removed;
      else ++refused;
    }
    printf("vertex_removal g=%d: dummies via remove_vertex: %zu removed, %zu refused; %zu dummies left after "
           "remove_dummies; then %zu user vertices removed, %zu refused; %zu vertices left\n",
           g, dummy_ok, dummy_refused, remaining, removed, refused, hdt_vertex_count(t));
    fflush(stdout);
    /* With no dummy left, not every vertex can go: a surface of genus g
       needs a minimum number of vertices for the guarantee. */
    if (remaining == 0) expect(refused > 0, "g=%d: every user vertex could be removed without dummies", g);
    hdt_destroy(t);
  }
}
END_TEST

/* ---- Point location and nearest vertex ---- */

/* f(z) = (a z + b) / (conj(b) z + conj(a)) for m = (Re a, Im a, Re b, Im b). */
static void mobius(const double m[4], double x, double y, double *ox, double *oy) {
  const double nr = m[0] * x - m[1] * y + m[2], ni = m[0] * y + m[1] * x + m[3];
  const double dr = m[2] * x + m[3] * y + m[0], di = m[2] * y - m[3] * x - m[1];
  const double d2 = dr * dr + di * di;
  *ox = (nr * dr + ni * di) / d2;
  *oy = (ni * dr - nr * di) / d2;
}

static void translation_matrix(const hdt_triangulation *t, int32_t id, double m[4]) {
  const hdt_status s = hdt_translation_matrix(t, id, m);
  expect(s == HDT_OK, "hdt_translation_matrix(%d): %s (%s)", id, hdt_status_string(s), hdt_last_error_message());
}

/* Klein model: geodesics are straight lines. */
static void klein(double x, double y, double *kx, double *ky) {
  const double s = 2 / (1 + x * x + y * y);
  *kx = s * x, *ky = s * y;
}

static double orient(const double a[2], const double b[2], const double c[2]) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* Query points: a third in F's inscribed disk, the rest up to |z| = 0.9. */
static void query_point(uint64_t *rng, int g, double *x, double *y) {
  const double r = (rng_below(rng, 3) == 0 ? inradius(g) : 0.9) * sqrt(uniform01(rng)), a = 2 * PI * uniform01(rng);
  *x = r * cos(a), *y = r * sin(a);
}

static void check_locate(hdt_triangulation *t, uint64_t *rng, int queries, const char *what) {
  const int g = hdt_genus(t);
  snapshot_t s = snapshot(t);
  for (int q = 0; q < queries; ++q) {
    double x, y;
    query_point(rng, g, &x, &y);
    size_t f = SIZE_MAX;
    int32_t h = -1;
    const hdt_status st = hdt_locate(t, x, y, &f, &h);
    expect(st == HDT_OK, "%s: hdt_locate(%.17g, %.17g): %s (%s)", what, x, y, hdt_status_string(st),
           hdt_last_error_message());
    expect(f < s.faces, "%s: hdt_locate gave face %zu of %zu", what, f, s.faces);
    double mh[4], k[3][2], kq[2];
    translation_matrix(t, h, mh);
    for (int i = 0; i < 3; ++i) {
      double px, py, mt[4], cx, cy, zx, zy;
      ck_assert_int_eq(hdt_vertex_point(t, s.v[3 * f + i], &px, &py), HDT_OK);
      translation_matrix(t, s.tr[3 * f + i], mt);
      mobius(mt, px, py, &cx, &cy); /* the corner in the canonical copy */
      mobius(mh, cx, cy, &zx, &zy); /* ... in the located copy */
      klein(zx, zy, &k[i][0], &k[i][1]);
    }
    klein(x, y, &kq[0], &kq[1]);
    const double area = orient(k[0], k[1], k[2]);
    expect(area > 0, "%s: face %zu under translation %d is not counterclockwise (%g)", what, f, h, area);
    for (int i = 0; i < 3; ++i) {
      const double side = orient(k[i], k[(i + 1) % 3], kq);
      expect(side >= -1e-9, "%s: (%.17g, %.17g) located in face %zu (%u %u %u) under translation %d, but %g outside "
             "its edge %d (Klein model)", what, x, y, f, s.v[3 * f], s.v[3 * f + 1], s.v[3 * f + 2], h, side, i);
    }
  }
  snapshot_free(&s);
}

/* u(z, w) = |z - w|^2 / ((1 - |z|^2)(1 - |w|^2)), increasing in the
   hyperbolic distance (cosh d = 1 + 2u). */
static double u_dist(double zx, double zy, double wx, double wy) {
  const double dx = zx - wx, dy = zy - wy;
  return (dx * dx + dy * dy) / ((1 - zx * zx - zy * zy) * (1 - wx * wx - wy * wy));
}

static void check_nearest(hdt_triangulation *t, uint64_t *rng, int queries, const char *what) {
  const int g = hdt_genus(t);
  size_t nn = 0;
  ck_assert_int_eq(hdt_neighbour_count(g, &nn), HDT_OK);
  double (*m)[4] = malloc(nn * sizeof *m);
  ck_assert_ptr_nonnull(m);
  for (size_t id = 0; id < nn; ++id) {
    word_t w = {0};
    ck_assert_int_eq(hdt_neighbour_word(g, id, w.a, TW_MAX, &w.n), HDT_OK);
    word_matrix(g, &w, m[id]);
  }
  /* All N-images of all vertices. */
  const size_t bound = hdt_vertex_id_bound(t);
  size_t nv = 0;
  double *img = malloc(2 * bound * nn * sizeof *img);
  uint32_t *owner = malloc(bound * sizeof *owner);
  ck_assert(img && owner);
  for (uint32_t v = 0; v < bound; ++v) {
    double px, py;
    if (hdt_vertex_point(t, v, &px, &py) != HDT_OK) continue;
    for (size_t id = 0; id < nn; ++id) mobius(m[id], px, py, &img[2 * (nv * nn + id)], &img[2 * (nv * nn + id) + 1]);
    owner[nv++] = v;
  }
  for (int q = 0; q < queries; ++q) {
    double x, y, rx, ry;
    size_t len;
    query_point(rng, g, &x, &y);
    /* The nearest vertex is within sys/4 of the query's representative, so its
       nearest copy is an N-image. */
    ck_assert_int_eq(hdt_point_representative(g, x, y, &rx, &ry, NULL, 0, &len), HDT_OK);
    uint32_t got = UINT32_MAX;
    const hdt_status st = hdt_nearest_vertex(t, x, y, &got);
    expect(st == HDT_OK, "%s: hdt_nearest_vertex(%.17g, %.17g): %s (%s)", what, x, y, hdt_status_string(st),
           hdt_last_error_message());
    double best = INFINITY, mine = INFINITY;
    uint32_t best_v = UINT32_MAX;
    for (size_t i = 0; i < nv; ++i)
      for (size_t id = 0; id < nn; ++id) {
        const double u = u_dist(rx, ry, img[2 * (i * nn + id)], img[2 * (i * nn + id) + 1]);
        if (u < best) best = u, best_v = owner[i];
        if (owner[i] == got && u < mine) mine = u;
      }
    expect(mine <= best * (1 + 1e-9) + 1e-300, "%s: nearest vertex of (%.17g, %.17g) is %u at u = %.17g, but %u is at u = %.17g",
           what, x, y, got, mine, best_v, best);
  }
  free(m);
  free(img);
  free(owner);
}

START_TEST(locate_and_nearest_vertex) {
  for (int g = 2; g <= 4; ++g) {
    uint64_t rng = 0x10CA7E + (uint64_t)g;
    hdt_triangulation *t = new_triangulation(g);
    char what[64];
    snprintf(what, sizeof what, "g=%d, dummies only", g);
    check_locate(t, &rng, 300, what);
    check_nearest(t, &rng, 100, what);
    double xy[2 * 600];
    mixed_points(&rng, g, 600, xy);
    insert_many_ok(t, xy, 600, "locate setup");
    snprintf(what, sizeof what, "g=%d, 600 points", g);
    check_locate(t, &rng, 500, what);
    check_nearest(t, &rng, 200, what);
    /* Query exactly at vertices: nearest is that vertex. */
    for (int i = 0; i < 50; ++i) {
      uint32_t v = UINT32_MAX;
      const size_t k = (size_t)rng_below(&rng, 600);
      ck_assert_int_eq(hdt_nearest_vertex(t, xy[2 * k], xy[2 * k + 1], &v), HDT_OK);
      uint32_t w = UINT32_MAX;
      ck_assert_int_eq(hdt_insert(t, xy[2 * k], xy[2 * k + 1], &w), HDT_EEXISTS);
      expect(v == w, "g=%d: nearest vertex of vertex %u's point is %u", g, w, v);
      size_t f;
      ck_assert_int_eq(hdt_locate(t, xy[2 * k], xy[2 * k + 1], &f, NULL), HDT_OK);
    }
    size_t remaining;
    ck_assert_int_eq(hdt_remove_dummies(t, &remaining), HDT_OK);
    snprintf(what, sizeof what, "g=%d, 600 points, %zu dummies left", g, remaining);
    check_locate(t, &rng, 300, what);
    check_nearest(t, &rng, 100, what);
    /* A third of the points removed: the walks' starting grid then names
       removed vertices in many of its cells (they fall back to samples). */
    size_t removed = 0;
    for (size_t k = 0; k < 600; k += 3) {
      uint32_t v = UINT32_MAX;
      ck_assert_int_eq(hdt_nearest_vertex(t, xy[2 * k], xy[2 * k + 1], &v), HDT_OK);
      removed += hdt_remove_vertex(t, v) == HDT_OK;
    }
    expect(removed > 150, "g=%d: only %zu of 200 removals done", g, removed);
    snprintf(what, sizeof what, "g=%d, %zu of 600 points removed", g, removed);
    check_locate(t, &rng, 300, what);
    check_nearest(t, &rng, 100, what);
    hdt_destroy(t);
  }
}
END_TEST

int main(void) {
  const TTest *const tests[] = {
      random_points,
      vertex_point_is_the_rounded_representative,
      symmetric_orbits,
      dyadic_grids,
      polygon_points,
      dummy_coordinates_reinserted,
      duplicates_and_close_points,
      points_near_the_circle,
      extreme_coordinates,
      bad_input_insert_point,
      bad_input_insert_many_point,
      bad_input_null_handle_status,
      bad_input_null_handle_answers,
      bad_input_null_outputs,
      bad_input_create,
      bad_input_faces_small_buffer,
      bad_input_faces_count_only,
      bad_input_vertex_ids,
      bad_input_translation_ids,
      bad_input_query_outside_disk,
      bad_input_removed_id,
      dummies_go_after_many_points,
      dummy_removal_statistics,
      vertex_removal,
      vertices_in_one_call,
      vertex_points_stay_true_through_changes,
      locate_and_nearest_vertex,
  };
  return run_tests("triangulation", tests, sizeof tests / sizeof tests[0]);
}
