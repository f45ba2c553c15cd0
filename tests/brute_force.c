/* The brute-force Delaunay method of brute_force.h (the why is there). */
#include "brute_force.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Relative margin below which a determinant counts as zero. The images carry
   errors near 1e-14; the margin is far above that and far below what random
   points produce. */
#define AMBIGUOUS 1e-10

/* Out of memory in a test helper: nothing sensible to report. */
static void *need(void *p) {
  if (!p) abort();
  return p;
}

/* Formats a message into msg and returns `code` (for `return fail(...)`). */
static int fail(int code, char *msg, size_t size, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, size, fmt, ap);
  va_end(ap);
  return code;
}

/* ---- The neighbour set: words and matrices ---- */

int bf_nset_make(bf_nset *n, int g, char *msg, size_t size) {
  memset(n, 0, sizeof *n);
  n->g = g;
  hdt_status s = hdt_neighbour_count(g, &n->count);
  if (s != HDT_OK) return fail(BF_BROKEN, msg, size, "hdt_neighbour_count(%d): %s", g, hdt_last_error_message());
  n->start = need(calloc(n->count + 1, sizeof *n->start));
  n->m = need(calloc(n->count, sizeof *n->m));
  size_t cap = 16 * n->count, used = 0;
  n->letters = need(malloc(cap * sizeof *n->letters));
  for (size_t id = 0; id < n->count; ++id) {
    size_t len = 0;
    s = hdt_neighbour_word(g, id, NULL, 0, &len);
    if (s != HDT_OK)
      return fail(BF_BROKEN, msg, size, "hdt_neighbour_word(%d, %zu): %s", g, id, hdt_last_error_message());
    if (used + len > cap) {
      cap = 2 * (used + len);
      n->letters = need(realloc(n->letters, cap * sizeof *n->letters));
    }
    s = hdt_neighbour_word(g, id, n->letters + used, len, &len);
    if (s != HDT_OK)
      return fail(BF_BROKEN, msg, size, "hdt_neighbour_word(%d, %zu): %s", g, id, hdt_last_error_message());
    s = hdt_word_matrix(g, n->letters + used, len, n->m[id]);
    if (s != HDT_OK) return fail(BF_BROKEN, msg, size, "hdt_word_matrix(genus %d): %s", g, hdt_last_error_message());
    used += len;
    n->start[id + 1] = used;
  }
  return 0;
}

void bf_nset_free(bf_nset *n) {
  free(n->start);
  free(n->letters);
  free(n->m);
  memset(n, 0, sizeof *n);
}

const int32_t *bf_nset_word(const bf_nset *n, size_t id, size_t *len) {
  *len = n->start[id + 1] - n->start[id];
  return n->letters + n->start[id];
}

long bf_nset_find(const bf_nset *n, const int32_t *w, size_t len) {
  for (size_t id = 0; id < n->count; ++id) {
    size_t l;
    const int32_t *x = bf_nset_word(n, id, &l);
    if (l == len && (len == 0 || memcmp(x, w, len * sizeof *w) == 0)) return (long)id;
  }
  return -1;
}

/* ---- Geometry in long double ---- */

/* f(z) = (a z + b) / (conj(b) z + conj(a)) for m = (Re a, Im a, Re b, Im b). */
static void mobius(const double m[4], long double x, long double y, long double *ox, long double *oy) {
  const long double ar = m[0], ai = m[1], br = m[2], bi = m[3];
  const long double nr = ar * x - ai * y + br, ni = ar * y + ai * x + bi;
  const long double dr = br * x + bi * y + ar, di = br * y - bi * x - ai;
  const long double d2 = dr * dr + di * di;
  *ox = (nr * dr + ni * di) / d2;
  *oy = (ni * dr - nr * di) / d2;
}

/* u(z, w) = |z - w|^2 / ((1 - |z|^2)(1 - |w|^2)); cosh d(z, w) = 1 + 2u. */
static long double u_dist(long double zx, long double zy, long double wx, long double wy) {
  const long double dx = zx - wx, dy = zy - wy;
  return (dx * dx + dy * dy) / ((1 - zx * zx - zy * zy) * (1 - wx * wx - wy * wy));
}

typedef struct image_t {
  uint32_t v;         /* vertex id */
  int32_t h;          /* translation id in N */
  long double x, y;   /* h(representative of v) */
  long double u;      /* u-distance to the current corner a */
} image_t;

static int by_u(const void *p, const void *q) {
  const image_t *a = p, *b = q;
  return (a->u > b->u) - (a->u < b->u);
}

/* ---- Faces in normal form ---- */

/* (v0, t0, v1, t1, v2, t2) counterclockwise, v0 the smallest id. */
typedef struct face_t {
  int64_t c[6];
} face_t;

