/* hdt_translation_homology (HDT_0.6): the class [h] in Z^{2g} of a
   translation id, checked against the relation of Gamma_g (it must count 0
   for the map to be well defined), the words of hdt_translation_word, and
   the group law the faces' translations obey across every edge. */
#include "hdt_test.h"

#define G_MAX 8

/* The abelianisation by the rule of hdt.h, computed here from a word. */
static void count_letters(int g, const int32_t *w, size_t n, int32_t out[2 * G_MAX]) {
  for (int k = 0; k < 2 * g; ++k) out[k] = 0;
  for (size_t i = 0; i < n; ++i) {
    if (w[i] < 2 * g)
      ++out[w[i]];
    else
      --out[w[i] - 2 * g];
  }
}

static void homology(const hdt_triangulation *t, int32_t id, int32_t out[2 * G_MAX]) {
  size_t count = 0;
  const hdt_status s = hdt_translation_homology(t, id, out, 2 * G_MAX, &count);
  expect(s == HDT_OK && count == (size_t)(2 * hdt_genus(t)), "hdt_translation_homology(%d): %s, count %zu (%s)", id,
         hdt_status_string(s), count, hdt_last_error_message());
}

/* The relator (letters j (2g+1) mod 4g) is the identity and counts 0 on
   every coordinate: each g_k and each g_k^-1 occurs once in it. A count
   that did not vanish on it would not be a function on Gamma_g. */
START_TEST(relator_abelianises_to_zero) {
  for (int g = 2; g <= G_MAX; ++g) {
    const word_t r = relator(g);
    size_t length = 99;
    OK(hdt_word_reduce(g, r.a, r.n, NULL, 0, &length));
    expect(length == 0, "genus %d: the relator reduces to %zu letters, not the identity", g, length);
    int32_t c[2 * G_MAX];
    count_letters(g, r.a, r.n, c);
    for (int k = 0; k < 2 * g; ++k) expect(c[k] == 0, "genus %d: the relator counts %d on coordinate %d", g, c[k], k);
  }
}
END_TEST

/* Ids 1..4g of the neighbour set are the single letters (shortlex order):
   letter k < 2g is +e_k, letter k + 2g is -e_k; id 0 is 0. */
START_TEST(generators_are_the_unit_vectors) {
  for (int g = 2; g <= 4; ++g) {
    hdt_triangulation *t = new_triangulation(g);
    for (int32_t id = 0; id <= 4 * g; ++id) {
      int32_t letter[4];
      size_t n = 0;
      OK(hdt_neighbour_word(g, (size_t)id, letter, 4, &n));
      expect(n == (id == 0 ? 0u : 1u), "genus %d: neighbour id %d has %zu letters", g, id, n);
      int32_t c[2 * G_MAX];
      homology(t, id, c);
      for (int k = 0; k < 2 * g; ++k) {
        const int want = n == 0 ? 0 : letter[0] == k ? 1 : letter[0] == k + 2 * g ? -1 : 0;
        expect(c[k] == want, "genus %d: id %d (letter %d) has coordinate %d = %d, not %d", g, id, n ? letter[0] : -1,
               k, c[k], want);
      }
    }
    hdt_destroy(t);
  }
}
END_TEST

/* Every corner translation of a triangulation with many copies: the class
   is the letter count of its canonical word; across every edge the corner
   translations compose (the shared vertex's copy in f is h applied to its
   copy in the neighbour placed by h: [t_f] = [h] + [t_f']), and the
   translation back across the edge is the inverse word, with the negative
   class. None of these sees the rule alone: a count that broke the group
   law (a relator not counting 0) would fail the composition. */
