/* The group Gamma_g: the relation, Dehn reduction and canonical words. */
#include "hdt_test.h"

/* ---- The relation ---- */

START_TEST(relator_is_identity) {
  for (int g = 2; g <= 32; ++g) {
    const word_t r = relator(g);
    double m[4];
    word_matrix(g, &r, m);
    expect(hypot(m[0] - 1, m[1]) < 1e-12 && hypot(m[2], m[3]) < 1e-12,
           "genus %d: relator product is a = %.17g%+.17gi, b = %.17g%+.17gi", g, m[0], m[1], m[2], m[3]);
  }
}
END_TEST

/* Every subword of every rotation, for g <= 16. Above, the cost of the
   multiprecision products grows, so a few rotations are taken (rotating the
   relator by s shifts its letters by s (2g+1), a conjugation by a rotation of
   the disk, so the others repeat these traces). */
START_TEST(relator_has_no_trivial_subword) {
  for (int g = 2; g <= 32; ++g) {
    const word_t r = relator(g);
    const size_t n = r.n;
    const size_t few[] = {0, 1, (size_t)(2 * g), n - 1};
    const size_t count = g <= 16 ? n : sizeof few / sizeof few[0];
    for (size_t i = 0; i < count; ++i) {
      const size_t shift = g <= 16 ? i : few[i];
      const word_t rot = word_rotate(&r, shift);
      /* The prefixes of the rotations are the proper cyclic subwords. A
         nontrivial element of a surface group is a translation, with
         |Re a| >= cosh(sys/2) ~ 3; the tolerance only says "not +-I". */
      for (size_t len = 1; len < n; ++len) {
        double m[4];
        expect(hdt_word_matrix(g, rot.a, len, m) == HDT_OK, "%s", hdt_last_error_message());
        expect(fabs(m[0]) > 1 + 1e-6, "genus %d: prefix of length %zu of rotation %zu has Re a = %.17g", g, len, shift,
               m[0]);
      }
    }
  }
}
END_TEST

START_TEST(relator_reduces_to_empty) {
  char buf[1024];
  for (int g = 2; g <= 32; ++g) {
    const word_t r = relator(g);
    const word_t ri = word_inverse(g, &r);
    for (size_t s = 0; s < r.n; ++s) {
      const word_t rots[2] = {word_rotate(&r, s), word_rotate(&ri, s)};
      for (int i = 0; i < 2; ++i) {
        const word_t c = reduce_word(g, &rots[i]);
        expect(c.n == 0, "genus %d: [%s] reduces to %zu letters", g, word_str(&rots[i], buf, sizeof buf), c.n);
      }
    }
  }
}
END_TEST

/* ---- Reduction of random words ---- */

/* w with a random rotation of the relator or its inverse inserted at a random
   place, and a few random x x^-1 pairs inserted: the same element. */
static word_t same_element(uint64_t *rng, int g, const word_t *w) {
  word_t r = relator(g);
  if (rng_below(rng, 2)) r = word_inverse(g, &r);
  r = word_rotate(&r, (size_t)rng_below(rng, (int)r.n));
  word_t out = {0};
  const size_t at = (size_t)rng_below(rng, (int)w->n + 1);
  for (size_t i = 0; i < at; ++i) word_push(&out, w->a[i]);
  word_append(&out, &r);
  for (size_t i = at; i < w->n; ++i) word_push(&out, w->a[i]);
  for (int pairs = rng_below(rng, 4); pairs > 0; --pairs) {
    const size_t pos = (size_t)rng_below(rng, (int)out.n + 1);
    const int32_t x = rng_below(rng, 4 * g);
    expect(out.n + 2 <= TW_MAX, "test word too long");
    memmove(out.a + pos + 2, out.a + pos, (out.n - pos) * sizeof out.a[0]);
    out.a[pos] = x;
    out.a[pos + 1] = inv_letter(g, x);
    out.n += 2;
  }
  return out;
}