static int face_cmp(const void *p, const void *q) {
  const face_t *a = p, *b = q;
  for (int i = 0; i < 6; ++i)
    if (a->c[i] != b->c[i]) return a->c[i] < b->c[i] ? -1 : 1;
  return 0;
}

static face_t face_normal(const uint32_t v[3], const int32_t t[3]) {
  int s = 0;
  for (int i = 1; i < 3; ++i)
    if (v[i] < v[s]) s = i;
  face_t f;
  for (int i = 0; i < 3; ++i) {
    f.c[2 * i] = v[(s + i) % 3];
    f.c[2 * i + 1] = t[(s + i) % 3];
  }
  return f;
}

static const char *face_str(const face_t *f, char *buf, size_t size) {
  snprintf(buf, size, "(%lld h%lld, %lld h%lld, %lld h%lld)", (long long)f->c[0], (long long)f->c[1],
           (long long)f->c[2], (long long)f->c[3], (long long)f->c[4], (long long)f->c[5]);
  return buf;
}

typedef struct face_list {
  face_t *f;
  size_t n, cap;
} face_list;

static void face_push(face_list *l, face_t f) {
  if (l->n == l->cap) {
    l->cap = l->cap ? 2 * l->cap : 256;
    l->f = need(realloc(l->f, l->cap * sizeof *l->f));
  }
  l->f[l->n++] = f;
}

static int face_in(const face_list *sorted, const face_t *f) {
  return sorted->n > 0 && bsearch(f, sorted->f, sorted->n, sizeof *f, face_cmp) != NULL;
}

/* ---- The brute force ---- */

typedef struct brute_t {
  face_list strict, weak;
  size_t ambiguous; /* candidate triangles with an undecided test */
  long double min_u;
  uint32_t closest[2];
} brute_t;

/* Sign of the in-circle test of d against the counterclockwise a, b, c, in
   coordinates relative to a: +1 inside, -1 outside, 0 ambiguous. */
static int in_circle(long double bx, long double by, long double cx, long double cy, long double dx, long double dy) {
  const long double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy, d2 = dx * dx + dy * dy;
  /* det of the rows (b, |b|^2), (c, |c|^2), (d, |d|^2) is negative when d is inside. */
  const long double det = bx * (cy * d2 - c2 * dy) - by * (cx * d2 - c2 * dx) + b2 * (cx * dy - cy * dx);
  const long double per = fabsl(bx) * (fabsl(cy) * d2 + c2 * fabsl(dy)) + fabsl(by) * (fabsl(cx) * d2 + c2 * fabsl(dx)) +
                          b2 * (fabsl(cx * dy) + fabsl(cy * dx));
  if (fabsl(det) <= AMBIGUOUS * per) return 0;
  return det < 0 ? 1 : -1;
}

/* All Delaunay faces whose smallest vertex id `a` sits at its representative,
   from the images `im` (every vertex under every element of N). */
