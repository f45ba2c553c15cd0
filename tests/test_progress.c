/* Progress reports and cancellation (hdt_set_progress, HDT_0.5): the
   callback's calls are counted against the stride the header promises, a
   call stopped part way is checked against the points it reports done (the
   rest are inserted afterwards and must all be new), and a callback that
   never stops must leave the result byte for byte as without one
   (hdt_save). A callback that calls back into its own handle (re-entry:
   hdt_set_progress, any other call, hdt_destroy) is refused or deferred,
   never a crash, in each of the three calls that report. */
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

/* ---- Re-entry: the callback uses its own handle ---- */

/* The three calls that run a callback, on t; n points for insert_many. */
enum long_call { INSERT_MANY, REFINE, EPSILON_NET };
static const char *const long_call_name[] = {"hdt_insert_many", "hdt_refine", "hdt_epsilon_net"};

#define REENTRY_N 3000 /* insert_many's points: 11 reports */
#define REENTRY_EPS 0.05 /* refine's, epsilon_net's bound: > 3 strides of points at genus 2 */

static hdt_status run_long_call(hdt_triangulation *t, enum long_call c, const double *xy, uint32_t *ids,
                                size_t *added, size_t *unmet) {
  switch (c) {
    case INSERT_MANY: return hdt_insert_many(t, xy, REENTRY_N, ids);
    case REFINE: return hdt_refine(t, REENTRY_EPS, INFINITY, SIZE_MAX, added, unmet);
    default: return hdt_epsilon_net(t, REENTRY_EPS, SIZE_MAX, added, unmet);
  }
}

enum reentry_action { SET_PROGRESS, OTHER_CALLS, DESTROY };

typedef struct reentry {
  hdt_triangulation *t, *other; /* the busy handle; an idle one */
  enum reentry_action action;
  const char *running;          /* the long call's name */
  size_t calls, attempts;       /* reports; calls tried on t */
  char wrong[512];              /* the first attempt not refused as promised ("" when none) */
} reentry;

/* A call on the busy handle must fail with HDT_EINVAL, the message saying
   it is busy in the running call. */
static void expect_busy(reentry *r, hdt_status got, const char *what) {
  ++r->attempts;
  if (r->wrong[0]) return;
  const char *msg = hdt_last_error_message();
  char busy[64];
  snprintf(busy, sizeof busy, "the triangulation is busy in %s", r->running);
  if (got != HDT_EINVAL || !msg || !strstr(msg, busy))
    snprintf(r->wrong, sizeof r->wrong, "%s from %s's callback: status %d, message \"%s\"", what, r->running,
             (int)got, msg ? msg : "(null)");
}

