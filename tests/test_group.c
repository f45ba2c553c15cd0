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

int main(void) {
  const TTest *const tests[] = {
      relator_is_identity,
      relator_has_no_trivial_subword,
      relator_reduces_to_empty,
      random_words_reduce_canonically,
      chain_example_g2,
      generator_powers_are_canonical,
      canonical_is_shortlex_least_g2,
  };
  return run_tests("group", tests, sizeof tests / sizeof tests[0]);
}
