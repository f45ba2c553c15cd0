/* The neighbour set N = { h : h(F_g) meets F_g } and its translation ids. */
#include "hdt_test.h"

/* The canonical word of the neighbour with translation id `id`. */
static word_t neighbour(int g, size_t id) {
  word_t w = {0};
  size_t len = 0;
  const hdt_status s = hdt_neighbour_word(g, id, w.a, TW_MAX, &len);
  expect(s == HDT_OK, "hdt_neighbour_word(%d, %zu): %s", g, id, hdt_last_error_message());
  w.n = len;
  return w;
}

static size_t neighbour_count(int g) {
  size_t count = 0;
  ck_assert_int_eq(hdt_neighbour_count(g, &count), HDT_OK);
  return count;
}

START_TEST(count_is_square) {
  const int genera[] = {2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 100, HDT_GENUS_MAX};
  for (size_t i = 0; i < sizeof genera / sizeof genera[0]; ++i) {
    const size_t q = 4 * (size_t)genera[i] - 1;
    ck_assert_uint_eq(neighbour_count(genera[i]), q * q);
  }
}
END_TEST

/* Id 0 is the identity, the words follow in strict shortlex order, each is
   canonical, and the lengths are 1, 4g, 8g (lengths 2..2g-1), 4g (length 2g). */
START_TEST(words_are_canonical_in_shortlex_order) {
  char b1[512], b2[512];
  for (int g = 2; g <= 10; ++g) {
    const size_t count = neighbour_count(g);
    size_t by_length[TW_MAX] = {0};
    word_t prev = {0};
    for (size_t id = 0; id < count; ++id) {
      const word_t w = neighbour(g, id);
      expect(w.n < TW_MAX, "genus %d: id %zu has %zu letters", g, id, w.n);
      ++by_length[w.n];
      if (id == 0) {
        expect(w.n == 0, "genus %d: id 0 is [%s], not the identity", g, word_str(&w, b1, sizeof b1));
      } else {
        expect(shortlex_cmp(&prev, &w) < 0, "genus %d: id %zu [%s] does not follow [%s]", g, id,
               word_str(&w, b1, sizeof b1), word_str(&prev, b2, sizeof b2));
      }
      const word_t c = reduce_word(g, &w);
      expect(word_eq(&w, &c), "genus %d: id %zu [%s] is not canonical ([%s])", g, id, word_str(&w, b1, sizeof b1),
             word_str(&c, b2, sizeof b2));
      prev = w;
    }
    ck_assert_uint_eq(by_length[0], 1);
    ck_assert_uint_eq(by_length[1], 4 * (size_t)g);
    for (int len = 2; len < 2 * g; ++len) ck_assert_uint_eq(by_length[len], 8 * (size_t)g);
    ck_assert_uint_eq(by_length[2 * g], 4 * (size_t)g);
  }
}
END_TEST

/* ---- An independent construction of N ---- */

/* A set of words (open addressing on a hash of the letters). */
typedef struct word_set {
  word_t *words;
  size_t size, capacity;
  long *slots; /* index into words, -1 when empty */
  size_t slot_count;
} word_set;

static size_t word_hash(const word_t *w) {
  uint64_t h = UINT64_C(1469598103934665603);
  for (size_t i = 0; i < w->n; ++i) h = (h ^ (uint64_t)(uint32_t)w->a[i]) * UINT64_C(1099511628211);
  return (size_t)(h ^ w->n);
}

static void set_init(word_set *s, size_t slot_count) {
  s->size = 0;
  s->capacity = slot_count / 2;
  s->words = malloc(s->capacity * sizeof *s->words);
  s->slots = malloc(slot_count * sizeof *s->slots);
  ck_assert_ptr_nonnull(s->words);
  ck_assert_ptr_nonnull(s->slots);
  for (size_t i = 0; i < slot_count; ++i) s->slots[i] = -1;
  s->slot_count = slot_count;
}

static void set_free(word_set *s) {
  free(s->words);
  free(s->slots);
}

