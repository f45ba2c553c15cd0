/* Refinement, epsilon-nets and quality statistics (HDT_0.4). The bounds
   are checked independently of the library's constructions: every face's
   circumradius, edge lengths and angles are recomputed here in 200-bit
   MPFR on the hyperboloid (Lorentz products, no disk isometries as the
   library uses) from the corners hdt_face_points gives. The library
   decides from the same rounded corners, so only its formulas' error (a
   relative 3.2e-13 on radii and lengths, measured by test_dual) separates
   the two: the checks allow a relative TOL = 1e-10, below the library's own
   margin of 1e-9, and a face left above a bound by more than that fails. */
#define _DEFAULT_SOURCE

#include <errno.h>
#include <mpfr.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "hdt_test.h"
#include "limited_child.h"

#define PREC 200
#define TOL 1e-10

static void *need(void *p) {
  ck_assert_ptr_nonnull(p);
  return p;
}

/* ---- 200-bit shapes on the hyperboloid ---- */

typedef struct shape {
  double radius, shortest, angle; /* circumradius, shortest edge, smallest angle */
} shape;

/* The hyperboloid point ((1 + |z|^2), 2x, 2y) / (1 - |z|^2) of z = x + iy. */
static void lift(double x, double y, mpfr_t P[3]) {
  mpfr_t n, d;
  mpfr_inits2(PREC, n, d, (mpfr_ptr)0);
  mpfr_set_d(n, x, MPFR_RNDN), mpfr_sqr(n, n, MPFR_RNDN);
  mpfr_set_d(d, y, MPFR_RNDN), mpfr_sqr(d, d, MPFR_RNDN);
  mpfr_add(n, n, d, MPFR_RNDN);       /* |z|^2 */
  mpfr_ui_sub(d, 1, n, MPFR_RNDN);    /* 1 - |z|^2 */
  mpfr_add_ui(P[0], n, 1, MPFR_RNDN), mpfr_div(P[0], P[0], d, MPFR_RNDN);
  mpfr_set_d(P[1], 2 * x, MPFR_RNDN), mpfr_div(P[1], P[1], d, MPFR_RNDN);
  mpfr_set_d(P[2], 2 * y, MPFR_RNDN), mpfr_div(P[2], P[2], d, MPFR_RNDN);
  mpfr_clears(n, d, (mpfr_ptr)0);
}

/* <A, B> = a_t b_t - a_u b_u - a_v b_v. */
static void lorentz(mpfr_t r, mpfr_t A[3], mpfr_t B[3]) {
  mpfr_t s;
  mpfr_init2(s, PREC);
  mpfr_mul(r, A[0], B[0], MPFR_RNDN);
  mpfr_mul(s, A[1], B[1], MPFR_RNDN), mpfr_sub(r, r, s, MPFR_RNDN);
  mpfr_mul(s, A[2], B[2], MPFR_RNDN), mpfr_sub(r, r, s, MPFR_RNDN);
  mpfr_clear(s);
}

/* The face with corners xy[0..5]: the circle through three points of the
   hyperboloid lies in a plane n . X = c; its centre C is the point with
   <C, X> proportional to n . X, C = (n_t, -n_u, -n_v) normalised, and
   cosh R = <C, P_0>. Edges: cosh d = <P, Q>; angles by the law of cosines. */
