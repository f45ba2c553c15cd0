/* Points sampled along curves: the Euclidean segment, a circle about 0, a
 * geodesic, a horocycle, a hypercycle and the polygon's two axes. They put
 * thousands of points on one Euclidean line or circle (exactly cocircular
 * in-circle tests) and give the dummies thousands of neighbours, which made
 * removal cubic (minutes at a few thousand points). Each case inserts the
 * points, removes every dummy that can go, and checks the result with the
 * library's exact validation, Euler's formula and the counts; the suite's
 * timeout (meson.build) bounds the time. */
#include "curve_points.h"
#include "hdt_test.h"

enum { POINTS = 3000 };

static void triangulate_curve(int genus, curve_shape shape) {
  double *xy = malloc(2 * POINTS * sizeof *xy);
  ck_assert_ptr_nonnull(xy);
  curve_points(shape, genus, POINTS, 7, xy);
  hdt_triangulation *t = NULL;
  ck_assert_int_eq(hdt_create(&t, genus), HDT_OK);
  ck_assert_int_eq(hdt_insert_many(t, xy, POINTS, NULL), HDT_OK);
  const size_t dummies = hdt_dummy_count(t);
  size_t remaining = 0;
  ck_assert_int_eq(hdt_remove_dummies(t, &remaining), HDT_OK);
  expect(hdt_validate(t) == HDT_OK, "%s at genus %d: %s", curve_shape_names[shape], genus, hdt_last_error_message());
  ck_assert_uint_eq(remaining, hdt_dummy_count(t));
  ck_assert_uint_le(remaining, dummies);
  /* Every sampled point is distinct here, so each is a vertex. */
  ck_assert_uint_eq(hdt_vertex_count(t), POINTS + remaining);
  ck_assert_uint_eq(hdt_face_count(t), 2 * (hdt_vertex_count(t) + 2 * (size_t)genus - 2));
  /* A dummy left behind is one whose removal is refused, so a second sweep
     removes nothing more and changes nothing. */
  size_t again = 0;
  ck_assert_int_eq(hdt_remove_dummies(t, &again), HDT_OK);
  ck_assert_uint_eq(again, remaining);
  hdt_destroy(t);
  free(xy);
}

START_TEST(curves_genus_2) { triangulate_curve(2, (curve_shape)_i); }
END_TEST

START_TEST(curves_genus_3) { triangulate_curve(3, (curve_shape)_i); }
END_TEST

/* Removing one dummy of very high degree directly. */
START_TEST(remove_high_degree_dummy) {
  double *xy = malloc(2 * POINTS * sizeof *xy);
  ck_assert_ptr_nonnull(xy);
  curve_points(CURVE_SEGMENT, 2, POINTS, 11, xy);
  hdt_triangulation *t = NULL;
  ck_assert_int_eq(hdt_create(&t, 2), HDT_OK);
  ck_assert_int_eq(hdt_insert_many(t, xy, POINTS, NULL), HDT_OK);
  /* Each dummy in turn, as hdt_remove_vertex: removed, or refused with
     nothing changed. */
  const size_t bound = hdt_vertex_id_bound(t);
  for (uint32_t v = 0; v < bound; ++v) {
    if (hdt_vertex_is_dummy(t, v) != 1) continue;
    const size_t before = hdt_vertex_count(t);
    const hdt_status s = hdt_remove_vertex(t, v);
    expect(s == HDT_OK || s == HDT_ENOTSUP, "dummy %u: %s", v, hdt_last_error_message());
    ck_assert_uint_eq(hdt_vertex_count(t), before - (s == HDT_OK));
    expect(hdt_validate(t) == HDT_OK, "after dummy %u: %s", v, hdt_last_error_message());
  }
  hdt_destroy(t);
  free(xy);
}
END_TEST

/* The faces, vertices and translations, in *out (malloc'ed). */
static size_t snapshot_faces(const hdt_triangulation *t, int32_t **out) {
  faces_t f = read_faces(t);
  *out = malloc(6 * f.n * sizeof **out + 1);
  ck_assert(*out);
  for (size_t i = 0; i < 3 * f.n; ++i) (*out)[i] = (int32_t)f.v[i], (*out)[3 * f.n + i] = f.tr[i];
  faces_free(&f);
  return f.n;
}

/* A refused removal, also one refused before its hole is filled (the
   dummy at the centre of the circle, those beside the segment), leaves
   every face as it was. */
START_TEST(refused_removal_changes_nothing) {
  const int genus = 2 + _i / 2;
  const curve_shape shape = _i % 2 ? CURVE_CIRCLE : CURVE_SEGMENT;
  double *xy = malloc(2 * POINTS * sizeof *xy);
  ck_assert_ptr_nonnull(xy);
  curve_points(shape, genus, POINTS, 5, xy);
  hdt_triangulation *t = NULL;
  ck_assert_int_eq(hdt_create(&t, genus), HDT_OK);
  ck_assert_int_eq(hdt_insert_many(t, xy, POINTS, NULL), HDT_OK);
  size_t remaining = 0;
  ck_assert_int_eq(hdt_remove_dummies(t, &remaining), HDT_OK);
  ck_assert_uint_gt(remaining, 0);
  const size_t bound = hdt_vertex_id_bound(t);
  for (uint32_t v = 0; v < bound; ++v) {
    if (hdt_vertex_is_dummy(t, v) != 1) continue;
    int32_t *before = NULL, *after = NULL;
    const size_t n = snapshot_faces(t, &before);
    expect(hdt_remove_vertex(t, v) == HDT_ENOTSUP, "dummy %u left by hdt_remove_dummies: %s", v,
           hdt_last_error_message());
    ck_assert_uint_eq(snapshot_faces(t, &after), n);
    expect(memcmp(before, after, 6 * n * sizeof *before) == 0, "refusing dummy %u changed the faces", v);
    free(before);
    free(after);
  }
  hdt_destroy(t);
  free(xy);
}
END_TEST

int main(void) {
  Suite *s = suite_create("curves");
  TCase *tc = tcase_create("curves");
  tcase_set_timeout(tc, 60);
  tcase_add_loop_test(tc, curves_genus_2, CURVE_SEGMENT, CURVE_SHAPES);
  tcase_add_loop_test(tc, curves_genus_3, CURVE_SEGMENT, CURVE_SHAPES);
  tcase_add_test(tc, remove_high_degree_dummy);
  tcase_add_loop_test(tc, refused_removal_changes_nothing, 0, 4);
  suite_add_tcase(s, tc);
  SRunner *sr = srunner_create(s);
  srunner_run_all(sr, CK_NORMAL);
  const int failed = srunner_ntests_failed(sr);
  srunner_free(sr);
  return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
