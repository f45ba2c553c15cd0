/* Faces double cannot resolve: the constructions (hdt_voronoi_vertices,
 * hdt_voronoi_edges, hdt_quality, refinement) must still answer, with the
 * circle through the face's corners. Each triangulation here comes from the
 * fuzzer (tests/fuzz/crashes/circumcircle-* and voronoi-needles), where
 * these calls returned HDT_EINTERNAL, a circle of radius above the
 * guarantee, or corners on the unit circle: corners at 1e-238 whose squares underflow, needles of points an
 * ulp off a line, a point an ulp from a dummy's algebraic point, a point
 * 2e-15 from the polygon's corner seen under a translation, a point 5e-5
 * from the unit circle.
 *
 * The check is independent of the library's formulas: every Voronoi vertex
 * is at the same hyperbolic distance, its radius, from the three corners
 * hdt_face_points gives (distances from hypot, which neither underflows
 * nor cancels; up to the rounding of corners that are translated or a
 * dummy's), and radii are positive and below sys/4.
 */
#include "hdt_test.h"

static double distance(const double *p, const double *q) {
  const double a = 1 - (p[0] * p[0] + p[1] * p[1]), b = 1 - (q[0] * q[0] + q[1] * q[1]);
  return 2 * asinh(hypot(p[0] - q[0], p[1] - q[1]) / sqrt(a * b));
}

static void check_circles(hdt_triangulation *t) {
  const size_t f = hdt_face_count(t);
  double *centres = malloc(16 * f), *radii = malloc(8 * f), *corners = malloc(48 * f), *edges = malloc(64 * f);
  size_t count = 0;
  hdt_status s = hdt_voronoi_vertices(t, centres, radii, f, &count);
  ck_assert_msg(s == HDT_OK, "hdt_voronoi_vertices: %s (%s)", hdt_status_string(s), hdt_last_error_message());
  ck_assert_int_eq(hdt_face_points(t, corners, f, &count), HDT_OK);
  uint32_t *vertices = malloc(12 * f);
  int32_t *translations = malloc(12 * f);
  ck_assert_int_eq(hdt_faces(t, vertices, translations, f, &count), HDT_OK);
  const double quarter_sys = hdt_systole(hdt_genus(t)) / 4;
  for (size_t i = 0; i < f; ++i) {
    expect(radii[i] > 0 && radii[i] < quarter_sys, "face %zu: radius %a", i, radii[i]);
    for (int k = 0; k < 3; ++k) {
      /* A translated corner, or a dummy's (maybe algebraic) point, is
         rounded: up to some tens of ulps through a translation, times the
         disk's conformal factor as a distance. (That hides nothing on
         faces of normal size: before the fix, the face near the corner had
         radius 1.18 for a true 0.55.) */
      const double *p = corners + 6 * i + 2 * k;
      const int rounded = translations[3 * i + k] != 0 || hdt_vertex_is_dummy(t, vertices[3 * i + k]);
      const double d = distance(centres + 2 * i, p), slack = rounded ? 128 * 0x1p-52 / (1 - (p[0] * p[0] + p[1] * p[1])) : 0;
      expect(fabs(d - radii[i]) <= 1e-9 * radii[i] + slack,
             "face %zu, corner %d: at %.17g from the centre, radius %.17g", i, k, d, radii[i]);
    }
  }
  s = hdt_voronoi_edges(t, edges, hdt_edge_count(t), &count);
  ck_assert_msg(s == HDT_OK, "hdt_voronoi_edges: %s (%s)", hdt_status_string(s), hdt_last_error_message());
  double min_angle, max_ratio, max_radius, min_edge;
  s = hdt_quality(t, &min_angle, &max_ratio, &max_radius, &min_edge);
  ck_assert_msg(s == HDT_OK, "hdt_quality: %s (%s)", hdt_status_string(s), hdt_last_error_message());
  ck_assert(min_angle >= 0 && min_angle < 1.0471975511965979 /* pi/3 */ && max_radius < quarter_sys && min_edge >= 0);
  /* The cells compute the centres through the handle's cache, by a path of
     their own (the radius kept for later); the Voronoi vertices then read
     them from there: the same bytes as computed directly above. */
  size_t n = 0;
  ck_assert_int_eq(hdt_voronoi_cells(t, NULL, NULL, 0, &n), HDT_OK);
  size_t *offsets = malloc((hdt_vertex_id_bound(t) + 1) * sizeof *offsets);
  double *cells = malloc(16 * n), *again = malloc(16 * f), *radii_again = malloc(8 * f);
  s = hdt_voronoi_cells(t, offsets, cells, n, &n);
  ck_assert_msg(s == HDT_OK, "hdt_voronoi_cells: %s (%s)", hdt_status_string(s), hdt_last_error_message());
  ck_assert_int_eq(hdt_voronoi_vertices(t, again, radii_again, f, &count), HDT_OK);
  ck_assert(memcmp(again, centres, 16 * f) == 0 && memcmp(radii_again, radii, 8 * f) == 0);
  free(offsets), free(cells), free(again), free(radii_again);
  free(centres), free(radii), free(corners), free(edges), free(vertices), free(translations);
}