static shape face_shape(const double *xy) {
  mpfr_t P[3][3], D1[3], D2[3], C[3], c[3], ch[3], sh[3], a, b;
  for (int i = 0; i < 3; ++i) {
    mpfr_inits2(PREC, P[i][0], P[i][1], P[i][2], D1[i], D2[i], C[i], c[i], ch[i], sh[i], (mpfr_ptr)0);
    lift(xy[2 * i], xy[2 * i + 1], P[i]);
  }
  mpfr_inits2(PREC, a, b, (mpfr_ptr)0);
  for (int k = 0; k < 3; ++k) mpfr_sub(D1[k], P[1][k], P[0][k], MPFR_RNDN), mpfr_sub(D2[k], P[2][k], P[0][k], MPFR_RNDN);
  for (int k = 0; k < 3; ++k) { /* the Euclidean cross product D1 x D2 */
    const int p = (k + 1) % 3, q = (k + 2) % 3;
    mpfr_mul(a, D1[p], D2[q], MPFR_RNDN), mpfr_mul(b, D1[q], D2[p], MPFR_RNDN);
    mpfr_sub(C[k], a, b, MPFR_RNDN);
  }
  mpfr_neg(C[1], C[1], MPFR_RNDN), mpfr_neg(C[2], C[2], MPFR_RNDN);
  lorentz(a, C, C);
  expect(mpfr_sgn(a) > 0, "a face's circle is not a hyperbolic circle");
  mpfr_sqrt(a, a, MPFR_RNDN);
  lorentz(b, C, P[0]);
  mpfr_div(b, b, a, MPFR_RNDN);
  mpfr_abs(b, b, MPFR_RNDN); /* C up to sign */
  mpfr_acosh(b, b, MPFR_RNDN);
  shape s;
  s.radius = mpfr_get_d(b, MPFR_RNDN);
  /* side i is opposite corner i: ch = cosh, sh = sinh of its length */
  s.shortest = INFINITY;
  for (int i = 0; i < 3; ++i) {
    lorentz(ch[i], P[(i + 1) % 3], P[(i + 2) % 3]);
    mpfr_sqr(sh[i], ch[i], MPFR_RNDN), mpfr_sub_ui(sh[i], sh[i], 1, MPFR_RNDN), mpfr_sqrt(sh[i], sh[i], MPFR_RNDN);
    mpfr_acosh(a, ch[i], MPFR_RNDN);
    s.shortest = fmin(s.shortest, mpfr_get_d(a, MPFR_RNDN));
  }
  s.angle = INFINITY;
  for (int i = 0; i < 3; ++i) { /* cos A_i = (cosh b cosh c - cosh a) / (sinh b sinh c) */
    const int p = (i + 1) % 3, q = (i + 2) % 3;
    mpfr_mul(a, ch[p], ch[q], MPFR_RNDN), mpfr_sub(a, a, ch[i], MPFR_RNDN);
    mpfr_mul(b, sh[p], sh[q], MPFR_RNDN), mpfr_div(a, a, b, MPFR_RNDN);
    mpfr_acos(a, a, MPFR_RNDN);
    s.angle = fmin(s.angle, mpfr_get_d(a, MPFR_RNDN));
  }
  for (int i = 0; i < 3; ++i) mpfr_clears(P[i][0], P[i][1], P[i][2], D1[i], D2[i], C[i], c[i], ch[i], sh[i], (mpfr_ptr)0);
  mpfr_clears(a, b, (mpfr_ptr)0);
  return s;
}

/* The extremes over all faces, recomputed here. */
static shape extremes(const hdt_triangulation *t, double *max_ratio) {
  size_t F = 0;
  OK(hdt_face_points(t, NULL, 0, &F));
  double *xy = need(malloc(6 * F * sizeof *xy));
  OK(hdt_face_points(t, xy, F, &F));
  shape e = {0, INFINITY, INFINITY};
  *max_ratio = 0;
  for (size_t f = 0; f < F; ++f) {
    const shape s = face_shape(xy + 6 * f);
    e.radius = fmax(e.radius, s.radius), e.shortest = fmin(e.shortest, s.shortest), e.angle = fmin(e.angle, s.angle);
    *max_ratio = fmax(*max_ratio, s.radius / s.shortest);
  }
  free(xy);
  return e;
}

/* Every face within the bounds (up to TOL), the triangulation valid and
   Euler's formula. Returns the extremes. */
static shape check_refined(const hdt_triangulation *t, double max_radius, double max_ratio) {
  OK(hdt_validate(t));
  const int g = hdt_genus(t);
  expect(hdt_face_count(t) == 2 * (hdt_vertex_count(t) + 2 * (size_t)g - 2), "Euler: F = %zu, V = %zu",
         hdt_face_count(t), hdt_vertex_count(t));
  double ratio;
  const shape e = extremes(t, &ratio);
  expect(e.radius <= max_radius * (1 + TOL), "a circumradius %.17g above the bound %.17g", e.radius, max_radius);
  expect(ratio <= max_ratio * (1 + TOL), "a radius-edge ratio %.17g above the bound %.17g", ratio, max_ratio);
  return e;
}