START_TEST(classes_obey_the_group_law_across_every_edge) {
  for (int g = 2; g <= 3; ++g) {
    hdt_triangulation *t = wide_disk_triangulation(g, 300, 11u + (uint64_t)g, 0);
    faces_t f = read_faces(t);
    uint32_t *nf = malloc(3 * f.n * sizeof *nf + 1);
    int32_t *nt = malloc(3 * f.n * sizeof *nt + 1);
    ck_assert(nf && nt);
    size_t count = 0;
    OK(hdt_face_neighbours(t, nf, nt, f.n, &count));
    size_t nontrivial = 0;
    for (size_t i = 0; i < f.n; ++i)
      for (int c = 0; c < 3; ++c) {
        int32_t word[TW_MAX];
        size_t n = 0;
        OK(hdt_translation_word(t, f.tr[3 * i + c], word, TW_MAX, &n));
        int32_t want[2 * G_MAX], got[2 * G_MAX], h[2 * G_MAX], back[2 * G_MAX];
        count_letters(g, word, n, want);
        homology(t, f.tr[3 * i + c], got);
        for (int k = 0; k < 2 * g; ++k) expect(got[k] == want[k], "face %zu corner %d: coordinate %d", i, c, k);

        const uint32_t j = nf[3 * i + c];
        homology(t, nt[3 * i + c], h);
        int back_corner = -1;  /* the corner of j across the same edge from i */
        for (int d = 0; d < 3; ++d)
          if (nf[3 * j + d] == i && f.v[3 * j + d] != f.v[3 * i + (c + 1) % 3] &&
              f.v[3 * j + d] != f.v[3 * i + (c + 2) % 3])
            back_corner = d;
        expect(back_corner >= 0, "face %u has no edge back to face %zu", j, i);
        homology(t, nt[3 * j + back_corner], back);
        int32_t hw[TW_MAX], bw[TW_MAX], inverse[TW_MAX];
        size_t hn = 0, bn = 0, in = 0;
        OK(hdt_translation_word(t, nt[3 * i + c], hw, TW_MAX, &hn));
        OK(hdt_translation_word(t, nt[3 * j + back_corner], bw, TW_MAX, &bn));
        for (size_t l = 0; l < hn; ++l) inverse[l] = inv_letter(g, hw[hn - 1 - l]);
        OK(hdt_word_reduce(g, inverse, hn, inverse, TW_MAX, &in));
        expect(in == bn && memcmp(inverse, bw, bn * sizeof *bw) == 0,
               "face %zu corner %d: the translation back is not the inverse word", i, c);
        for (int k = 0; k < 2 * g; ++k)
          expect(back[k] == -h[k], "face %zu corner %d: back across the edge %d, not %d", i, c, back[k], -h[k]);
        nontrivial += hn > 0;

        for (int e = 1; e <= 2; ++e) {
          const uint32_t v = f.v[3 * i + (c + e) % 3];
          int d = 0;
          while (d < 3 && f.v[3 * j + d] != v) ++d;
          expect(d < 3, "vertex %u of face %zu's edge is not in face %u", v, i, j);
          int32_t mine[2 * G_MAX], theirs[2 * G_MAX];
          homology(t, f.tr[3 * i + (c + e) % 3], mine);
          homology(t, f.tr[3 * j + d], theirs);
          for (int k = 0; k < 2 * g; ++k)
            expect(mine[k] == h[k] + theirs[k], "genus %d, face %zu, vertex %u, coordinate %d: %d != %d + %d", g, i,
                   v, k, mine[k], h[k], theirs[k]);
        }
      }
    expect(nontrivial > 0, "genus %d: no edge crosses a copy's side; the test sees nothing", g);
    free(nf), free(nt);
    faces_free(&f);
    hdt_destroy(t);
  }
}
END_TEST

START_TEST(arguments) {
  hdt_triangulation *t = new_triangulation(2);
  int32_t out[8];
  size_t count = 77;
  expect_failure(hdt_translation_homology(NULL, 0, out, 8, &count), HDT_EINVAL, "hdt_translation_homology");
  expect_failure(hdt_translation_homology(t, 0, out, 8, NULL), HDT_EINVAL, "hdt_translation_homology");
  const int32_t bad[] = {-1, INT32_MIN, INT32_MAX, 1000000};
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
    for (int k = 0; k < 8; ++k) out[k] = 1234;
    count = 77;
    expect_failure(hdt_translation_homology(t, bad[i], out, 8, &count), HDT_EINVAL, "hdt_translation_homology");
    expect(count == 77 && out[0] == 1234, "id %d: something was written", bad[i]);
    expect(strstr(hdt_last_error_message(), "unknown translation id") != NULL, "message: %s",
           hdt_last_error_message());
  }
  expect_failure(hdt_translation_homology(t, 1, NULL, 4, &count), HDT_EINVAL, "hdt_translation_homology");
  /* The two-call pattern: a size query, a buffer too small, one too large. */
  count = 0;
  OK(hdt_translation_homology(t, 1, NULL, 0, &count));
  expect(count == 4, "genus 2: %zu coordinates, not 4", count);
  for (int k = 0; k < 8; ++k) out[k] = 1234;
  count = 0;
  expect_failure(hdt_translation_homology(t, 1, out, 3, &count), HDT_EBUFS, "hdt_translation_homology");
  expect(count == 4 && out[0] == 1234, "HDT_EBUFS: count %zu, out[0] %d", count, out[0]);
  OK(hdt_translation_homology(t, 1, out, 8, &count));
  expect(count == 4 && out[0] == 1 && out[1] == 0 && out[2] == 0 && out[3] == 0 && out[4] == 1234,
         "id 1 (g_0): (%d, %d, %d, %d), out[4] %d", out[0], out[1], out[2], out[3], out[4]);
  hdt_destroy(t);
}
END_TEST

int main(void) {
  const TTest *const tests[] = {
      relator_abelianises_to_zero,
      generators_are_the_unit_vectors,
      classes_obey_the_group_law_across_every_edge,
      arguments,
  };
  return run_tests("homology", tests, sizeof tests / sizeof tests[0]);
}
