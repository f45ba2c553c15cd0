/* Progress reports and cancellation (hdt_set_progress, HDT_0.5): the
   callback's calls are counted against the stride the header promises, a
   call stopped part way is checked against the points it reports done (the
   rest are inserted afterwards and must all be new), and a callback that
   never stops must leave the result byte for byte as without one
   (hdt_save). */
#include <math.h>

#include "hdt_test.h"

#define STRIDE 256 /* hdt.h: the clock is read once per 256 points */

typedef struct record {
  size_t calls, stop_at; /* stop at call number stop_at (0: never) */
  size_t last_done, last_total;
  int monotone, bounded;
} record;

static int note(void *user, size_t done, size_t total) {
  record *r = user;
  if (r->calls > 0 && done < r->last_done) r->monotone = 0;
  if (total != 0 && done > total) r->bounded = 0;
  r->last_done = done, r->last_total = total;
  ++r->calls;
  return r->stop_at != 0 && r->calls == r->stop_at;
}

static record fresh(size_t stop_at) { return (record){0, stop_at, 0, 0, 1, 1}; }

/* hdt_save's bytes (malloc'd), for comparing two triangulations. */
static unsigned char *saved(const hdt_triangulation *t, size_t *size) {
  OK(hdt_save(t, NULL, 0, size));
  unsigned char *bytes = malloc(*size);
  ck_assert_ptr_nonnull(bytes);
  OK(hdt_save(t, bytes, *size, size));
  return bytes;
}

START_TEST(insert_many_reports_every_stride) {
  const size_t n = 10000;
  double *xy = small_disk_points(n, 11);
  hdt_triangulation *t = new_triangulation(2);
  record r = fresh(0);
  OK(hdt_set_progress(t, note, &r, 0));
  OK(hdt_insert_many(t, xy, n, NULL));
  /* interval 0: once per stride, then the final report done == total. */
  ck_assert_uint_eq(r.calls, n / STRIDE + 1);
  ck_assert(r.monotone && r.bounded);
  ck_assert_uint_eq(r.last_done, n);
  ck_assert_uint_eq(r.last_total, n);
  OK(hdt_validate(t));
  hdt_destroy(t);
  free(xy);
}
END_TEST

START_TEST(insert_many_interval_limits_calls) {
  const size_t n = 20000;
  double *xy = small_disk_points(n, 12);
  hdt_triangulation *t = new_triangulation(2);
  record r = fresh(0);
  /* An hour between reports: only the final one comes. */
  OK(hdt_set_progress(t, note, &r, 3600));
  OK(hdt_insert_many(t, xy, n, NULL));
  ck_assert_uint_eq(r.calls, 1);
  ck_assert_uint_eq(r.last_done, n);
  hdt_destroy(t);
  free(xy);
}
END_TEST

START_TEST(insert_many_stops) {
  const size_t n = 10000, k = 3;
  double *xy = small_disk_points(n, 13);
  uint32_t *ids = malloc(n * sizeof *ids);
  ck_assert_ptr_nonnull(ids);
  hdt_triangulation *t = new_triangulation(2);
  const size_t V0 = hdt_vertex_count(t), bound0 = hdt_vertex_id_bound(t);
  record r = fresh(k);
  OK(hdt_set_progress(t, note, &r, 0));
  OK(hdt_insert_many(t, xy, n, ids));
  ck_assert_uint_eq(r.calls, k); /* no report after the stop */
  OK(hdt_validate(t));
  size_t written = 0, fresh_ids = 0;
  for (size_t i = 0; i < n; ++i) {
    if (ids[i] == HDT_NO_VERTEX) continue;
    ++written;
    fresh_ids += ids[i] >= bound0;
    double x, y;
    OK(hdt_vertex_point(t, ids[i], &x, &y));
    expect(x == xy[2 * i] && y == xy[2 * i + 1], "point %zu is not vertex %u", i, ids[i]);
  }
  ck_assert_uint_eq(written, k * STRIDE);
  ck_assert_uint_eq(hdt_vertex_count(t), V0 + fresh_ids);
  /* The points not reported done are not in the triangulation. */
  OK(hdt_set_progress(t, NULL, NULL, 0));
  for (size_t i = 0; i < n; ++i)
    if (ids[i] == HDT_NO_VERTEX) OK(hdt_insert(t, xy[2 * i], xy[2 * i + 1], NULL));
  ck_assert_uint_eq(hdt_vertex_count(t), V0 + n);
  OK(hdt_validate(t));
  hdt_destroy(t);
  free(ids);
  free(xy);
}
END_TEST

