/* Soak test: 10^5 mixed operations on one triangulation of genus 2 and one
 * of genus 5 -- single inserts, small hdt_insert_many batches, duplicates of
 * live points (HDT_EEXISTS), removals of random live user vertices (a
 * refusal, HDT_ENOTSUP, must change nothing), hdt_remove_dummies now and
 * then -- with hdt_validate every 5000 operations and at the end. The final
 * triangulation must then equal, as a set of faces on M_g, the one built
 * from scratch from the surviving points.
 *
 * HDT_TEST_SCALE (a positive number, default 1) scales the number of
 * operations, e.g. HDT_TEST_SCALE=0.2 for a quick run under a sanitizer; the
 * default is the 10^5.
 *
 * Comparing the two triangulations. Vertex ids differ between them (the
 * soak's ids follow its history, the fresh one's the Hilbert order of
 * hdt_insert_many), and so do translation ids past the neighbour set (each
 * handle interns them as it meets them). What both share is the input
 * point of each vertex, whose representative in F_g both compute the same
 * way, and the group Gamma_g itself. So each surviving point gets a label
 * (its rank among the soak's surviving ids), and a face is described by
 *   - its three corners' labels, rotated (orientation kept) to start at the
 *     smallest label L0, then L1, L2 counterclockwise;
 *   - the copy of the face that has L0 at its representative: the corners
 *     of the face as reported sit at h_i(rep(L_i)); applying h_0^{-1} to the
 *     whole triangle gives a copy with corner 0 at rep(L0) (translation the
 *     identity) and corners 1, 2 at (h_0^{-1} h_1)(rep(L1)),
 *     (h_0^{-1} h_2)(rep(L2)).
 * The key is (L0, L1, L2, canon(h_0^{-1} h_1), canon(h_0^{-1} h_2)), with
 * canon the canonical word of hdt_word_reduce (unique per group element;
 * computed from the words of hdt_translation_word, never from ids). Two
 * faces are the same triangle of M_g exactly when their lifts differ by one
 * element of Gamma_g, and since Gamma_g acts freely, fixing corner L0 at its
 * representative leaves exactly one lift: equal faces have equal keys and
 * different faces different keys. The key does not depend on which copy a
 * triangulation calls canonical nor on any id. The sorted key lists must be
 * identical. (For random input no four points are cocircular, so the
 * Delaunay triangulation is unique and both must find the same one.)
 *
 * Both triangulations have their dummies removed first; if some dummy
 * stayed in either (not expected with thousands of points), the vertex sets
 * differ and only the counts are compared (and reported). */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include <time.h>

#include "hdt_test.h"

/* Uniform by Euclidean area in the disk of radius 0.95: most points lie
   outside F_g and are mapped to their representatives. */
static void random_point(uint64_t *rng, double *x, double *y) {
  const double r = 0.95 * sqrt(uniform01(rng)), a = 6.283185307179586 * uniform01(rng);
  *x = r * cos(a), *y = r * sin(a);
}

static double test_scale(void) {
  const char *s = getenv("HDT_TEST_SCALE");
  const double v = s ? atof(s) : 1.0;
  return v > 0 ? v : 1.0;
}

static void expect_valid(const hdt_triangulation *t, const char *what, size_t op) {
  const hdt_status s = hdt_validate(t);
  expect(s == HDT_OK, "%s (operation %zu): hdt_validate: %s (%s)", what, op, hdt_status_string(s),
         hdt_last_error_message());
}

/* ---- The soak's own record of the triangulation ---- */

typedef struct state_t {
  hdt_triangulation *t;
  size_t cap;       /* entries of px, py, pos */
  double *px, *py;  /* input point of each user vertex id (as given) */
  size_t *pos;      /* position in `live`, SIZE_MAX when not a live user vertex */
  uint32_t *live;   /* the live user vertex ids, in no order */
  size_t nlive;
} state_t;

static void grow(state_t *s, size_t bound) {
  if (bound <= s->cap) return;
  size_t cap = s->cap ? s->cap : 1024;
  while (cap < bound) cap *= 2;
  s->px = realloc(s->px, cap * sizeof *s->px);
  s->py = realloc(s->py, cap * sizeof *s->py);
  s->pos = realloc(s->pos, cap * sizeof *s->pos);
  s->live = realloc(s->live, cap * sizeof *s->live);
  ck_assert(s->px && s->py && s->pos && s->live);
  for (size_t i = s->cap; i < cap; ++i) s->pos[i] = SIZE_MAX;
  s->cap = cap;
}