/* The packing bound of docs/refinement.md: vertices pairwise delta apart
   on M_g number at most 2 (g - 1) / (cosh(delta / 2) - 1). */
static double packing_bound(int g, double delta) { return 2.0 * (g - 1) / (cosh(delta / 2) - 1); }

static double min_edge(const hdt_triangulation *t) {
  double e;
  OK(hdt_quality(t, NULL, NULL, NULL, &e));
  return e;
}

/* n random points of the disk of radius 0.4 (inside F_g). */
static void insert_random(hdt_triangulation *t, size_t n, uint64_t seed) {
  double *xy = need(malloc(2 * n * sizeof *xy));
  for (size_t i = 0; i < n;) {
    const double x = 0.8 * uniform01(&seed) - 0.4, y = 0.8 * uniform01(&seed) - 0.4;
    if (x * x + y * y >= 0.16) continue;
    xy[2 * i] = x, xy[2 * i + 1] = y;
    ++i;
  }
  OK(hdt_insert_many(t, xy, n, NULL));
  free(xy);
}

/* ---- The cases ---- */

START_TEST(uniform_mesh_from_the_dummies) {
  const struct {
    int g;
    double radius, ratio;
  } cases[] = {{2, 0.3, INFINITY}, {2, 0.15, 1.5}, {3, 0.25, 2}, {2, 0.5, 1}, {5, 0.3, 1.2}};
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
    hdt_triangulation *t;
    OK(hdt_create(&t, cases[k].g));
    const double d0 = min_edge(t);
    const size_t V0 = hdt_vertex_count(t), bound0 = hdt_vertex_id_bound(t);
    size_t added = 99, unmet = 99;
    OK(hdt_refine(t, cases[k].radius, cases[k].ratio, SIZE_MAX, &added, &unmet));
    expect(unmet == 0, "case %zu: %zu faces unmet", k, unmet);
    expect(hdt_vertex_count(t) == V0 + added, "case %zu: %zu vertices, %zu added", k, hdt_vertex_count(t), added);
    expect(added > 0, "case %zu: nothing added", k);
    for (size_t v = bound0; v < hdt_vertex_id_bound(t); ++v)
      expect(hdt_vertex_is_dummy(t, (uint32_t)v) == 0, "Steiner point %zu is not a user vertex", v);
    const shape e = check_refined(t, cases[k].radius, cases[k].ratio);
    /* the proof's packing: pairwise at least min(r_max, d0) apart (the
       shortest edge, up to TOL), hence at most the packing bound */
    const double delta = fmin(cases[k].radius, d0);
    expect(e.shortest >= delta * (1 - 1e-8), "case %zu: two vertices %.17g apart, below %.17g", k, e.shortest,
           delta);
    expect((double)hdt_vertex_count(t) <= packing_bound(cases[k].g, delta), "case %zu: %zu vertices", k,
           hdt_vertex_count(t));
    /* a second call has nothing to do */
    OK(hdt_refine(t, cases[k].radius, cases[k].ratio, SIZE_MAX, &added, &unmet));
    expect(added == 0 && unmet == 0, "case %zu: a second call added %zu", k, added);
    hdt_destroy(t);
  }
}
END_TEST

START_TEST(point_set_refined) {
  for (int g = 2; g <= 3; ++g) {
    hdt_triangulation *t;
    OK(hdt_create(&t, g));
    insert_random(t, 150, 7 + (uint64_t)g);
    OK(hdt_remove_dummies(t, NULL));
    const double d0 = min_edge(t);
    size_t added, unmet;
    OK(hdt_refine(t, 0.2, 1.0, SIZE_MAX, &added, &unmet));
    expect(unmet == 0, "genus %d: %zu unmet", g, unmet);
    const shape e = check_refined(t, 0.2, 1.0);
    expect(e.shortest >= fmin(0.2, d0) * (1 - 1e-8), "genus %d: shortest edge %.17g", g, e.shortest);
    /* ratio <= 1 means every angle >= 30 degrees in the Euclidean limit;
       hyperbolic angles are smaller than Euclidean ones, by the area */
    expect(e.angle > 0.45, "genus %d: an angle of %.17g radians", g, e.angle);
    hdt_destroy(t);
  }
}
END_TEST