START_TEST(callback_changes_nothing) {
  const size_t n = 5000;
  double *xy = small_disk_points(n, 14);
  hdt_triangulation *a = new_triangulation(3), *b = new_triangulation(3);
  record r = fresh(0);
  OK(hdt_insert_many(a, xy, n, NULL));
  OK(hdt_set_progress(b, note, &r, 0));
  OK(hdt_insert_many(b, xy, n, NULL));
  OK(hdt_epsilon_net(a, 0.1, SIZE_MAX, NULL, NULL));
  OK(hdt_epsilon_net(b, 0.1, SIZE_MAX, NULL, NULL));
  size_t sa, sb;
  unsigned char *ba = saved(a, &sa), *bb = saved(b, &sb);
  ck_assert_uint_eq(sa, sb);
  ck_assert(memcmp(ba, bb, sa) == 0);
  free(ba), free(bb);
  hdt_destroy(a), hdt_destroy(b);
  free(xy);
}
END_TEST

START_TEST(refine_reports_and_stops) {
  /* Complete: the total is unknown (0) until the final report. */
  hdt_triangulation *t = new_triangulation(2);
  record r = fresh(0);
  size_t added, unmet;
  OK(hdt_set_progress(t, note, &r, 0));
  OK(hdt_epsilon_net(t, 0.05, SIZE_MAX, &added, &unmet));
  ck_assert_uint_eq(unmet, 0);
  ck_assert_uint_gt(added, 3 * STRIDE);
  ck_assert_uint_eq(r.calls, added / STRIDE + 1);
  ck_assert(r.monotone);
  ck_assert_uint_eq(r.last_done, added);
  ck_assert_uint_eq(r.last_total, added);
  const size_t complete = hdt_vertex_count(t);
  hdt_destroy(t);

  /* Stopped after 2 reports: 2 strides of points, valid, bounds unmet;
     going on afterwards completes the same bounds. */
  t = new_triangulation(2);
  const size_t V0 = hdt_vertex_count(t);
  r = fresh(2);
  OK(hdt_set_progress(t, note, &r, 0));
  OK(hdt_epsilon_net(t, 0.05, SIZE_MAX, &added, &unmet));
  ck_assert_uint_eq(r.calls, 2);
  ck_assert_uint_eq(added, 2 * STRIDE);
  ck_assert_uint_gt(unmet, 0);
  ck_assert_uint_eq(hdt_vertex_count(t), V0 + added);
  OK(hdt_validate(t));
  OK(hdt_set_progress(t, NULL, NULL, 0));
  OK(hdt_epsilon_net(t, 0.05, SIZE_MAX, &added, &unmet));
  ck_assert_uint_eq(unmet, 0);
  double radius;
  OK(hdt_quality(t, NULL, NULL, &radius, NULL));
  ck_assert(radius <= 0.05);
  /* Not necessarily the same points (another order), a similar count. */
  ck_assert(fabs((double)hdt_vertex_count(t) - (double)complete) < 0.1 * (double)complete);
  hdt_destroy(t);
}
END_TEST

START_TEST(bad_arguments) {
  record r = fresh(0);
  ck_assert_int_eq(hdt_set_progress(NULL, note, &r, 0), HDT_EINVAL);
  hdt_triangulation *t = new_triangulation(2);
  ck_assert_int_eq(hdt_set_progress(t, note, &r, -1), HDT_EINVAL);
  ck_assert_int_eq(hdt_set_progress(t, note, &r, NAN), HDT_EINVAL);
  ck_assert_int_eq(hdt_set_progress(t, note, &r, INFINITY), HDT_OK); /* only the final report */
  /* A refused call leaves the previous callback: none, here. */
  OK(hdt_set_progress(t, NULL, NULL, 0));
  ck_assert_int_eq(hdt_set_progress(t, note, &r, NAN), HDT_EINVAL);
  double xy[2] = {0.1, 0.2};
  OK(hdt_insert_many(t, xy, 1, NULL));
  ck_assert_uint_eq(r.calls, 0);
  hdt_destroy(t);
}
END_TEST

int main(void) {
  const TTest *const tests[] = {
      insert_many_reports_every_stride, insert_many_interval_limits_calls, insert_many_stops,
      callback_changes_nothing, refine_reports_and_stops, bad_arguments,
  };
  return run_tests("progress", tests, sizeof tests / sizeof *tests);
}