/* Vertex v was answered for the input point (x, y) with status OK (a new
   vertex, or a dummy that became a user vertex). */
static void note_new_user(state_t *s, uint32_t v, double x, double y, const char *what) {
  grow(s, (size_t)v + 1);
  expect(s->pos[v] == SIZE_MAX, "%s: vertex %u answered as new, but it is a live user vertex already", what, v);
  expect(hdt_vertex_is_dummy(s->t, v) == 0, "%s: vertex %u is not a live user vertex (%d)", what, v,
         hdt_vertex_is_dummy(s->t, v));
  s->px[v] = x, s->py[v] = y;
  s->pos[v] = s->nlive;
  s->live[s->nlive++] = v;
}

static void note_removed(state_t *s, uint32_t v) {
  const size_t p = s->pos[v];
  s->live[p] = s->live[--s->nlive];
  s->pos[s->live[p]] = p;
  s->pos[v] = SIZE_MAX;
}

/* ---- Id-free face keys (see the comment at the top) ---- */

/* Interned canonical words, shared by both triangulations. */
typedef struct words_t {
  size_t n, cap;
  word_t *w;
  size_t *slot; /* open addressing: index + 1, 0 empty; capacity 2^k >= 2n */
  size_t nslot;
} words_t;

static uint64_t word_hash(const word_t *w) {
  uint64_t h = UINT64_C(1469598103934665603) ^ w->n;
  for (size_t i = 0; i < w->n; ++i) h = (h ^ (uint64_t)w->a[i]) * UINT64_C(1099511628211);
  return h;
}

static size_t intern(words_t *ws, const word_t *w) {
  if (2 * (ws->n + 1) > ws->nslot) {
    const size_t nslot = ws->nslot ? 2 * ws->nslot : 1024;
    size_t *slot = calloc(nslot, sizeof *slot);
    ck_assert_ptr_nonnull(slot);
    for (size_t i = 0; i < ws->n; ++i) {
      size_t h = word_hash(&ws->w[i]) & (nslot - 1);
      while (slot[h]) h = (h + 1) & (nslot - 1);
      slot[h] = i + 1;
    }
    free(ws->slot);
    ws->slot = slot, ws->nslot = nslot;
  }
  size_t h = word_hash(w) & (ws->nslot - 1);
  for (; ws->slot[h]; h = (h + 1) & (ws->nslot - 1))
    if (word_eq(&ws->w[ws->slot[h] - 1], w)) return ws->slot[h] - 1;
  if (ws->n == ws->cap) {
    ws->cap = ws->cap ? 2 * ws->cap : 256;
    ws->w = realloc(ws->w, ws->cap * sizeof *ws->w);
    ck_assert_ptr_nonnull(ws->w);
  }
  ws->w[ws->n] = *w;
  ws->slot[h] = ws->n + 1;
  return ws->n++;
}

/* Per triangulation: the word of each translation id, and the interned
   canonical word of h_a^{-1} h_b per pair (a, b) met. */
typedef struct pairs_t {
  const hdt_triangulation *t;
  int g;
  size_t nids;
  word_t **word_of; /* by translation id, NULL until needed */
  size_t nslot, n;
  uint64_t *key;    /* (a << 32 | b) + 1, 0 empty */
  size_t *value;
} pairs_t;

static const word_t *translation_word(pairs_t *p, int32_t id) {
  expect(id >= 0, "negative translation id %d", id);
  if ((size_t)id >= p->nids) {
    size_t n = p->nids ? p->nids : 256;
    while (n <= (size_t)id) n *= 2;
    p->word_of = realloc(p->word_of, n * sizeof *p->word_of);
    ck_assert_ptr_nonnull(p->word_of);
    for (size_t i = p->nids; i < n; ++i) p->word_of[i] = NULL;
    p->nids = n;
  }
  if (!p->word_of[id]) {
    word_t *w = calloc(1, sizeof *w);
    ck_assert_ptr_nonnull(w);
    const hdt_status s = hdt_translation_word(p->t, id, w->a, TW_MAX, &w->n);
    expect(s == HDT_OK, "hdt_translation_word(%d): %s (%s)", id, hdt_status_string(s), hdt_last_error_message());
    p->word_of[id] = w;
  }
  return p->word_of[id];
}

