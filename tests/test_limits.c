/* The genus limits, at the limits: every function that takes a genus
   answers at HDT_GENUS_MAX (hdt_create at HDT_CREATE_GENUS_MAX) and refuses
   just beyond with HDT_ENOTSUP and a message naming the limit. The suite's
   timeout is the bound on time; the answers are checked against other
   functions of the API. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "hdt.h"
#include "hdt_test.h"

/* A point of F_g moved across side s_a by g_a comes back: its
   representative is the point again, to the rounding of the moved point
   (about 2^-53 / (1 - |m|^2) in hyperbolic distance), and the
   representative's word is the letter a + 2g, as hdt_word_reduce spells it. */
static void check_representative_round_trip(int genus, double x, double y, int32_t a) {
  const int32_t w[1] = {a};
  const int32_t inverse[1] = {(a + 2 * genus) % (4 * genus)};
  double mx, my, rx, ry;
  ck_assert_int_eq(hdt_word_apply(genus, w, 1, x, y, &mx, &my), HDT_OK);
  int32_t expected[1], got[1];
  size_t expected_length = 0, length = 0;
  ck_assert_int_eq(hdt_word_reduce(genus, inverse, 1, expected, 1, &expected_length), HDT_OK);
  const hdt_status s = hdt_point_representative(genus, mx, my, &rx, &ry, got, 1, &length);
  ck_assert_msg(s == HDT_OK, "genus %d: %s", genus, hdt_last_error_message());
  ck_assert_uint_eq(length, 1);
  ck_assert_int_eq(got[0], expected[0]);
  const double tolerance = 1e-14 / (1 - (mx * mx + my * my));
  ck_assert_msg(fabs(rx - x) < tolerance && fabs(ry - y) < tolerance, "genus %d: (%g, %g) came back as (%g, %g)",
                genus, x, y, rx, ry);
}

START_TEST(representative_at_the_maximum) {
  const int g = HDT_GENUS_MAX;
  double vx, vy, mx, my;
  ck_assert_int_eq(hdt_polygon_vertex(g, 0, &vx, &vy), HDT_OK);
  ck_assert_int_eq(hdt_polygon_side_midpoint(g, 1, &mx, &my), HDT_OK);
  /* Near the centre, near the corner v_0 and near the middle of side s_1
     (inside F_g), moved across near and far sides. */
  check_representative_round_trip(g, 0.1, 0.05, 0);
  check_representative_round_trip(g, 0.1, 0.05, 2 * g + 3);
  check_representative_round_trip(g, 0.9999 * vx, 0.9999 * vy, 1);
  check_representative_round_trip(g, 0.999 * mx, 0.999 * my, 3 * g);
  size_t length = 0;
  ck_assert_int_eq(hdt_point_representative(g + 1, 0.1, 0.1, NULL, NULL, NULL, 0, &length), HDT_ENOTSUP);
  ck_assert(strstr(hdt_last_error_message(), "HDT_GENUS_MAX") != NULL);
}
END_TEST

/* The neighbour set's last element at the maximum, without enumerating
   N: a run of 2g letters round a vertex of F_g, whose tile is the one
   opposite F_g at that vertex, so its centre is 2R from O (cosh R = A^2,
   A = cot(pi/4g), R the circumradius): L_00 = cosh 2R = 2 A^4 - 1. */
START_TEST(neighbour_word_at_the_maximum) {
  const int g = HDT_GENUS_MAX;
  size_t count = 0, length = 0;
  ck_assert_int_eq(hdt_neighbour_count(g, &count), HDT_OK);
  ck_assert_uint_eq(count, (size_t)(4 * g - 1) * (4 * g - 1));
  int32_t *w = malloc(2 * g * sizeof *w);
  ck_assert(w != NULL);
  ck_assert_int_eq(hdt_neighbour_word(g, count - 1, w, 2 * g, &length), HDT_OK);
  ck_assert_uint_eq(length, 2 * g);
  double L[9];
  ck_assert_int_eq(hdt_word_lorentz(g, w, length, L), HDT_OK);
  const long double A = 1.0L / tanl(3.14159265358979323846264338327950288L / (4 * g));
  const double expected = (double)(2 * A * A * A * A - 1);
  ck_assert_msg(fabs(L[0] - expected) < 1e-9 * expected, "L_00 = %.17g, expected %.17g", L[0], expected);
  free(w);
}
END_TEST

START_TEST(create_at_the_maximum) {
  const int g = HDT_CREATE_GENUS_MAX;
  hdt_triangulation *t = NULL;
  ck_assert_msg(hdt_create(&t, g) == HDT_OK, "%s", hdt_last_error_message());
  ck_assert_int_eq(hdt_validate(t), HDT_OK);
  const size_t V = hdt_vertex_count(t);
  ck_assert_uint_eq(hdt_dummy_count(t), V);
  ck_assert_uint_eq(hdt_face_count(t), 2 * (V + 2 * (size_t)g - 2));
  hdt_destroy(t);
}
END_TEST

START_TEST(create_beyond_the_maximum_names_the_limit) {
  const int too_large[] = {HDT_CREATE_GENUS_MAX + 1, HDT_GENUS_MAX};
  for (size_t i = 0; i < sizeof too_large / sizeof too_large[0]; ++i) {
    hdt_triangulation *t = (hdt_triangulation *)&t;
    ck_assert_int_eq(hdt_create(&t, too_large[i]), HDT_ENOTSUP);
    ck_assert(t == NULL);
    ck_assert_msg(strstr(hdt_last_error_message(), "HDT_CREATE_GENUS_MAX") != NULL, "%s", hdt_last_error_message());
  }
}
END_TEST

int main(void) {
  const TTest *const tests[] = {
      representative_at_the_maximum,
      neighbour_word_at_the_maximum,
      create_beyond_the_maximum_names_the_limit,
      create_at_the_maximum,
  };
  return run_tests("limits", tests, sizeof tests / sizeof tests[0]);
}
