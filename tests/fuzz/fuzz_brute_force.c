/* libFuzzer target: differential test of small triangulations. From the
 * input it builds a small point set on M_g (genus 2 or 3 mostly, at most
 * MAX_POINTS points, many of them nasty: symmetric, cocircular, on and near
 * the sides of F_g, the polygon's vertices and side midpoints, near the unit
 * circle, exact duplicates, dummy points, close pairs), triangulates it
 * through the C API (hdt_insert_many and/or hdt_insert, then maybe
 * hdt_remove_vertex and hdt_remove_dummies), and compares the faces with the
 * independent brute-force method of tests/brute_force.h. A finding:
 *
 *   - a call fails where the header promises success, or crashes, or a
 *     sanitizer reports;
 *   - hdt_validate is not HDT_OK;
 *   - bf_cross_check says BF_BROKEN (counts, repeated faces, translations
 *     outside N), or BF_DIFFERS (the faces are not the brute force's
 *     Delaunay faces) while the vertices are far enough apart for the brute
 *     force's margins (bf_outcome.min_u >= MIN_U; see compare for closer
 *     ones).
 *
 * HDT_FUZZ_TRACE=1 prints the C calls and what each comparison saw;
 * HDT_FUZZ_STATS=1 prints at exit how many comparisons were exact
 * equalities, sandwiches (cocircular candidates) or left out (close vertices).
 *
 * Input format: byte 0 picks the genus and how the points go in (see
 * read_header); then records, each a kind byte and its arguments (see
 * read_record); missing bytes read as 0 and end the input. make_seeds.py
 * writes the seeds (corpus-brute-force/). */
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "brute_force.h"
#include "fuzz_points.h"
#include "fuzz_reader.h"
#include "hdt.h"

/* Small sets keep an input at tens of milliseconds under ASan: the brute
   force (|N| = 49 images per vertex in genus 2, 121 in genus 3, 225 in
   genus 4) takes a few, the library's calls on nasty points the rest. */
enum {
  MAX_POINTS = 20,  /* points per input */
  MAX_REMOVALS = 4, /* hdt_remove_vertex calls per input */
  MAX_FAR = 1,      /* points with |z|^2 > 1 - 1e-6 per input (each call on them costs ~50 ms) */
  MAX_RECORDS = 64,
};

/* Below this u-distance between two vertices (hyperbolic distance ~2e-4,
   Euclidean ~5e-5 in F_g) the brute force's determinants, on images carrying
   errors near 1e-14, may round beyond its margin of 1e-10. */
#define MIN_U 1e-8

/* ---- Reporting ---- */

static int trace_on = -1;

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
  fprintf(stderr, "\nfuzz_brute_force: finding: ");
  va_start(ap, fmt);
  vfprintf(stderr, fmt, ap);
  va_end(ap);
  fprintf(stderr, "\n  last error message: \"%s\"\n", hdt_last_error_message());
  abort();
}

static const char *st(hdt_status s) { return hdt_status_string(s); }

static struct {
  unsigned long exact, sandwich, close;
} stats;

static void print_stats(void) {
  fprintf(stderr, "fuzz_brute_force: %lu comparisons exact, %lu up to cocircular candidates, %lu left out "
          "(vertices closer than u = %g)\n", stats.exact, stats.sandwich, stats.close, MIN_U);
}

/* ---- The point set ---- */

typedef struct input {
  int g;
  int mode;          /* 0 insert_many, 1 insert, 2 half and half, 3 insert in reverse order */
  int drop_dummies;  /* hdt_remove_dummies at the end */
  int compare_early; /* compare after the insertions too */
  point p[MAX_POINTS];
  size_t n;
  size_t removals[MAX_REMOVALS]; /* indices into p */
  size_t n_removals;
  unsigned far;
  const hdt_triangulation *fresh; /* for the dummies' points */
} input;

static void add(input *in, point p) {
  if (in->n >= MAX_POINTS || !in_open_disk(p.x, p.y)) return;
  if (p.x * p.x + p.y * p.y > 1 - 1e-6) {
    if (in->far >= MAX_FAR) return;
    ++in->far;
  }
  in->p[in->n++] = p;
}

static void perturb(reader *r, point *p) {
  const uint8_t b = u8(r);
  if (b & 0x80) return; /* half the time: as computed */
  p->x = ulps(p->x, (int)(b & 7) - 4);
  p->y = ulps(p->y, (int)((b >> 3) & 7) - 4);
}