START_TEST(random_words_reduce_canonically) {
  uint64_t rng = UINT64_C(0x9e3779b97f4a7c15);
  char b1[2048], b2[2048];
  for (int g = 2; g <= 5; ++g)
    for (int trial = 0; trial < 120; ++trial) {
      const word_t w = random_word(&rng, g, 40);
      const word_t c = reduce_word(g, &w);
      expect(c.n <= w.n, "genus %d: [%s] grew to [%s]", g, word_str(&w, b1, sizeof b1), word_str(&c, b2, sizeof b2));
      double mw[4], mc[4];
      word_matrix(g, &w, mw);
      word_matrix(g, &c, mc);
      expect(matrix_gap(mw, mc) < 1e-9, "genus %d: [%s] and its reduction [%s] differ (gap %g)", g,
             word_str(&w, b1, sizeof b1), word_str(&c, b2, sizeof b2), matrix_gap(mw, mc));
      const word_t cc = reduce_word(g, &c);
      expect(word_eq(&c, &cc), "genus %d: reduction of [%s] is not idempotent", g, word_str(&c, b1, sizeof b1));
      const word_t v = same_element(&rng, g, &w);
      const word_t cv = reduce_word(g, &v);
      expect(word_eq(&c, &cv), "genus %d: [%s] and [%s] (same element) reduce differently", g,
             word_str(&w, b1, sizeof b1), word_str(&v, b2, sizeof b2));
    }
}
END_TEST

START_TEST(chain_example_g2) {
  const word_t w = {8, {0, 5, 2, 7, 5, 2, 7, 4}};
  const word_t c = reduce_word(2, &w);
  char buf[256];
  expect(c.n == 6, "[0 5 2 7 5 2 7 4] reduces to [%s]", word_str(&c, buf, sizeof buf));
  double mw[4], mc[4];
  word_matrix(2, &w, mw);
  word_matrix(2, &c, mc);
  ck_assert_double_lt(matrix_gap(mw, mc), 1e-9);
}
END_TEST

/* Powers of a generator are geodesic and lexicographically least: a long
   reduced word either comes back unchanged or is refused with HDT_ENOTSUP
   (and then nothing is written). */
START_TEST(generator_powers_are_canonical) {
  for (size_t n = 25; n <= 200; n *= 2) {
    word_t w = {0};
    for (size_t i = 0; i < n; ++i) word_push(&w, 0);
    word_t out = {0};
    size_t len = 12345;
    const hdt_status s = hdt_word_reduce(2, w.a, w.n, out.a, TW_MAX, &len);
    if (s == HDT_ENOTSUP) {
      ck_assert_uint_eq(len, 12345);
      continue;
    }
    ck_assert_int_eq(s, HDT_OK);
    out.n = len;
    expect(word_eq(&w, &out), "g_0^%zu is not its own canonical word", n);
  }
}
END_TEST

/* Past the compile-time precision ladder (Dehn-reduced words of about
   1370 letters at genus 2): g_0^1500 is its own canonical word, a word of
   1608 letters comes back canonical and names the same element (Dehn's
   algorithm takes its product with the inverse to the empty word), and a
   word that needs a run-time precision is refused past 2048 letters, as
   hdt.h says, with nothing written. */
START_TEST(canonical_words_past_the_precision_ladder) {
  enum { N = 1500, M = 800, CAP = 4 * M + 16 };
  static int32_t w[CAP], c[CAP], both[2 * CAP];
  size_t n = 0;
  for (size_t i = 0; i < N; ++i) w[i] = 0;
  OK(hdt_word_reduce(2, w, N, c, CAP, &n));
  expect(n == N && memcmp(w, c, N * sizeof *w) == 0, "g_0^%d comes back with %zu letters", N, n);
  const int32_t middle[] = {0, 5, 2, 7, 5, 2, 7, 4};
  size_t len = 0;
  for (size_t i = 0; i < M; ++i) w[len++] = 0;
  for (size_t i = 0; i < 8; ++i) w[len++] = middle[i];
  for (size_t i = 0; i < M; ++i) w[len++] = 1;
  OK(hdt_word_reduce(2, w, len, c, CAP, &n));
  expect(n > 2 * M && n <= len, "the canonical word has %zu letters", n);
  static int32_t again[CAP];
  size_t m = 0;
  OK(hdt_word_reduce(2, c, n, again, CAP, &m));
  expect(m == n && memcmp(c, again, n * sizeof *c) == 0, "the canonical word of %zu letters is not canonical", n);
  memcpy(both, c, n * sizeof *c);
  for (size_t i = 0; i < len; ++i) both[n + i] = (w[len - 1 - i] + 4) % 8; /* w^-1 at genus 2 */
  OK(hdt_word_reduce(2, both, n + len, again, CAP, &m));
  expect(m == 0, "c w^-1 reduces to %zu letters, not the identity", m);
  static int32_t power[2049];
  size_t untouched = 12345;
  memset(power, 0, sizeof power);
  const hdt_status s = hdt_word_reduce(2, power, 2049, c, CAP, &untouched);
  expect(s == HDT_ENOTSUP && untouched == 12345, "g_0^2049: %s, length %zu", hdt_status_string(s), untouched);
}
END_TEST