static void brute_corner(int g, uint32_t a, long double ax, long double ay, const image_t *im, size_t nim,
                         image_t *near, brute_t *out) {
  const long double c = cosl(acosl(-1.0L) / (2 * g)); /* u-distance of sys/2 */
  const long double reach = c * (1 + 1e-9L);
  size_t nn = 0;
  for (size_t i = 0; i < nim; ++i) {
    if (im[i].v == a && im[i].h == 0) continue;
    const long double u = u_dist(ax, ay, im[i].x, im[i].y);
    if (u <= reach) {
      near[nn] = im[i];
      near[nn].u = u;
      ++nn;
      if (u < out->min_u) {
        out->min_u = u;
        out->closest[0] = a, out->closest[1] = im[i].v;
      }
    }
  }
  /* The nearest first: they are the likeliest to fall inside a circle. */
  qsort(near, nn, sizeof *near, by_u);
  for (size_t i = 0; i < nn; ++i) {
    if (near[i].v < a) continue;
    for (size_t j = i + 1; j < nn; ++j) {
      if (near[j].v < a) continue;
      if (u_dist(near[i].x, near[i].y, near[j].x, near[j].y) > reach) continue;
      long double bx = near[i].x - ax, by = near[i].y - ay, cx = near[j].x - ax, cy = near[j].y - ay;
      const long double orient = bx * cy - by * cx;
      if (fabsl(orient) <= 1e-18L * (fabsl(bx * cy) + fabsl(by * cx))) continue; /* collinear: no circle */
      size_t ib = i, ic = j;
      if (orient < 0) { /* counterclockwise: a, b, c */
        ib = j, ic = i;
        long double tx = bx, ty = by;
        bx = cx, by = cy, cx = tx, cy = ty;
      }
      /* Euclidean circumcircle. */
      const long double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy, d = 2 * (bx * cy - by * cx);
      const long double ox = ax + (cy * b2 - by * c2) / d, oy = ay + (bx * c2 - cx * b2) / d;
      const long double rho2 = (ox - ax) * (ox - ax) + (oy - ay) * (oy - ay);
      const long double s2 = ox * ox + oy * oy;
      /* Inside the disk, and hyperbolic diameter < sys/2:
         4 rho^2 < cos(pi/2g) ((1 - s^2 - rho^2)^2 - 4 s^2 rho^2) (the
         circumdiameter bound sys/2 written in the Euclidean centre s and radius rho). */
      const long double w = 1 - s2 - rho2;
      if (w <= 0) continue;
      const long double bracket = w * w - 4 * s2 * rho2;
      if (bracket <= 0) continue;
      const long double lhs = 4 * rho2, rhs = c * bracket;
      if (lhs > rhs * (1 + 1e-9L)) continue;
      int ambiguous = lhs >= rhs * (1 - 1e-9L);
      int empty = 1;
      for (size_t k = 0; k < nn && empty; ++k) {
        if (k == ib || k == ic) continue;
        const int s = in_circle(bx, by, cx, cy, near[k].x - ax, near[k].y - ay);
        if (s > 0) empty = 0;
        if (s == 0) ambiguous = 1;
      }
      if (!empty) continue;
      const uint32_t v[3] = {a, near[ib].v, near[ic].v};
      const int32_t t[3] = {0, near[ib].h, near[ic].h};
      face_t f;
      for (int q = 0; q < 3; ++q) f.c[2 * q] = v[q], f.c[2 * q + 1] = t[q];
      face_push(&out->weak, f);
      if (ambiguous)
        ++out->ambiguous;
      else
        face_push(&out->strict, f);
    }
  }
}

typedef struct vertex_set {
  size_t n;
  uint32_t *id;
  double *x, *y;
  size_t dummies;
} vertex_set;

static void vertex_set_free(vertex_set *s) {
  free(s->id);
  free(s->x);
  free(s->y);
}

/* The live vertices and their representatives (hdt_vertex_point). */
static int live_vertices(const hdt_triangulation *t, vertex_set *s, char *msg, size_t size) {
  memset(s, 0, sizeof *s);
  const size_t bound = hdt_vertex_id_bound(t);
  s->id = need(malloc(bound * sizeof *s->id + 1));
  s->x = need(malloc(bound * sizeof *s->x + 1));
  s->y = need(malloc(bound * sizeof *s->y + 1));
  for (uint32_t v = 0; v < bound; ++v) {
    const int dummy = hdt_vertex_is_dummy(t, v);
    if (dummy < 0) continue;
    const hdt_status st = hdt_vertex_point(t, v, &s->x[s->n], &s->y[s->n]);
    if (st != HDT_OK)
      return fail(BF_BROKEN, msg, size, "hdt_vertex_point(%u) of a live vertex: %s", v, hdt_last_error_message());
    s->id[s->n++] = v;
    s->dummies += (size_t)dummy;
  }
  if (s->n != hdt_vertex_count(t))
    return fail(BF_BROKEN, msg, size, "%zu live ids, hdt_vertex_count says %zu", s->n, hdt_vertex_count(t));
  if (s->dummies != hdt_dummy_count(t))
    return fail(BF_BROKEN, msg, size, "%zu dummy ids, hdt_dummy_count says %zu", s->dummies, hdt_dummy_count(t));
  return 0;
}

static brute_t brute_force(const bf_nset *ns, const vertex_set *vs) {
  brute_t b = {{NULL, 0, 0}, {NULL, 0, 0}, 0, INFINITY, {0, 0}};
  const size_t nim = vs->n * ns->count;
  image_t *im = need(malloc(nim * sizeof *im + 1)), *near = need(malloc(nim * sizeof *near + 1));
  for (size_t i = 0; i < vs->n; ++i)
    for (size_t h = 0; h < ns->count; ++h) {
      image_t *p = &im[i * ns->count + h];
      p->v = vs->id[i];
      p->h = (int32_t)h;
      mobius(ns->m[h], vs->x[i], vs->y[i], &p->x, &p->y);
    }
  for (size_t i = 0; i < vs->n; ++i) brute_corner(ns->g, vs->id[i], vs->x[i], vs->y[i], im, nim, near, &b);
  free(im);
  free(near);
  if (b.strict.n) qsort(b.strict.f, b.strict.n, sizeof *b.strict.f, face_cmp);
  if (b.weak.n) qsort(b.weak.f, b.weak.n, sizeof *b.weak.f, face_cmp);
  return b;
}

