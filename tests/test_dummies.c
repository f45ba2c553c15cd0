/* The size of the dummy point sets, through the public API: a new
   triangulation holds only its genus's dummies (hdt_vertex_count), certified
   (hdt_validate), each face's circle below sys/4 (recomputed here from the
   corners), and not many more than any certified set can have: at most 14
   at genus 2 (the published Bolza set has 14), and within 1.5 times the
   area lower bound from genus 4 to 256 (the refinement alone left about 2,
   the local thinning about 1.6: docs/design.md#dummy-points). */
#include <math.h>
#include <mpfr.h>
#include <stdio.h>
#include <stdlib.h>

#include "hdt.h"
#include "hdt_test.h"

/* The area lower bound, in MPFR at 256 bits: a face of circumradius below
   r = sys/4 has less area than the equilateral triangle inscribed in that
   circle, A = pi - 3 alpha with cot(alpha / 2) = sqrt(3) cosh r, and the
   F = 2 (V + 2g - 2) faces cover the area 4 pi (g - 1), so
   V > 2 pi (g - 1) / A - 2g + 2. cosh(sys/4)^2 = 1 + cos(pi / 2g). */
static long area_bound(int g) {
  mpfr_t pi, c, a, t;
  mpfr_inits2(256, pi, c, a, t, (mpfr_ptr)0);
  mpfr_const_pi(pi, MPFR_RNDN);
  mpfr_div_ui(c, pi, (unsigned long)(2 * g), MPFR_RNDN);
  mpfr_cos(c, c, MPFR_RNDN);
  mpfr_add_ui(c, c, 1, MPFR_RNDN);
  mpfr_sqrt(c, c, MPFR_RNDN);             /* cosh r */
  mpfr_sqrt_ui(t, 3, MPFR_RNDN);
  mpfr_mul(t, t, c, MPFR_RNDN);
  mpfr_ui_div(t, 1, t, MPFR_RNDN);
  mpfr_atan(a, t, MPFR_RNDN);             /* alpha / 2 */
  mpfr_mul_ui(a, a, 6, MPFR_RNDN);
  mpfr_sub(a, pi, a, MPFR_RNDN);          /* A */
  mpfr_mul_ui(t, pi, (unsigned long)(2 * (g - 1)), MPFR_RNDN);
  mpfr_div(t, t, a, MPFR_RNDN);
  mpfr_sub_ui(t, t, (unsigned long)(2 * g - 2), MPFR_RNDN);
  const double bound = mpfr_get_d(t, MPFR_RNDN);
  mpfr_clears(pi, c, a, t, (mpfr_ptr)0);
  ck_assert_msg(fabs(bound - nearbyint(bound)) > 1e-6, "g=%d: the bound %.12f is too near an integer", g, bound);
  return (long)ceil(bound);
}

/* cosh of the circumradius of three disk points: the circle's plane through
   the hyperboloid points N, its Minkowski normal m, cosh R = <m, N> / |m|. */
static long double cosh_circumradius(const double *xy) {
  long double P[3][3];
  for (int i = 0; i < 3; ++i) {
    const long double x = xy[2 * i], y = xy[2 * i + 1], w = 1 - x * x - y * y;
    P[i][0] = (1 + x * x + y * y) / w, P[i][1] = 2 * x / w, P[i][2] = 2 * y / w;
  }
  long double u[3], v[3];
  for (int j = 0; j < 3; ++j) u[j] = P[1][j] - P[0][j], v[j] = P[2][j] - P[0][j];
  const long double m[3] = {u[1] * v[2] - u[2] * v[1], -(u[2] * v[0] - u[0] * v[2]), -(u[0] * v[1] - u[1] * v[0])};
  const long double mm = m[0] * m[0] - m[1] * m[1] - m[2] * m[2];
  if (!(mm > 0)) return INFINITY;
  return fabsl(m[0] * P[0][0] - m[1] * P[0][1] - m[2] * P[0][2]) / sqrtl(mm);
}

/* A new triangulation of genus g: only dummies, certified, every face's
   circle (from hdt_face_points) below sys/4 up to the corners' rounding.
   Returns the dummy count. */
static size_t checked_dummies(int g) {
  hdt_triangulation *t = NULL;
  ck_assert_msg(hdt_create(&t, g) == HDT_OK, "g=%d: %s", g, hdt_last_error_message());
  ck_assert_int_eq(hdt_validate(t), HDT_OK);
  const size_t V = hdt_vertex_count(t), F = hdt_face_count(t);
  ck_assert_uint_eq(hdt_dummy_count(t), V);
  ck_assert_uint_eq(F, 2 * (V + 2 * (size_t)g - 2));
  double *xy = malloc(6 * F * sizeof *xy);
  ck_assert_ptr_nonnull(xy);
  size_t count = 0;
  ck_assert_int_eq(hdt_face_points(t, xy, F, &count), HDT_OK);
  ck_assert_uint_eq(count, F);
  const long double limit = sqrtl(1 + cosl(acosl(-1.0L) / (2 * g)));  /* cosh(sys/4) */
  for (size_t f = 0; f < F; ++f) {
    const long double c = cosh_circumradius(xy + 6 * f);
    ck_assert_msg(c < limit * (1 + 1e-9L), "g=%d: face %zu has cosh(circumradius) %.12Lg, the limit is %.12Lg", g, f, c,
                  limit);
  }
  free(xy);
  hdt_destroy(t);
  return V;
}

