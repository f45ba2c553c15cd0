/* An independent cross-check of the triangulations: the Delaunay faces of a
 * small point set found by brute force over the images of the vertices under
 * the neighbour set N, compared with hdt_faces. The method and why it is
 * sound are in brute_force.h (shared with the differential fuzz target
 * tests/fuzz/fuzz_brute_force.c); this suite checks its premises and runs it
 * on random point sets. */
#include "brute_force.h"
#include "hdt_test.h"

/* ---- The neighbour set, asserted ---- */

static bf_nset nset_make(int g) {
  bf_nset n;
  char msg[512];
  expect(bf_nset_make(&n, g, msg, sizeof msg) == 0, "%s", msg);
  return n;
}

/* The translation id of the element with canonical word w, or -1. */
static long nset_find(const bf_nset *n, const word_t *w) { return bf_nset_find(n, w->a, w->n); }

/* The canonical word of id as a word_t. */
static word_t nset_word(const bf_nset *n, size_t id) {
  word_t w = {0};
  size_t len;
  const int32_t *a = bf_nset_word(n, id, &len);
  for (size_t i = 0; i < len; ++i) word_push(&w, a[i]);
  return w;
}

/* ---- The premise: balls of radius sys/2 about points of F lie in D_N ---- */

/* Every point p within sys/2 of a point a of F_g is h(rep) for some h in N:
   hdt_point_representative gives w with w(p) in F_g, so h = w^-1. */
START_TEST(half_systole_balls_lie_in_d_n) {
  uint64_t rng = 0x5eed;
  for (int g = 2; g <= 4; ++g) {
    bf_nset ns = nset_make(g);
    const double sys = hdt_systole(g);
    double vx, vy;
    ck_assert_int_eq(hdt_polygon_vertex(g, 0, &vx, &vy), HDT_OK);
    const double rv = hypot(vx, vy);
    int tried = 0;
    while (tried < 600) {
      /* a: uniform in the disk of F's vertices, kept when in F; every third one
         just inside a vertex of F (on the ray from 0, F is star-shaped), where
         the ball reaches farthest out. */
      double ax, ay;
      if (tried % 3 == 0) {
        const double s = 1 - 1e-3 * (double)(rng_next(&rng) >> 11) * 0x1p-53;
        ck_assert_int_eq(hdt_polygon_vertex(g, rng_below(&rng, 4 * g), &ax, &ay), HDT_OK);
        ax *= s, ay *= s;
      } else {
        const double ang = 2 * acos(-1.0) * (double)(rng_next(&rng) >> 11) * 0x1p-53;
        const double r = rv * sqrt((double)(rng_next(&rng) >> 11) * 0x1p-53);
        ax = r * cos(ang), ay = r * sin(ang);
      }
      size_t len = 0;
      ck_assert_int_eq(hdt_point_representative(g, ax, ay, NULL, NULL, NULL, 0, &len), HDT_OK);
      if (len != 0) continue;
      ++tried;
      /* p at hyperbolic distance d < sys/2 from a: translate a point at
         Euclidean radius tanh(d/2) from 0 to a. */
      const double d = sys / 2 * (1 - 1e-6) * sqrt((double)(rng_next(&rng) >> 11) * 0x1p-53);
      const double phi = 2 * acos(-1.0) * (double)(rng_next(&rng) >> 11) * 0x1p-53;
      const double wx = tanh(d / 2) * cos(phi), wy = tanh(d / 2) * sin(phi);
      /* (w + a) / (1 + conj(a) w) */
      const double nr = wx + ax, ni = wy + ay, dr = 1 + ax * wx + ay * wy, di = ax * wy - ay * wx;
      const double px = (nr * dr + ni * di) / (dr * dr + di * di), py = (ni * dr - nr * di) / (dr * dr + di * di);
      word_t w = {0};
      const hdt_status s = hdt_point_representative(g, px, py, NULL, NULL, w.a, TW_MAX, &w.n);
      expect(s == HDT_OK, "hdt_point_representative: %s", hdt_last_error_message());
      const word_t inv = word_inverse(g, &w);
      const word_t h = reduce_word(g, &inv);
      char buf[512];
      expect(nset_find(&ns, &h) >= 0, "g=%d: p (%.17g, %.17g) at distance %g < sys/2 of a (%.17g, %.17g) in F lies in h(F), h = [%s] not in N",
             g, px, py, d, ax, ay, word_str(&h, buf, sizeof buf));
    }
    bf_nset_free(&ns);
  }
}
END_TEST

/* The matrices the brute force uses agree with the triangulation's own
   table for ids 0..|N|-1 (hdt_translation_matrix). */