static void insert_all(hdt_triangulation *t, const double *xy, size_t n) {
  for (size_t i = 0; i < n; ++i) {
    const hdt_status s = hdt_insert(t, xy[2 * i], xy[2 * i + 1], NULL);
    ck_assert_msg(s == HDT_OK || s == HDT_EEXISTS, "hdt_insert(%a, %a): %s", xy[2 * i], xy[2 * i + 1],
                  hdt_status_string(s));
  }
}

START_TEST(corners_at_1e_238) {
  hdt_triangulation *t;
  ck_assert_int_eq(hdt_create(&t, 3), HDT_OK);
  const double xy[] = {-0.5, -0.5, -0x0.0000000000001p-1022, 0x0.0000000000001p-1022, -0x1.3p-2, 0x1.3p-2,
                       -0x1.e8e8e8e8e0002p-791, -0x1.e8e8e8e8e8e8ep-791};
  insert_all(t, xy, 4);
  check_circles(t);
  hdt_destroy(t);
}
END_TEST

START_TEST(needles_an_ulp_off_a_line) {
  hdt_triangulation *t;
  ck_assert_int_eq(hdt_create(&t, 3), HDT_OK);
  const double xy[] = {-0.5, -0.5, -0.5, -0x1.3p-2, -0.5, -0x1.8p-4, -0x1.ed47188fc0474p-3, 0x1.cc3c0020af284p-1,
                       -0x1.8p-4, 0x1.8p-4, -0x1.8000000000003p-4, 0x1.8000000000002p-4, -0x1.0000000000003p-1,
                       -0x1.2fffffffffffep-2, -0x1.0000000000003p-1, -0x1.ffffffffffffep-2};
  insert_all(t, xy, 8);
  check_circles(t);
  hdt_destroy(t);
}
END_TEST

START_TEST(an_ulp_from_a_dummy) {
  /* (0.455, 0.455) rounds the side midpoint m_1, a dummy's algebraic point;
     the next point is an ulp from the midpoint m_3. */
  hdt_triangulation *t;
  ck_assert_int_eq(hdt_create(&t, 2), HDT_OK);
  const double xy[] = {0, 0, 0x1.d203138f6c828p-2, 0x1.d203138f6c828p-2, -0x1.d203138f6c827p-2, 0x1.d203138f6c829p-2};
  insert_all(t, xy, 3);
  check_circles(t);
  hdt_destroy(t);
}
END_TEST

START_TEST(near_a_corner_under_a_translation) {
  /* A point 2e-15 from a polygon vertex's copy: the face holding both sees
     them through translations, whose rounded images bound no useful circle. */
  hdt_triangulation *t;
  ck_assert_int_eq(hdt_create(&t, 3), HDT_OK);
  const double xy[] = {-0x1.ed47188fc0474p-3, -0x1.cc3c0020af281p-1, -0x1.ed47188fc0477p-3, -0x1.cc3c0020af285p-1};
  insert_all(t, xy, 2);
  check_circles(t);
  /* Refinement meets the same face and must place its circumcentre. */
  size_t added = 0, unmet = 1;
  ck_assert_int_eq(hdt_refine(t, 0.4, 2, 50, &added, &unmet), HDT_OK);
  ck_assert_int_eq(hdt_validate(t), HDT_OK);
  hdt_destroy(t);
}
END_TEST

START_TEST(a_point_near_the_circle) {
  /* A point 5e-5 from the unit circle: its face corners came out on the
     circle, (0.6, 0.8), from the long translation applied to it in double. */
  hdt_triangulation *t;
  ck_assert_int_eq(hdt_create(&t, 2), HDT_OK);
  const double xy[] = {0x1.8p-4, 0x1.9p-3, 0x1.e9c49086985d9p-1, -0x1.2a78fbf3c777ap-2, 0x1.e9c49086985d9p-2,
                       -0x1.2a78fbf3c777ap-3, 0x1.4000d21000d02p-751, 0x1.3000d05000dp-807};
  insert_all(t, xy, 4);
  const size_t f = hdt_face_count(t);
  double *corners = malloc(48 * f);
  size_t count = 0;
  ck_assert_int_eq(hdt_face_points(t, corners, f, &count), HDT_OK);
  /* F_g's copies that canonical faces reach stay well inside (|z| < 0.95 at genus 2). */
  for (size_t i = 0; i < 3 * f; ++i)
    expect(hypot(corners[2 * i], corners[2 * i + 1]) < 0.95, "corner %zu at (%a, %a)", i, corners[2 * i],
           corners[2 * i + 1]);
  free(corners);
  check_circles(t);
  hdt_destroy(t);
}
END_TEST

int main(void) {
  const TTest *const tests[] = {corners_at_1e_238, needles_an_ulp_off_a_line, an_ulp_from_a_dummy,
                                near_a_corner_under_a_translation, a_point_near_the_circle};
  return run_tests("degenerate_faces", tests, sizeof tests / sizeof tests[0]);
}