static size_t relative_word(pairs_t *p, words_t *ws, int32_t a, int32_t b) {
  if (2 * (p->n + 1) > p->nslot) {
    const size_t nslot = p->nslot ? 2 * p->nslot : 4096;
    uint64_t *key = calloc(nslot, sizeof *key);
    size_t *value = malloc(nslot * sizeof *value);
    ck_assert(key && value);
    for (size_t i = 0; i < p->nslot; ++i) {
      if (!p->key[i]) continue;
      size_t h = (size_t)((p->key[i] * UINT64_C(0x9E3779B97F4A7C15)) >> 20) & (nslot - 1);
      while (key[h]) h = (h + 1) & (nslot - 1);
      key[h] = p->key[i], value[h] = p->value[i];
    }
    free(p->key);
    free(p->value);
    p->key = key, p->value = value, p->nslot = nslot;
  }
  const uint64_t k = ((uint64_t)(uint32_t)a << 32 | (uint32_t)b) + 1;
  size_t h = (size_t)((k * UINT64_C(0x9E3779B97F4A7C15)) >> 20) & (p->nslot - 1);
  for (; p->key[h]; h = (h + 1) & (p->nslot - 1))
    if (p->key[h] == k) return p->value[h];
  word_t w = word_inverse(p->g, translation_word(p, a));
  word_append(&w, translation_word(p, b));
  const word_t c = reduce_word(p->g, &w);
  p->key[h] = k;
  p->value[h] = intern(ws, &c);
  ++p->n;
  return p->value[h];
}

static void pairs_free(pairs_t *p) {
  for (size_t i = 0; i < p->nids; ++i) free(p->word_of[i]);
  free(p->word_of);
  free(p->key);
  free(p->value);
}

typedef struct key_t {
  uint32_t l[3];
  uint32_t w[2];
} key_t;

static int key_cmp(const void *x, const void *y) {
  const key_t *a = x, *b = y;
  for (int i = 0; i < 3; ++i)
    if (a->l[i] != b->l[i]) return a->l[i] < b->l[i] ? -1 : 1;
  for (int i = 0; i < 2; ++i)
    if (a->w[i] != b->w[i]) return a->w[i] < b->w[i] ? -1 : 1;
  return 0;
}

/* The sorted keys of t's faces; label[v] is the label of vertex id v. */
static key_t *face_keys(const hdt_triangulation *t, const uint32_t *label, words_t *ws, size_t *count) {
  faces_t f = read_faces(t);
  pairs_t p = {t, hdt_genus(t), 0, NULL, 0, 0, NULL, NULL};
  key_t *keys = malloc(f.n * sizeof *keys + 1);
  ck_assert_ptr_nonnull(keys);
  for (size_t i = 0; i < f.n; ++i) {
    uint32_t L[3];
    for (int c = 0; c < 3; ++c) {
      L[c] = label[f.v[3 * i + c]];
      expect(L[c] != UINT32_MAX, "face %zu uses vertex %u, which has no label (a dummy?)", i, f.v[3 * i + c]);
    }
    const int j = L[0] < L[1] ? (L[0] < L[2] ? 0 : 2) : (L[1] < L[2] ? 1 : 2);
    const int32_t *tr = &f.tr[3 * i];
    key_t k;
    for (int c = 0; c < 3; ++c) k.l[c] = L[(j + c) % 3];
    for (int c = 1; c < 3; ++c) k.w[c - 1] = (uint32_t)relative_word(&p, ws, tr[j], tr[(j + c) % 3]);
    keys[i] = k;
  }
  qsort(keys, f.n, sizeof *keys, key_cmp);
  *count = f.n;
  pairs_free(&p);
  faces_free(&f);
  return keys;
}

/* ---- The soak ---- */

/* Operations between two hdt_validate checkpoints. */
#define VALIDATE_EVERY 5000

/* What the closing report counts. */
typedef struct tally_t {
  size_t single, batches, batch_points, dups, removed, refused, refusals_checked, validations, peak;
  double t_validate; /* seconds in hdt_validate */
} tally_t;

/* One soak: the handle and the record of it, the PRNG, the operations done
   so far and the checkpoints to come. */
typedef struct soak_t {
  int g;
  uint64_t rng;
  state_t s;
  size_t op;
  size_t next_dummy;    /* index of the next hdt_remove_dummies in the plan */
  size_t next_validate; /* operation count of the next checkpoint */
  tally_t n;
  char what[160];
} soak_t;