/* p moved a few ulps, or 2^-8 .. 2^-12 away: a point a few ulps from a
   dummy vertex is too close to it for the brute force (see compare), one
   2^-12 away is not. */
static void perturb_or_move(reader *r, point *p) {
  const uint8_t b = u8(r);
  if (b & 0x40) {
    const double a = (b & 7) * (2 * HDT_FUZZ_PI / 8), dist = ldexp(1, -8 - ((b >> 3) & 7) % 5);
    p->x += dist * cos(a);
    p->y += dist * sin(a);
  } else if (!(b & 0x80)) {
    p->x = ulps(p->x, (int)(b & 7) - 4);
    p->y = ulps(p->y, (int)((b >> 3) & 7) - 4);
  }
}

/* A point at hyperbolic distance up to F_g's circumradius from 0, uniform
   for area (as test_brute_force's random points). */
static point spread(int g, uint16_t radius, uint16_t angle) {
  double vx, vy;
  hdt_polygon_vertex(g, 0, &vx, &vy);
  const double rv2 = vx * vx + vy * vy, cosh_max = (1 + rv2) / (1 - rv2);
  const double ch = 1 + radius / 65536.0 * (cosh_max - 1), r = sqrt((ch - 1) / (ch + 1));
  const double a = angle * (2 * HDT_FUZZ_PI / 65536);
  return (point){r * cos(a), r * sin(a)};
}

/* Byte 0: the genus (2 for 4 values of 8, 3 for 3, 4 for 1), how the points
   go in, whether the dummies go and whether to compare before the removals. */
static void read_header(reader *r, input *in) {
  const uint8_t b = u8(r);
  static const int genus[8] = {2, 2, 2, 2, 3, 3, 3, 4};
  in->g = genus[b & 7];
  in->mode = (b >> 3) & 3;
  in->drop_dummies = (b >> 5) & 1;
  in->compare_early = (b >> 6) & 1;
}

static void read_record(reader *r, input *in) {
  const int g = in->g;
  const uint8_t kind = u8(r) % 11;
  point p = {0, 0};
  switch (kind) {
    case 0: { /* anywhere */
      const uint16_t radius = u16(r);
      add(in, spread(g, radius, u16(r)));
      break;
    }
    case 1: { /* a dyadic grid: many exactly cocircular and collinear sets */
      const int8_t x = (int8_t)u8(r);
      p = (point){x / 128.0, (int8_t)u8(r) / 128.0};
      add(in, p);
      break;
    }
    case 2: { /* images under the polygon's exact symmetries: rotations by
                 quarter turns and reflections in the axes and diagonals */
      const int8_t x = (int8_t)u8(r);
      const double a = x / 128.0, c = (int8_t)u8(r) / 128.0;
      const uint8_t mask = u8(r);
      const point img[8] = {{a, c}, {-c, a}, {-a, -c}, {c, -a}, {a, -c}, {-a, c}, {c, a}, {-c, -a}};
      for (int i = 0; i < 8; ++i)
        if (mask & (1u << i)) add(in, img[i]);
      break;
    }
    case 3: { /* on one Euclidean (so hyperbolic) circle, rounded */
      const int8_t cx = (int8_t)u8(r), cy = (int8_t)u8(r);
      const double rad = 0.02 + u8(r) / 512.0;
      const int m = 3 + u8(r) % 4;
      for (int i = 0; i < m; ++i) {
        const double a = u8(r) * (2 * HDT_FUZZ_PI / 256);
        add(in, (point){cx / 256.0 + rad * cos(a), cy / 256.0 + rad * sin(a)});
      }
      break;
    }
    case 4: { /* on a side of F_g, a few ulps off */
      const int k = u8(r);
      if (side_point(g, k, u16(r) / 65535.0, &p)) {
        perturb(r, &p);
        add(in, p);
      }
      break;
    }
    case 5: { /* a vertex or a side midpoint of F_g (a dummy sits there), nearby */
      const uint8_t b = u8(r);
      const hdt_status s = (b & 1) ? hdt_polygon_vertex(g, b >> 1, &p.x, &p.y)
                                   : hdt_polygon_side_midpoint(g, b >> 1, &p.x, &p.y);
      if (s == HDT_OK) {
        perturb_or_move(r, &p);
        add(in, p);
      }
      break;
    }
    case 6: { /* near the unit circle (one per input) */
      static const double radii[] = {0.99999999999999989, 1 - 2.220446049250313e-16, 1 - 1e-15, 1 - 1e-12,
                                     1 - 1e-9, 1 - 1e-6, 0.999, 0.99};
      const double a = u16(r) * (2 * HDT_FUZZ_PI / 65536), rad = radii[u8(r) % (sizeof radii / sizeof radii[0])];
      p = (point){rad * cos(a), rad * sin(a)};
      perturb(r, &p);
      add(in, p);
      break;
    }
    case 7: /* an exact duplicate of an earlier point */
      if (in->n > 0) add(in, in->p[u8(r) % in->n]);
      break;
    case 8: { /* a dummy vertex's point (rounded: a new vertex next to the dummy), or nearby */
      const size_t d = hdt_dummy_count(in->fresh);
      if (d > 0 && hdt_vertex_point(in->fresh, (uint32_t)(u8(r) % d), &p.x, &p.y) == HDT_OK) {
        perturb_or_move(r, &p);
        add(in, p);
      }
      break;
    }
    case 9: /* next to an earlier point, 2^-6 .. 2^-12 away */
      if (in->n > 0) {
        const point q = in->p[u8(r) % in->n];
        const uint8_t b = u8(r);
        const double a = (b >> 4) * (2 * HDT_FUZZ_PI / 16), dist = ldexp(1, -6 - (b & 15) % 7);
        add(in, (point){q.x + dist * cos(a), q.y + dist * sin(a)});
      }
      break;
    default: /* remove an earlier point's vertex after the insertions */
      if (in->n > 0 && in->n_removals < MAX_REMOVALS) in->removals[in->n_removals++] = u8(r) % in->n;
      break;
  }
}

