/* hdt_point_representative: the canonical representative of a disk point
 * in the half-open fundamental domain, through the public header. */
#include <mpfr.h>

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

/* ---- Words beyond the compile-time precision ladder ----
   Points within 2e-15 of the circle at genus 256 have words of up to about
   500 letters; the ladder's top rung canonicalises Dehn-reduced words of up
   to 412 (these points were refused with HDT_ENOTSUP before run-time
   precision took over past it). */

#define LONG_MAX_LETTERS 4096
#define REF_BITS 4096

/* The image of z under the word in MPFR at REF_BITS, independently of the
   library: g_k = [[A, B_k], [conj B_k, A]], A = cot(pi/4g), B_k = sqrt(A^2 -
   1) e^{i k pi/2g}, the last letter acting first (hdt_word_apply's order).
   Writes the image to (ix, iy) and whether it lies in the closed F_g to
   *inside_f: for every k, d(z', O) <= d(z', g_k(O)), i.e. |z'|^2 (1 -
   |c_k|^2) <= |z' - c_k|^2 for c_k = g_k(O) = B_k / A (with 2^-1000 of
   slack for the rounding at REF_BITS). */
static void reference_image(int g, const int32_t *word, size_t n, double x, double y, mpfr_t ix, mpfr_t iy,
                            int *inside_f) {
  mpfr_t A, modulus, angle, br, bi, zr, zi, nr, ni, dr, di, t, u, d;
  mpfr_inits2(REF_BITS, A, modulus, angle, br, bi, zr, zi, nr, ni, dr, di, t, u, d, (mpfr_ptr)0);
  mpfr_const_pi(t, MPFR_RNDN);
  mpfr_div_ui(t, t, 4 * (unsigned long)g, MPFR_RNDN);
  mpfr_cot(A, t, MPFR_RNDN);
  mpfr_sqr(modulus, A, MPFR_RNDN);
  mpfr_sub_ui(modulus, modulus, 1, MPFR_RNDN);
  mpfr_sqrt(modulus, modulus, MPFR_RNDN);
  mpfr_set_d(zr, x, MPFR_RNDN);
  mpfr_set_d(zi, y, MPFR_RNDN);
  for (size_t i = n; i-- > 0;) {
    /* z <- (A z + B) / (conj(B) z + A) */
    mpfr_const_pi(angle, MPFR_RNDN);
    mpfr_mul_ui(angle, angle, (unsigned long)word[i], MPFR_RNDN);
    mpfr_div_ui(angle, angle, 2 * (unsigned long)g, MPFR_RNDN);
    mpfr_sin_cos(bi, br, angle, MPFR_RNDN);
    mpfr_mul(br, br, modulus, MPFR_RNDN);
    mpfr_mul(bi, bi, modulus, MPFR_RNDN);
    mpfr_fma(nr, A, zr, br, MPFR_RNDN);
    mpfr_fma(ni, A, zi, bi, MPFR_RNDN);
    mpfr_fmma(dr, br, zr, bi, zi, MPFR_RNDN); /* Re(conj(B) z) */
    mpfr_add(dr, dr, A, MPFR_RNDN);
    mpfr_fmms(di, br, zi, bi, zr, MPFR_RNDN); /* Im(conj(B) z) */
    mpfr_fmma(d, dr, dr, di, di, MPFR_RNDN);
    mpfr_fmma(t, nr, dr, ni, di, MPFR_RNDN);
    mpfr_fmms(u, ni, dr, nr, di, MPFR_RNDN);
    mpfr_div(zr, t, d, MPFR_RNDN);
    mpfr_div(zi, u, d, MPFR_RNDN);
  }
  mpfr_set(ix, zr, MPFR_RNDN);
  mpfr_set(iy, zi, MPFR_RNDN);
  *inside_f = 1;
  for (int k = 0; k < 4 * g; ++k) {
    mpfr_const_pi(angle, MPFR_RNDN);
    mpfr_mul_ui(angle, angle, (unsigned long)k, MPFR_RNDN);
    mpfr_div_ui(angle, angle, 2 * (unsigned long)g, MPFR_RNDN);
    mpfr_sin_cos(bi, br, angle, MPFR_RNDN);
    mpfr_mul(br, br, modulus, MPFR_RNDN);
    mpfr_mul(bi, bi, modulus, MPFR_RNDN);
    mpfr_div(br, br, A, MPFR_RNDN); /* c_k */
    mpfr_div(bi, bi, A, MPFR_RNDN);
    mpfr_fmma(t, br, br, bi, bi, MPFR_RNDN);
    mpfr_ui_sub(t, 1, t, MPFR_RNDN);         /* 1 - |c_k|^2 */
    mpfr_fmma(u, zr, zr, zi, zi, MPFR_RNDN); /* |z'|^2 */
    mpfr_mul(t, t, u, MPFR_RNDN);
    mpfr_sub(nr, zr, br, MPFR_RNDN);
    mpfr_sub(ni, zi, bi, MPFR_RNDN);
    mpfr_fmma(u, nr, nr, ni, ni, MPFR_RNDN); /* |z' - c_k|^2 */
    mpfr_sub(t, t, u, MPFR_RNDN);
    if (mpfr_cmp_d(t, 0x1p-1000) > 0) *inside_f = 0;
  }
  mpfr_clears(A, modulus, angle, br, bi, zr, zi, nr, ni, dr, di, t, u, d, (mpfr_ptr)0);
}