/* One new point: hdt_insert makes it a new live user vertex. */
static void insert_one(soak_t *k) {
  double x, y;
  random_point(&k->rng, &x, &y);
  uint32_t v = UINT32_MAX;
  const hdt_status st = hdt_insert(k->s.t, x, y, &v);
  snprintf(k->what, sizeof k->what, "g=%d, op %zu: hdt_insert(%.17g, %.17g)", k->g, k->op, x, y);
  expect(st == HDT_OK, "%s: %s (%s)", k->what, hdt_status_string(st), hdt_last_error_message());
  note_new_user(&k->s, v, x, y, k->what);
  ++k->n.single, ++k->op;
}

/* A batch of 2..8 points, sometimes with a live point among them: that one
   is answered with its vertex, every other with a new vertex or a former
   dummy. */
static void insert_batch(soak_t *k) {
  state_t *s = &k->s;
  const size_t n = 2 + (size_t)rng_below(&k->rng, 7);
  double xy[2 * 8];
  uint32_t ids[8];
  for (size_t i = 0; i < n; ++i) random_point(&k->rng, &xy[2 * i], &xy[2 * i + 1]);
  size_t dup_at = SIZE_MAX;
  uint32_t dup_of = 0;
  if (rng_below(&k->rng, 4) == 0) {
    dup_at = (size_t)rng_below(&k->rng, (int)n), dup_of = s->live[rng_below(&k->rng, (int)s->nlive)];
    xy[2 * dup_at] = s->px[dup_of], xy[2 * dup_at + 1] = s->py[dup_of];
  }
  const size_t bound = hdt_vertex_id_bound(s->t);
  const hdt_status st = hdt_insert_many(s->t, xy, n, ids);
  snprintf(k->what, sizeof k->what, "g=%d, op %zu: hdt_insert_many(%zu points)", k->g, k->op, n);
  expect(st == HDT_OK, "%s: %s (%s)", k->what, hdt_status_string(st), hdt_last_error_message());
  for (size_t i = 0; i < n; ++i) {
    if (i == dup_at) {
      expect(ids[i] == dup_of, "%s: the live point of vertex %u got vertex %u", k->what, dup_of, ids[i]);
      continue;
    }
    expect(ids[i] >= bound || hdt_vertex_is_dummy(s->t, ids[i]) == 0, "%s: point %zu got old vertex %u", k->what,
           i, ids[i]);
    grow(s, (size_t)ids[i] + 1);
    if (s->pos[ids[i]] == SIZE_MAX) note_new_user(s, ids[i], xy[2 * i], xy[2 * i + 1], k->what);
  }
  ++k->n.batches, k->n.batch_points += n, k->op += n;
}

/* A live point again: HDT_EEXISTS naming its vertex, and no vertex added. */
static void insert_duplicate(soak_t *k) {
  hdt_triangulation *t = k->s.t;
  const uint32_t v = k->s.live[rng_below(&k->rng, (int)k->s.nlive)];
  const size_t V = hdt_vertex_count(t);
  uint32_t got = UINT32_MAX;
  const hdt_status st = hdt_insert(t, k->s.px[v], k->s.py[v], &got);
  expect(st == HDT_EEXISTS && got == v, "g=%d, op %zu: re-inserting the point of vertex %u: %s, vertex %u (%s)",
         k->g, k->op, v, hdt_status_string(st), got, hdt_last_error_message());
  expect(hdt_vertex_count(t) == V, "g=%d, op %zu: a duplicate changed the vertex count", k->g, k->op);
  ++k->n.dups, ++k->op;
}

/* After a refused removal of v: the counts are V, F and bound as before and
   v is still a user vertex; when `before` is given, the faces are the same
   id for id. */
static void expect_refusal_changed_nothing(soak_t *k, uint32_t v, size_t V, size_t F, size_t bound,
                                           const faces_t *before) {
  const hdt_triangulation *t = k->s.t;
  expect(hdt_vertex_count(t) == V && hdt_face_count(t) == F && hdt_vertex_id_bound(t) == bound &&
             hdt_vertex_is_dummy(t, v) == 0,
         "g=%d, op %zu: a refused removal of vertex %u changed the counts", k->g, k->op, v);
  if (!before) return;
  faces_t after = read_faces(t);
  expect(after.n == before->n && memcmp(after.v, before->v, 3 * after.n * sizeof *after.v) == 0 &&
             memcmp(after.tr, before->tr, 3 * after.n * sizeof *after.tr) == 0,
         "g=%d, op %zu: a refused removal of vertex %u changed the faces", k->g, k->op, v);
  faces_free(&after);
  ++k->n.refusals_checked;
}