/* The slot holding w, or the empty slot where it goes. */
static size_t set_slot(const word_set *s, const word_t *w) {
  size_t i = word_hash(w) % s->slot_count;
  while (s->slots[i] >= 0 && !word_eq(&s->words[s->slots[i]], w)) i = (i + 1) % s->slot_count;
  return i;
}

static int set_has(const word_set *s, const word_t *w) { return s->slots[set_slot(s, w)] >= 0; }

static void set_add(word_set *s, const word_t *w) {
  const size_t i = set_slot(s, w);
  if (s->slots[i] >= 0) return;
  expect(s->size < s->capacity, "word set full: the tile search runs away");
  s->words[s->size] = *w;
  s->slots[i] = (long)s->size++;
}

/* h(F) meets F: some vertex of h(F) is a vertex of F. A shared vertex puts
   the centre h(0) within 2R of 0 (R: the circumradius, Euclidean radius
   r_v of the vertices), i.e. within Euclidean radius 2 r_v / (1 + r_v^2);
   that cheap necessary condition is tried first. */
static int tile_meets_f(int g, const word_t *h, const double (*fv)[2]) {
  const double rv = hypot(fv[0][0], fv[0][1]);
  double x, y;
  apply_word(g, h, 0, 0, &x, &y);
  if (hypot(x, y) > 2 * rv / (1 + rv * rv) + 1e-9) return 0;
  for (int j = 0; j < 4 * g; ++j) {
    apply_word(g, h, fv[j][0], fv[j][1], &x, &y);
    for (int i = 0; i < 4 * g; ++i)
      if (hypot(x - fv[i][0], y - fv[i][1]) < 1e-9) return 1;
  }
  return 0;
}

static int by_shortlex(const void *x, const void *y) { return shortlex_cmp(x, y); }

START_TEST(set_matches_tile_search) {
  const int genera[] = {2, 3, 4, 5, 6, 8};
  char b1[512], b2[512];
  for (size_t gi = 0; gi < sizeof genera / sizeof genera[0]; ++gi) {
    const int g = genera[gi];
    double(*fv)[2] = malloc(4 * (size_t)g * sizeof *fv);
    ck_assert_ptr_nonnull(fv);
    for (int k = 0; k < 4 * g; ++k) ck_assert_int_eq(hdt_polygon_vertex(g, k, &fv[k][0], &fv[k][1]), HDT_OK);
    /* Breadth-first over tiles: extend the kept elements by one letter and
       keep the new elements whose tile meets F. The set's words, in the
       order they were added, are the queue. */
    const size_t expected = (4 * (size_t)g - 1) * (4 * (size_t)g - 1);
    word_set set;
    set_init(&set, 4 * expected);
    set_add(&set, &(word_t){0});
    for (size_t q = 0; q < set.size; ++q)
      for (int k = 0; k < 4 * g; ++k) {
        word_t cand = set.words[q];
        word_push(&cand, k);
        const word_t c = reduce_word(g, &cand);
        if (!set_has(&set, &c) && tile_meets_f(g, &c, fv)) set_add(&set, &c);
      }
    const size_t nkept = set.size;
    word_t *kept = set.words;
    ck_assert_uint_eq(nkept, expected);
    ck_assert_uint_eq(neighbour_count(g), expected);
    qsort(kept, nkept, sizeof *kept, by_shortlex);
    for (size_t id = 0; id < nkept; ++id) {
      const word_t w = neighbour(g, id);
      expect(word_eq(&w, &kept[id]), "genus %d: id %zu is [%s], the tile search gives [%s]", g, id,
             word_str(&w, b1, sizeof b1), word_str(&kept[id], b2, sizeof b2));
    }
    set_free(&set);
    free(fv);
  }
}
END_TEST

int main(void) {
  const TTest *const tests[] = {
      count_is_square,
      words_are_canonical_in_shortlex_order,
      set_matches_tile_search,
  };
  return run_tests("neighbours", tests, sizeof tests / sizeof tests[0]);
}