/* ---- The comparison ---- */

static const bf_nset *nset(int g) {
  static bf_nset sets[8];
  static int made[8];
  if (!made[g]) {
    char msg[256];
    if (bf_nset_make(&sets[g], g, msg, sizeof msg) != 0) fail("the neighbour set of genus %d: %s", g, msg);
    made[g] = 1;
  }
  return &sets[g];
}

/* hdt_validate, then the brute force. Two vertices closer than MIN_U (a
   point next to a dummy, the same surface point given twice with different
   roundings ...) make the brute force unreliable: the newer user vertex of
   the pair goes (hdt_remove_vertex next to a near-duplicate: a nasty case
   of its own) and the comparison runs again; when that is refused (or
   after 8 removals) the faces are not compared. */
static void compare(hdt_triangulation *t, int g, const char *stage) {
  const hdt_status v = hdt_validate(t);
  trace("hdt_validate(t) = %d", (int)v);
  if (v != HDT_OK) fail("hdt_validate %s: %s", stage, st(v));
  bf_outcome o;
  char msg[1024];
  for (int tries = 0;; ++tries) {
    const int r = bf_cross_check(nset(g), t, &o, msg, sizeof msg);
    trace("/* %s: %zu vertices, %zu faces, %zu ambiguous candidates, min u %g (vertices %u, %u): %s */", stage,
          o.vertices, o.faces, o.ambiguous, o.min_u, o.closest[0], o.closest[1], r == BF_OK ? "the faces agree" : msg);
    if (r == BF_BROKEN || (r == BF_DIFFERS && o.min_u >= MIN_U))
      fail("%s (genus %d): %s (%zu vertices, %zu ambiguous candidates, min u %g)", stage, g, msg, o.vertices,
           o.ambiguous, o.min_u);
    if (o.min_u >= MIN_U) break;
    const uint32_t a = o.closest[0] > o.closest[1] ? o.closest[0] : o.closest[1];
    const uint32_t b = a == o.closest[0] ? o.closest[1] : o.closest[0];
    const uint32_t user = hdt_vertex_is_dummy(t, a) == 0 ? a : b;
    if (tries == 8 || hdt_vertex_is_dummy(t, user) != 0) break;
    const hdt_status s = hdt_remove_vertex(t, user);
    trace("hdt_remove_vertex(t, %u) = %d", user, (int)s);
    if (s == HDT_ENOTSUP) break;
    if (s != HDT_OK) fail("hdt_remove_vertex(%u), a live user vertex: %s", user, st(s));
    const hdt_status w = hdt_validate(t);
    trace("hdt_validate(t) = %d", (int)w);
    if (w != HDT_OK) fail("hdt_validate %s, after removing vertex %u next to vertex %u: %s", stage, user, b, st(w));
  }
  if (o.min_u < MIN_U) ++stats.close;
  else if (o.ambiguous) ++stats.sandwich;
  else ++stats.exact;
}