START_TEST(translation_ids_of_n_are_fixed) {
  for (int g = 2; g <= 3; ++g) {
    bf_nset ns = nset_make(g);
    hdt_triangulation *t = NULL;
    ck_assert_int_eq(hdt_create(&t, g), HDT_OK);
    char b1[512], b2[512];
    for (size_t id = 0; id < ns.count; ++id) {
      double m[4];
      word_t w = {0};
      ck_assert_int_eq(hdt_translation_matrix(t, (int32_t)id, m), HDT_OK);
      expect(matrix_gap(m, ns.m[id]) < 1e-12, "g=%d id %zu: translation matrix differs from the word's", g, id);
      ck_assert_int_eq(hdt_translation_word(t, (int32_t)id, w.a, TW_MAX, &w.n), HDT_OK);
      const word_t nw = nset_word(&ns, id);
      expect(word_eq(&w, &nw), "g=%d id %zu: translation word [%s], neighbour word [%s]", g, id,
             word_str(&w, b1, sizeof b1), word_str(&nw, b2, sizeof b2));
    }
    hdt_destroy(t);
    bf_nset_free(&ns);
  }
}
END_TEST

/* ---- The cross-check ---- */

/* n random points uniform for hyperbolic area in F_g: uniform in the
   hyperbolic disk about 0 through F's vertices, kept when their
   representative is themselves. */
static void random_points_in_f(uint64_t *rng, int g, size_t n, double *xy) {
  double vx, vy;
  ck_assert_int_eq(hdt_polygon_vertex(g, 0, &vx, &vy), HDT_OK);
  const double rv = hypot(vx, vy);
  const double cosh_max = (1 + rv * rv) / (1 - rv * rv); /* cosh of the hyperbolic radius */
  for (size_t i = 0; i < n;) {
    const double u = (double)(rng_next(rng) >> 11) * 0x1p-53;
    const double ch = 1 + u * (cosh_max - 1);
    const double r = sqrt((ch - 1) / (ch + 1)); /* tanh(d/2) from cosh d */
    const double ang = 2 * acos(-1.0) * (double)(rng_next(rng) >> 11) * 0x1p-53;
    const double x = r * cos(ang), y = r * sin(ang);
    size_t len = 1;
    if (hdt_point_representative(g, x, y, NULL, NULL, NULL, 0, &len) != HDT_OK || len != 0) continue;
    xy[2 * i] = x, xy[2 * i + 1] = y;
    ++i;
  }
}

typedef struct tally_t {
  size_t runs, exact_runs, ambiguous_runs, ambiguous_generic_runs, generic_runs;
} tally_t;

/* Compares the brute force with the library on t (bf_cross_check); returns
   1 when nothing was ambiguous (an exact equality check). */
static int cross_check(const bf_nset *ns, const hdt_triangulation *t, const char *what) {
  bf_outcome o;
  char msg[1024];
  expect(bf_cross_check(ns, t, &o, msg, sizeof msg) == 0, "%s: %s", what, msg);
  return o.ambiguous == 0;
}

static void run_cross_checks(int g, const size_t *sizes, size_t nsizes, int seeds, tally_t *tally) {
  bf_nset ns = nset_make(g);
  for (int seed = 1; seed <= seeds; ++seed) {
    for (size_t si = 0; si < nsizes; ++si) {
      const size_t n = sizes[si];
      for (int remove = 0; remove <= 1; ++remove) {
        uint64_t rng = 0x9e3779b97f4a7c15ULL * (uint64_t)(1000 * g + 10 * seed + (int)si) + 1;
        double *xy = malloc(2 * n * sizeof *xy);
        uint32_t *ids = malloc(n * sizeof *ids);
        ck_assert(xy && ids);
        random_points_in_f(&rng, g, n, xy);
        hdt_triangulation *t = NULL;
        ck_assert_int_eq(hdt_create(&t, g), HDT_OK);
        /* Half through insert_many, half one by one. */
        const size_t half = n / 2;
        hdt_status s = hdt_insert_many(t, xy, half, ids);
        expect(s == HDT_OK, "insert_many: %s (%s)", hdt_status_string(s), hdt_last_error_message());
        for (size_t i = half; i < n; ++i) {
          s = hdt_insert(t, xy[2 * i], xy[2 * i + 1], &ids[i]);
          expect(s == HDT_OK, "insert (%.17g, %.17g): %s (%s)", xy[2 * i], xy[2 * i + 1], hdt_status_string(s),
                 hdt_last_error_message());
        }
        size_t remaining = hdt_dummy_count(t);
        if (remove) {
          s = hdt_remove_dummies(t, &remaining);
          expect(s == HDT_OK, "remove_dummies: %s (%s)", hdt_status_string(s), hdt_last_error_message());
        }
        char what[128];
        snprintf(what, sizeof what, "g=%d seed %d n=%zu %s (%zu dummies left)", g, seed, n,
                 remove ? "dummies removed" : "dummies kept", remaining);
        const int exact = cross_check(&ns, t, what);
        ++tally->runs;
        tally->exact_runs += (size_t)exact;
        tally->ambiguous_runs += (size_t)!exact;
        if (remaining == 0) {
          ++tally->generic_runs;
          tally->ambiguous_generic_runs += (size_t)!exact;
        }
        hdt_destroy(t);
        free(xy);
        free(ids);
      }
    }
  }
  bf_nset_free(&ns);
}

