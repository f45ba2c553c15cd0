/* hdt_point_representative: the canonical representative of a disk point
 * in the half-open fundamental domain, through the public header. */
#include "hdt_test.h"

/* cosh d(z, w) for disk points: 1 + 2|z - w|^2 / ((1 - |z|^2)(1 - |w|^2)). */
static double cosh_distance(double zx, double zy, double wx, double wy) {
  const double dx = zx - wx, dy = zy - wy;
  return 1 + 2 * (dx * dx + dy * dy) / ((1 - zx * zx - zy * zy) * (1 - wx * wx - wy * wy));
}

/* How far (x, y) is inside the closed F_g, as min over sides k of
   cosh d(z, g_k 0) - cosh d(z, 0): >= 0 inside, 0 on a side line. */
static double inside_margin(int g, double x, double y) {
  double margin = INFINITY;
  for (int k = 0; k < 4 * g; ++k) {
    const int32_t letter = k;
    double cx, cy;
    ck_assert_int_eq(hdt_word_apply(g, &letter, 1, 0, 0, &cx, &cy), HDT_OK);
    const double m = cosh_distance(x, y, cx, cy) - cosh_distance(x, y, 0, 0);
    if (m < margin) margin = m;
  }
  return margin;
}

typedef struct representative_t {
  double x, y;
  word_t word;
} representative_t;

static representative_t representative(int g, double x, double y) {
  representative_t r = {0};
  hdt_status s = hdt_point_representative(g, x, y, &r.x, &r.y, r.word.a, TW_MAX, &r.word.n);
  expect(s == HDT_OK, "hdt_point_representative(%d, %a, %a): %s", g, x, y, hdt_last_error_message());
  return r;
}

/* A point at Euclidean radius `radius` in a random direction. */
static void random_point(uint64_t *rng, double radius, double *x, double *y) {
  const double angle = 2 * acos(-1.0) * (double)(rng_next(rng) >> 11) * 0x1p-53;
  *x = radius * cos(angle);
  *y = radius * sin(angle);
}

START_TEST(interior_points_are_their_own_representative) {
  uint64_t rng = 7;
  for (int g = 2; g <= 8; ++g) {
    double mx, my;
    ck_assert_int_eq(hdt_polygon_side_midpoint(g, 0, &mx, &my), HDT_OK);
    const double inradius = hypot(mx, my); /* F contains the Euclidean disk of this radius */
    for (int i = 0; i < 200; ++i) {
      double x, y;
      random_point(&rng, 0.999 * inradius * sqrt((double)(rng_next(&rng) >> 11) * 0x1p-53), &x, &y);
      const representative_t r = representative(g, x, y);
      expect(r.word.n == 0 && r.x == x && r.y == y, "g=%d: interior point (%a, %a) moved", g, x, y);
    }
  }
}
END_TEST

START_TEST(representative_lies_in_f_and_is_reached_by_its_word) {
  uint64_t rng = 11;
  for (int g = 2; g <= 6; ++g) {
    for (int i = 0; i < 150; ++i) {
      double x, y;
      const double gap = pow(10.0, -1 - (double)rng_below(&rng, 12)); /* 1 - |z| from 0.1 down to 1e-12 */
      random_point(&rng, 1 - gap, &x, &y);
      const representative_t r = representative(g, x, y);
      expect(inside_margin(g, r.x, r.y) > -1e-9, "g=%d: representative of (%a, %a) outside F", g, x, y);
      const word_t canonical = reduce_word(g, &r.word);
      expect(word_eq(&canonical, &r.word), "g=%d: the representative's word is not canonical", g);
      double ix, iy; /* hdt_word_apply is accurate near the circle too */
      apply_word(g, &r.word, x, y, &ix, &iy);
      expect(hypot(ix - r.x, iy - r.y) < 1e-14, "g=%d: word image (%g, %g) vs (%g, %g)", g, ix, iy, r.x, r.y);
    }
  }
}
END_TEST

/* Points 1e-15 from the circle at larger genus, where the walk into F_g
   takes hundreds of letters (the tracked walk, then the exact tests): the
   same checks, and the image's word against hdt_word_apply. */