/* ---- The tiles around the vertex of F_g: canonical words known without geometry ---- */

/* The 4g tiles around a corner of F_g are h_j(F_g) for the prefixes h_j of
   length j of a rotation of the relator (or of its inverse). Only the 2g lines
   through that corner separate two of them, so for j < 2g the one geodesic
   word of h_j is the prefix itself, and for j = 2g the two geodesic words
   are the prefix and the inverse of the rest of the rotation; the canonical
   word is the lexicographically least. Checks the peeling of long words at
   large genus (2g letters, near O all the way) against combinatorics. */
START_TEST(tiles_around_the_vertex_have_known_canonical_words) {
  char b1[4096], b2[4096];
  const int genera[] = {2, 3, 8, 24, 60};
  for (size_t gi = 0; gi < sizeof genera / sizeof genera[0]; ++gi) {
    const int g = genera[gi];
    const word_t r = relator(g);
    const word_t ri = word_inverse(g, &r);
    const size_t shifts[] = {0, 1, (size_t)(2 * g + 1), r.n - 1};
    const size_t lengths[] = {1, 2, 3, (size_t)g, (size_t)(2 * g - 1), (size_t)(2 * g)};
    for (size_t si = 0; si < sizeof shifts / sizeof shifts[0]; ++si)
      for (int inv = 0; inv < 2; ++inv) {
        const word_t rot = word_rotate(inv ? &ri : &r, shifts[si]);
        for (size_t li = 0; li < sizeof lengths / sizeof lengths[0]; ++li) {
          const size_t j = lengths[li];
          word_t prefix = {0}, rest = {0};
          for (size_t i = 0; i < rot.n; ++i) word_push(i < j ? &prefix : &rest, rot.a[i]);
          word_t expected = prefix;
          if (j == (size_t)(2 * g)) {
            const word_t other = word_inverse(g, &rest);
            if (shortlex_cmp(&other, &prefix) < 0) expected = other;
          }
          const word_t c = reduce_word(g, &prefix);
          expect(word_eq(&c, &expected), "genus %d: [%s] reduces to [%s]", g, word_str(&prefix, b1, sizeof b1),
                 word_str(&c, b2, sizeof b2));
        }
      }
  }
}
END_TEST

/* ---- Exhaustive shortlex check for g = 2, words of length <= 4 ---- */

typedef struct member {
  word_t word, canonical;
} member;

static int by_canonical_then_shortlex(const void *x, const void *y) {
  const member *a = x, *b = y;
  const int c = shortlex_cmp(&a->canonical, &b->canonical);
  return c ? c : shortlex_cmp(&a->word, &b->word);
}