static void report(int g, const tally_t *t) {
  printf("brute_force g=%d: %zu runs, %zu exact equalities, %zu with ambiguous (cocircular) tests; "
         "%zu runs without dummies, %zu of them ambiguous\n",
         g, t->runs, t->exact_runs, t->ambiguous_runs, t->generic_runs, t->ambiguous_generic_runs);
  fflush(stdout);
  /* Random points are in general position: once the dummies are gone an
     ambiguous run means trouble in the test's numerics, and must be rare.
     (The dummy sets seen so far are in general position too.) */
  expect(t->ambiguous_generic_runs * 10 <= t->generic_runs, "g=%d: %zu of %zu runs without dummies were ambiguous", g,
         t->ambiguous_generic_runs, t->generic_runs);
  expect(t->ambiguous_runs * 4 <= t->runs, "g=%d: %zu of %zu runs were ambiguous", g, t->ambiguous_runs, t->runs);
}

static const size_t sizes[] = {1, 5, 30, 100, 200};

START_TEST(genus2_matches_brute_force) {
  tally_t tally = {0, 0, 0, 0, 0};
  run_cross_checks(2, sizes, sizeof sizes / sizeof sizes[0], 10, &tally);
  report(2, &tally);
}
END_TEST

START_TEST(genus3_matches_brute_force) {
  tally_t tally = {0, 0, 0, 0, 0};
  run_cross_checks(3, sizes, sizeof sizes / sizeof sizes[0], 6, &tally);
  report(3, &tally);
}
END_TEST

/* Enough points that remove_dummies clears every dummy, so the equality is
   exact (no cocircular dummies left). */
START_TEST(large_sets_without_dummies) {
  const size_t big[] = {400, 800};
  for (int g = 2; g <= 3; ++g) {
    tally_t tally = {0, 0, 0, 0, 0};
    run_cross_checks(g, big, 2, 2, &tally);
    report(g, &tally);
  }
}
END_TEST

/* Points within 2e-15 of the unit circle: their homes are long words, and
   the library evaluates them from their images in F_g (home images); the
   brute force reads the representatives hdt_vertex_point rounds from its
   own multiprecision image. Half inserted at once, half one by one. */
START_TEST(points_near_the_circle_match_brute_force) {
  for (int g = 2; g <= 3; ++g) {
    bf_nset ns = nset_make(g);
    size_t exact = 0, runs = 0;
    for (int seed = 1; seed <= 3; ++seed) {
      const size_t n = 60;
      uint64_t rng = 0x51ed2701u * (uint64_t)(100 * g + seed);
      double xy[2 * 60];
      for (size_t i = 0; i < n; ++i) {
        const double r = 1 - 1e-15 * (1 + (double)(rng_next(&rng) >> 11) * 0x1p-53);
        const double a = 2 * acos(-1.0) * (double)(rng_next(&rng) >> 11) * 0x1p-53;
        xy[2 * i] = r * cos(a), xy[2 * i + 1] = r * sin(a);
      }
      for (int remove = 0; remove <= 1; ++remove) {
        hdt_triangulation *t = NULL;
        ck_assert_int_eq(hdt_create(&t, g), HDT_OK);
        hdt_status s = hdt_insert_many(t, xy, n / 2, NULL);
        expect(s == HDT_OK, "insert_many: %s (%s)", hdt_status_string(s), hdt_last_error_message());
        for (size_t i = n / 2; i < n; ++i) {
          s = hdt_insert(t, xy[2 * i], xy[2 * i + 1], NULL);
          expect(s == HDT_OK, "insert (%a, %a): %s (%s)", xy[2 * i], xy[2 * i + 1], hdt_status_string(s),
                 hdt_last_error_message());
        }
        ck_assert_int_eq(hdt_validate(t), HDT_OK);
        if (remove) ck_assert_int_eq(hdt_remove_dummies(t, NULL), HDT_OK);
        char what[96];
        snprintf(what, sizeof what, "g=%d seed %d, points near the circle%s", g, seed, remove ? ", dummies removed" : "");
        exact += (size_t)cross_check(&ns, t, what);
        ++runs;
        hdt_destroy(t);
      }
    }
    expect(2 * exact >= runs, "g=%d: only %zu of %zu runs were exact equalities", g, exact, runs);
    bf_nset_free(&ns);
  }
}
END_TEST

int main(void) {
  const TTest *const tests[] = {
      half_systole_balls_lie_in_d_n,
      translation_ids_of_n_are_fixed,
      genus2_matches_brute_force,
      genus3_matches_brute_force,
      large_sets_without_dummies,
      points_near_the_circle_match_brute_force,
  };
  return run_tests("brute_force", tests, sizeof tests / sizeof tests[0]);
}