static int reenter(void *user, size_t done, size_t total) {
  (void)done, (void)total;
  reentry *r = user;
  ++r->calls;
  hdt_triangulation *t = r->t;
  if (r->action == SET_PROGRESS) {
    expect_busy(r, hdt_set_progress(t, NULL, NULL, 0), "hdt_set_progress");
  } else if (r->action == DESTROY) {
    hdt_destroy(t); /* freed when the running call returns */
    hdt_destroy(t); /* twice: still nothing but the mark */
    expect_busy(r, hdt_validate(t), "hdt_validate after hdt_destroy");
  } else if (r->calls == 2) {
    uint32_t v = 7, ids[4];
    int32_t tr[4], word[8];
    size_t count = 0, face = 0, length = 0;
    double x = 0, y = 0, m[4];
    const double xy[2] = {0.01, 0.02};
    char text[16];
    expect_busy(r, hdt_insert(t, 0.01, 0.02, &v), "hdt_insert");
    expect_busy(r, hdt_insert_many(t, xy, 1, ids), "hdt_insert_many");
    expect_busy(r, hdt_remove_vertex(t, 0), "hdt_remove_vertex");
    expect_busy(r, hdt_remove_dummies(t, &count), "hdt_remove_dummies");
    expect_busy(r, hdt_refine(t, 0.01, INFINITY, 10, NULL, NULL), "hdt_refine");
    expect_busy(r, hdt_epsilon_net(t, 0.01, 10, NULL, NULL), "hdt_epsilon_net");
    expect_busy(r, hdt_faces(t, NULL, NULL, 0, &count), "hdt_faces");
    expect_busy(r, hdt_vertices(t, NULL, NULL, NULL, 0, &count), "hdt_vertices");
    expect_busy(r, hdt_vertex_point(t, 0, &x, &y), "hdt_vertex_point");
    expect_busy(r, hdt_locate(t, 0.1, 0.1, &face, tr), "hdt_locate");
    expect_busy(r, hdt_nearest_vertex(t, 0.1, 0.1, &v), "hdt_nearest_vertex");
    expect_busy(r, hdt_translation_word(t, 1, word, 8, &length), "hdt_translation_word");
    expect_busy(r, hdt_translation_matrix(t, 1, m), "hdt_translation_matrix");
    expect_busy(r, hdt_validate(t), "hdt_validate");
    expect_busy(r, hdt_quality(t, NULL, NULL, NULL, NULL), "hdt_quality");
    expect_busy(r, hdt_save(t, NULL, 0, &count), "hdt_save");
    expect_busy(r, hdt_edges(t, NULL, NULL, NULL, NULL, 0, &count), "hdt_edges");
    expect_busy(r, hdt_vertex_star(t, 0, NULL, NULL, NULL, 0, &count), "hdt_vertex_star");
    expect_busy(r, hdt_vertex_stars(t, NULL, NULL, NULL, NULL, 0, &count), "hdt_vertex_stars");
    expect_busy(r, hdt_voronoi_cells(t, NULL, NULL, 0, &count), "hdt_voronoi_cells");
    expect_busy(r, hdt_svg(t, 100, NULL, 0, text, sizeof text, &length), "hdt_svg");
    expect_busy(r, hdt_set_progress(t, NULL, NULL, 0), "hdt_set_progress");
    /* The counts stay allowed, and agree (the triangulation is whole
       between two points). */
    const size_t V = hdt_vertex_count(t);
    if (hdt_face_count(t) != 2 * (V + 2 * 2 - 2) || hdt_edge_count(t) != 3 * (V + 2) || hdt_genus(t) != 2 ||
        hdt_vertex_id_bound(t) < V || hdt_dummy_count(t) > V || hdt_vertex_is_dummy(t, 0) < 0)
      snprintf(r->wrong, sizeof r->wrong, "the counts inside %s disagree (V = %zu)", r->running, V);
    /* Another handle is not busy. */
    if (hdt_insert(r->other, 0.01, 0.02, NULL) != HDT_OK)
      snprintf(r->wrong, sizeof r->wrong, "hdt_insert on another handle: %s", hdt_last_error_message());
  }
  return 0;
}

static reentry new_reentry(hdt_triangulation *t, enum long_call c, enum reentry_action a) {
  reentry r = {t, NULL, a, long_call_name[c], 0, 0, ""};
  return r;
}

/* hdt_set_progress(t, NULL, NULL, 0) inside the callback is refused: the
   call goes on reporting to the same callback and completes. */
static void set_progress_in_callback(enum long_call c) {
  double *xy = small_disk_points(REENTRY_N, 21);
  uint32_t *ids = malloc(REENTRY_N * sizeof *ids);
  ck_assert_ptr_nonnull(ids);
  hdt_triangulation *t = new_triangulation(2);
  const size_t V0 = hdt_vertex_count(t);
  reentry r = new_reentry(t, c, SET_PROGRESS);
  OK(hdt_set_progress(t, reenter, &r, 0));
  size_t added = 0, unmet = 1;
  OK(run_long_call(t, c, xy, ids, &added, &unmet));
  expect(!r.wrong[0], "%s", r.wrong);
  ck_assert_uint_eq(r.attempts, r.calls);
  OK(hdt_validate(t));
  if (c == INSERT_MANY) {
    ck_assert_uint_eq(r.calls, REENTRY_N / STRIDE + 1);
    ck_assert_uint_eq(hdt_vertex_count(t), V0 + REENTRY_N);
    for (size_t i = 0; i < REENTRY_N; ++i) {
      double x, y;
      OK(hdt_vertex_point(t, ids[i], &x, &y));
      expect(x == xy[2 * i] && y == xy[2 * i + 1], "point %zu is not vertex %u", i, ids[i]);
    }
  } else {
    ck_assert_uint_eq(r.calls, added / STRIDE + 1);
    ck_assert_uint_eq(unmet, 0);
    ck_assert_uint_eq(hdt_vertex_count(t), V0 + added);
  }
  /* The callback is still t's: the next call reports to it too. */
  const size_t before = r.calls;
  OK(hdt_insert_many(t, xy, 1, NULL));
  ck_assert_uint_eq(r.calls, before + 1);
  hdt_destroy(t);
  free(ids), free(xy);
}

START_TEST(set_progress_in_insert_many_callback) { set_progress_in_callback(INSERT_MANY); }
END_TEST
START_TEST(set_progress_in_refine_callback) { set_progress_in_callback(REFINE); }
END_TEST
START_TEST(set_progress_in_epsilon_net_callback) { set_progress_in_callback(EPSILON_NET); }
END_TEST

