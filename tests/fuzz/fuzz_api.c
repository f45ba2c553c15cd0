/* libFuzzer target: drives libhdt's C API with operation sequences decoded
 * from arbitrary bytes, and checks the contract:
 *
 * after every call, cheaply:
 *   - no crash, no sanitizer report (the build uses ASan + UBSan);
 *   - statuses agree with the header: HDT_EDOMAIN exactly for points that are
 *     not finite points of the open unit disk (decided here with GMP),
 *     HDT_EINVAL exactly for dead vertex ids and unknown translation ids,
 *     HDT_EBUFS with the needed size, no write beyond a capacity, never
 *     HDT_EINTERNAL / HDT_ERROR / HDT_ENOMEM;
 *   - the counts: F = 2 (V + 2g - 2), dummies <= V <= id bound, and the
 *     change each call must make (one vertex more, one dummy less ...);
 *   - a call that fails leaves the triangulation exactly as it was: a hash
 *     of everything observable (counts, the face list with translations,
 *     every vertex id, point and dummy flag) is the same before and after;
 *   - outputs are untouched on failure and written only where documented;
 *
 * on a bounded sample of each input (the first MAX_FULL_CHECKS inserted
 * points, MAX_REPRESENTATIVES vertex and word-function points):
 *   - the inserted point's nearest vertex is the vertex returned, it is a
 *     corner of the face located there, its vertex point is its
 *     representative; a vertex point is its own representative; canonical
 *     words reduce to themselves and have the matrix of the word they came
 *     from;
 *
 * every VALIDATE_EVERY changes of a triangulation and at the end of the
 * input: hdt_validate (every invariant, with exact predicates) is HDT_OK.
 * HDT_FUZZ_VALIDATE_EVERY=1 validates after every change instead, to find
 * the first call that broke a triangulation.
 *
 * Each input is bounded (MAX_OPS operations, MAX_POINTS points, MAX_FAR
 * points near the unit circle, where every predicate is expensive ...) so
 * that an execution takes tens of milliseconds under the sanitizers, not
 * seconds: the fuzzer's power is in the number of inputs it tries.
 *
 * A broken check prints what it saw and calls abort(), which libFuzzer
 * reports as a crash. HDT_FUZZ_TRACE=1 prints every C call made (doubles in
 * %a notation) to stderr, to turn a crashing input into a C call sequence.
 *
 * Input format: byte 0 picks the genus of the first triangulation; then each
 * operation is one byte (the kind, an index into ops[] below) followed by
 * the bytes it consumes; missing bytes read as 0 and end the input. The
 * encoders in make_seeds.py, which writes the seed corpus, spell it out.
 */
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_points.h"
#include "fuzz_reader.h"
#include "hdt.h"

/* Work bounds per input, so that executions stay fast. Costs under the
   sanitizers: hdt_create 2-12 ms (genus 2-6), hdt_validate 1-10 ms,
   hdt_point_representative of a point on the polygon 5-15 ms; any call on a
   point within 1e-6 of the unit circle 20-500 ms. */
enum {
  MAX_OPS = 24,            /* operations per input */
  MAX_POINTS = 96,         /* points offered to insert / insert_many per input */
  MAX_MANY = 32,           /* points per insert_many call */
  MAX_FAR = 1,             /* points with |z|^2 > 1 - 1e-6 per input (each costs much more) */
  MAX_CREATES = 1,         /* hdt_create calls per input beyond the first (2-12 ms each) */
  MAX_FULL_CHECKS = 2,     /* inserted points cross-checked per input */
  MAX_REPRESENTATIVES = 3, /* hdt_point_representative calls of op_vertex and op_words per input */
  MAX_DUMMY_CALLS = 2,     /* hdt_remove_dummies calls on an unchanged triangulation */
  VALIDATE_EVERY = 8,      /* hdt_validate after every 8th change of a triangulation, and at the end */
  FINGERPRINT_MAX_V = 200, /* the unchanged-on-failure hash covers faces and points below this size */
  MAX_WORD = 24,           /* letters per word */
  HISTORY = 64,            /* remembered points, for duplicates */
  SLOTS = 2,               /* triangulations alive at once */
  MAX_LOADS = 2,           /* op_save_load calls per input (each loads three times, validating) */
  MAX_STEINER = 8,         /* points one hdt_refine / hdt_epsilon_net call may add */
};

/* ---- Reporting ---- */

static int trace_on = -1;
static unsigned op_index;

static void trace(const char *fmt, ...) {
  if (!trace_on) return;
  va_list ap;
  va_start(ap, fmt);
  vfprintf(stderr, fmt, ap);
  va_end(ap);
  fputc('\n', stderr);
}

_Noreturn static void fail(const char *fmt, ...) {
  va_list ap;
  fprintf(stderr, "\nfuzz_api: contract broken at operation %u: ", op_index);
  va_start(ap, fmt);
  vfprintf(stderr, fmt, ap);
  va_end(ap);
  fprintf(stderr, "\n  last error message: \"%s\"\n", hdt_last_error_message());
  abort();
}

#define CHECK(cond, ...) \
  do {                   \
    if (!(cond)) fail(__VA_ARGS__); \
  } while (0)

static const char *st(hdt_status s) { return hdt_status_string(s); }

/* Statuses no call may return on its own (bugs, or no memory in a tiny run). */
static void no_internal(hdt_status s, const char *call) {
  CHECK(s != HDT_EINTERNAL && s != HDT_ERROR && s != HDT_ENOMEM, "%s returned %d (%s)", call, (int)s, st(s));
  CHECK(s <= 0 && (s >= HDT_ENOTSUP || s == HDT_EINTERNAL), "%s returned the unknown status %d", call, (int)s);
}

/* ---- Rounding of matrix products ---- */

static double hyp_norm_factor(int g) {
  /* ||g_k|| <= A + |B| with A = cot(pi / 4g), |B| = sqrt(A^2 - 1). */
  const double a = 1 / tan(HDT_FUZZ_PI / (4 * g));
  return a + sqrt(a * a - 1);
}

/* ---- State ---- */

/* What a progress function saw (op_refine sets one). */
typedef struct progress_state {
  size_t last_done, calls;
} progress_state;

typedef struct state {
  hdt_triangulation *t[SLOTS];
  unsigned unvalidated[SLOTS]; /* changes since the last hdt_validate */
  unsigned dummy_calls[SLOTS]; /* hdt_remove_dummies calls since the last other change */
  point history[HISTORY];
  unsigned history_n;
  unsigned points_used;
  unsigned far_used;
  unsigned creates;
  unsigned full_checks;     /* check_inserted calls so far */
  unsigned representatives; /* hdt_point_representative calls of op_vertex and op_words */
  unsigned loads;           /* op_save_load calls */
  progress_state progress[SLOTS];
} state;

static void remember(state *s, double x, double y) {
  s->history[s->history_n % HISTORY] = (point){x, y};
  ++s->history_n;
}

/* ---- Fingerprints: a hash of the whole observable triangulation ---- */

/* Two bulk calls and a hash instead of a copy of every face and vertex:
   cheap enough to take before every call that may fail. */