/* ---- The triangulation ---- */

static void insert_one(hdt_triangulation *t, const input *in, size_t i, uint32_t *ids) {
  const hdt_status s = hdt_insert(t, in->p[i].x, in->p[i].y, &ids[i]);
  trace("hdt_insert(t, %a, %a, &v) = %d, vertex %u", in->p[i].x, in->p[i].y, (int)s, ids[i]);
  if (s != HDT_OK && s != HDT_EEXISTS) fail("hdt_insert(%a, %a) in the disk: %s", in->p[i].x, in->p[i].y, st(s));
}

static void insert_many(hdt_triangulation *t, const input *in, size_t from, size_t n, uint32_t *ids) {
  double xy[2 * MAX_POINTS];
  for (size_t i = 0; i < n; ++i) xy[2 * i] = in->p[from + i].x, xy[2 * i + 1] = in->p[from + i].y;
  const hdt_status s = hdt_insert_many(t, xy, n, ids + from);
  if (trace_on) {
    trace("double xy[%zu] = {", 2 * n);
    for (size_t i = 0; i < n; ++i) trace("  %a, %a,", xy[2 * i], xy[2 * i + 1]);
    trace("};\nhdt_insert_many(t, xy, %zu, vs) = %d", n, (int)s);
  }
  if (s != HDT_OK) fail("hdt_insert_many of %zu points in the disk: %s", n, st(s));
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (trace_on < 0) {
    const char *e = getenv("HDT_FUZZ_TRACE");
    trace_on = e != NULL && *e != '\0' && *e != '0';
    e = getenv("HDT_FUZZ_STATS");
    if (e != NULL && *e != '\0' && *e != '0') atexit(print_stats);
  }
  reader r = {data, size, 0};
  input in;
  memset(&in, 0, sizeof in);
  read_header(&r, &in);
  hdt_triangulation *t = NULL;
  hdt_status s = hdt_create(&t, in.g);
  trace("hdt_create(&t, %d) = %d", in.g, (int)s);
  if (s != HDT_OK) fail("hdt_create(%d): %s", in.g, st(s));
  in.fresh = t;
  for (int k = 0; k < MAX_RECORDS && !r.empty && r.n > 0; ++k) read_record(&r, &in);

  uint32_t ids[MAX_POINTS];
  const size_t n = in.n, half = n / 2;
  switch (in.mode) {
    case 0: insert_many(t, &in, 0, n, ids); break;
    case 1:
      for (size_t i = 0; i < n; ++i) insert_one(t, &in, i, ids);
      break;
    case 2:
      insert_many(t, &in, 0, half, ids);
      for (size_t i = half; i < n; ++i) insert_one(t, &in, i, ids);
      break;
    default:
      for (size_t i = n; i-- > 0;) insert_one(t, &in, i, ids);
      break;
  }
  if (in.compare_early && (in.n_removals > 0 || in.drop_dummies)) compare(t, in.g, "after the insertions");

  for (size_t k = 0; k < in.n_removals; ++k) {
    const uint32_t v = ids[in.removals[k]];
    const int live = hdt_vertex_is_dummy(t, v) >= 0;
    s = hdt_remove_vertex(t, v);
    trace("hdt_remove_vertex(t, %u) = %d", v, (int)s);
    /* Two points may share a vertex, removed already. */
    if (live ? s != HDT_OK && s != HDT_ENOTSUP : s != HDT_EINVAL) fail("hdt_remove_vertex(%u): %s", v, st(s));
  }
  if (in.drop_dummies) {
    size_t left = 0;
    s = hdt_remove_dummies(t, &left);
    trace("hdt_remove_dummies(t, &left) = %d, %zu left", (int)s, left);
    if (s != HDT_OK) fail("hdt_remove_dummies: %s", st(s));
  }
  compare(t, in.g, "at the end");
  hdt_destroy(t);
  return 0;
}