/* Removes a random live user vertex: it goes (one vertex fewer, its id
   dead), or the removal is refused with HDT_ENOTSUP and changes nothing. */
static void remove_one(soak_t *k) {
  hdt_triangulation *t = k->s.t;
  const uint32_t v = k->s.live[rng_below(&k->rng, (int)k->s.nlive)];
  const size_t V = hdt_vertex_count(t), F = hdt_face_count(t), bound = hdt_vertex_id_bound(t);
  /* Refusals are only possible once hdt_remove_dummies has run (with every
     dummy present, any superset keeps the guarantee); the full face
     comparison costs O(F), so it runs for every removal while the
     triangulation is small (when refusals happen) and for one in 20 later. */
  const int full_check = k->next_dummy > 0 && (F < 4000 || rng_below(&k->rng, 20) == 0);
  faces_t before = {0, NULL, NULL};
  if (full_check) before = read_faces(t);
  const hdt_status st = hdt_remove_vertex(t, v);
  if (st == HDT_OK) {
    expect(hdt_vertex_count(t) == V - 1 && hdt_vertex_is_dummy(t, v) == -1,
           "g=%d, op %zu: vertex %u removed, count %zu -> %zu", k->g, k->op, v, V, hdt_vertex_count(t));
    note_removed(&k->s, v);
    ++k->n.removed;
  } else {
    expect(st == HDT_ENOTSUP, "g=%d, op %zu: hdt_remove_vertex(%u): %s (%s)", k->g, k->op, v, hdt_status_string(st),
           hdt_last_error_message());
    expect_refusal_changed_nothing(k, v, V, F, bound, full_check ? &before : NULL);
    ++k->n.refused;
  }
  if (full_check) faces_free(&before);
  ++k->op;
}

/* Once the operation count reaches the next entry of plan[0..count):
   hdt_remove_dummies succeeds and reports the dummies left truthfully. */
static void maybe_remove_dummies(soak_t *k, const size_t *plan, size_t count) {
  if (k->next_dummy >= count || k->op < plan[k->next_dummy]) return;
  hdt_triangulation *t = k->s.t;
  size_t remaining = SIZE_MAX;
  const hdt_status st = hdt_remove_dummies(t, &remaining);
  expect(st == HDT_OK && remaining == hdt_dummy_count(t), "g=%d, op %zu: hdt_remove_dummies: %s, %zu left (%s)",
         k->g, k->op, hdt_status_string(st), remaining, hdt_last_error_message());
  printf("soak g=%d: hdt_remove_dummies after %zu operations (%zu vertices): %zu dummies left\n", k->g, k->op,
         hdt_vertex_count(t), remaining);
  ++k->next_dummy;
}

/* Every VALIDATE_EVERY operations: hdt_validate passes, the vertices are the
   live user vertices of the record plus the dummies, and the faces number
   2 (V + 2g - 2) (Euler). */
static void maybe_validate(soak_t *k) {
  if (k->op < k->next_validate) return;
  const hdt_triangulation *t = k->s.t;
  const double tv = seconds();
  expect_valid(t, "soak checkpoint", k->op);
  k->n.t_validate += seconds() - tv;
  ++k->n.validations;
  expect(hdt_vertex_count(t) == k->s.nlive + hdt_dummy_count(t),
         "g=%d, op %zu: %zu vertices, but %zu live user vertices and %zu dummies", k->g, k->op, hdt_vertex_count(t),
         k->s.nlive, hdt_dummy_count(t));
  expect(hdt_face_count(t) == 2 * (hdt_vertex_count(t) + 2 * (size_t)k->g - 2),
         "g=%d, op %zu: %zu faces, %zu vertices", k->g, k->op, hdt_face_count(t), hdt_vertex_count(t));
  k->next_validate += VALIDATE_EVERY;
}