START_TEST(canonical_is_shortlex_least_g2) {
  const int g = 2, letters = 4 * g, max_len = 4;
  size_t total = 0;
  for (int len = 0, p = 1; len <= max_len; ++len, p *= letters) total += (size_t)p;
  member *all = calloc(total, sizeof *all);
  ck_assert_ptr_nonnull(all);
  size_t n = 0;
  for (int len = 0; len <= max_len; ++len) {
    int32_t digits[8] = {0};
    for (;;) {
      member *m = &all[n++];
      m->word.n = (size_t)len;
      memcpy(m->word.a, digits, (size_t)len * sizeof digits[0]);
      m->canonical = reduce_word(g, &m->word);
      int i = len - 1;
      while (i >= 0 && digits[i] == letters - 1) digits[i--] = 0;
      if (i < 0) break;
      ++digits[i];
    }
  }
  ck_assert_uint_eq(n, total);
  qsort(all, n, sizeof *all, by_canonical_then_shortlex);
  char b1[256], b2[256];
  size_t groups = 0;
  double(*mats)[4] = calloc(n, sizeof *mats);
  ck_assert_ptr_nonnull(mats);
  for (size_t i = 0; i < n; ++i) {
    if (i > 0 && word_eq(&all[i].canonical, &all[i - 1].canonical)) continue;
    /* The first member of the group is its shortlex-least word. */
    expect(word_eq(&all[i].word, &all[i].canonical), "canonical word [%s] is not the shortlex-least [%s]",
           word_str(&all[i].canonical, b1, sizeof b1), word_str(&all[i].word, b2, sizeof b2));
    word_matrix(g, &all[i].canonical, mats[groups]);
    ++groups;
  }
  /* Distinct canonical words are distinct elements. */
  for (size_t i = 0; i < groups; ++i)
    for (size_t j = 0; j < i; ++j) expect(matrix_gap(mats[i], mats[j]) > 1e-6, "two groups share an element");
  free(mats);
  free(all);
}
END_TEST

/* ---- Results that fit in double, and those that do not ---- */

/* Outputs that a failing call must leave alone. */
#define UNTOUCHED (-12345.5)

static void fill_untouched(double *out, size_t n) {
  for (size_t i = 0; i < n; ++i) out[i] = UNTOUCHED;
}

static void expect_untouched(const double *out, size_t n, const char *function) {
  for (size_t i = 0; i < n; ++i)
    expect(out[i] == UNTOUCHED, "%s wrote output %zu on failure (%s)", function, i, hdt_last_error_message());
}

/* A failure with HDT_EDOMAIN whose message names the function and says why. */
static void expect_domain_failure(hdt_status s, const char *function, const char *why) {
  expect_failure(s, HDT_EDOMAIN, function);
  expect(strstr(hdt_last_error_message(), why) != NULL, "%s: message \"%s\" does not say \"%s\"", function,
         hdt_last_error_message(), why);
}

static int bits_equal(double x, double y) { return memcmp(&x, &y, sizeof x) == 0; }

/* g_0^n at genus 2 is [[cosh nt, sinh nt], [sinh nt, cosh nt]] with
   cosh t = A = cot(pi/8), and its Lorentz matrix has L_00 = cosh 2nt. An
   entry overflows double exactly when it reaches 2^1024 (the rounding
   threshold 2^1024 - 2^970 is within 2^-54 of it): cosh x ~ e^x / 2 there,
   so at x = 1025 ln 2. */