/* Every other call on t inside the callback is refused and changes
   nothing: the result is byte for byte the one without a callback. The
   counts stay allowed; another handle is not busy. */
static void calls_in_callback(enum long_call c) {
  double *xy = small_disk_points(REENTRY_N, 22);
  hdt_triangulation *plain = new_triangulation(2), *t = new_triangulation(2);
  reentry r = new_reentry(t, c, OTHER_CALLS);
  r.other = new_triangulation(2);
  OK(hdt_set_progress(t, reenter, &r, 0));
  size_t added = 0, unmet = 0, plain_added = 0, plain_unmet = 0;
  OK(run_long_call(t, c, xy, NULL, &added, &unmet));
  OK(run_long_call(plain, c, xy, NULL, &plain_added, &plain_unmet));
  expect(!r.wrong[0], "%s", r.wrong);
  ck_assert_uint_gt(r.attempts, 20);
  ck_assert_uint_eq(hdt_vertex_count(r.other), hdt_vertex_count(plain) - (c == INSERT_MANY ? REENTRY_N : added) + 1);
  ck_assert_uint_eq(added, plain_added);
  ck_assert_uint_eq(unmet, plain_unmet);
  size_t sa, sb;
  unsigned char *a = saved(t, &sa), *b = saved(plain, &sb);
  ck_assert_uint_eq(sa, sb);
  ck_assert(memcmp(a, b, sa) == 0);
  OK(hdt_validate(t));
  free(a), free(b);
  hdt_destroy(t), hdt_destroy(plain), hdt_destroy(r.other);
  free(xy);
}

START_TEST(calls_in_insert_many_callback) { calls_in_callback(INSERT_MANY); }
END_TEST
START_TEST(calls_in_refine_callback) { calls_in_callback(REFINE); }
END_TEST
START_TEST(calls_in_epsilon_net_callback) { calls_in_callback(EPSILON_NET); }
END_TEST

/* hdt_destroy(t) inside the callback: the call stops at that report (no
   other comes), returns HDT_OK with its outputs written, and frees t as it
   returns (valgrind: no leak, no invalid access). Also from the final
   report of a call too short for any other (insert_many of 100 points). */
static void destroy_in_callback(enum long_call c) {
  double *xy = small_disk_points(REENTRY_N, 23);
  uint32_t *ids = malloc(REENTRY_N * sizeof *ids);
  ck_assert_ptr_nonnull(ids);
  hdt_triangulation *t = new_triangulation(2);
  reentry r = new_reentry(t, c, DESTROY);
  OK(hdt_set_progress(t, reenter, &r, 0));
  size_t added = 0, unmet = 0;
  OK(run_long_call(t, c, xy, ids, &added, &unmet));
  expect(!r.wrong[0], "%s", r.wrong);
  ck_assert_uint_eq(r.calls, 1);
  if (c == INSERT_MANY) {
    size_t written = 0;
    for (size_t i = 0; i < REENTRY_N; ++i) written += ids[i] != HDT_NO_VERTEX;
    ck_assert_uint_eq(written, STRIDE);
  } else {
    ck_assert_uint_eq(added, STRIDE);
    ck_assert_uint_gt(unmet, 0);
  }
  if (c == INSERT_MANY) {
    t = new_triangulation(2);
    r = new_reentry(t, c, DESTROY);
    OK(hdt_set_progress(t, reenter, &r, 0));
    OK(hdt_insert_many(t, xy, 100, ids));
    ck_assert_uint_eq(r.calls, 1);
    for (size_t i = 0; i < 100; ++i) ck_assert_uint_ne(ids[i], HDT_NO_VERTEX);
  }
  free(ids), free(xy);
}

START_TEST(destroy_in_insert_many_callback) { destroy_in_callback(INSERT_MANY); }
END_TEST
START_TEST(destroy_in_refine_callback) { destroy_in_callback(REFINE); }
END_TEST
START_TEST(destroy_in_epsilon_net_callback) { destroy_in_callback(EPSILON_NET); }
END_TEST

int main(void) {
  const TTest *const tests[] = {
      insert_many_reports_every_stride, insert_many_interval_limits_calls, insert_many_stops,
      callback_changes_nothing, refine_reports_and_stops, bad_arguments,
      set_progress_in_insert_many_callback, set_progress_in_refine_callback, set_progress_in_epsilon_net_callback,
      calls_in_insert_many_callback, calls_in_refine_callback, calls_in_epsilon_net_callback,
      destroy_in_insert_many_callback, destroy_in_refine_callback, destroy_in_epsilon_net_callback,
  };
  return run_tests("progress", tests, sizeof tests / sizeof *tests);
}