/* The mixed operations, `ops` of them, with their checkpoints. */
static void run_operations(soak_t *k, size_t ops) {
  /* hdt_remove_dummies after these many operations (early, with a few
     hundred points or less: some dummies stay and removals can be refused;
     later: none should stay), and at the end. */
  const size_t plan[] = {ops < 20000 ? ops / 100 : 200, ops / 50, ops / 10, ops / 3};
  while (k->op < ops) {
    const int r = rng_below(&k->rng, 100);
    if (r < 44 || k->s.nlive == 0) insert_one(k);
    else if (r < 48) insert_batch(k);
    else if (r < 53) insert_duplicate(k);
    else remove_one(k);
    if (hdt_vertex_count(k->s.t) > k->n.peak) k->n.peak = hdt_vertex_count(k->s.t);
    maybe_remove_dummies(k, plan, sizeof plan / sizeof plan[0]);
    maybe_validate(k);
  }
}

/* The last hdt_remove_dummies and validation; the vertices are the live
   user vertices plus the dummies left, which it gives. */
static size_t finish_operations(soak_t *k) {
  hdt_triangulation *t = k->s.t;
  size_t left = SIZE_MAX;
  ck_assert_int_eq(hdt_remove_dummies(t, &left), HDT_OK);
  expect_valid(t, "soak end", k->op);
  ++k->n.validations;
  expect(hdt_vertex_count(t) == k->s.nlive + left, "g=%d: %zu vertices at the end, %zu live user points, %zu dummies",
         k->g, hdt_vertex_count(t), k->s.nlive, left);
  return left;
}

/* ---- From scratch ---- */

/* The labels of the soak's vertex ids, by rank among the surviving ids
   (UINT32_MAX for the others), and the survivors' points in that order into
   *xy (both malloc'ed). */
static uint32_t *label_survivors(const state_t *s, double **xy) {
  const size_t bound = hdt_vertex_id_bound(s->t);
  uint32_t *label = malloc(bound * sizeof *label + 1);
  *xy = malloc(2 * s->nlive * sizeof **xy + 1);
  ck_assert(label && *xy);
  size_t k = 0;
  for (uint32_t v = 0; v < bound; ++v) {
    label[v] = UINT32_MAX;
    if (v < s->cap && s->pos[v] != SIZE_MAX) {
      label[v] = (uint32_t)k;
      (*xy)[2 * k] = s->px[v], (*xy)[2 * k + 1] = s->py[v];
      ++k;
    }
  }
  ck_assert_uint_eq(k, s->nlive);
  return label;
}

typedef struct fresh_t {
  hdt_triangulation *u;
  uint32_t *label; /* by vertex id: index of its point, UINT32_MAX for none */
  size_t left;     /* dummies left */
} fresh_t;

/* The triangulation of the n points xy built in one hdt_insert_many, its
   dummies removed: valid, one distinct vertex per point, no other vertices
   than those and the dummies left. */
static fresh_t fresh_triangulation(int g, const double *xy, size_t n, size_t op) {
  fresh_t f = {new_triangulation(g), NULL, SIZE_MAX};
  uint32_t *ids = malloc(n * sizeof *ids + 1);
  ck_assert_ptr_nonnull(ids);
  const hdt_status st = hdt_insert_many(f.u, xy, n, ids);
  expect(st == HDT_OK, "g=%d: from scratch, hdt_insert_many(%zu): %s (%s)", g, n, hdt_status_string(st),
         hdt_last_error_message());
  ck_assert_int_eq(hdt_remove_dummies(f.u, &f.left), HDT_OK);
  expect_valid(f.u, "from scratch", op);
  const size_t bound = hdt_vertex_id_bound(f.u);
  f.label = malloc(bound * sizeof *f.label + 1);
  ck_assert_ptr_nonnull(f.label);
  for (size_t v = 0; v < bound; ++v) f.label[v] = UINT32_MAX;
  for (size_t i = 0; i < n; ++i) {
    expect(ids[i] < bound && f.label[ids[i]] == UINT32_MAX,
           "g=%d: from scratch, point %zu got vertex %u, already given (two survivors with one representative?)", g,
           i, ids[i]);
    f.label[ids[i]] = (uint32_t)i;
  }
  expect(hdt_vertex_count(f.u) == n + f.left, "g=%d: from scratch, %zu vertices for %zu points and %zu dummies", g,
         hdt_vertex_count(f.u), n, f.left);
  free(ids);
  return f;
}

/* t (labels label_t) and u (labels label_u) have the same faces on M_g:
   equal sorted lists of id-free keys. */