START_TEST(generator_powers_overflow_with_edomain) {
  const long double t = acoshl(1 / tanl(acosl(-1) / 8)), limit = 1025 * logl(2);
  int32_t *w = calloc(1000, sizeof *w); /* g_0^n: n zeros */
  ck_assert_ptr_nonnull(w);
  const size_t ns[] = {200, 225, 230, 231, 232, 233, 234, 235, 240, 400, 460, 463, 464, 465, 466, 470, 1000};
  for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i) {
    const size_t n = ns[i];
    double m[9];
    fill_untouched(m, 9);
    hdt_status s = hdt_word_matrix(2, w, n, m);
    if (n * t < limit) {
      expect(s == HDT_OK, "g_0^%zu: hdt_word_matrix %s (%s)", n, hdt_status_string(s), hdt_last_error_message());
      const long double a = coshl(n * t);
      expect(fabsl(m[0] - a) <= 1e-14L * a && fabsl(m[2] - sinhl(n * t)) <= 1e-14L * a &&
                 fabs(m[1]) <= 1e-15 * m[0] && fabs(m[3]) <= 1e-15 * m[0],
             "g_0^%zu: a = %.17g%+.17gi, b = %.17g%+.17gi, expected cosh %.17Lg", n, m[0], m[1], m[2], m[3], a);
    } else {
      expect_domain_failure(s, "hdt_word_matrix", "exceed the double range");
      expect_untouched(m, 9, "hdt_word_matrix");
    }
    fill_untouched(m, 9);
    s = hdt_word_lorentz(2, w, n, m);
    if (2 * n * t < limit) {
      expect(s == HDT_OK, "g_0^%zu: hdt_word_lorentz %s (%s)", n, hdt_status_string(s), hdt_last_error_message());
      const long double l00 = coshl(2 * n * t);
      expect(fabsl(m[0] - l00) <= 1e-14L * l00, "g_0^%zu: L_00 = %.17g, expected %.17Lg", n, m[0], l00);
      for (int j = 0; j < 9; ++j) expect(isfinite(m[j]), "g_0^%zu: Lorentz entry %d is %g", n, j, m[j]);
    } else {
      expect_domain_failure(s, "hdt_word_lorentz", "exceed the double range");
      expect_untouched(m, 9, "hdt_word_lorentz");
    }
  }
  free(w);
}
END_TEST

/* The identity, however it is spelled, is exactly the identity: the
   relator's rotations and their inverses, [k, k+2g], and w w^-1. */
static void expect_exact_identity(int g, const word_t *w) {
  char buf[2048];
  double m[4], L[9];
  ck_assert_int_eq(hdt_word_matrix(g, w->a, w->n, m), HDT_OK);
  expect(m[0] == 1 && m[1] == 0 && m[2] == 0 && m[3] == 0, "genus %d: [%s] gives a = %a%+ai, b = %a%+ai", g,
         word_str(w, buf, sizeof buf), m[0], m[1], m[2], m[3]);
  ck_assert_int_eq(hdt_word_lorentz(g, w->a, w->n, L), HDT_OK);
  for (int i = 0; i < 9; ++i)
    expect(L[i] == (i % 4 == 0 ? 1 : 0), "genus %d: [%s] gives Lorentz entry %d = %a", g, word_str(w, buf, sizeof buf),
           i, L[i]);
  const double points[][2] = {{0, 0.14}, {0.1, -0.2}, {-0.0, 0.5}, {0.999999999999, 0}, {-0.6, 0.7999999999999999}};
  for (size_t i = 0; i < sizeof points / sizeof points[0]; ++i) {
    double x, y;
    ck_assert_int_eq(hdt_word_apply(g, w->a, w->n, points[i][0], points[i][1], &x, &y), HDT_OK);
    expect(bits_equal(x, points[i][0]) && bits_equal(y, points[i][1]), "genus %d: [%s] maps (%a, %a) to (%a, %a)", g,
           word_str(w, buf, sizeof buf), points[i][0], points[i][1], x, y);
  }
}

START_TEST(identity_words_give_the_exact_identity) {
  uint64_t rng = UINT64_C(0x2545f4914f6cdd1d);
  for (int g = 2; g <= 32; g += (g < 6 ? 1 : 9)) {
    const word_t r = relator(g), ri = word_inverse(g, &r);
    for (size_t s = 0; s < r.n; s += (g <= 4 ? 1 : 5)) {
      const word_t rot = word_rotate(&r, s), roti = word_rotate(&ri, s);
      expect_exact_identity(g, &rot);
      expect_exact_identity(g, &roti);
    }
    for (int k = 0; k < 4 * g; ++k) {
      const word_t pair = {2, {k, inv_letter(g, k)}};
      expect_exact_identity(g, &pair);
    }
    for (int trial = 0; trial < 5; ++trial) {
      word_t w = random_word(&rng, g, 60);
      const word_t wi = word_inverse(g, &w);
      word_append(&w, &wi);
      expect_exact_identity(g, &w);
    }
  }
}
END_TEST

/* g_0 preserves the real axis and moves it by 2t (cosh t = A): g_0^n (0.5)
   = tanh((2nt + d) / 2) with d = 2 artanh 0.5, which rounds to 1 (onto the
   circle) once 1 - it is below 2^-54, half the spacing of doubles below 1. */