/* The library's faces in normal form, sorted. */
static int library_faces(const hdt_triangulation *t, face_list *l, char *msg, size_t size) {
  memset(l, 0, sizeof *l);
  size_t n = 0;
  hdt_status s = hdt_faces(t, NULL, NULL, 0, &n);
  if (s != HDT_OK) return fail(BF_BROKEN, msg, size, "hdt_faces(capacity 0): %s", hdt_status_string(s));
  uint32_t *v = need(malloc(3 * n * sizeof *v + 1));
  int32_t *tr = need(malloc(3 * n * sizeof *tr + 1));
  size_t got = 0;
  s = hdt_faces(t, v, tr, n, &got);
  if (s == HDT_OK && got == n)
    for (size_t f = 0; f < n; ++f) face_push(l, face_normal(&v[3 * f], &tr[3 * f]));
  free(v);
  free(tr);
  if (s != HDT_OK || got != n)
    return fail(BF_BROKEN, msg, size, "hdt_faces: %s, %zu faces of %zu", hdt_status_string(s), got, n);
  if (l->n) qsort(l->f, l->n, sizeof *l->f, face_cmp);
  return 0;
}

/* The checks of bf_cross_check on computed lists. */
static int compare(const bf_nset *ns, const hdt_triangulation *t, const vertex_set *vs, const face_list *lib,
                   const brute_t *bf, char *msg, size_t size) {
  const int g = ns->g;
  char b1[128], b2[128];
  const size_t expected = 2 * (vs->n + 2 * (size_t)g - 2);
  if (hdt_face_count(t) != expected)
    return fail(BF_BROKEN, msg, size, "hdt_face_count %zu, expected 2 (V + 2g - 2) = %zu", hdt_face_count(t), expected);
  if (lib->n != expected) return fail(BF_BROKEN, msg, size, "hdt_faces gave %zu faces, expected %zu", lib->n, expected);
  for (size_t i = 0; i < lib->n; ++i) {
    const face_t *f = &lib->f[i];
    if (i > 0 && face_cmp(&lib->f[i - 1], f) == 0)
      return fail(BF_BROKEN, msg, size, "face %s listed twice", face_str(f, b1, sizeof b1));
    if (f->c[1] != 0)
      return fail(BF_BROKEN, msg, size, "face %s: smallest vertex not at translation 0", face_str(f, b1, sizeof b1));
    for (int q = 1; q < 3; ++q)
      if (f->c[2 * q + 1] < 0 || (size_t)f->c[2 * q + 1] >= ns->count)
        return fail(BF_BROKEN, msg, size, "face %s uses translation %lld outside N (|N| = %zu)",
                    face_str(f, b1, sizeof b1), (long long)f->c[2 * q + 1], ns->count);
  }
  /* Every face the brute force finds without doubt is a library face ... */
  for (size_t i = 0; i < bf->strict.n; ++i)
    if (!face_in(lib, &bf->strict.f[i]))
      return fail(BF_DIFFERS, msg, size, "Delaunay face %s (brute force, %zu vertices) missing from hdt_faces",
                  face_str(&bf->strict.f[i], b1, sizeof b1), vs->n);
  /* ... and every library face has an empty circle. */
  for (size_t i = 0; i < lib->n; ++i)
    if (!face_in(&bf->weak, &lib->f[i]))
      return fail(BF_DIFFERS, msg, size,
                  "face %s of hdt_faces is not Delaunay by brute force (%zu vertices; first brute face %s)",
                  face_str(&lib->f[i], b1, sizeof b1), vs->n,
                  bf->weak.n ? face_str(&bf->weak.f[0], b2, sizeof b2) : "-");
  if (bf->ambiguous == 0 && bf->strict.n != lib->n)
    return fail(BF_DIFFERS, msg, size, "brute force found %zu faces, hdt_faces %zu", bf->strict.n, lib->n);
  return 0;
}

int bf_cross_check(const bf_nset *ns, const hdt_triangulation *t, bf_outcome *out, char *msg, size_t size) {
  memset(out, 0, sizeof *out);
  out->min_u = INFINITY;
  vertex_set vs;
  face_list lib = {NULL, 0, 0};
  int bad = live_vertices(t, &vs, msg, size) || library_faces(t, &lib, msg, size);
  if (!bad) {
    brute_t bf = brute_force(ns, &vs);
    out->vertices = vs.n;
    out->faces = lib.n;
    out->ambiguous = bf.ambiguous;
    out->min_u = (double)bf.min_u;
    out->closest[0] = bf.closest[0], out->closest[1] = bf.closest[1];
    bad = compare(ns, t, &vs, &lib, &bf, msg, size);
    free(bf.strict.f);
    free(bf.weak.f);
  }
  free(lib.f);
  vertex_set_free(&vs);
  return bad;
}
