/* libFuzzer target: drives libhdt's C API with operation sequences decoded
 * from arbitrary bytes, and checks the contract on every call:
 *
 *   - no crash, no sanitizer report (the build uses ASan + UBSan);
 *   - hdt_validate is HDT_OK after the steps that may change a triangulation
 *     (each of the first EVERY_STEP, then every LATER_STEP-th, and the last);
 *   - a call that fails leaves the triangulation exactly as it was (counts,
 *     the full face list with translations, every vertex point), checked
 *     while the triangulation is small;
 *   - statuses agree with the header: HDT_EDOMAIN exactly for points that are
 *     not finite points of the open unit disk (decided here with GMP),
 *     HDT_EINVAL exactly for dead vertex ids and unknown translation ids,
 *     HDT_EBUFS with the needed size, no write beyond a capacity, never
 *     HDT_EINTERNAL / HDT_ERROR / HDT_ENOMEM;
 *   - a few cross-checks: the inserted point's nearest vertex is the vertex
 *     returned, it is a corner of the face located there, its vertex point is
 *     its representative, F = 2 (V + 2g - 2), canonical words reduce to
 *     themselves and have the matrix of the word they came from.
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
#include <gmp.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hdt.h"

#define HDT_FUZZ_PI 3.14159265358979323846

/* Work bounds per input, so that executions stay fast. */
enum {
  MAX_OPS = 64,          /* operations per input */
  MAX_POINTS = 256,      /* points offered to insert / insert_many per input */
  MAX_FULL_CHECKS = 16,  /* inserted points cross-checked per input */
  MAX_FAR = 2,           /* points with |z|^2 > 1 - 1e-6 per input (each costs much more) */
  EVERY_STEP = 8,        /* hdt_validate after each of the first 8 changes, */
  LATER_STEP = 4,        /* then after every 4th, and at the end of the input */
  MAX_MANY = 48,         /* points per insert_many call */
  MAX_WORD = 24,         /* letters per word */
  SNAPSHOT_MAX_V = 200,  /* the unchanged-on-failure check runs below this size */
  HISTORY = 64,          /* remembered points, for duplicates */
  SLOTS = 2,             /* triangulations alive at once */
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

/* ---- The byte reader ---- */

typedef struct reader {
  const uint8_t *p;
  size_t n;
  int empty; /* a read ran past the end */
} reader;

static uint8_t u8(reader *r) {
  if (r->n == 0) {
    r->empty = 1;
    return 0;
  }
  --r->n;
  return *r->p++;
}
static uint16_t u16(reader *r) { return (uint16_t)(u8(r) | (u8(r) << 8)); }
static uint32_t u32(reader *r) { return (uint32_t)u16(r) | ((uint32_t)u16(r) << 16); }
static uint64_t u64(reader *r) { return (uint64_t)u32(r) | ((uint64_t)u32(r) << 32); }
static double f64(reader *r) {
  const uint64_t b = u64(r);
  double d;
  memcpy(&d, &b, sizeof d);
  return d;
}

/* ---- Exact facts about doubles ---- */

/* 1 when (x, y) is a finite point of the open unit disk, decided exactly. */
static int in_open_disk(double x, double y) {
  if (!isfinite(x) || !isfinite(y)) return 0;
  if (fabs(x) >= 1 || fabs(y) >= 1) return 0;
  mpq_t a, b;
  mpq_inits(a, b, NULL);
  mpq_set_d(a, x);
  mpq_mul(a, a, a);
  mpq_set_d(b, y);
  mpq_mul(b, b, b);
  mpq_add(a, a, b);
  const int inside = mpq_cmp_ui(a, 1, 1) < 0;
  mpq_clears(a, b, NULL);
  return inside;
}

/* x moved by `steps` ulps (toward +inf for steps > 0). */
static double ulps(double x, int steps) {
  for (; steps > 0; --steps) x = nextafter(x, INFINITY);
  for (; steps < 0; ++steps) x = nextafter(x, -INFINITY);
  return x;
}

static double hyp_norm_factor(int g) {
  /* ||g_k|| <= A + |B| with A = cot(pi / 4g), |B| = sqrt(A^2 - 1). */
  const double a = 1 / tan(HDT_FUZZ_PI / (4 * g));
  return a + sqrt(a * a - 1);
}

/* ---- State ---- */

typedef struct point {
  double x, y;
} point;

typedef struct state {
  hdt_triangulation *t[SLOTS];
  point history[HISTORY];
  unsigned history_n;
  unsigned points_used;
  unsigned far_used;
  unsigned full_checks; /* check_inserted calls so far */
  unsigned changes; /* calls that may have changed a triangulation */
} state;

static void remember(state *s, double x, double y) {
  s->history[s->history_n % HISTORY] = (point){x, y};
  ++s->history_n;
}

/* ---- Snapshots: the whole observable triangulation ---- */

typedef struct snapshot {
  int valid;
  size_t v, d, bound, f;
  uint32_t *fv;
  int32_t *ft;
  double *pts; /* 2 per id; NaN for a dead id */
  signed char *dummy;
} snapshot;

static void snapshot_free(snapshot *s) {
  free(s->fv);
  free(s->ft);
  free(s->pts);
  free(s->dummy);
  memset(s, 0, sizeof *s);
}

static void take(snapshot *s, const hdt_triangulation *t) {
  memset(s, 0, sizeof *s);
  s->v = hdt_vertex_count(t);
  if (s->v >= SNAPSHOT_MAX_V) return;
  s->valid = 1;
  s->d = hdt_dummy_count(t);
  s->bound = hdt_vertex_id_bound(t);
  s->f = hdt_face_count(t);
  s->fv = malloc(3 * s->f * sizeof *s->fv + 1);
  s->ft = malloc(3 * s->f * sizeof *s->ft + 1);
  s->pts = malloc(2 * s->bound * sizeof *s->pts + 1);
  s->dummy = malloc(s->bound + 1);
  if (!s->fv || !s->ft || !s->pts || !s->dummy) abort();
  size_t count = 0;
  const hdt_status st_ = hdt_faces(t, s->fv, s->ft, s->f, &count);
  CHECK(st_ == HDT_OK && count == s->f, "snapshot: hdt_faces %s, %zu faces of %zu", st(st_), count, s->f);
  for (size_t i = 0; i < s->bound; ++i) {
    s->dummy[i] = (signed char)hdt_vertex_is_dummy(t, (uint32_t)i);
    s->pts[2 * i] = s->pts[2 * i + 1] = NAN;
    if (s->dummy[i] >= 0) {
      const hdt_status p = hdt_vertex_point(t, (uint32_t)i, &s->pts[2 * i], &s->pts[2 * i + 1]);
      CHECK(p == HDT_OK, "snapshot: hdt_vertex_point(%zu) of a live vertex: %s", i, st(p));
    }
  }
}

/* Aborts unless t still looks exactly like the snapshot. */
static void expect_unchanged(const snapshot *s, const hdt_triangulation *t, const char *call) {
  CHECK(hdt_vertex_count(t) == s->v, "%s failed but changed the vertex count %zu -> %zu", call, s->v,
        hdt_vertex_count(t));
  if (!s->valid) return;
  snapshot now;
  take(&now, t);
  CHECK(now.d == s->d && now.bound == s->bound && now.f == s->f,
        "%s failed but changed dummies %zu -> %zu, id bound %zu -> %zu, faces %zu -> %zu", call, s->d, now.d,
        s->bound, now.bound, s->f, now.f);
  CHECK(memcmp(now.fv, s->fv, 3 * s->f * sizeof *s->fv) == 0, "%s failed but changed the faces", call);
  CHECK(memcmp(now.ft, s->ft, 3 * s->f * sizeof *s->ft) == 0, "%s failed but changed the face translations", call);
  CHECK(memcmp(now.dummy, s->dummy, s->bound) == 0, "%s failed but changed which vertices are live or dummy", call);
  for (size_t i = 0; i < 2 * s->bound; ++i)
    CHECK((isnan(now.pts[i]) && isnan(s->pts[i])) || now.pts[i] == s->pts[i],
          "%s failed but moved vertex %zu", call, i / 2);
  snapshot_free(&now);
}

static void validate_now(const hdt_triangulation *t, const char *after) {
  const hdt_status s = hdt_validate(t);
  trace("hdt_validate(t) = %d", (int)s);
  CHECK(s == HDT_OK, "hdt_validate after %s: %d (%s)", after, (int)s, st(s));
  const int g = hdt_genus(t);
  const size_t v = hdt_vertex_count(t), f = hdt_face_count(t);
  CHECK(f == 2 * (v + 2 * (size_t)g - 2), "after %s: %zu faces for %zu vertices, genus %d", after, f, v, g);
  CHECK(hdt_dummy_count(t) <= v && v <= hdt_vertex_id_bound(t), "after %s: %zu dummies, %zu vertices, id bound %zu",
        after, hdt_dummy_count(t), v, hdt_vertex_id_bound(t));
}

/* hdt_validate after a call that may have changed t: after every change at
   first, then after every LATER_STEP-th (and at the end of the input): with
   points near the unit circle one validation can take a large part of a
   second under the sanitizers. */
static void validate(state *s, const hdt_triangulation *t, const char *after) {
  const unsigned n = s->changes++;
  if (n < EVERY_STEP || n % LATER_STEP == 0) validate_now(t, after);
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

/* A point on side s_k of F_g at parameter u in [0, 1] (ends at v_{k-1}, v_k),
   rounded. The side is the arc of the circle orthogonal to the unit circle
   through m_k, centred on the ray of m_k. */
static point side_point(int g, int k, double u) {
  double mx, my, ax, ay, bx, by;
  point p = {0, 0};
  if (hdt_polygon_side_midpoint(g, k, &mx, &my) != HDT_OK || hdt_polygon_vertex(g, k - 1, &ax, &ay) != HDT_OK ||
      hdt_polygon_vertex(g, k, &bx, &by) != HDT_OK)
    fail("hdt_polygon_* failed for genus %d", g);
  const double rm = hypot(mx, my), c = (1 + rm * rm) / (2 * rm), rad = c - rm;
  const double cx = c * mx / rm, cy = c * my / rm;
  const double a0 = atan2(ay - cy, ax - cx), a1 = atan2(by - cy, bx - cx);
  double da = a1 - a0;
  while (da > HDT_FUZZ_PI) da -= 2 * HDT_FUZZ_PI;
  while (da < -HDT_FUZZ_PI) da += 2 * HDT_FUZZ_PI;
  const double a = a0 + u * da;
  p.x = cx + rad * cos(a);
  p.y = cy + rad * sin(a);
  return p;
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
      p = side_point(g, k, u16(r) / 65535.0);
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
  /* Points very near the unit circle make every later predicate on their
     vertex expensive: only MAX_FAR of them per input, the others are pulled in. */
  if (in_open_disk(p.x, p.y) && p.x * p.x + p.y * p.y > 1 - 1e-6) {
    if (s->far_used < MAX_FAR) {
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

  if (hdt_vertex_count(t) >= SNAPSHOT_MAX_V) return;
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

static hdt_triangulation **slot_of(reader *r, state *s, int *slot) {
  *slot = u8(r) & 1;
  if (!s->t[*slot]) {
    const int g = 2 + *slot;
    const hdt_status c = hdt_create(&s->t[*slot], g);
    trace("hdt_create(&t%d, %d) = %d", *slot, g, (int)c);
    CHECK(c == HDT_OK && s->t[*slot], "hdt_create(genus %d): %s", g, st(c));
  }
  return &s->t[*slot];
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
  const int g = 2 + b % 5;
  hdt_destroy(s->t[slot]);
  s->t[slot] = NULL;
  trace("hdt_destroy(t%d)", slot);
  const hdt_status c = hdt_create(&s->t[slot], g);
  trace("hdt_create(&t%d, %d) = %d", slot, g, (int)c);
  CHECK(c == HDT_OK && s->t[slot], "hdt_create(genus %d): %s", g, st(c));
  CHECK(hdt_genus(s->t[slot]) == g, "hdt_genus: %d, created with %d", hdt_genus(s->t[slot]), g);
  CHECK(hdt_dummy_count(s->t[slot]) == hdt_vertex_count(s->t[slot]) &&
            hdt_vertex_id_bound(s->t[slot]) == hdt_vertex_count(s->t[slot]),
        "a new triangulation holds only its dummies");
  validate_now(s->t[slot], "hdt_create");
}

static void op_insert(reader *r, state *s) {
  int slot;
  hdt_triangulation *t = *slot_of(r, s, &slot);
  if (s->points_used >= MAX_POINTS) return;
  ++s->points_used;
  const point p = gen_point(r, s, slot);
  const int with_out = !(u8(r) & 0x10);
  const int inside = in_open_disk(p.x, p.y);
  snapshot before;
  take(&before, t);
  const size_t bound = hdt_vertex_id_bound(t), dummies = hdt_dummy_count(t);
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
    validate(s, t, "hdt_insert");
    if (with_out) {
      if (v < bound) {
        CHECK(before.valid == 0 || before.dummy[v] == 1, "hdt_insert: HDT_OK with the old vertex %u, not a dummy", v);
        CHECK(hdt_dummy_count(t) == dummies - 1 && hdt_vertex_id_bound(t) == bound,
              "hdt_insert: a dummy became a user vertex, but the counts say otherwise");
      } else {
        CHECK(v == bound && hdt_vertex_id_bound(t) == bound + 1, "hdt_insert: new vertex %u, id bound was %zu", v,
              bound);
      }
      check_inserted(s, t, p.x, p.y, v);
    }
  }
  snapshot_free(&before);
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
  snapshot before;
  take(&before, t);
  const size_t v0 = hdt_vertex_count(t);
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
    validate(s, t, "hdt_insert_many");
    CHECK(hdt_vertex_count(t) <= v0 + n, "hdt_insert_many of %zu points: %zu -> %zu vertices", n, v0,
          hdt_vertex_count(t));
    if (with_out)
      for (size_t i = 0; i < n; ++i) {
        /* Each answer is a live user vertex; check a few fully. */
        CHECK(hdt_vertex_is_dummy(t, vs[i]) == 0, "hdt_insert_many: vertices[%zu] = %u is no live user vertex", i,
              vs[i]);
        if (i < 4 || i == n - 1) check_inserted(s, t, xy[2 * i], xy[2 * i + 1], vs[i]);
      }
  }
  snapshot_free(&before);
  free(xy);
  free(vs);
}

static void op_remove(reader *r, state *s) {
  int slot;
  hdt_triangulation *t = *slot_of(r, s, &slot);
  const uint32_t v = gen_vertex(r, t);
  const int was = hdt_vertex_is_dummy(t, v);
  const size_t n = hdt_vertex_count(t), d = hdt_dummy_count(t), bound = hdt_vertex_id_bound(t);
  snapshot before;
  take(&before, t);
  const hdt_status st_ = hdt_remove_vertex(t, v);
  trace("hdt_remove_vertex(t%d, %u) = %d", slot, v, (int)st_);
  no_internal(st_, "hdt_remove_vertex");
  if (was < 0) CHECK(st_ == HDT_EINVAL, "hdt_remove_vertex(%u), no live vertex: %s", v, st(st_));
  else CHECK(st_ == HDT_OK || st_ == HDT_ENOTSUP, "hdt_remove_vertex(%u), live: %s", v, st(st_));
  if (st_ != HDT_OK) {
    expect_unchanged(&before, t, "hdt_remove_vertex");
  } else {
    validate(s, t, "hdt_remove_vertex");
    CHECK(hdt_vertex_count(t) == n - 1 && hdt_dummy_count(t) == d - (size_t)(was == 1) &&
              hdt_vertex_id_bound(t) == bound && hdt_vertex_is_dummy(t, v) == -1,
          "hdt_remove_vertex(%u): counts after removal", v);
    double x, y;
    CHECK(hdt_vertex_point(t, v, &x, &y) == HDT_EINVAL, "hdt_vertex_point of the removed vertex %u", v);
  }
  snapshot_free(&before);
}

static void op_remove_dummies(reader *r, state *s) {
  int slot;
  hdt_triangulation *t = *slot_of(r, s, &slot);
  const int with_out = u8(r) & 1;
  const size_t n = hdt_vertex_count(t), d = hdt_dummy_count(t);
  size_t left = SIZE_MAX;
  const hdt_status st_ = hdt_remove_dummies(t, with_out ? &left : NULL);
  trace("hdt_remove_dummies(t%d, %s) = %d, %zu left", slot, with_out ? "&left" : "NULL", (int)st_, left);
  no_internal(st_, "hdt_remove_dummies");
  CHECK(st_ == HDT_OK, "hdt_remove_dummies: %s", st(st_));
  validate(s, t, "hdt_remove_dummies");
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
  if (st_ == HDT_OK) {
    CHECK(in_open_disk(x, y), "vertex %u at (%a, %a), outside the disk", v, x, y);
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
  } else if (!(b & 3)) {
    CHECK(isnan(x) && isnan(y), "hdt_vertex_point failed but wrote its outputs");
  }
}

/* The functions without a handle: words, matrices, the polygon. */
static void op_words(reader *r, state *s) {
  (void)s;
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
  if (valid_g && g <= 8) {
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
                            hdt_translation_word(NULL, 0, NULL, 0, &n),
                            hdt_translation_matrix(NULL, 0, m),
                            hdt_locate(NULL, 0, 0, &n, &tr),
                            hdt_nearest_vertex(NULL, 0, 0, &v),
                            hdt_validate(NULL)};
  for (size_t i = 0; i < sizeof got / sizeof got[0]; ++i)
    CHECK(got[i] == HDT_EINVAL, "call %zu of the NULL-handle list: %s", i, st(got[i]));
  CHECK(v == 7 && n == 7 && tr == 7, "a call on a NULL handle wrote an output");
  hdt_destroy(NULL);
}

typedef void (*op_fn)(reader *, state *);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  static const op_fn ops[] = {
      op_create,         op_insert, op_insert, op_insert,      op_insert,   op_insert_many, op_insert_many,
      op_remove,         op_remove, op_remove, op_remove_dummies, op_locate, op_locate,    op_faces,
      op_translation,    op_vertex, op_words,  op_null,
  };
  if (trace_on < 0) {
    const char *e = getenv("HDT_FUZZ_TRACE");
    trace_on = e != NULL && *e != '\0' && *e != '0';
  }
  reader r = {data, size, 0};
  state s;
  memset(&s, 0, sizeof s);
  const int g = 2 + u8(&r) % 5;
  const hdt_status c = hdt_create(&s.t[0], g);
  trace("hdt_create(&t0, %d) = %d", g, (int)c);
  CHECK(c == HDT_OK, "hdt_create(genus %d): %s", g, st(c));
  for (op_index = 0; op_index < MAX_OPS && !r.empty && r.n > 0; ++op_index) {
    const uint8_t k = u8(&r);
    trace("/* op %u: kind %u */", op_index, k % (unsigned)(sizeof ops / sizeof ops[0]));
    ops[k % (sizeof ops / sizeof ops[0])](&r, &s);
  }
  for (int i = 0; i < SLOTS; ++i) {
    if (s.t[i]) validate_now(s.t[i], "the last operation");
    hdt_destroy(s.t[i]);
  }
  return 0;
}