START_TEST(images_on_the_circle_are_refused) {
  const long double t = acoshl(1 / tanl(acosl(-1) / 8)), d = 2 * atanhl(0.5L);
  int32_t w[40] = {0};
  for (size_t n = 1; n <= 40; ++n) {
    const long double gap = 2 / (expl(2 * n * t + d) + 1); /* 1 - g_0^n (0.5) */
    if (fabsl(log2l(gap) + 54) < 0.01L) continue;  /* too close to call in long double */
    double out[2];
    fill_untouched(out, 2);
    const hdt_status s = hdt_word_apply(2, w, n, 0.5, 0, &out[0], &out[1]);
    if (gap > 0x1p-54L) {
      expect(s == HDT_OK, "g_0^%zu (0.5): %s (%s)", n, hdt_status_string(s), hdt_last_error_message());
      expect(out[1] == 0 && out[0] < 1 && fabsl(out[0] - (1 - gap)) <= 0x1p-53L,
             "g_0^%zu (0.5) = (%.17g, %g), 1 - it should be %Lg", n, out[0], out[1], gap);
    } else {
      expect_failure(s, HDT_EDOMAIN, "hdt_word_apply");
      expect_untouched(out, 2, "hdt_word_apply");
    }
  }
  /* Far from the circle in the input, 1e-133 from it in the image. */
  int32_t power[100] = {0};
  double out[2];
  fill_untouched(out, 2);
  expect_failure(hdt_word_apply(2, power, 100, 0.1, 0.2, &out[0], &out[1]), HDT_EDOMAIN, "hdt_word_apply");
  expect_untouched(out, 2, "hdt_word_apply");
}
END_TEST

/* The longest words finish quickly; their statuses make sense. */
START_TEST(million_letter_words) {
  const size_t n = HDT_WORD_MAX_LENGTH;
  int32_t *w = malloc(n * sizeof *w);
  ck_assert_ptr_nonnull(w);
  uint64_t rng = UINT64_C(0x853c49e6748fea9b);
  /* A random word runs away: its matrices overflow and its images round to
     the circle. */
  for (size_t i = 0; i < n; ++i) w[i] = rng_below(&rng, 8);
  double m[9];
  fill_untouched(m, 9);
  expect_domain_failure(hdt_word_matrix(2, w, n, m), "hdt_word_matrix", "exceed the double range");
  expect_domain_failure(hdt_word_lorentz(2, w, n, m), "hdt_word_lorentz", "exceed the double range");
  expect_failure(hdt_word_apply(2, w, n, 0.1, 0.2, &m[0], &m[1]), HDT_EDOMAIN, "hdt_word_apply");
  expect_untouched(m, 9, "the word functions");
  /* v v^-1 x with a random v of n/2 - 2 letters is x = [1 2 3 1]. */
  const size_t half = n / 2 - 2;
  for (size_t i = 0; i < half; ++i) w[half + i] = inv_letter(2, w[half - 1 - i]);
  const int32_t x[4] = {1, 2, 3, 1};
  memcpy(w + 2 * half, x, sizeof x);
  double mx[4], Lw[9], Lx[9], zw[2], zx[2];
  ck_assert_int_eq(hdt_word_matrix(2, w, n, m), HDT_OK);
  ck_assert_int_eq(hdt_word_matrix(2, x, 4, mx), HDT_OK);
  for (int i = 0; i < 4; ++i) expect(bits_equal(m[i], mx[i]), "matrix entry %d: %a, not %a", i, m[i], mx[i]);
  ck_assert_int_eq(hdt_word_lorentz(2, w, n, Lw), HDT_OK);
  ck_assert_int_eq(hdt_word_lorentz(2, x, 4, Lx), HDT_OK);
  for (int i = 0; i < 9; ++i) expect(bits_equal(Lw[i], Lx[i]), "Lorentz entry %d: %a, not %a", i, Lw[i], Lx[i]);
  ck_assert_int_eq(hdt_word_apply(2, w, n, 0.1, 0.2, &zw[0], &zw[1]), HDT_OK);
  ck_assert_int_eq(hdt_word_apply(2, x, 4, 0.1, 0.2, &zx[0], &zx[1]), HDT_OK);
  expect(bits_equal(zw[0], zx[0]) && bits_equal(zw[1], zx[1]), "image (%a, %a), not (%a, %a)", zw[0], zw[1], zx[0],
         zx[1]);
  /* g_0^n overflows at once. */
  for (size_t i = 0; i < n; ++i) w[i] = 0;
  fill_untouched(m, 9);
  expect_domain_failure(hdt_word_matrix(2, w, n, m), "hdt_word_matrix", "exceed the double range");
  expect_untouched(m, 9, "hdt_word_matrix");
  free(w);
}
END_TEST