/* The checks of one point with a long word: HDT_OK, its word canonical
   (hdt_word_reduce gives it back), the rounded representative the image of
   the point under the word (hdt_word_apply and the MPFR reference), the
   reference image in the closed F_g. Returns the word's length. */
static size_t check_long_word_point(int g, double x, double y) {
  static int32_t word[LONG_MAX_LETTERS], again[LONG_MAX_LETTERS];
  double rx, ry;
  size_t n = 0, m = 0;
  const hdt_status s = hdt_point_representative(g, x, y, &rx, &ry, word, LONG_MAX_LETTERS, &n);
  expect(s == HDT_OK, "hdt_point_representative(%d, %a, %a): %s (%s)", g, x, y, hdt_status_string(s),
         hdt_last_error_message());
  OK(hdt_word_reduce(g, word, n, again, LONG_MAX_LETTERS, &m));
  expect(m == n && memcmp(word, again, n * sizeof *word) == 0, "g=%d: the word of (%a, %a) is not canonical", g, x, y);
  double ax, ay;
  OK(hdt_word_apply(g, word, n, x, y, &ax, &ay));
  expect(hypot(ax - rx, ay - ry) < 1e-14, "g=%d: hdt_word_apply gives (%a, %a), the representative is (%a, %a)", g,
         ax, ay, rx, ry);
  mpfr_t ix, iy;
  mpfr_inits2(REF_BITS, ix, iy, (mpfr_ptr)0);
  int inside_f = 0;
  reference_image(g, word, n, x, y, ix, iy, &inside_f);
  const double ex = mpfr_get_d(ix, MPFR_RNDN), ey = mpfr_get_d(iy, MPFR_RNDN);
  mpfr_clears(ix, iy, (mpfr_ptr)0);
  expect(hypot(ex - rx, ey - ry) < 1e-14, "g=%d: the MPFR image (%a, %a) vs the representative (%a, %a)", g, ex, ey,
         rx, ry);
  expect(inside_f, "g=%d: the MPFR image of (%a, %a) under its word is outside F_g", g, x, y);
  return n;
}

START_TEST(point_with_a_word_past_the_top_rung_at_genus_256) {
  /* Refused with "the Dehn-reduced word has 490 letters; canonical words
     are computed up to 412 letters" (issue 33), and one more found so. */
  const size_t a = check_long_word_point(256, 0x1.ffc4c33220bc6p-1, 0x1.ec86b3b49c3e3p-6);
  const size_t b = check_long_word_point(256, -0x1.98e023b2ce724p-2, -0x1.d569e6882e0ap-1);
  expect(a > 412 && b > 412, "the words have %zu and %zu letters, within the top rung's reach", a, b);
}
END_TEST

START_TEST(points_within_2e_15_of_the_circle_inserted_at_genus_256) {
  hdt_triangulation *t = new_triangulation(256);
  double xy[2 * 12] = {0x1.ffc4c33220bc6p-1, 0x1.ec86b3b49c3e3p-6, -0x1.98e023b2ce724p-2, -0x1.d569e6882e0ap-1};
  uint64_t rng = 33;
  for (int i = 2; i < 12; ++i) random_point(&rng, 1 - 1e-15 * (1 + uniform01(&rng)), &xy[2 * i], &xy[2 * i + 1]);
  for (int i = 0; i < 12; ++i) {
    const hdt_status s = hdt_insert(t, xy[2 * i], xy[2 * i + 1], NULL);
    expect(s == HDT_OK, "hdt_insert(%a, %a) at genus 256: %s (%s)", xy[2 * i], xy[2 * i + 1], hdt_status_string(s),
           hdt_last_error_message());
  }
  OK(hdt_validate(t));
  hdt_destroy(t);
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
      point_with_a_word_past_the_top_rung_at_genus_256,
      points_within_2e_15_of_the_circle_inserted_at_genus_256,
      images_share_the_representative,
      rounded_vertices_stay_at_a_vertex,
      bad_input_changes_nothing,
  };
  return run_tests("representative", tests, sizeof tests / sizeof tests[0]);
}