START_TEST(quality_against_mpfr) {
  hdt_triangulation *t;
  OK(hdt_create(&t, 2));
  insert_random(t, 80, 3);
  for (int step = 0; step < 2; ++step) {
    double angle, ratio, radius, edge, mratio;
    OK(hdt_quality(t, &angle, &ratio, &radius, &edge));
    const shape e = extremes(t, &mratio);
    expect(fabs(radius - e.radius) <= 1e-11 * e.radius, "max radius %.17g, MPFR %.17g", radius, e.radius);
    expect(fabs(edge - e.shortest) <= 1e-11 * e.shortest, "min edge %.17g, MPFR %.17g", edge, e.shortest);
    expect(fabs(ratio - mratio) <= 1e-11 * mratio, "max ratio %.17g, MPFR %.17g", ratio, mratio);
    expect(fabs(angle - e.angle) <= 1e-10, "min angle %.17g, MPFR %.17g", angle, e.angle);
    OK(hdt_refine(t, 0.3, 1.4, SIZE_MAX, NULL, NULL));
  }
  OK(hdt_quality(t, NULL, NULL, NULL, NULL));
  expect(hdt_quality(NULL, NULL, NULL, NULL, NULL) == HDT_EINVAL, "hdt_quality(NULL)");
  hdt_destroy(t);
}
END_TEST

START_TEST(cap_is_honoured) {
  hdt_triangulation *t;
  OK(hdt_create(&t, 2));
  const size_t V0 = hdt_vertex_count(t);
  size_t added = 99, unmet = 0;
  OK(hdt_refine(t, 0.2, 1.2, 7, &added, &unmet));
  expect(added == 7 && unmet > 0, "added %zu, unmet %zu", added, unmet);
  expect(hdt_vertex_count(t) == V0 + 7, "%zu vertices", hdt_vertex_count(t));
  OK(hdt_validate(t));
  /* unmet counts the faces above a bound, recomputed here */
  size_t F = 0;
  OK(hdt_face_points(t, NULL, 0, &F));
  double *xy = need(malloc(6 * F * sizeof *xy));
  OK(hdt_face_points(t, xy, F, &F));
  size_t above = 0, near = 0;
  for (size_t f = 0; f < F; ++f) {
    const shape s = face_shape(xy + 6 * f);
    const double worst = fmax(s.radius / 0.2, s.radius / (1.2 * s.shortest));
    above += worst > 1 + 1e-8;
    near += fabs(worst - 1) <= 1e-8;
  }
  free(xy);
  expect(near == 0 && above == unmet, "unmet %zu, faces above a bound %zu", unmet, above);
  /* max_points 0 adds nothing and counts */
  size_t unmet2;
  OK(hdt_refine(t, 0.2, 1.2, 0, &added, &unmet2));
  expect(added == 0 && unmet2 == unmet, "added %zu, unmet %zu then %zu", added, unmet, unmet2);
  /* and the rest completes it */
  OK(hdt_refine(t, 0.2, 1.2, SIZE_MAX, &added, &unmet));
  expect(unmet == 0, "unmet %zu", unmet);
  check_refined(t, 0.2, 1.2);
  hdt_destroy(t);
}
END_TEST