/* ---- Against products computed here, in long double ---- */

typedef struct ld_matrix {
  long double complex_a[2], complex_b[2]; /* a = [0] + i [1], b likewise */
} ld_matrix;

static ld_matrix ld_generator(int g, int k) {
  const long double pi = acosl(-1), A = 1 / tanl(pi / (4 * g)), r = sqrtl(A * A - 1), angle = k * pi / (2 * g);
  return (ld_matrix){{A, 0}, {r * cosl(angle), r * sinl(angle)}};
}

/* [[a, b], [b~, a~]] [[c, d], [d~, c~]] = [[a c + b d~, a d + b c~], ...] */
static ld_matrix ld_product(ld_matrix x, ld_matrix y) {
  const long double *a = x.complex_a, *b = x.complex_b, *c = y.complex_a, *d = y.complex_b;
  return (ld_matrix){{a[0] * c[0] - a[1] * c[1] + b[0] * d[0] + b[1] * d[1],
                      a[0] * c[1] + a[1] * c[0] + b[1] * d[0] - b[0] * d[1]},
                     {a[0] * d[0] - a[1] * d[1] + b[0] * c[0] + b[1] * c[1],
                      a[0] * d[1] + a[1] * d[0] + b[1] * c[0] - b[0] * c[1]}};
}

static ld_matrix ld_word(int g, const word_t *w) {
  ld_matrix m = {{1, 0}, {0, 0}};
  for (size_t i = 0; i < w->n; ++i) m = ld_product(m, ld_generator(g, w->a[i]));
  return m;
}

static long double ld_gap(const double m[4], ld_matrix e) {
  const long double d[4] = {e.complex_a[0], e.complex_a[1], e.complex_b[0], e.complex_b[1]};
  const long double size = hypotl(d[0], d[1]) + hypotl(d[2], d[3]);
  long double gap = 0;
  for (int i = 0; i < 4; ++i) gap = fmaxl(gap, fabsl(m[i] - d[i]));
  return gap / size;
}

/* Random freely reduced words (no cancellation to amplify the long double
   rounding: about m 2^-64 relative), the group law on pairs, and the three
   functions against each other: L maps the hyperboloid point of z to that of
   the image of z. */