static void expect_same_faces(int g, const hdt_triangulation *t, const uint32_t *label_t, const hdt_triangulation *u,
                              const uint32_t *label_u, double t0) {
  words_t ws = {0, 0, NULL, NULL, 0};
  size_t nt = 0, nu = 0;
  key_t *kt = face_keys(t, label_t, &ws, &nt);
  key_t *ku = face_keys(u, label_u, &ws, &nu);
  expect(nt == nu, "g=%d: %zu faces after the soak, %zu from scratch", g, nt, nu);
  for (size_t i = 0; i < nt; ++i) {
    if (key_cmp(&kt[i], &ku[i]) == 0) continue;
    /* Report the first key found in one list and not the other. */
    const key_t *miss = key_cmp(&kt[i], &ku[i]) < 0 ? &kt[i] : &ku[i];
    char w1[256], w2[256];
    ck_abort_msg("g=%d: the soak's faces differ from the fresh triangulation's (%zu faces each): face of points "
                 "%u %u %u (corners at [] [%s] [%s]) is only in %s",
                 g, nt, miss->l[0], miss->l[1], miss->l[2], word_str(&ws.w[miss->w[0]], w1, sizeof w1),
                 word_str(&ws.w[miss->w[1]], w2, sizeof w2), miss == &kt[i] ? "the soak" : "the fresh one");
  }
  printf("soak g=%d: %zu faces equal to the fresh triangulation's (%zu distinct relative words); %.2f s in all\n", g,
         nt, ws.n, seconds() - t0);
  free(kt);
  free(ku);
  free(ws.w);
  free(ws.slot);
}

/* ---- The soak, end to end ---- */

static void print_tally(const soak_t *k, double t_soak) {
  const tally_t *n = &k->n;
  printf("soak g=%d: %zu operations (%zu single inserts, %zu batches of %zu points, %zu duplicates, %zu removals, "
         "%zu refused, %zu refusals checked face by face); peak %zu vertices, final %zu; %zu validations in %.2f s; "
         "soak %.2f s\n",
         k->g, k->op, n->single, n->batches, n->batch_points, n->dups, n->removed, n->refused, n->refusals_checked,
         n->peak, hdt_vertex_count(k->s.t), n->validations, n->t_validate, t_soak);
}

/* The soak of genus g, then the comparison with the fresh triangulation of
   the survivors: the same faces, or (with dummies left in either) the same
   number of user vertices. */
static void soak(int g, uint64_t seed) {
  const double t0 = seconds();
  const size_t ops = (size_t)(100000 * test_scale() + 0.5);
  soak_t k = {.g = g, .rng = seed, .next_validate = VALIDATE_EVERY};
  k.s.t = new_triangulation(g);
  hdt_triangulation *t = k.s.t;
  grow(&k.s, hdt_vertex_id_bound(t) + 1);
  run_operations(&k, ops);
  const size_t left_t = finish_operations(&k);
  const double t_soak = seconds() - t0;
  double *xy = NULL;
  uint32_t *label_t = label_survivors(&k.s, &xy);
  fresh_t f = fresh_triangulation(g, xy, k.s.nlive, k.op);
  print_tally(&k, t_soak);
  if (left_t != 0 || f.left != 0) {
    /* Different vertex sets: only the counts can be compared. */
    printf("soak g=%d: dummies left: %zu in the soak, %zu from scratch; comparing counts only\n", g, left_t, f.left);
    expect(hdt_vertex_count(t) - left_t == hdt_vertex_count(f.u) - f.left, "g=%d: %zu and %zu user vertices", g,
           hdt_vertex_count(t) - left_t, hdt_vertex_count(f.u) - f.left);
  } else {
    expect_same_faces(g, t, label_t, f.u, f.label, t0);
  }
  fflush(stdout);
  hdt_destroy(f.u);
  hdt_destroy(t);
  free(label_t), free(f.label), free(xy);
  free(k.s.px), free(k.s.py), free(k.s.pos), free(k.s.live);
}

START_TEST(soak_genus_2) { soak(2, UINT64_C(0x50A6002)); }
END_TEST

START_TEST(soak_genus_5) { soak(5, UINT64_C(0x50A6005)); }
END_TEST

int main(void) {
  const TTest *const tests[] = {soak_genus_2, soak_genus_5};
  return run_tests("soak", tests, sizeof tests / sizeof tests[0]);
}