START_TEST(points_near_the_circle_at_larger_genus) {
  uint64_t rng = 17;
  const int genera[] = {12, 40};
  for (size_t j = 0; j < sizeof genera / sizeof genera[0]; ++j) {
    const int g = genera[j];
    size_t longest = 0;
    for (int i = 0; i < 25; ++i) {
      double x, y;
      random_point(&rng, 1 - 1e-15 * (1 + (double)rng_below(&rng, 9)), &x, &y);
      const representative_t r = representative(g, x, y);
      expect(inside_margin(g, r.x, r.y) > -1e-9, "g=%d: representative of (%a, %a) outside F", g, x, y);
      const word_t canonical = reduce_word(g, &r.word);
      expect(word_eq(&canonical, &r.word), "g=%d: the representative's word is not canonical", g);
      double ix, iy;
      apply_word(g, &r.word, x, y, &ix, &iy);
      expect(hypot(ix - r.x, iy - r.y) < 1e-14, "g=%d: word image (%g, %g) vs (%g, %g)", g, ix, iy, r.x, r.y);
      if (r.word.n > longest) longest = r.word.n;
    }
    /* (The walk is long: at least the distance over a generator's translation length.) */
    expect(longest >= 8, "g=%d: the longest word has %zu letters", g, longest);
  }
}
END_TEST

START_TEST(images_share_the_representative) {
  uint64_t rng = 13;
  for (int g = 2; g <= 6; ++g) {
    int compared = 0;
    for (int i = 0; i < 250; ++i) {
      double x, y, ix, iy;
      random_point(&rng, 0.9 * sqrt((double)(rng_next(&rng) >> 11) * 0x1p-53), &x, &y);
      const word_t w = random_word(&rng, g, 6);
      apply_word(g, &w, x, y, &ix, &iy);
      if (1 - hypot(ix, iy) < 1e-6) continue; /* too close to the circle to round well */
      const representative_t a = representative(g, x, y), b = representative(g, ix, iy);
      /* Rounding of the image may carry a point within ~1e-12 of a side to
         its paired side: compare only representatives clearly inside. */
      if (inside_margin(g, a.x, a.y) < 1e-6) continue;
      expect(hypot(a.x - b.x, a.y - b.y) < 1e-8, "g=%d: representatives (%g, %g) and (%g, %g) differ", g, a.x, a.y,
             b.x, b.y);
      ++compared;
    }
    expect(compared > 120, "g=%d: only %d images compared", g, compared);
  }
}
END_TEST

START_TEST(rounded_vertices_stay_at_a_vertex) {
  for (int g = 2; g <= 8; ++g) {
    for (int k = 0; k < 4 * g; ++k) {
      double vx, vy;
      ck_assert_int_eq(hdt_polygon_vertex(g, k, &vx, &vy), HDT_OK);
      const representative_t r = representative(g, vx, vy);
      double best = INFINITY;
      for (int j = 0; j < 4 * g; ++j) {
        double wx, wy;
        ck_assert_int_eq(hdt_polygon_vertex(g, j, &wx, &wy), HDT_OK);
        best = fmin(best, hypot(r.x - wx, r.y - wy));
      }
      expect(best < 1e-12, "g=%d: rounded v_%d went %g from every vertex", g, k, best);
    }
  }
}
END_TEST

START_TEST(bad_input_changes_nothing) {
  double rx = 42, ry = 43;
  int32_t word[2] = {7, 7};
  size_t length = 99;
  expect_failure(hdt_point_representative(2, NAN, 0, &rx, &ry, word, 2, &length), HDT_EDOMAIN,
                 "hdt_point_representative");
  expect_failure(hdt_point_representative(2, 1, 0, &rx, &ry, word, 2, &length), HDT_EDOMAIN,
                 "hdt_point_representative");
  expect_failure(hdt_point_representative(2, 0.6, 0.8, &rx, &ry, word, 2, &length), HDT_EDOMAIN,
                 "hdt_point_representative");
  expect_failure(hdt_point_representative(1, 0, 0, &rx, &ry, word, 2, &length), HDT_EINVAL,
                 "hdt_point_representative");
  expect_failure(hdt_point_representative(2, 0, 0, &rx, &ry, word, 2, NULL), HDT_EINVAL, "hdt_point_representative");
  expect(rx == 42 && ry == 43 && word[0] == 7 && length == 99, "a failed call wrote its outputs");
  /* A point far out needs a long word: too small a buffer reports the length. */
  const double x = 0.999999, y = 0.0001;
  hdt_status s = hdt_point_representative(2, x, y, &rx, &ry, word, 1, &length);
  ck_assert_int_eq(s, HDT_EBUFS);
  expect(length > 1 && rx == 42, "EBUFS must report the length and leave the point");
  size_t needed = 0;
  ck_assert_int_eq(hdt_point_representative(2, x, y, NULL, NULL, NULL, 0, &needed), HDT_OK);
  ck_assert_uint_eq(needed, length);
}
END_TEST

int main(void) {
  const TTest *tests[] = {
      interior_points_are_their_own_representative,
      representative_lies_in_f_and_is_reached_by_its_word,
      points_near_the_circle_at_larger_genus,
      images_share_the_representative,
      rounded_vertices_stay_at_a_vertex,
      bad_input_changes_nothing,
  };
  return run_tests("representative", tests, sizeof tests / sizeof tests[0]);
}