START_TEST(words_agree_with_independent_products) {
  uint64_t rng = UINT64_C(0xda942042e4dd58b5);
  char buf[512];
  for (int g = 2; g <= 5; ++g)
    for (int trial = 0; trial < 150; ++trial) {
      word_t u = {0}, v = {0}, uv;
      for (word_t *w = &u; w != NULL; w = (w == &u ? &v : NULL)) {
        const size_t len = (size_t)rng_below(&rng, 13);
        while (w->n < len) {
          const int32_t k = rng_below(&rng, 4 * g);
          if (w->n == 0 || k != inv_letter(g, w->a[w->n - 1])) word_push(w, k);
        }
      }
      uv = u;
      word_append(&uv, &v);
      double mu[4], mv[4], muv[4];
      word_matrix(g, &u, mu);
      word_matrix(g, &v, mv);
      word_matrix(g, &uv, muv);
      const ld_matrix eu = ld_word(g, &u), ev = ld_word(g, &v);
      expect(ld_gap(mu, eu) < 1e-15L, "genus %d: [%s] is %Lg from the long double product", g,
             word_str(&u, buf, sizeof buf), ld_gap(mu, eu));
      /* The group law: the product of u and v's long double matrices. */
      expect(ld_gap(muv, ld_product(eu, ev)) < 1e-15L, "genus %d: [%s] is %Lg from the product of its halves", g,
             word_str(&uv, buf, sizeof buf), ld_gap(muv, ld_product(eu, ev)));
      /* The action: L(uv) maps the hyperboloid point of z to that of uv(z),
         and uv(z) = u(v(z)). Near the circle the image may round onto it. */
      const double z[2] = {0.3 - 0.002 * trial, 0.1};
      double L[9], direct[2], vz[2], uvz[2];
      ck_assert_int_eq(hdt_word_lorentz(g, uv.a, uv.n, L), HDT_OK);
      const long double r2 = (long double)z[0] * z[0] + (long double)z[1] * z[1];
      const long double p[3] = {(1 + r2) / (1 - r2), 2 * z[0] / (1 - r2), 2 * z[1] / (1 - r2)};
      long double q[3];
      for (int i = 0; i < 3; ++i) q[i] = L[3 * i] * p[0] + L[3 * i + 1] * p[1] + L[3 * i + 2] * p[2];
      const hdt_status s = hdt_word_apply(g, uv.a, uv.n, z[0], z[1], &direct[0], &direct[1]);
      if (s != HDT_OK) {
        /* 1 - |uv(z)| = 2 / (1 + t) */
        expect_failure(s, HDT_EDOMAIN, "hdt_word_apply");
        expect(2 / (1 + q[0]) < 0x1p-50L, "genus %d: [%s]: z refused, yet 1 - |uv(z)| = %Lg", g,
               word_str(&uv, buf, sizeof buf), 2 / (1 + q[0]));
        continue;
      }
      /* Back to the disk: (u, v) / (1 + t). */
      const long double ex = q[1] / (1 + q[0]), ey = q[2] / (1 + q[0]);
      expect(fabsl(ex - direct[0]) < 1e-12L && fabsl(ey - direct[1]) < 1e-12L,
             "genus %d: [%s]: the Lorentz matrix maps z to (%.17Lg, %.17Lg), the word to (%.17g, %.17g)", g,
             word_str(&uv, buf, sizeof buf), ex, ey, direct[0], direct[1]);
      if (hdt_word_apply(g, v.a, v.n, z[0], z[1], &vz[0], &vz[1]) != HDT_OK) continue;
      apply_word(g, &u, vz[0], vz[1], &uvz[0], &uvz[1]);
      /* Rounding v(z) moves it by 1e-16, hyperbolically 2e-16 / (1 - |v(z)|^2);
         u keeps that, and it is (1 - |uv(z)|^2) / 2 times as much Euclidean. */
      const long double inner = 1 - ((long double)vz[0] * vz[0] + (long double)vz[1] * vz[1]);
      const long double moved =
          1e-14L * (1 + (1 - ((long double)direct[0] * direct[0] + (long double)direct[1] * direct[1])) /
                            fmaxl(inner, 0x1p-64L));
      expect(fabs(uvz[0] - direct[0]) < moved && fabs(uvz[1] - direct[1]) < moved,
             "genus %d: [%s] maps z to (%.17g, %.17g), its halves to (%.17g, %.17g)", g, word_str(&uv, buf, sizeof buf),
             direct[0], direct[1], uvz[0], uvz[1]);
    }
}
END_TEST

int main(void) {
  const TTest *const tests[] = {
      relator_is_identity,
      relator_has_no_trivial_subword,
      relator_reduces_to_empty,
      random_words_reduce_canonically,
      chain_example_g2,
      generator_powers_are_canonical,
      canonical_words_past_the_precision_ladder,
      canonical_is_shortlex_least_g2,
      tiles_around_the_vertex_have_known_canonical_words,
      generator_powers_overflow_with_edomain,
      identity_words_give_the_exact_identity,
      images_on_the_circle_are_refused,
      million_letter_words,
      words_agree_with_independent_products,
  };
  return run_tests("group", tests, sizeof tests / sizeof tests[0]);
}