START_TEST(bad_arguments_change_nothing) {
  hdt_triangulation *t;
  OK(hdt_create(&t, 3));
  insert_random(t, 30, 11);
  size_t n0, n1;
  unsigned char *before = observable_bytes(t, &n0);
  const double bad_radius[] = {NAN, 0, -0.0, -1, -INFINITY};
  const double bad_ratio[] = {NAN, 0.999999, 0, -1, -INFINITY};
  size_t added = 12345, unmet = 12345;
  for (size_t i = 0; i < 5; ++i) {
    expect(hdt_refine(t, bad_radius[i], 2, SIZE_MAX, &added, &unmet) == HDT_EINVAL, "radius %g", bad_radius[i]);
    expect(hdt_refine(t, 0.2, bad_ratio[i], SIZE_MAX, &added, &unmet) == HDT_EINVAL, "ratio %g", bad_ratio[i]);
    expect(hdt_epsilon_net(t, bad_radius[i], SIZE_MAX, &added, &unmet) == HDT_EINVAL, "epsilon %g", bad_radius[i]);
  }
  expect(hdt_epsilon_net(t, INFINITY, SIZE_MAX, &added, &unmet) == HDT_EINVAL, "epsilon inf");
  expect(strlen(hdt_last_error_message()) > 0, "no message");
  /* the counts are written on every return: nothing added, nothing looked at */
  expect(added == 0 && unmet == 0, "after a refused call: added %zu, unmet %zu", added, unmet);
  expect(hdt_refine(NULL, 0.2, 2, SIZE_MAX, NULL, NULL) == HDT_EINVAL, "NULL handle");
  added = unmet = 7; /* a NULL handle writes nothing, as everywhere */
  expect(hdt_refine(NULL, 0.2, 2, SIZE_MAX, &added, &unmet) == HDT_EINVAL && added == 7 && unmet == 7,
         "NULL handle: outputs written");
  expect(hdt_epsilon_net(NULL, 0.2, SIZE_MAX, &added, &unmet) == HDT_EINVAL && added == 7 && unmet == 7,
         "NULL handle: outputs written");
  expect(hdt_epsilon_net(t, NAN, SIZE_MAX, &added, &unmet) == HDT_EINVAL && added == 0 && unmet == 0,
         "a refused epsilon: the counts not written");
  expect(hdt_epsilon_net(NULL, 0.2, SIZE_MAX, NULL, NULL) == HDT_EINVAL, "NULL handle");
  /* no bound at all, or max_points 0: nothing to do */
  OK(hdt_refine(t, INFINITY, INFINITY, SIZE_MAX, &added, &unmet));
  expect(added == 0 && unmet == 0, "added %zu, unmet %zu", added, unmet);
  OK(hdt_refine(t, 0.1, 1, 0, &added, &unmet));
  expect(added == 0 && unmet > 0, "added %zu, unmet %zu", added, unmet);
  unsigned char *after = observable_bytes(t, &n1);
  expect(n0 == n1 && memcmp(before, after, n0) == 0, "the triangulation changed");
  free(before), free(after);
  hdt_destroy(t);
}
END_TEST

START_TEST(epsilon_nets) {
  const struct {
    int g;
    double eps;
  } cases[] = {{2, 0.2}, {2, 0.1}, {3, 0.15}};
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
    hdt_triangulation *t;
    OK(hdt_create(&t, cases[k].g));
    const double eps = cases[k].eps;
    expect(min_edge(t) >= eps, "the dummies of genus %d are %.17g apart", cases[k].g, min_edge(t));
    size_t added, unmet;
    OK(hdt_epsilon_net(t, eps, SIZE_MAX, &added, &unmet));
    expect(unmet == 0, "unmet %zu", unmet);
    const shape e = check_refined(t, eps, INFINITY);
    expect(e.radius <= eps * (1 + TOL), "covering radius %.17g", e.radius);
    expect(e.shortest >= eps * (1 - 1e-8), "packing: two vertices %.17g apart", e.shortest);
    double radius, edge;
    OK(hdt_quality(t, NULL, NULL, &radius, &edge));
    expect(radius <= eps && edge >= eps * (1 - 1e-8), "hdt_quality: %.17g, %.17g", radius, edge);
    expect((double)hdt_vertex_count(t) <= packing_bound(cases[k].g, eps), "%zu vertices", hdt_vertex_count(t));
    hdt_destroy(t);
  }
}
END_TEST

/* Two user points closer than double can refine between (1 ulp, 1e-300,
   subnormal), dummies removed, on and off the axes: hdt_refine returns
   HDT_OK, the triangulation valid; the faces left breaking a bound are the
   few next to the pair (below the resolution of double: counted in
   *unmet), every other face meets the bound (recomputed here in MPFR), and
   a second call adds nothing. The library used to fail with HDT_EINTERNAL
   ("a circumcentre fell on a vertex") part way, with the triangulation
   changed. */