START_TEST(at_most_14_at_genus_2) {
  const size_t V = checked_dummies(2);
  printf("genus 2: %zu dummy points (the area bound: %ld)\n", V, area_bound(2));
  ck_assert_msg(V <= 14, "genus 2 has %zu dummy points, more than the 14 of the published set", V);
}
END_TEST

/* At most 1.5 times the bound from genus 4 on (genus 3: 20 dummies, 1.54). */
static void expect_near_the_bound(int g) {
  const size_t V = checked_dummies(g);
  const long bound = area_bound(g);
  printf("genus %d: %zu dummy points, area bound %ld, ratio %.3f\n", g, V, bound, (double)V / (double)bound);
  /* Below the bound, some face would have a circle too large: the
     certificate would be wrong. */
  ck_assert_msg((long)V >= bound, "g=%d: %zu dummies, fewer than the area bound %ld", g, V, bound);
  if (g >= 4) ck_assert_msg((double)V <= 1.5 * (double)bound, "g=%d: %zu dummies, %.3f times the area bound %ld", g, V,
                            (double)V / (double)bound, bound);
}

START_TEST(near_the_area_bound) {
  for (int g = 3; g <= 16; ++g) expect_near_the_bound(g);
}
END_TEST

/* Beyond 16: both sides of genus 32, where the relaxation's effort drops,
   and genus 64. */
START_TEST(near_the_area_bound_to_genus_64) {
  const int genera[] = {17, 24, 31, 32, 33, 36, 48, 64};
  for (size_t k = 0; k < sizeof genera / sizeof *genera; ++k) expect_near_the_bound(genera[k]);
}
END_TEST

/* Above 128: the first genus past the old limit, the largest, 256, and
   the two genera (159 and 192) where the refinement's rounded radii hide
   a circle of diameter >= sys/2 that only the exact test then finds (its
   centroid is inserted): the only genera up to 256 that take that path.
   Each set certified and within 1.5 times the area bound as above. */
START_TEST(near_the_area_bound_to_genus_256) {
  const int genera[] = {128, 129, 159, 192, 256};
  for (size_t k = 0; k < sizeof genera / sizeof *genera; ++k) expect_near_the_bound(genera[k]);
}
END_TEST

/* The first triangulation of a genus in a process builds the dummy points
   and its surface's exact sites; later ones copy both from the template.
   A copy must be the first triangulation again: the same bytes, certified
   with exact predicates on the copied sites, and the same faces after the
   same insertions (among them points on the sites' side lines). Each Check
   case runs in its own process, so the first hdt_create here builds. */
START_TEST(later_triangulations_are_the_first) {
  const int genera[] = {2, 5, 12};
  for (size_t k = 0; k < sizeof genera / sizeof *genera; ++k) {
    const int g = genera[k];
    hdt_triangulation *first = new_triangulation(g), *later = new_triangulation(g);
    size_t n1, n2;
    unsigned char *b1 = observable_bytes(first, &n1), *b2 = observable_bytes(later, &n2);
    expect(n1 == n2 && memcmp(b1, b2, n1) == 0, "g=%d: a later triangulation differs from the first", g);
    free(b1), free(b2);
    OK(hdt_validate(later));
    double xy[2 * 41];
    uint64_t seed = 7;
    for (int i = 0; i < 40; ++i) {
      const double r = 0.9 * uniform01(&seed), a = 2 * acos(-1.0) * uniform01(&seed);
      xy[2 * i] = r * cos(a), xy[2 * i + 1] = r * sin(a);
    }
    OK(hdt_polygon_side_midpoint(g, 1, &xy[80], &xy[81])); /* a site itself */
    OK(hdt_insert_many(first, xy, 41, NULL));
    OK(hdt_insert_many(later, xy, 41, NULL));
    OK(hdt_validate(later));
    b1 = observable_bytes(first, &n1), b2 = observable_bytes(later, &n2);
    expect(n1 == n2 && memcmp(b1, b2, n1) == 0, "g=%d: the same insertions gave other faces", g);
    free(b1), free(b2);
    hdt_destroy(first), hdt_destroy(later);
  }
}
END_TEST

int main(void) {
  const TTest *const tests[] = {at_most_14_at_genus_2, near_the_area_bound, near_the_area_bound_to_genus_64,
                                near_the_area_bound_to_genus_256, later_triangulations_are_the_first};
  return run_tests("dummies", tests, sizeof tests / sizeof tests[0]);
}