static uint64_t fnv1a(uint64_t h, const void *p, size_t n) {
  const unsigned char *b = p;
  for (size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 0x100000001b3ULL;
  return h;
}
#define FNV_BASIS 0xcbf29ce484222325ULL

typedef struct fingerprint {
  size_t v, d, bound, f;
  int full;        /* faces and vertices hashed (below FINGERPRINT_MAX_V vertices) */
  uint64_t faces;  /* vertex ids and translations of every face, in order */
  uint64_t points; /* id, point and dummy flag of every live vertex */
} fingerprint;

static fingerprint take(const hdt_triangulation *t) {
  fingerprint p = {hdt_vertex_count(t), hdt_dummy_count(t), hdt_vertex_id_bound(t), hdt_face_count(t), 0, 0, 0};
  if (p.v >= FINGERPRINT_MAX_V) return p;
  p.full = 1;
  /* Exact sizes: ASan sees a write beyond the capacity passed. */
  uint32_t *fv = malloc(3 * p.f * sizeof *fv + 1), *ids = malloc(p.v * sizeof *ids + 1);
  int32_t *ft = malloc(3 * p.f * sizeof *ft + 1);
  double *xy = malloc(2 * p.v * sizeof *xy + 1);
  uint8_t *dummy = malloc(p.v + 1);
  if (!fv || !ids || !ft || !xy || !dummy) abort();
  size_t count = 0;
  hdt_status s = hdt_faces(t, fv, ft, p.f, &count);
  CHECK(s == HDT_OK && count == p.f, "fingerprint: hdt_faces %s, %zu faces of %zu", st(s), count, p.f);
  s = hdt_vertices(t, ids, xy, dummy, p.v, &count);
  CHECK(s == HDT_OK && count == p.v, "fingerprint: hdt_vertices %s, %zu vertices of %zu", st(s), count, p.v);
  size_t dummies = 0;
  for (size_t i = 0; i < p.v; ++i) {
    CHECK(ids[i] < p.bound && (i == 0 || ids[i - 1] < ids[i]) && dummy[i] <= 1,
          "hdt_vertices: entry %zu is id %u, dummy %u (id bound %zu)", i, ids[i], dummy[i], p.bound);
    dummies += dummy[i];
  }
  CHECK(dummies == p.d, "hdt_vertices: %zu dummies, hdt_dummy_count %zu", dummies, p.d);
  p.faces = fnv1a(fnv1a(FNV_BASIS, fv, 3 * p.f * sizeof *fv), ft, 3 * p.f * sizeof *ft);
  p.points = fnv1a(fnv1a(fnv1a(FNV_BASIS, ids, p.v * sizeof *ids), xy, 2 * p.v * sizeof *xy), dummy, p.v);
  free(fv);
  free(ids);
  free(ft);
  free(xy);
  free(dummy);
  return p;
}

/* Aborts unless t still has the fingerprint `before`. */
static void expect_unchanged(const fingerprint *before, const hdt_triangulation *t, const char *call) {
  const fingerprint now = take(t);
  CHECK(now.v == before->v && now.d == before->d && now.bound == before->bound && now.f == before->f,
        "%s failed but changed vertices %zu -> %zu, dummies %zu -> %zu, id bound %zu -> %zu, faces %zu -> %zu", call,
        before->v, now.v, before->d, now.d, before->bound, now.bound, before->f, now.f);
  if (!before->full) return;
  CHECK(now.faces == before->faces, "%s failed but changed the faces or their translations", call);
  CHECK(now.points == before->points, "%s failed but changed a vertex (its point or dummy flag)", call);
}

/* ---- Validation ---- */

static int validate_every = -1; /* VALIDATE_EVERY, or HDT_FUZZ_VALIDATE_EVERY */

/* The counts every triangulation keeps: cheap, after every change. */
static void check_counts(const hdt_triangulation *t, const char *after) {
  const int g = hdt_genus(t);
  const size_t v = hdt_vertex_count(t), f = hdt_face_count(t);
  CHECK(f == 2 * (v + 2 * (size_t)g - 2), "after %s: %zu faces for %zu vertices, genus %d", after, f, v, g);
  CHECK(hdt_dummy_count(t) <= v && v <= hdt_vertex_id_bound(t), "after %s: %zu dummies, %zu vertices, id bound %zu",
        after, hdt_dummy_count(t), v, hdt_vertex_id_bound(t));
}

static void validate_now(state *s, int slot, const char *after) {
  const hdt_status v = hdt_validate(s->t[slot]);
  trace("hdt_validate(t%d) = %d", slot, (int)v);
  CHECK(v == HDT_OK, "hdt_validate after %s: %d (%s)", after, (int)v, st(v));
  check_counts(s->t[slot], after);
  s->unvalidated[slot] = 0;
}

/* After a call that may have changed slot's triangulation: the counts now,
   hdt_validate every validate_every changes (one validation costs up to a
   large part of a second with points near the unit circle). */
static void changed(state *s, int slot, const char *after) {
  check_counts(s->t[slot], after);
  s->dummy_calls[slot] = 0;
  if (++s->unvalidated[slot] >= (unsigned)validate_every) validate_now(s, slot, after);
}

/* A new triangulation: hdt_create is deterministic, so each genus is
   validated fresh once per process. */
static void created(state *s, int slot) {
  static unsigned char seen[64];
  const int g = hdt_genus(s->t[slot]);
  check_counts(s->t[slot], "hdt_create");
  s->unvalidated[slot] = 0;
  s->dummy_calls[slot] = 0;
  if (g < 0 || g >= 64 || !seen[g]) validate_now(s, slot, "hdt_create");
  if (g >= 0 && g < 64) seen[g] = 1;
}

/* Every change is validated before its triangulation goes. */
static void retire(state *s, int slot) {
  if (!s->t[slot]) return;
  if (s->unvalidated[slot]) validate_now(s, slot, "the last change");
  hdt_destroy(s->t[slot]);
  trace("hdt_destroy(t%d)", slot);
  s->t[slot] = NULL;
}

/* ---- Choosing arguments ---- */

static const double special[] = {
    0.0, -0.0, 1.0, -1.0, 0.5, -0.5, 0.99999999999999989 /* nextafter(1, 0) */, -0.99999999999999989,
    1.0000000000000002, DBL_MIN, -DBL_MIN, 4.9406564584124654e-324 /* smallest subnormal */,
    -4.9406564584124654e-324, 2.2250738585072009e-308 /* largest subnormal */, DBL_MAX, -DBL_MAX, 1e-300, 1e-17,
    0.70710678118654746 /* ~sqrt(1/2), just inside */, 0.70710678118654757 /* just outside with itself */,
    0.70710678118654752, 1 - 1e-12, 0.3, 1e-8, -1e-8, 1e-160, 2.0,
    /* last three replaced at run time: NaN, +inf, -inf */
    0, 0, 0};
#define N_SPECIAL (sizeof special / sizeof special[0])

static double special_value(unsigned i) {
  i %= N_SPECIAL;
  if (i == N_SPECIAL - 3) return NAN;
  if (i == N_SPECIAL - 2) return INFINITY;
  if (i == N_SPECIAL - 1) return -INFINITY;
  return special[i];
}

static int genus_of(const state *s, int slot) {
  const int g = hdt_genus(s->t[slot]);
  return g ? g : 2;
}

/* Euclidean distance from (x, y) to the nearest side circle of F_g (a
   point near a side, or near a vertex: two sides). */
static double side_distance(int g, double x, double y) {
  double best = INFINITY;
  for (int k = 0; k < 4 * g; ++k) {
    double mx, my;
    if (hdt_polygon_side_midpoint(g, k, &mx, &my) != HDT_OK) fail("hdt_polygon_side_midpoint(%d, %d)", g, k);
    const double rm = hypot(mx, my), c = (1 + rm * rm) / (2 * rm), rad = c - rm;
    const double d = fabs(hypot(x - c * mx / rm, y - c * my / rm) - rad);
    if (d < best) best = d;
  }
  return best;
}

static void perturb(reader *r, point *p) {
  const uint8_t b = u8(r);
  if (b & 0x80) return; /* half the time: as computed */
  p->x = ulps(p->x, (int)(b & 7) - 4);
  p->y = ulps(p->y, (int)((b >> 3) & 7) - 4);
}

static size_t read_word(reader *r, int g, int32_t *w) {
  const uint8_t b = u8(r);
  const size_t n = b % (MAX_WORD + 1);
  const int wild = (b & 0xE0) == 0xE0; /* rarely: any int32 letter */
  for (size_t i = 0; i < n; ++i) w[i] = wild ? (int32_t)u32(r) : (int32_t)(u8(r) % (4 * g));
  return n;
}

static int is_far(point p) { return p.x * p.x + p.y * p.y > 1 - 1e-6; }

/* A point, mostly nasty. May use the library (polygon, word images). */
static point gen_point(reader *r, state *s, int slot) {
  const int g = genus_of(s, slot);
  const uint8_t kind = u8(r) % 14;
  point p = {0, 0};
  switch (kind) {
    case 0: /* raw bits */
      p.x = f64(r);
      p.y = f64(r);
      break;
    case 1: /* from the table of special values */
      p.x = special_value(u8(r));
      p.y = special_value(u8(r));
      break;
    case 2: { /* a polygon vertex, a few ulps off */
      const int k = (int)u8(r);
      if (hdt_polygon_vertex(g, k, &p.x, &p.y) != HDT_OK) fail("hdt_polygon_vertex(%d, %d)", g, k);
      perturb(r, &p);
      break;
    }
    case 3: { /* a side midpoint */
      const int k = (int)u8(r);
      if (hdt_polygon_side_midpoint(g, k, &p.x, &p.y) != HDT_OK) fail("hdt_polygon_side_midpoint(%d, %d)", g, k);
      perturb(r, &p);
      break;
    }
    case 4: { /* on a side */
      const int k = (int)u8(r);
      if (!side_point(g, k, u16(r) / 65535.0, &p)) fail("hdt_polygon_* failed for genus %d", g);
      perturb(r, &p);
      break;
    }
    case 5: { /* near the unit circle */
      static const double radii[] = {0.99999999999999989, 1.0, 1 - 2.220446049250313e-16, 1 - 1e-15, 1 - 1e-12,
                                     1 - 1e-9, 1 - 1e-6, 0.999, 0.99};
      const double a = u16(r) * (2 * HDT_FUZZ_PI / 65536), rad = radii[u8(r) % (sizeof radii / sizeof radii[0])];
      p.x = rad * cos(a);
      p.y = rad * sin(a);
      perturb(r, &p);
      break;
    }
    case 6: /* a point given before: a duplicate, or nearly one */
    case 7:
      if (s->history_n > 0) {
        p = s->history[u8(r) % (s->history_n < HISTORY ? s->history_n : HISTORY)];
        perturb(r, &p);
      }
      break;
    case 8: { /* a vertex point of the triangulation (dummies too) */
      const size_t bound = hdt_vertex_id_bound(s->t[slot]);
      if (bound > 0) {
        const uint32_t v = (uint32_t)(u16(r) % bound);
        if (hdt_vertex_point(s->t[slot], v, &p.x, &p.y) != HDT_OK) p.x = p.y = 0.25;
        perturb(r, &p);
      }
      break;
    }
    case 9: /* a coarse point, maybe outside the disk */
      p.x = (int16_t)u16(r) / 32768.0 * 1.2;
      p.y = (int16_t)u16(r) / 32768.0 * 1.2;
      break;
    case 10: { /* an image of a remembered point under a word: another copy */
      point q = s->history_n ? s->history[u8(r) % (s->history_n < HISTORY ? s->history_n : HISTORY)]
                             : (point){0.1, 0.2};
      int32_t w[MAX_WORD];
      size_t n = read_word(r, g, w);
      if (n > 4) n = 4;
      if (hdt_word_apply(g, w, n, q.x, q.y, &p.x, &p.y) != HDT_OK) p = q;
      break;
    }
    case 11: /* dyadic grid */
      p.x = (int8_t)u8(r) / 128.0;
      p.y = (int8_t)u8(r) / 128.0;
      break;
    case 12: /* subnormal and tiny */
      p.x = (int8_t)u8(r) * 4.9406564584124654e-324;
      p.y = ldexp((int8_t)u8(r), -(int)(u16(r) % 1100));
      break;
    default: /* a raw x with a special y, or the reverse */
      if (u8(r) & 1) {
        p.x = f64(r);
        p.y = special_value(u8(r));
      } else {
        p.x = special_value(u8(r));
        p.y = f64(r);
      }
      break;
  }
  /* Points very near the unit circle make every call on them expensive
     (their representative, then every predicate on their vertex: 20-70 ms
     per call under the sanitizers in genus 2 and 3, up to 0.5 s in genus 6):
     only MAX_FAR of them per input, in genus 2 and 3; the others are pulled in. */
  if (is_far(p) && in_open_disk(p.x, p.y)) {
    if (s->far_used < MAX_FAR && g <= 3) {
      ++s->far_used;
    } else {
      p.x *= 0.5;
      p.y *= 0.5;
    }
  }
  return p;
}

/* A vertex id: mostly a plausible one, sometimes anything. */
static uint32_t gen_vertex(reader *r, const hdt_triangulation *t) {
  const uint8_t b = u8(r);
  const size_t bound = hdt_vertex_id_bound(t);
  switch (b % 4) {
    case 0: return u32(r);
    case 1: return (uint32_t)bound + (b >> 2);
    default: return bound ? (uint32_t)(u16(r) % bound) : 0;
  }
}

/* ---- Checks after an insertion ---- */

/* The point (x, y) was inserted as vertex v: it is its own nearest vertex, a
   corner of the face located at it, and its vertex point is its representative. */
static void check_inserted(state *st_, const hdt_triangulation *t, double x, double y, uint32_t v) {
  CHECK(hdt_vertex_is_dummy(t, v) == 0, "inserted vertex %u is not a live user vertex (%d)", v,
        hdt_vertex_is_dummy(t, v));
  if (st_->full_checks++ >= MAX_FULL_CHECKS) return;
  uint32_t near = UINT32_MAX;
  hdt_status s = hdt_nearest_vertex(t, x, y, &near);
  trace("hdt_nearest_vertex(t, %a, %a) = %d, %u", x, y, (int)s, near);
  CHECK(s == HDT_OK && near == v, "hdt_nearest_vertex(%a, %a) = %s, %u; the point is vertex %u", x, y, st(s), near, v);

  const int g = hdt_genus(t);
  double rx = NAN, ry = NAN, vx = NAN, vy = NAN;
  size_t len = 0;
  s = hdt_point_representative(g, x, y, &rx, &ry, NULL, 0, &len);
  CHECK(s == HDT_OK, "hdt_point_representative(%d, %a, %a): %s", g, x, y, st(s));
  s = hdt_vertex_point(t, v, &vx, &vy);
  CHECK(s == HDT_OK, "hdt_vertex_point(%u): %s", v, st(s));
  CHECK(fabs(rx - vx) <= 1e-12 && fabs(ry - vy) <= 1e-12,
        "vertex %u of point (%a, %a): vertex point (%a, %a), representative (%a, %a)", v, x, y, vx, vy, rx, ry);

  if (hdt_vertex_count(t) >= FINGERPRINT_MAX_V) return;
  size_t face = SIZE_MAX;
  int32_t tr = -1;
  s = hdt_locate(t, x, y, &face, &tr);
  trace("hdt_locate(t, %a, %a) = %d, face %zu, translation %d", x, y, (int)s, face, (int)tr);
  CHECK(s == HDT_OK, "hdt_locate(%a, %a) of vertex %u: %s", x, y, v, st(s));
  const size_t f = hdt_face_count(t);
  CHECK(face < f, "hdt_locate: face %zu of %zu", face, f);
  uint32_t *fv = malloc(3 * f * sizeof *fv);
  size_t count = 0;
  s = hdt_faces(t, fv, NULL, f, &count);
  CHECK(s == HDT_OK && count == f, "hdt_faces: %s", st(s));
  CHECK(fv[3 * face] == v || fv[3 * face + 1] == v || fv[3 * face + 2] == v,
        "hdt_locate(%a, %a) gave face %zu (%u %u %u), which has not vertex %u", x, y, face, fv[3 * face],
        fv[3 * face + 1], fv[3 * face + 2], v);
  free(fv);
}

/* ---- Operations ---- */

/* The triangulation an operation works on: slot 1 once op_create made it
   (creating one costs more than most inputs' other calls), else slot 0. */
static hdt_triangulation **slot_of(reader *r, state *s, int *slot) {
  *slot = (u8(r) & 1) && s->t[1] ? 1 : 0;
  return &s->t[*slot];
}

/* The genus a byte picks: bytes 0..4 give 2..6 (as make_seeds.py writes
   them), the others mostly 2 and 3, whose triangulations are the cheapest to
   create and to check. */
static int genus_of_byte(uint8_t b) {
  static const int genus[16] = {2, 3, 4, 5, 6, 2, 3, 2, 3, 2, 3, 2, 3, 2, 3, 4};
  return genus[b % 16];
}

static void op_create(reader *r, state *s) {
  const int slot = u8(r) & 1;
  const uint8_t b = u8(r);
  if (b >= 0xF0) { /* invalid genus, or no out pointer */
    static const int bad[] = {INT_MIN, -1, 0, 1, HDT_GENUS_MAX + 1, INT_MAX};
    hdt_triangulation *t = (hdt_triangulation *)&op_index; /* must become NULL */
    const int g = bad[b % 6];
    const hdt_status c = hdt_create(&t, g);
    trace("hdt_create(&t, %d) = %d", g, (int)c);
    CHECK(c == (g < 2 ? HDT_EINVAL : HDT_ENOTSUP) && t == NULL, "hdt_create(genus %d) = %s, out %p", g, st(c),
          (void *)t);
    CHECK(hdt_create(NULL, 2) == HDT_EINVAL, "hdt_create(NULL, 2) must be HDT_EINVAL");
    return;
  }
  if (s->creates >= MAX_CREATES) return;
  ++s->creates;
  const int g = genus_of_byte(b);
  retire(s, slot);
  const hdt_status c = hdt_create(&s->t[slot], g);
  trace("hdt_create(&t%d, %d) = %d", slot, g, (int)c);
  CHECK(c == HDT_OK && s->t[slot], "hdt_create(genus %d): %s", g, st(c));
  CHECK(hdt_genus(s->t[slot]) == g, "hdt_genus: %d, created with %d", hdt_genus(s->t[slot]), g);
  CHECK(hdt_dummy_count(s->t[slot]) == hdt_vertex_count(s->t[slot]) &&
            hdt_vertex_id_bound(s->t[slot]) == hdt_vertex_count(s->t[slot]),
        "a new triangulation holds only its dummies");
  created(s, slot);
}

static void op_insert(reader *r, state *s) {
  int slot;
  hdt_triangulation *t = *slot_of(r, s, &slot);
  if (s->points_used >= MAX_POINTS) return;
  ++s->points_used;
  const point p = gen_point(r, s, slot);
  const int with_out = !(u8(r) & 0x10);
  const int inside = in_open_disk(p.x, p.y);
  const fingerprint before = take(t);
  const size_t bound = hdt_vertex_id_bound(t), dummies = hdt_dummy_count(t), count = hdt_vertex_count(t);
  uint32_t v = UINT32_MAX;
  const hdt_status st_ = hdt_insert(t, p.x, p.y, with_out ? &v : NULL);
  trace("hdt_insert(t%d, %a, %a, %s) = %d, vertex %u", slot, p.x, p.y, with_out ? "&v" : "NULL", (int)st_, v);
  no_internal(st_, "hdt_insert");
  if (!inside) {
    CHECK(st_ == HDT_EDOMAIN, "hdt_insert(%a, %a), not in the open disk: %s", p.x, p.y, st(st_));
    CHECK(v == UINT32_MAX, "hdt_insert failed with HDT_EDOMAIN but wrote the vertex");
  } else {
    /* hdt.h documents no other failure for a point of the disk. */
    CHECK(st_ == HDT_OK || st_ == HDT_EEXISTS, "hdt_insert(%a, %a) in the disk: %s", p.x, p.y, st(st_));
    remember(s, p.x, p.y);
  }
  if (st_ != HDT_OK) {
    expect_unchanged(&before, t, "hdt_insert");
    if (st_ == HDT_EEXISTS && with_out) {
      CHECK(hdt_vertex_is_dummy(t, v) == 0, "hdt_insert: HDT_EEXISTS with vertex %u, not a user vertex", v);
      check_inserted(s, t, p.x, p.y, v);
    }
  } else {
    changed(s, slot, "hdt_insert");
    /* Either a dummy became a user vertex or a new vertex came. */
    const int onto_dummy = hdt_vertex_count(t) == count;
    if (onto_dummy)
      CHECK(hdt_dummy_count(t) == dummies - 1 && hdt_vertex_id_bound(t) == bound,
            "hdt_insert: HDT_OK without a new vertex, but dummies %zu -> %zu, id bound %zu -> %zu", dummies,
            hdt_dummy_count(t), bound, hdt_vertex_id_bound(t));
    else
      CHECK(hdt_vertex_count(t) == count + 1 && hdt_dummy_count(t) == dummies && hdt_vertex_id_bound(t) == bound + 1,
            "hdt_insert: HDT_OK, but vertices %zu -> %zu, dummies %zu -> %zu, id bound %zu -> %zu", count,
            hdt_vertex_count(t), dummies, hdt_dummy_count(t), bound, hdt_vertex_id_bound(t));
    if (with_out) {
      CHECK(onto_dummy ? v < bound : v == bound, "hdt_insert: vertex %u, id bound was %zu, %s", v, bound,
            onto_dummy ? "a dummy became a user vertex" : "a new vertex");
      check_inserted(s, t, p.x, p.y, v);
    }
  }
}

static void op_insert_many(reader *r, state *s) {
  int slot;
  hdt_triangulation *t = *slot_of(r, s, &slot);
  const uint8_t b = u8(r);
  size_t n = b % (MAX_MANY + 1);
  if (s->points_used + n > MAX_POINTS) n = MAX_POINTS - s->points_used;
  s->points_used += (unsigned)n;
  const int with_out = !(b & 0x40);
  const int null_xy = n > 0 && (b & 0xC0) == 0xC0 && (u8(r) & 3) == 0;
  double *xy = malloc(2 * n * sizeof *xy + 1);
  uint32_t *vs = malloc(n * sizeof *vs + 1);
  if (!xy || !vs) abort();
  int all_inside = 1;
  for (size_t i = 0; i < n; ++i) {
    const point p = gen_point(r, s, slot);
    xy[2 * i] = p.x, xy[2 * i + 1] = p.y;
    vs[i] = UINT32_MAX;
    all_inside &= in_open_disk(p.x, p.y);
  }
  const fingerprint before = take(t);
  const size_t v0 = hdt_vertex_count(t);
  s->progress[slot].last_done = 0; /* done grows within one call (op_refine may set a progress function) */
  const hdt_status st_ = hdt_insert_many(t, null_xy ? NULL : xy, n, with_out ? vs : NULL);
  if (trace_on) {
    trace("double xy[%zu] = {", 2 * n);
    for (size_t i = 0; i < n; ++i) trace("  %a, %a,", xy[2 * i], xy[2 * i + 1]);
    trace("};\nhdt_insert_many(t%d, %s, %zu, %s) = %d", slot, null_xy ? "NULL" : "xy", n, with_out ? "vs" : "NULL",
          (int)st_);
  }
  no_internal(st_, "hdt_insert_many");
  if (null_xy)
    CHECK(st_ == HDT_EINVAL, "hdt_insert_many(xy NULL, n %zu): %s", n, st(st_));
  else if (!all_inside)
    CHECK(st_ == HDT_EDOMAIN, "hdt_insert_many with a point outside the disk: %s", st(st_));
  else
    CHECK(st_ == HDT_OK, "hdt_insert_many of %zu points in the disk: %s", n, st(st_));
  if (st_ != HDT_OK) {
    for (size_t i = 0; i < n; ++i)
      CHECK(vs[i] == UINT32_MAX, "hdt_insert_many failed (%s) but wrote vertices[%zu]", st(st_), i);
    expect_unchanged(&before, t, "hdt_insert_many");
  } else {
    for (size_t i = 0; i < n; ++i) remember(s, xy[2 * i], xy[2 * i + 1]);
    changed(s, slot, "hdt_insert_many");
    CHECK(hdt_vertex_count(t) <= v0 + n, "hdt_insert_many of %zu points: %zu -> %zu vertices", n, v0,
          hdt_vertex_count(t));
    if (with_out)
      for (size_t i = 0; i < n; ++i) {
        /* Each answer is a live user vertex; check a few fully. */
        CHECK(hdt_vertex_is_dummy(t, vs[i]) == 0, "hdt_insert_many: vertices[%zu] = %u is no live user vertex", i,
              vs[i]);
        if (i < 2 || i == n - 1) check_inserted(s, t, xy[2 * i], xy[2 * i + 1], vs[i]);
      }
  }
  free(xy);
  free(vs);
}

static void op_remove(reader *r, state *s) {
  int slot;
  hdt_triangulation *t = *slot_of(r, s, &slot);
  const uint32_t v = gen_vertex(r, t);
  const int was = hdt_vertex_is_dummy(t, v);
  const size_t n = hdt_vertex_count(t), d = hdt_dummy_count(t), bound = hdt_vertex_id_bound(t);
  const fingerprint before = take(t);
  const hdt_status st_ = hdt_remove_vertex(t, v);
  trace("hdt_remove_vertex(t%d, %u) = %d", slot, v, (int)st_);
  no_internal(st_, "hdt_remove_vertex");
  if (was < 0) CHECK(st_ == HDT_EINVAL, "hdt_remove_vertex(%u), no live vertex: %s", v, st(st_));
  else CHECK(st_ == HDT_OK || st_ == HDT_ENOTSUP, "hdt_remove_vertex(%u), live: %s", v, st(st_));
  if (st_ != HDT_OK) {
    expect_unchanged(&before, t, "hdt_remove_vertex");
  } else {
    changed(s, slot, "hdt_remove_vertex");
    CHECK(hdt_vertex_count(t) == n - 1 && hdt_dummy_count(t) == d - (size_t)(was == 1) &&
              hdt_vertex_id_bound(t) == bound && hdt_vertex_is_dummy(t, v) == -1,
          "hdt_remove_vertex(%u): counts after removal", v);
    double x, y;
    CHECK(hdt_vertex_point(t, v, &x, &y) == HDT_EINVAL, "hdt_vertex_point of the removed vertex %u", v);
  }
}

static void op_remove_dummies(reader *r, state *s) {
  int slot;
  hdt_triangulation *t = *slot_of(r, s, &slot);
  const int with_out = u8(r) & 1;
  /* Once more on an unchanged triangulation checks that it is a no-op;
     more calls would only spend time. */
  const unsigned calls = s->dummy_calls[slot];
  if (calls >= MAX_DUMMY_CALLS) return;
  const size_t n = hdt_vertex_count(t), d = hdt_dummy_count(t);
  size_t left = SIZE_MAX;
  const hdt_status st_ = hdt_remove_dummies(t, with_out ? &left : NULL);
  trace("hdt_remove_dummies(t%d, %s) = %d, %zu left", slot, with_out ? "&left" : "NULL", (int)st_, left);
  no_internal(st_, "hdt_remove_dummies");
  CHECK(st_ == HDT_OK, "hdt_remove_dummies: %s", st(st_));
  changed(s, slot, "hdt_remove_dummies");
  s->dummy_calls[slot] = calls + 1;
  const size_t d2 = hdt_dummy_count(t);
  CHECK(!with_out || left == d2, "hdt_remove_dummies: %zu left, hdt_dummy_count %zu", left, d2);
  CHECK(d2 <= d && hdt_vertex_count(t) == n - (d - d2), "hdt_remove_dummies removed user vertices");
}

static void op_locate(reader *r, state *s) {
  int slot;
  hdt_triangulation *t = *slot_of(r, s, &slot);
  const point p = gen_point(r, s, slot);
  const uint8_t b = u8(r);
  const int inside = in_open_disk(p.x, p.y);
  size_t face = SIZE_MAX;
  int32_t tr = INT32_MIN;
  hdt_status st_;
  if (b & 1) {
    st_ = hdt_locate(t, p.x, p.y, (b & 2) ? NULL : &face, (b & 4) ? NULL : &tr);
    trace("hdt_locate(t%d, %a, %a) = %d, face %zu, translation %d", slot, p.x, p.y, (int)st_, face, (int)tr);
    no_internal(st_, "hdt_locate");
    CHECK(st_ == (inside ? HDT_OK : HDT_EDOMAIN), "hdt_locate(%a, %a): %s", p.x, p.y, st(st_));
    if (st_ == HDT_OK) {
      if (!(b & 2)) CHECK(face < hdt_face_count(t), "hdt_locate: face %zu of %zu", face, hdt_face_count(t));
      if (!(b & 4)) {
        size_t len = 0;
        const hdt_status w = hdt_translation_word(t, tr, NULL, 0, &len);
        CHECK(w == HDT_OK, "hdt_locate gave translation %d, which hdt_translation_word does not know: %s", (int)tr,
              st(w));
      }
    } else {
      CHECK(face == SIZE_MAX && tr == INT32_MIN, "hdt_locate failed but wrote its outputs");
    }
  } else {
    uint32_t v = UINT32_MAX;
    st_ = hdt_nearest_vertex(t, p.x, p.y, (b & 2) && (b & 4) ? NULL : &v);
    trace("hdt_nearest_vertex(t%d, %a, %a) = %d, %u", slot, p.x, p.y, (int)st_, v);
    no_internal(st_, "hdt_nearest_vertex");
    if ((b & 2) && (b & 4)) CHECK(st_ == HDT_EINVAL, "hdt_nearest_vertex(vertex NULL): %s", st(st_));
    else CHECK(st_ == (inside ? HDT_OK : HDT_EDOMAIN), "hdt_nearest_vertex(%a, %a): %s", p.x, p.y, st(st_));
    if (st_ == HDT_OK) CHECK(hdt_vertex_is_dummy(t, v) >= 0, "hdt_nearest_vertex gave %u, no live vertex", v);
    else CHECK(v == UINT32_MAX, "hdt_nearest_vertex failed but wrote its output");
  }
}

static void op_faces(reader *r, state *s) {
  int slot;
  hdt_triangulation *t = *slot_of(r, s, &slot);
  const size_t f = hdt_face_count(t);
  const uint8_t b = u8(r);
  size_t cap;
  switch (b % 6) {
    case 0: cap = 0; break;
    case 1: cap = f ? f - 1 : 0; break;
    case 2: cap = f; break;
    case 3: cap = f + 1 + (b >> 3); break;
    case 4: cap = u16(r) % (2 * f + 2); break;
    default: cap = (b & 0x80) ? SIZE_MAX : SIZE_MAX / 3 + 1; break; /* only with NULL buffers */
  }
  const int huge = cap > 4 * f + 64;
  const int null_v = huge || (b & 0x40), null_t = huge || (b & 0x20);
  /* Exactly `cap` faces of room (plus a guard word checked below): ASan sees any overrun. */
  uint32_t *fv = null_v ? NULL : malloc(3 * cap * sizeof *fv + sizeof *fv);
  int32_t *ft = null_t ? NULL : malloc(3 * cap * sizeof *ft + sizeof *ft);
  if (!null_v) memset(fv, 0xAB, 3 * cap * sizeof *fv + sizeof *fv);
  if (!null_t) memset(ft, 0xAB, 3 * cap * sizeof *ft + sizeof *ft);
  size_t count = SIZE_MAX;
  const int null_count = (b & 0x18) == 0x18 && (u8(r) & 1);
  const hdt_status st_ = hdt_faces(t, fv, ft, cap, null_count ? NULL : &count);
  trace("hdt_faces(t%d, %s, %s, %zu, %s) = %d, count %zu", slot, null_v ? "NULL" : "fv", null_t ? "NULL" : "ft", cap,
        null_count ? "NULL" : "&count", (int)st_, count);
  no_internal(st_, "hdt_faces");
  size_t written = 0;
  if (null_count) {
    CHECK(st_ == HDT_EINVAL, "hdt_faces(count NULL): %s", st(st_));
  } else if (cap == 0) {
    CHECK(st_ == HDT_OK && count == f, "hdt_faces(capacity 0): %s, count %zu of %zu", st(st_), count, f);
  } else if (cap < f) {
    CHECK(st_ == HDT_EBUFS && count == f, "hdt_faces(capacity %zu < %zu): %s, count %zu", cap, f, st(st_), count);
  } else if (null_v) {
    CHECK(st_ == HDT_EINVAL, "hdt_faces(vertices NULL, capacity %zu): %s", cap, st(st_));
  } else {
    CHECK(st_ == HDT_OK && count == f, "hdt_faces(capacity %zu >= %zu): %s, count %zu", cap, f, st(st_), count);
    written = 3 * f;
  }
  uint32_t fill;
  memset(&fill, 0xAB, sizeof fill);
  if (!null_v)
    for (size_t i = written; i < 3 * cap + 1; ++i)
      CHECK(fv[i] == fill, "hdt_faces (%s) wrote vertices[%zu] beyond what it returned", st(st_), i);
  if (!null_t)
    for (size_t i = written; i < 3 * cap + 1; ++i)
      CHECK((uint32_t)ft[i] == fill, "hdt_faces (%s) wrote translations[%zu] beyond what it returned", st(st_), i);
  if (written) {
    for (size_t i = 0; i < 3 * f; ++i) {
      CHECK(hdt_vertex_is_dummy(t, fv[i]) >= 0, "hdt_faces: corner %zu is vertex %u, not live", i, fv[i]);
      if (!null_t) CHECK(ft[i] >= 0, "hdt_faces: corner %zu has translation %d", i, (int)ft[i]);
    }
    for (size_t i = 0; i < f; ++i)
      CHECK(fv[3 * i] != fv[3 * i + 1] && fv[3 * i] != fv[3 * i + 2] && fv[3 * i + 1] != fv[3 * i + 2],
            "hdt_faces: face %zu has a repeated vertex", i);
    if (!null_t) {
      /* Every corner translation is a known id; the smallest vertex of each
         face sits at translation 0. */
      for (size_t i = 0; i < f; ++i) {
        size_t m = 3 * i;
        for (size_t c = 1; c < 3; ++c)
          if (fv[3 * i + c] < fv[m]) m = 3 * i + c;
        CHECK(ft[m] == 0, "hdt_faces: face %zu, its smallest vertex %u has translation %d", i, fv[m], (int)ft[m]);
      }
      const size_t i = (b >> 1) % (3 * f);
      size_t len = 0;
      const hdt_status w = hdt_translation_word(t, ft[i], NULL, 0, &len);
      CHECK(w == HDT_OK, "hdt_faces gave translation %d, unknown to hdt_translation_word: %s", (int)ft[i], st(w));
    }
  }
  free(fv);
  free(ft);
}

/* hdt_vertices with every kind of capacity and NULL output. */
static void op_vertices(reader *r, state *s) {
  int slot;
  hdt_triangulation *t = *slot_of(r, s, &slot);
  const size_t v = hdt_vertex_count(t), bound = hdt_vertex_id_bound(t);
  const uint8_t b = u8(r);
  size_t cap;
  switch (b % 5) {
    case 0: cap = 0; break;
    case 1: cap = v ? v - 1 : 0; break;
    case 2: cap = v; break;
    case 3: cap = v + 1 + (b >> 6); break;
    default: cap = (b & 0x80) ? SIZE_MAX : SIZE_MAX / 2 + 1; break; /* only with NULL buffers */
  }
  const int huge = cap > 4 * v + 64;
  const int null_ids = huge || (b & 0x08), null_xy = huge || (b & 0x10), null_d = huge || (b & 0x20);
  const int null_count = (b & 0x40) && (u8(r) & 1);
  /* Exactly `cap` vertices of room plus a guard entry, filled with 0xAB. */
  uint32_t *ids = null_ids ? NULL : malloc((cap + 1) * sizeof *ids);
  double *xy = null_xy ? NULL : malloc(2 * (cap + 1) * sizeof *xy);
  uint8_t *dummy = null_d ? NULL : malloc(cap + 1);
  if (ids) memset(ids, 0xAB, (cap + 1) * sizeof *ids);
  if (xy) memset(xy, 0xAB, 2 * (cap + 1) * sizeof *xy);
  if (dummy) memset(dummy, 0xAB, cap + 1);
  size_t count = SIZE_MAX;
  const hdt_status st_ = hdt_vertices(t, ids, xy, dummy, cap, null_count ? NULL : &count);
  trace("hdt_vertices(t%d, %s, %s, %s, %zu, %s) = %d, count %zu", slot, ids ? "ids" : "NULL", xy ? "xy" : "NULL",
        dummy ? "dummy" : "NULL", cap, null_count ? "NULL" : "&count", (int)st_, count);
  no_internal(st_, "hdt_vertices");
  size_t written = 0;
  if (null_count) {
    CHECK(st_ == HDT_EINVAL, "hdt_vertices(count NULL): %s", st(st_));
  } else if (cap == 0) {
    CHECK(st_ == HDT_OK && count == v, "hdt_vertices(capacity 0): %s, count %zu of %zu", st(st_), count, v);
  } else if (cap < v) {
    CHECK(st_ == HDT_EBUFS && count == v, "hdt_vertices(capacity %zu < %zu): %s, count %zu", cap, v, st(st_), count);
  } else {
    CHECK(st_ == HDT_OK && count == v, "hdt_vertices(capacity %zu >= %zu): %s, count %zu", cap, v, st(st_), count);
    written = v;
  }
  uint8_t fill[sizeof(double)];
  memset(fill, 0xAB, sizeof fill);
  for (size_t i = written; i < cap + 1 && i < v + 2; ++i) {
    if (ids) CHECK(memcmp(&ids[i], fill, sizeof *ids) == 0, "hdt_vertices (%s) wrote ids[%zu]", st(st_), i);
    if (xy) CHECK(memcmp(&xy[2 * i], fill, sizeof *xy) == 0 && memcmp(&xy[2 * i + 1], fill, sizeof *xy) == 0,
                  "hdt_vertices (%s) wrote xy[%zu]", st(st_), 2 * i);
    if (dummy) CHECK(dummy[i] == 0xAB, "hdt_vertices (%s) wrote dummy[%zu]", st(st_), i);
  }
  if (written && ids) {
    size_t dummies = 0;
    for (size_t i = 0; i < v; ++i) {
      CHECK(ids[i] < bound && (i == 0 || ids[i - 1] < ids[i]), "hdt_vertices: ids[%zu] = %u", i, ids[i]);
      const int d = hdt_vertex_is_dummy(t, ids[i]);
      CHECK(d >= 0, "hdt_vertices: ids[%zu] = %u is no live vertex", i, ids[i]);
      if (dummy) CHECK(dummy[i] == d, "hdt_vertices: dummy[%zu] = %u, vertex %u has %d", i, dummy[i], ids[i], d);
      dummies += (size_t)d;
    }
    CHECK(dummies == hdt_dummy_count(t), "hdt_vertices: %zu dummies, hdt_dummy_count %zu", dummies,
          hdt_dummy_count(t));
    if (xy) {
      /* The points are hdt_vertex_point's: one sampled entry. */
      const size_t i = (size_t)(b >> 3) % v;
      double px = NAN, py = NAN;
      CHECK(hdt_vertex_point(t, ids[i], &px, &py) == HDT_OK && px == xy[2 * i] && py == xy[2 * i + 1],
            "hdt_vertices: xy of vertex %u (%a, %a), hdt_vertex_point (%a, %a)", ids[i], xy[2 * i], xy[2 * i + 1], px,
            py);
    }
  }
  if (written && xy)
    for (size_t i = 0; i < v; ++i)
      CHECK(in_open_disk(xy[2 * i], xy[2 * i + 1]), "hdt_vertices: point %zu (%a, %a) outside the disk", i, xy[2 * i],
            xy[2 * i + 1]);
  free(ids);
  free(xy);
  free(dummy);
}

/* Compares two SU(1,1) matrices up to the rounding of products of `letters`
   generators of genus g. */
static int matrices_close(const double *a, const double *b, int g, size_t letters) {
  const double tol = 1e-12 + 64.0 * (double)(letters + 1) * DBL_EPSILON * pow(hyp_norm_factor(g), (double)letters);
  for (int i = 0; i < 4; ++i)
    if (!(fabs(a[i] - b[i]) <= tol)) return 0;
  return 1;
}

static void op_translation(reader *r, state *s) {
  int slot;
  hdt_triangulation *t = *slot_of(r, s, &slot);
  const int g = hdt_genus(t);
  const uint8_t b = u8(r);
  int32_t id;
  switch (b % 4) {
    case 0: id = (int32_t)u32(r); break;
    case 1: id = -(int32_t)(u8(r) % 4) - 1; break;
    default: id = (int32_t)u16(r) % ((4 * g - 1) * (4 * g - 1) + 64); break;
  }
  size_t cap = (b >> 2) % 8 == 0 ? 0 : (size_t)u8(r) % (4 * g + 2);
  const int null_out = cap == 0 && (b & 0x80);
  int32_t *out = null_out ? NULL : malloc(cap * sizeof *out + 1);
  size_t len = SIZE_MAX;
  hdt_status st_ = hdt_translation_word(t, id, out, cap, &len);
  trace("hdt_translation_word(t%d, %d, %s, %zu, &len) = %d, len %zu", slot, (int)id, out ? "out" : "NULL", cap,
        (int)st_, len);
  no_internal(st_, "hdt_translation_word");
  double m[4] = {NAN, NAN, NAN, NAN};
  const hdt_status sm = hdt_translation_matrix(t, id, m);
  trace("hdt_translation_matrix(t%d, %d, m) = %d", slot, (int)id, (int)sm);
  no_internal(sm, "hdt_translation_matrix");
  CHECK((sm == HDT_OK) == (st_ == HDT_OK || st_ == HDT_EBUFS),
        "hdt_translation_word(%d) = %s but hdt_translation_matrix = %s", (int)id, st(st_), st(sm));
  if (id < 0) CHECK(st_ == HDT_EINVAL, "hdt_translation_word(negative id %d): %s", (int)id, st(st_));
  if (st_ == HDT_EBUFS) CHECK(cap < len, "hdt_translation_word: HDT_EBUFS for capacity %zu, length %zu", cap, len);
  if (st_ == HDT_OK && cap > 0) {
    CHECK(len <= cap, "hdt_translation_word: length %zu > capacity %zu", len, cap);
    for (size_t i = 0; i < len; ++i)
      CHECK(out[i] >= 0 && out[i] < 4 * g, "hdt_translation_word: letter %d, genus %d", (int)out[i], g);
    double wm[4];
    CHECK(hdt_word_matrix(g, out, len, wm) == HDT_OK, "hdt_word_matrix of a canonical word");
    CHECK(matrices_close(m, wm, g, len), "translation %d: hdt_translation_matrix and the matrix of its word differ",
          (int)id);
    /* A canonical word reduces to itself. */
    int32_t red[MAX_WORD + 64];
    size_t rl = 0;
    if (len <= MAX_WORD + 64) {
      const hdt_status rs = hdt_word_reduce(g, out, len, red, len, &rl);
      no_internal(rs, "hdt_word_reduce");
      CHECK(rs == HDT_OK && rl == len && (len == 0 || memcmp(red, out, len * sizeof *out) == 0),
            "translation %d: its word does not reduce to itself (%s)", (int)id, st(rs));
    }
  }
  free(out);
}

static void op_vertex(reader *r, state *s) {
  int slot;
  hdt_triangulation *t = *slot_of(r, s, &slot);
  const uint32_t v = gen_vertex(r, t);
  const uint8_t b = u8(r);
  double x = NAN, y = NAN;
  const hdt_status st_ = hdt_vertex_point(t, v, (b & 1) ? NULL : &x, (b & 2) ? NULL : &y);
  trace("hdt_vertex_point(t%d, %u) = %d", slot, v, (int)st_);
  no_internal(st_, "hdt_vertex_point");
  const int d = hdt_vertex_is_dummy(t, v);
  CHECK(d >= -1 && d <= 1, "hdt_vertex_is_dummy: %d", d);
  if (b & 3) CHECK(st_ == HDT_EINVAL, "hdt_vertex_point with a NULL output: %s", st(st_));
  else CHECK((st_ == HDT_OK) == (d >= 0), "hdt_vertex_point(%u) = %s, hdt_vertex_is_dummy = %d", v, st(st_), d);
  if (st_ != HDT_OK) {
    if (!(b & 3)) CHECK(isnan(x) && isnan(y), "hdt_vertex_point failed but wrote its outputs");
    return;
  }
  CHECK(in_open_disk(x, y), "vertex %u at (%a, %a), outside the disk", v, x, y);
  if (s->representatives++ < MAX_REPRESENTATIVES) {
    /* The vertex point is a representative: its own representative. */
    double rx, ry;
    size_t len = SIZE_MAX;
    const hdt_status rs = hdt_point_representative(hdt_genus(t), x, y, &rx, &ry, NULL, 0, &len);
    no_internal(rs, "hdt_point_representative");
    CHECK(rs == HDT_OK, "hdt_point_representative of vertex point %u: %s", v, st(rs));
    /* Rounding may put a point of a side just outside F_g: its representative
       is then near the paired side. */
    CHECK((fabs(rx - x) <= 1e-12 && fabs(ry - y) <= 1e-12) ||
              (side_distance(hdt_genus(t), x, y) <= 1e-12 && side_distance(hdt_genus(t), rx, ry) <= 1e-12),
          "vertex %u: point (%a, %a) has representative (%a, %a) (word of %zu letters)", v, x, y, rx, ry, len);
  }
}

/* The functions without a handle: words, matrices, the polygon. */
static void op_words(reader *r, state *s) {
  const uint8_t b = u8(r);
  static const int weird[] = {INT_MIN, -2, 0, 1, HDT_GENUS_MAX + 1, INT_MAX};
  const int g = (b & 0xF0) == 0xF0 ? weird[b % 6] : 2 + b % 7;
  const int valid_g = g >= 2 && g <= HDT_GENUS_MAX;
  int32_t w[MAX_WORD];
  const size_t n = read_word(r, valid_g ? g : 2, w);
  int letters_ok = 1;
  for (size_t i = 0; i < n; ++i) letters_ok &= valid_g && w[i] >= 0 && w[i] < 4 * g;
  const uint8_t what = u8(r);
  const size_t cap = what & 1 ? n : (size_t)(u8(r) % (MAX_WORD + 1));
  int32_t *out = malloc(cap * sizeof *out + 1);
  size_t len = SIZE_MAX;
  const hdt_status rs = hdt_word_reduce(g, n ? w : NULL, n, out, cap, &len);
  trace("hdt_word_reduce(%d, w[%zu], out, %zu) = %d, len %zu", g, n, cap, (int)rs, len);
  no_internal(rs, "hdt_word_reduce");
  if (!valid_g) CHECK(rs == (g < 2 ? HDT_EINVAL : HDT_ENOTSUP), "hdt_word_reduce(genus %d): %s", g, st(rs));
  else if (!letters_ok) CHECK(rs == HDT_EINVAL, "hdt_word_reduce with a bad letter: %s", st(rs));
  else CHECK(rs == HDT_OK || rs == HDT_EBUFS || rs == HDT_ENOTSUP, "hdt_word_reduce: %s", st(rs));
  if (rs == HDT_OK || rs == HDT_EBUFS) CHECK(len <= n, "hdt_word_reduce: %zu letters from %zu", len, n);
  if (rs == HDT_EBUFS) CHECK(cap < len && cap > 0, "hdt_word_reduce: HDT_EBUFS, capacity %zu, length %zu", cap, len);
  if (rs == HDT_OK && cap >= len) {
    double m1[4], m2[4];
    /* One element: both matrices, or both beyond the double range. */
    const hdt_status s1 = hdt_word_matrix(g, w, n, m1), s2 = hdt_word_matrix(g, out, len, m2);
    CHECK(s1 == s2 && (s1 == HDT_OK || s1 == HDT_EDOMAIN), "hdt_word_matrix: %s, %s", st(s1), st(s2));
    CHECK(s1 != HDT_OK || matrices_close(m1, m2, g, n),
          "hdt_word_reduce changed the element (genus %d, %zu -> %zu letters)", g, n, len);
    int32_t again[MAX_WORD];
    size_t len2 = SIZE_MAX;
    const hdt_status rs2 = hdt_word_reduce(g, out, len, again, MAX_WORD, &len2);
    CHECK(rs2 == HDT_OK && len2 == len && (len == 0 || memcmp(again, out, len * sizeof *out) == 0),
          "a canonical word does not reduce to itself (genus %d)", g);
  }
  free(out);

  double m[9];
  hdt_status ms = hdt_word_lorentz(g, n ? w : NULL, n, m);
  no_internal(ms, "hdt_word_lorentz");
  /* A valid word may overflow double: HDT_EDOMAIN saying so. */
  const int lorentz_too_large = ms == HDT_EDOMAIN && strstr(hdt_last_error_message(), "double range") != NULL;
  CHECK((ms == HDT_OK || lorentz_too_large) == (valid_g && letters_ok), "hdt_word_lorentz: %s", st(ms));
  ms = hdt_word_matrix(g, n ? w : NULL, n, (what & 2) ? NULL : m);
  no_internal(ms, "hdt_word_matrix");
  const int matrix_too_large = ms == HDT_EDOMAIN && strstr(hdt_last_error_message(), "double range") != NULL;
  CHECK((ms == HDT_OK || matrix_too_large) == (valid_g && letters_ok && !(what & 2)), "hdt_word_matrix: %s", st(ms));

  /* A point, mapped and represented. */
  const point p = gen_point(r, s, 0);
  const int inside = in_open_disk(p.x, p.y);
  double ox = NAN, oy = NAN;
  const hdt_status as = hdt_word_apply(g, n ? w : NULL, n, p.x, p.y, &ox, &oy);
  trace("hdt_word_apply(%d, w[%zu], %a, %a) = %d, (%a, %a)", g, n, p.x, p.y, (int)as, ox, oy);
  no_internal(as, "hdt_word_apply");
  if (valid_g && letters_ok) {
    /* An inside point's image may round onto the circle: HDT_EDOMAIN too. */
    CHECK(as == (inside ? HDT_OK : HDT_EDOMAIN) ||
              (inside && as == HDT_EDOMAIN && strstr(hdt_last_error_message(), "unit circle") != NULL),
          "hdt_word_apply(%a, %a): %s", p.x, p.y, st(as));
    /* Rounding may land on the circle itself; only finiteness and |z| <= 1. */
    if (as == HDT_OK) CHECK(isfinite(ox) && isfinite(oy) && hypot(ox, oy) <= 1 + 1e-15, "hdt_word_apply image");
  }
  /* (A point near the circle only in genus 2 and 3: see gen_point.) */
  if (valid_g && g <= 8 && !(g > 3 && is_far(p)) && s->representatives++ < MAX_REPRESENTATIVES) {
    double rx = NAN, ry = NAN;
    int32_t rw[64];
    size_t rl = SIZE_MAX;
    const size_t rcap = (what & 4) ? 64 : (what >> 4);
    const hdt_status ps = hdt_point_representative(g, p.x, p.y, &rx, &ry, rcap ? rw : NULL, rcap, &rl);
    trace("hdt_point_representative(%d, %a, %a, cap %zu) = %d, (%a, %a), %zu letters", g, p.x, p.y, rcap, (int)ps,
          rx, ry, rl);
    no_internal(ps, "hdt_point_representative");
    if (!inside) CHECK(ps == HDT_EDOMAIN, "hdt_point_representative(%a, %a): %s", p.x, p.y, st(ps));
    else CHECK(ps == HDT_OK || ps == HDT_EBUFS || ps == HDT_ENOTSUP, "hdt_point_representative: %s", st(ps));
    if (ps == HDT_OK) {
      CHECK(in_open_disk(rx, ry), "representative (%a, %a) outside the disk", rx, ry);
      double vx, vy;
      CHECK(hdt_polygon_vertex(g, 0, &vx, &vy) == HDT_OK, "hdt_polygon_vertex");
      CHECK(hypot(rx, ry) <= hypot(vx, vy) * (1 + 1e-12), "representative (%a, %a) outside F_%d", rx, ry, g);
      if (rcap >= rl && rl <= 64) {
        /* The word maps the point to its representative. */
        double ix, iy;
        const hdt_status a2 = hdt_word_apply(g, rw, rl, p.x, p.y, &ix, &iy);
        CHECK(a2 == HDT_OK && fabs(ix - rx) <= 1e-12 && fabs(iy - ry) <= 1e-12,
              "the representative's word does not map (%a, %a) to (%a, %a)", p.x, p.y, rx, ry);
      }
    }
  }
  /* Polygon and systole with arbitrary arguments. */
  const int k = (int)u32(r);
  double px = NAN, py = NAN;
  hdt_status qs = hdt_polygon_vertex(g, k, &px, &py);
  no_internal(qs, "hdt_polygon_vertex");
  CHECK((qs == HDT_OK) == valid_g, "hdt_polygon_vertex(%d, %d): %s", g, k, st(qs));
  qs = hdt_polygon_side_midpoint(g, k, (what & 8) ? NULL : &px, &py);
  no_internal(qs, "hdt_polygon_side_midpoint");
  CHECK((qs == HDT_OK) == (valid_g && !(what & 8)), "hdt_polygon_side_midpoint(%d, %d): %s", g, k, st(qs));
  const double sys = hdt_systole(g);
  CHECK(g < 2 ? isnan(sys) : (sys > 3 && isfinite(sys)), "hdt_systole(%d) = %g", g, sys);
  if (valid_g && g <= 8) {
    size_t count = 0;
    CHECK(hdt_neighbour_count(g, &count) == HDT_OK && count == (size_t)(4 * g - 1) * (size_t)(4 * g - 1),
          "hdt_neighbour_count(%d)", g);
    const size_t id = (size_t)u32(r) % (count + 4);
    int32_t nw[64];
    size_t nl = SIZE_MAX;
    const hdt_status ns = hdt_neighbour_word(g, id, nw, 64, &nl);
    no_internal(ns, "hdt_neighbour_word");
    CHECK((ns == HDT_OK) == (id < count), "hdt_neighbour_word(%d, %zu of %zu): %s", g, id, count, st(ns));
  }
}

/* Every handle function with a NULL handle. */
/* ---- The HDT_0.3 .. HDT_0.5 functions ---- */

/* An output array of `cap` items of `per` elements of `size` bytes, plus one
   guard element, filled with 0xAB so that a write beyond what a call returns
   shows. NULL when the array is left out. */
typedef struct out_array {
  unsigned char *p;
  size_t per, size;
} out_array;

static out_array out_alloc(int present, size_t cap, size_t per, size_t size) {
  out_array a = {NULL, per, size};
  if (!present) return a;
  a.p = malloc((cap * per + 1) * size);
  if (!a.p) abort();
  memset(a.p, 0xAB, (cap * per + 1) * size);
  return a;
}

/* No byte of items written.. cap (and the guard) changed. */
static void out_untouched_from(const out_array *a, size_t written, size_t cap, const char *call, const char *what) {
  if (!a->p) return;
  for (size_t i = written * a->per * a->size; i < (cap * a->per + 1) * a->size; ++i)
    CHECK(a->p[i] == 0xAB, "%s wrote %s byte %zu beyond the %zu items it returned", call, what, i, written);
}

/* A capacity for a list of `needed` items: 0 (asks), one short, exact, more. */
static size_t pick_capacity(uint8_t b, size_t needed) {
  switch (b % 4) {
    case 0: return 0;
    case 1: return needed ? needed - 1 : 0;
    case 2: return needed;
    default: return needed + 1 + (b >> 5);
  }
}

static int in_disk(const double *xy) { return isfinite(xy[0]) && isfinite(xy[1]) && xy[0] * xy[0] + xy[1] * xy[1] < 1; }

/* The degree of live vertex v, counted from the face list. */
static size_t degree_of(const hdt_triangulation *t, uint32_t v, uint32_t **faces_out) {
  const size_t f = hdt_face_count(t);
  uint32_t *fv = malloc(3 * f * sizeof *fv + 1);
  size_t count = 0, d = 0;
  CHECK(hdt_faces(t, fv, NULL, f, &count) == HDT_OK && count == f, "hdt_faces");
  for (size_t i = 0; i < 3 * f; ++i) d += fv[i] == v;
  *faces_out = fv;
  return d;
}

enum { DUAL_NEIGHBOURS, DUAL_STAR, DUAL_EDGES, DUAL_POINTS, DUAL_VORONOI_VERTICES, DUAL_VORONOI_EDGES, DUAL_CELL };

/* Adjacency, edges, corner points and the Voronoi diagram: the two-call
   contract with every kind of capacity, nothing written beyond what a call
   returns, and properties a wrong answer breaks (adjacency is symmetric, a
   star's faces hold the vertex and number its degree, E = 3F/2 with each
   face on three edges, every point in the open disk, radii and lengths
   positive and below the guarantee). */
static void op_dual(reader *r, state *s) {
  int slot;
  hdt_triangulation *t = *slot_of(r, s, &slot);
  if (hdt_vertex_count(t) >= FINGERPRINT_MAX_V) return;
  const uint8_t kind = u8(r) % 7, b = u8(r);
  const size_t f = hdt_face_count(t), e = hdt_edge_count(t);
  CHECK(2 * e == 3 * f, "hdt_edge_count %zu for %zu faces", e, f);
  uint32_t v = 0, *fv = NULL;
  size_t needed = f;
  int live = 1;
  if (kind == DUAL_STAR || kind == DUAL_CELL) {
    v = gen_vertex(r, t);
    live = hdt_vertex_is_dummy(t, v) >= 0;
    needed = live ? degree_of(t, v, &fv) : 0;
  } else if (kind == DUAL_EDGES || kind == DUAL_VORONOI_EDGES) {
    needed = e;
  }
  const size_t cap = pick_capacity(b, needed);
  const int drop = (b >> 2) & 7; /* which optional outputs are NULL */
  out_array a = {0}, c = {0}, d = {0}, l = {0};
  size_t count = SIZE_MAX;
  hdt_status st_ = HDT_ERROR;
  const char *call = "";
  switch (kind) {
    case DUAL_NEIGHBOURS:
      call = "hdt_face_neighbours";
      a = out_alloc(!(drop & 1), cap, 3, 4), c = out_alloc(!(drop & 2), cap, 3, 4);
      st_ = hdt_face_neighbours(t, (uint32_t *)a.p, (int32_t *)c.p, cap, &count);
      break;
    case DUAL_STAR:
      call = "hdt_vertex_star";
      a = out_alloc(!(drop & 1), cap, 1, 4), c = out_alloc(!(drop & 2), cap, 1, 1), d = out_alloc(!(drop & 4), cap, 1, 4);
      st_ = hdt_vertex_star(t, v, (uint32_t *)a.p, c.p, (int32_t *)d.p, cap, &count);
      break;
    case DUAL_EDGES:
      call = "hdt_edges";
      a = out_alloc(!(drop & 1), cap, 2, 4), c = out_alloc(!(drop & 2), cap, 1, 4), d = out_alloc(!(drop & 4), cap, 2, 4);
      l = out_alloc(drop != 7, cap, 1, 8);
      st_ = hdt_edges(t, (uint32_t *)a.p, (int32_t *)c.p, (uint32_t *)d.p, (double *)l.p, cap, &count);
      break;
    case DUAL_POINTS:
      call = "hdt_face_points";
      a = out_alloc(1, cap, 6, 8);
      st_ = hdt_face_points(t, (double *)a.p, cap, &count);
      break;
    case DUAL_VORONOI_VERTICES:
      call = "hdt_voronoi_vertices";
      a = out_alloc(!(drop & 1), cap, 2, 8), c = out_alloc(!(drop & 2), cap, 1, 8);
      st_ = hdt_voronoi_vertices(t, (double *)a.p, (double *)c.p, cap, &count);
      break;
    case DUAL_VORONOI_EDGES:
      call = "hdt_voronoi_edges";
      a = out_alloc(1, cap, 4, 8);
      st_ = hdt_voronoi_edges(t, (double *)a.p, cap, &count);
      break;
    default:
      call = "hdt_voronoi_cell";
      a = out_alloc(1, cap, 2, 8);
      st_ = hdt_voronoi_cell(t, v, (double *)a.p, cap, &count);
      break;
  }
  trace("%s(t%d, v %u, capacity %zu, drop %d) = %d, count %zu", call, slot, v, cap, drop, (int)st_, count);
  no_internal(st_, call);
  size_t written = 0;
  if (!live) {
    CHECK(st_ == HDT_EINVAL, "%s(vertex %u, not live): %s", call, v, st(st_));
  } else if (cap < needed) {
    CHECK(st_ == (cap == 0 ? HDT_OK : HDT_EBUFS) && count == needed, "%s(capacity %zu of %zu): %s, count %zu", call,
          cap, needed, st(st_), count);
  } else {
    CHECK(st_ == HDT_OK && count == needed, "%s(capacity %zu >= %zu): %s, count %zu", call, cap, needed, st(st_),
          count);
    written = needed;
  }
  out_untouched_from(&a, written, cap, call, "output 1");
  out_untouched_from(&c, written, cap, call, "output 2");
  out_untouched_from(&d, written, cap, call, "output 3");
  out_untouched_from(&l, written, cap, call, "lengths");
  const double quarter_sys = hdt_systole(hdt_genus(t)) / 4;
  if (written) switch (kind) {
      case DUAL_NEIGHBOURS:
        if (a.p)
          for (size_t i = 0; i < 3 * f; ++i) {
            const uint32_t *nb = (const uint32_t *)a.p, n = nb[i];
            CHECK(n < f && n != i / 3, "hdt_face_neighbours: face %zu, corner %zu: %u", i / 3, i % 3, n);
            CHECK(nb[3 * n] == i / 3 || nb[3 * n + 1] == i / 3 || nb[3 * n + 2] == i / 3,
                  "hdt_face_neighbours: %zu is across from %u, not back", i / 3, n);
          }
        break;
      case DUAL_STAR:
        if (a.p && c.p)
          for (size_t k = 0; k < needed; ++k) {
            const uint32_t face = ((const uint32_t *)a.p)[k];
            CHECK(face < f && c.p[k] < 3 && fv[3 * face + c.p[k]] == v, "hdt_vertex_star(%u): face %u corner %u", v,
                  face, c.p[k]);
          }
        break;
      case DUAL_EDGES:
        if (d.p) {
          unsigned *seen = calloc(f, sizeof *seen);
          for (size_t i = 0; i < 2 * e; ++i) {
            const uint32_t face = ((const uint32_t *)d.p)[i];
            CHECK(face < f && ++seen[face] <= 3, "hdt_edges: face %u on more than 3 edges", face);
          }
          free(seen);
        }
        if (l.p)
          for (size_t i = 0; i < e; ++i) {
            const double len = ((const double *)l.p)[i];
            /* >= 0, not > 0: a user point within an ulp of a dummy's
               algebraic point rounds to the same double, length 0. */
            CHECK(len >= 0 && len < 2 * quarter_sys * (1 + 1e-9), "hdt_edges: edge %zu has length %a", i, len);
          }
        break;
      case DUAL_VORONOI_VERTICES:
        if (c.p)
          for (size_t i = 0; i < f; ++i) {
            const double rad = ((const double *)c.p)[i];
            CHECK(rad > 0 && rad < quarter_sys * (1 + 1e-9), "hdt_voronoi_vertices: face %zu has radius %a", i, rad);
          }
        /* fall through: the centres */
      default:
        if (a.p)
          for (size_t i = 0; i < written * a.per; i += 2)
            CHECK(in_disk((const double *)a.p + i), "%s: point %zu not in the open disk", call, i / 2);
        break;
    }
  free(a.p), free(c.p), free(d.p), free(l.p), free(fv);
}

/* Save and load: the loaded triangulation gives the same faces and
   vertices; a prefix of the bytes, or the bytes with one changed, load to
   HDT_EINVAL (or, for a change the checksum cannot see, a valid
   triangulation) and nothing else. Sometimes the loaded one replaces the
   original, so that later calls run on it. */
static void op_save_load(reader *r, state *s) {
  int slot;
  hdt_triangulation *t = *slot_of(r, s, &slot);
  const uint8_t b = u8(r);
  if (s->loads >= MAX_LOADS || hdt_vertex_count(t) >= FINGERPRINT_MAX_V) return;
  ++s->loads;
  const fingerprint before = take(t);
  size_t size = 0;
  hdt_status st_ = hdt_save(t, NULL, 0, &size);
  CHECK(st_ == HDT_OK && size > 0, "hdt_save(capacity 0): %s, size %zu", st(st_), size);
  const size_t cap = b % 4 ? pick_capacity(b, size) : size; /* 0 was the call above */
  out_array bytes = out_alloc(1, cap, 1, 1);
  size_t size2 = SIZE_MAX;
  st_ = hdt_save(t, bytes.p, cap, &size2);
  trace("hdt_save(t%d, bytes, %zu) = %d, size %zu", slot, cap, (int)st_, size2);
  no_internal(st_, "hdt_save");
  CHECK(size2 == size && st_ == (cap < size ? HDT_EBUFS : HDT_OK), "hdt_save(capacity %zu of %zu): %s", cap, size,
        st(st_));
  out_untouched_from(&bytes, st_ == HDT_OK ? size : 0, cap, "hdt_save", "byte");
  expect_unchanged(&before, t, "hdt_save");
  if (st_ != HDT_OK) {
    free(bytes.p);
    return;
  }
  hdt_triangulation *u = NULL;
  st_ = hdt_load(&u, bytes.p, size);
  trace("hdt_load(&u, bytes, %zu) = %d", size, (int)st_);
  CHECK(st_ == HDT_OK && u, "hdt_load of hdt_save's bytes: %s (%s)", st(st_), hdt_last_error_message());
  expect_unchanged(&before, u, "hdt_load (compared with the saved triangulation)");
  /* A strict prefix, then one byte changed. */
  const size_t cut = u16(r) % size, at = u16(r) % size;
  hdt_triangulation *bad = (hdt_triangulation *)&op_index;
  st_ = hdt_load(&bad, bytes.p, cut);
  CHECK(st_ == HDT_EINVAL && bad == (hdt_triangulation *)&op_index, "hdt_load of %zu of %zu bytes: %s", cut, size,
        st(st_));
  bytes.p[at] ^= (unsigned char)(u8(r) | 1);
  st_ = hdt_load(&bad, bytes.p, size);
  trace("hdt_load(&bad, bytes with byte %zu changed, %zu) = %d", at, size, (int)st_);
  no_internal(st_, "hdt_load");
  if (st_ == HDT_OK) {
    CHECK(hdt_validate(bad) == HDT_OK, "hdt_load accepted changed bytes and gave an invalid triangulation");
    hdt_destroy(bad);
  } else {
    CHECK(st_ == HDT_EINVAL && bad == (hdt_triangulation *)&op_index, "hdt_load of changed bytes: %s", st(st_));
  }
  free(bytes.p);
  if (b & 0x80) {
    retire(s, slot);
    s->t[slot] = u;
    s->unvalidated[slot] = 1;
    s->dummy_calls[slot] = 0;
  } else {
    hdt_destroy(u);
  }
}

/* A progress function that checks its contract: done only grows, and
   never passes a known total. */
static int progress_check(void *user, size_t done, size_t total) {
  progress_state *p = user;
  CHECK(done >= p->last_done && (total == 0 || done <= total), "progress: done %zu after %zu, total %zu", done,
        p->last_done, total);
  p->last_done = done;
  ++p->calls;
  return 0;
}

/* Refinement, epsilon-nets and quality, with a progress function set or
   not; invalid bounds change nothing. A call that completes (no face left
   unmet) leaves hdt_quality's statistics within its bounds. */
static void op_refine(reader *r, state *s) {
  int slot;
  hdt_triangulation *t = *slot_of(r, s, &slot);
  static const double radii[] = {0.3, 0.5, 1.0, 0.2, INFINITY, 0, -1, NAN, -INFINITY};
  static const double ratios[] = {1, 1.5, 2, INFINITY, 0.99, 0, NAN, -1};
  const uint8_t b = u8(r);
  const double rad = radii[u8(r) % 9], ratio = ratios[u8(r) % 8];
  const size_t cap = u8(r) % (MAX_STEINER + 1);
  if (b & 0x10) {
    const double interval = (b & 0x20) ? INFINITY : (b & 0x40) ? NAN : 0;
    s->progress[slot] = (progress_state){0, 0};
    const hdt_status p = hdt_set_progress(t, (b & 0x80) ? NULL : progress_check, &s->progress[slot], interval);
    CHECK(p == (isnan(interval) ? HDT_EINVAL : HDT_OK), "hdt_set_progress(interval %g): %s", interval, st(p));
  }
  const fingerprint before = take(t);
  size_t added = SIZE_MAX, unmet = SIZE_MAX;
  hdt_status st_;
  int valid;
  double want_radius = rad, want_ratio = ratio;
  const int what = (b & 3) % 3; /* 0 refine, 1 epsilon-net, 2 quality */
  s->progress[slot].last_done = 0; /* done grows within one call */
  if (what == 2) {
    double q[4] = {NAN, NAN, NAN, NAN};
    st_ = hdt_quality(t, (b & 4) ? NULL : &q[0], &q[1], &q[2], (b & 8) ? NULL : &q[3]);
    trace("hdt_quality(t%d) = %d: %g %g %g %g", slot, (int)st_, q[0], q[1], q[2], q[3]);
    CHECK(st_ == HDT_OK, "hdt_quality: %s", st(st_));
    CHECK(q[1] > 0 && q[2] > 0 && q[2] < hdt_systole(hdt_genus(t)) / 4 * (1 + 1e-9), "hdt_quality: ratio %g, radius %g",
          q[1], q[2]);
    /* A hyperbolic triangle's angles sum to less than pi; the shortest edge
       is a chord of some face's circumcircle (>= 0 for both: see op_dual). */
    if (!(b & 4)) CHECK(q[0] >= 0 && q[0] < HDT_FUZZ_PI / 3 * (1 + 1e-12), "hdt_quality: smallest angle %g", q[0]);
    if (!(b & 8)) CHECK(q[3] >= 0 && q[3] <= 2 * q[2] * (1 + 1e-12), "hdt_quality: shortest edge %g, radius %g", q[3], q[2]);
    return;
  }
  if (what == 0) {
    valid = rad > 0 && !isnan(rad) && ratio >= 1;
    st_ = hdt_refine(t, rad, ratio, cap, &added, &unmet);
    trace("hdt_refine(t%d, %g, %g, %zu) = %d, added %zu, unmet %zu", slot, rad, ratio, cap, (int)st_, added, unmet);
  } else {
    valid = rad > 0 && isfinite(rad);
    want_ratio = INFINITY;
    st_ = hdt_epsilon_net(t, rad, cap, &added, &unmet);
    trace("hdt_epsilon_net(t%d, %g, %zu) = %d, added %zu, unmet %zu", slot, rad, cap, (int)st_, added, unmet);
  }
  no_internal(st_, what == 0 ? "hdt_refine" : "hdt_epsilon_net");
  if (!valid) {
    CHECK(st_ == HDT_EINVAL, "refinement with radius %g, ratio %g: %s", rad, ratio, st(st_));
    expect_unchanged(&before, t, "a refinement with invalid bounds");
    return;
  }
  CHECK(st_ == HDT_OK && added <= cap && hdt_vertex_count(t) == before.v + added && hdt_dummy_count(t) == before.d,
        "refinement (cap %zu): %s, added %zu, vertices %zu -> %zu", cap, st(st_), added, before.v, hdt_vertex_count(t));
  if (added) changed(s, slot, "a refinement");
  if (unmet == 0) {
    double ratio_now = NAN, radius_now = NAN;
    CHECK(hdt_quality(t, NULL, &ratio_now, &radius_now, NULL) == HDT_OK, "hdt_quality");
    CHECK(radius_now <= want_radius && ratio_now <= want_ratio,
          "refinement complete but radius %g > %g or ratio %g > %g", radius_now, want_radius, ratio_now, want_ratio);
  }
}

/* hdt_svg: the two-call contract in bytes, refused flags and sizes. */
static void op_svg(reader *r, state *s) {
  int slot;
  hdt_triangulation *t = *slot_of(r, s, &slot);
  if (hdt_vertex_count(t) >= FINGERPRINT_MAX_V / 2) return;
  static const double sizes[] = {200, 64, HDT_SVG_SIZE_MAX, 0, -1, NAN, INFINITY, HDT_SVG_SIZE_MAX * 2};
  const uint8_t b = u8(r);
  const double size = sizes[b % 8];
  // Bit 7: side labels (HDT_SVG_SIDE_LABELS, 8), or 16, a bit no version defines.
  const unsigned flags = (b & 0x80) ? ((b & 1) ? 16u : (unsigned)HDT_SVG_SIDE_LABELS)
                                    : (unsigned)((b >> 3) & 7) & ~(unsigned)HDT_SVG_NEIGHBOURS;
  const char *title = (b & 0x40) ? "<&\x01\xff>" : NULL;
  const int valid = size > 0 && size <= HDT_SVG_SIZE_MAX && flags < 16;
  size_t len = SIZE_MAX;
  hdt_status st_ = hdt_svg(t, size, title, flags, NULL, 0, &len);
  trace("hdt_svg(t%d, %g, flags %u, capacity 0) = %d, length %zu", slot, size, flags, (int)st_, len);
  no_internal(st_, "hdt_svg");
  if (!valid) {
    CHECK(st_ == HDT_EINVAL && len == SIZE_MAX, "hdt_svg(size %g, flags %u): %s", size, flags, st(st_));
    return;
  }
  CHECK(st_ == HDT_OK && len > 0, "hdt_svg(capacity 0): %s", st(st_));
  const uint8_t c = u8(r);
  const size_t cap = c % 4 ? pick_capacity(c, len + 1) : len + 1; /* 0 was the call above */
  out_array text = out_alloc(1, cap, 1, 1);
  size_t len2 = SIZE_MAX;
  st_ = hdt_svg(t, size, title, flags, (char *)text.p, cap, &len2);
  CHECK(len2 == len && st_ == (cap < len + 1 ? HDT_EBUFS : HDT_OK), "hdt_svg(capacity %zu, length %zu): %s", cap, len,
        st(st_));
  out_untouched_from(&text, st_ == HDT_OK ? len + 1 : 0, cap, "hdt_svg", "text");
  if (st_ == HDT_OK) CHECK(text.p[len] == 0 && strlen((char *)text.p) == len, "hdt_svg: text not NUL-terminated at %zu", len);
  free(text.p);
}

static void op_null(reader *r, state *s) {
  (void)r;
  (void)s;
  uint32_t v = 7;
  size_t n = 7;
  int32_t tr = 7;
  double x = 0, y = 0, m[4];
  CHECK(hdt_genus(NULL) == 0 && hdt_vertex_count(NULL) == 0 && hdt_dummy_count(NULL) == 0 &&
            hdt_vertex_id_bound(NULL) == 0 && hdt_face_count(NULL) == 0 && hdt_vertex_is_dummy(NULL, 0) == -1,
        "queries on a NULL handle");
  const hdt_status got[] = {hdt_insert(NULL, 0, 0, &v),
                            hdt_insert_many(NULL, &x, 0, &v),
                            hdt_remove_vertex(NULL, 0),
                            hdt_remove_dummies(NULL, &n),
                            hdt_vertex_point(NULL, 0, &x, &y),
                            hdt_faces(NULL, NULL, NULL, 0, &n),
                            hdt_vertices(NULL, NULL, NULL, NULL, 0, &n),
                            hdt_translation_word(NULL, 0, NULL, 0, &n),
                            hdt_translation_matrix(NULL, 0, m),
                            hdt_locate(NULL, 0, 0, &n, &tr),
                            hdt_nearest_vertex(NULL, 0, 0, &v),
                            hdt_validate(NULL),
                            hdt_svg(NULL, 100, NULL, 0, NULL, 0, &n),
                            hdt_save(NULL, NULL, 0, &n),
                            hdt_face_neighbours(NULL, NULL, NULL, 0, &n),
                            hdt_vertex_star(NULL, 0, NULL, NULL, NULL, 0, &n),
                            hdt_edges(NULL, NULL, NULL, NULL, NULL, 0, &n),
                            hdt_face_points(NULL, NULL, 0, &n),
                            hdt_voronoi_vertices(NULL, NULL, NULL, 0, &n),
                            hdt_voronoi_edges(NULL, NULL, 0, &n),
                            hdt_voronoi_cell(NULL, 0, NULL, 0, &n),
                            hdt_refine(NULL, 1, 1, 0, &n, &n),
                            hdt_epsilon_net(NULL, 1, 0, &n, &n),
                            hdt_quality(NULL, &x, &y, &x, &y),
                            hdt_set_progress(NULL, NULL, NULL, 0)};
  for (size_t i = 0; i < sizeof got / sizeof got[0]; ++i)
    CHECK(got[i] == HDT_EINVAL, "call %zu of the NULL-handle list: %s", i, st(got[i]));
  CHECK(v == 7 && n == 7 && tr == 7 && x == 0 && y == 0, "a call on a NULL handle wrote an output");
  CHECK(hdt_edge_count(NULL) == 0, "hdt_edge_count(NULL)");
  hdt_destroy(NULL);
}

typedef void (*op_fn)(reader *, state *);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  static const op_fn ops[] = {
      op_create,         op_insert, op_insert, op_insert,      op_insert,   op_insert_many, op_insert_many,
      op_remove,         op_remove, op_remove, op_remove_dummies, op_locate, op_locate,    op_faces,
      op_translation,    op_vertex, op_words,  op_null,        op_vertices,
      /* HDT_0.3 .. HDT_0.5 */
      op_dual,           op_dual,   op_save_load, op_refine,   op_svg,
  };
  if (trace_on < 0) {
    const char *e = getenv("HDT_FUZZ_TRACE");
    trace_on = e != NULL && *e != '\0' && *e != '0';
    e = getenv("HDT_FUZZ_VALIDATE_EVERY");
    validate_every = e && atoi(e) > 0 ? atoi(e) : VALIDATE_EVERY;
  }
  reader r = {data, size, 0};
  state s;
  memset(&s, 0, sizeof s);
  const int g = genus_of_byte(u8(&r));
  const hdt_status c = hdt_create(&s.t[0], g);
  trace("hdt_create(&t0, %d) = %d", g, (int)c);
  CHECK(c == HDT_OK, "hdt_create(genus %d): %s", g, st(c));
  created(&s, 0);
  for (op_index = 0; op_index < MAX_OPS && !r.empty && r.n > 0; ++op_index) {
    const uint8_t k = u8(&r);
    trace("/* op %u: kind %u */", op_index, k % (unsigned)(sizeof ops / sizeof ops[0]));
    ops[k % (sizeof ops / sizeof ops[0])](&r, &s);
  }
  for (int i = 0; i < SLOTS; ++i) retire(&s, i);
  return 0;
}