START_TEST(near_duplicates_are_refined_around) {
  const double tiny = 0x1p-1074; /* the smallest subnormal */
  const struct {
    double x0, y0, x1, y1;
  } pairs[] = {
      {0.3, 0.1, 0.3, 0x1.999999999999bp-4},    /* (0.3, 0.1) and (0.3, nextafter(0.1, 1)) */
      {0.3, 0, 0.3, tiny},                      /* subnormal, on an axis */
      {0.3, 1e-300, 0.3, 2e-300},               /* 1e-300 */
      {1e-300, -0.2, 2e-300, -0.2},             /* 1e-300, about the other axis */
      {-0.45, 0.2, -0x1.cccccccccccccp-2, 0.2}, /* 1 ulp in x, off the axes */
      {0, 0, tiny, 0},                          /* subnormal at the centre */
  };
  const double ratios[] = {1, M_SQRT2, 2, 10};
  for (int g = 2; g <= 3; ++g)
    for (size_t p = 0; p < sizeof pairs / sizeof pairs[0]; ++p)
      for (size_t k = 0; k < sizeof ratios / sizeof ratios[0]; ++k) {
        hdt_triangulation *t;
        OK(hdt_create(&t, g));
        const double xy[] = {pairs[p].x0, pairs[p].y0, pairs[p].x1, pairs[p].y1};
        uint32_t ids[2];
        OK(hdt_insert_many(t, xy, 2, ids));
        expect(ids[0] != ids[1], "pair %zu: one vertex", p);
        size_t left;
        OK(hdt_remove_dummies(t, &left));
        size_t added = 99, unmet = 99;
        const hdt_status s = hdt_refine(t, INFINITY, ratios[k], SIZE_MAX, &added, &unmet);
        expect(s == HDT_OK, "genus %d, pair %zu, ratio %g: %s (%s)", g, p, ratios[k], hdt_status_string(s),
               hdt_last_error_message());
        OK(hdt_validate(t));
        expect(added > 0 && added < 10000, "genus %d, pair %zu, ratio %g: added %zu", g, p, ratios[k], added);
        expect(unmet >= 1 && unmet <= 8, "genus %d, pair %zu, ratio %g: unmet %zu", g, p, ratios[k], unmet);
        size_t F = 0;
        OK(hdt_face_points(t, NULL, 0, &F));
        double *fxy = need(malloc(6 * F * sizeof *fxy));
        OK(hdt_face_points(t, fxy, F, &F));
        size_t above = 0;
        for (size_t f = 0; f < F; ++f) {
          const shape sh = face_shape(fxy + 6 * f);
          if (sh.radius <= ratios[k] * sh.shortest * (1 + TOL)) continue;
          ++above;
          double dmin = INFINITY; /* a face left is one next to the pair */
          for (int c = 0; c < 3; ++c)
            dmin = fmin(dmin, hypot(fxy[6 * f + 2 * c] - pairs[p].x0, fxy[6 * f + 2 * c + 1] - pairs[p].y0));
          expect(dmin < 1e-8, "genus %d, pair %zu: a face left %.3g from the pair", g, p, dmin);
        }
        free(fxy);
        expect(above <= unmet, "genus %d, pair %zu, ratio %g: %zu faces above the bound, %zu unmet", g, p,
               ratios[k], above, unmet);
        size_t unmet2 = 0;
        OK(hdt_refine(t, INFINITY, ratios[k], SIZE_MAX, &added, &unmet2));
        expect(added == 0 && unmet2 == unmet, "a second call: added %zu, unmet %zu then %zu", added, unmet, unmet2);
        hdt_destroy(t);
      }
}
END_TEST

/* Work that memory cannot hold is refused before it starts: an
   epsilon-net of M_2 with epsilon 1e-4 needs more than 4 10^8 vertices
   (disks of radius epsilon cover the area 4 pi), over 40 GiB. HDT_ENOMEM at
   once, with the count in the message, the triangulation unchanged; with a
   cap the same call runs and stops at the cap. The library used to run
   until memory was gone (the OOM killer, without a ulimit). */
START_TEST(work_that_cannot_fit_is_refused_up_front) {
  hdt_triangulation *t;
  OK(hdt_create(&t, 2));
  size_t n0, n1;
  unsigned char *before = observable_bytes(t, &n0);
  size_t added = 99, unmet = 99;
  const double tiny[] = {1e-4, 1e-9, 1e-300};
  for (size_t k = 0; k < 3; ++k) {
    expect(hdt_epsilon_net(t, tiny[k], SIZE_MAX, &added, &unmet) == HDT_ENOMEM, "epsilon %g: %s", tiny[k],
           hdt_last_error_message());
    expect(strstr(hdt_last_error_message(), "vertices") != NULL, "message \"%s\"", hdt_last_error_message());
    expect(added == 0, "added %zu", added);
    expect(hdt_refine(t, tiny[k], 2, SIZE_MAX, &added, &unmet) == HDT_ENOMEM, "radius %g: %s", tiny[k],
           hdt_last_error_message());
  }
  unsigned char *after = observable_bytes(t, &n1);
  expect(n0 == n1 && memcmp(before, after, n0) == 0, "the triangulation changed");
  free(before), free(after);
  OK(hdt_epsilon_net(t, 1e-4, 500, &added, &unmet));
  expect(added == 500 && unmet > 0, "with a cap: added %zu, unmet %zu", added, unmet);
  OK(hdt_validate(t));
  hdt_destroy(t);
}
END_TEST

/* Out of memory part way (as tests/test_enomem.c does for insertions: a
   forked child under a tight address-space limit; skipped where RLIMIT_AS
   means nothing): hdt_refine returns HDT_ENOMEM, the points inserted so far
   stay in a valid triangulation, and with memory back the refinement
   completes. */

static void enomem_child(void) {
  hdt_triangulation *t = NULL;
  require(hdt_create(&t, 2) == HDT_OK, "hdt_create: %s", hdt_last_error_message());
  const size_t V0 = hdt_vertex_count(t);
  struct rlimit old;
  require(getrlimit(RLIMIT_AS, &old) == 0, "getrlimit: %s", strerror(errno));
  /* 83,000 points need about 15 MB; 4 MiB runs out part way. */
  struct rlimit tight = {(rlim_t)(address_space_bytes() + ((size_t)4 << 20)), old.rlim_max};
  require(setrlimit(RLIMIT_AS, &tight) == 0, "setrlimit: %s", strerror(errno));
  size_t added = 12345, unmet = 12345;
  const hdt_status s = hdt_refine(t, 0.01, INFINITY, SIZE_MAX, &added, &unmet);
  require(setrlimit(RLIMIT_AS, &old) == 0, "setrlimit back: %s", strerror(errno));
  require(s == HDT_ENOMEM, "hdt_refine returned %s under the limit", hdt_status_string(s));
  require(strstr(hdt_last_error_message(), "memory") != NULL, "message \"%s\"", hdt_last_error_message());
  const size_t V1 = hdt_vertex_count(t);
  require(V1 > V0, "no point stayed (%zu vertices)", V1);
  require(hdt_validate(t) == HDT_OK, "after ENOMEM: %s", hdt_last_error_message());
  require(hdt_refine(t, 0.01, INFINITY, SIZE_MAX, &added, &unmet) == HDT_OK && unmet == 0,
                "with memory back: %s", hdt_last_error_message());
  require(hdt_validate(t) == HDT_OK, "after completing: %s", hdt_last_error_message());
  printf("refine enomem: %zu vertices when memory ran out, %zu at the end\n", V1, hdt_vertex_count(t));
  fflush(stdout);
  hdt_destroy(t);
  _exit(0);
}

START_TEST(out_of_memory_keeps_a_valid_triangulation) {
  const char *preload = getenv("LD_PRELOAD");
  if (UNDER_SANITIZER || (preload && strstr(preload, "vgpreload"))) {
    printf("refine enomem: skipped under a sanitizer or valgrind (RLIMIT_AS does not apply)\n");
    return;
  }
  run_child(enomem_child);
}
END_TEST

int main(void) {
  const TTest *const tests[] = {uniform_mesh_from_the_dummies, point_set_refined,           quality_against_mpfr,
                                cap_is_honoured,               bad_arguments_change_nothing, epsilon_nets,
                                out_of_memory_keeps_a_valid_triangulation, near_duplicates_are_refined_around,
                                work_that_cannot_fit_is_refused_up_front};
  return run_tests("refine", tests, sizeof tests / sizeof tests[0]);
}
