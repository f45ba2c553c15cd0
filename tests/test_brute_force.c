/* An independent cross-check of the triangulations: the Delaunay faces of a
 * small point set found by brute force over the images of the vertices under
 * the neighbour set N, compared with hdt_faces.
 *
 * Nothing here goes through the incremental code path: the only inputs taken
 * from the triangulation are its vertices' representatives (hdt_vertex_point),
 * and the group elements come from hdt_neighbour_word + hdt_word_matrix.
 *
 * Why N suffices: every face of the triangulation has hyperbolic
 * circumdiameter < sys/2 (the guarantee of the header), so its circumdisk
 * lies within distance sys/2 of its corner a in F_g, and the ball of radius
 * sys/2 about any point of F_g lies in D_N = union of h(F_g), h in N (checked
 * below by sampling). So the orbit points that can lie in such a disk are
 * exactly the N-images of the vertices.
 *
 * In-circle tests are Euclidean determinants on Poincare coordinates: a
 * hyperbolic circle is a Euclidean circle inside the disk, so the Euclidean
 * answer is the hyperbolic one. Decisions within a tiny relative margin of 0
 * are "ambiguous": the dummy points sit at symmetric positions (0, the
 * midpoints and vertex of F_g ...) and are cocircular, where any
 * triangulation of the cocircular polygon is Delaunay. So the check is
 *   strict  subset of  library faces  subset of  weak,
 * where strict = triangles with every other point clearly outside their
 * circle, weak = triangles with no point clearly inside; when nothing is
 * ambiguous the two sets coincide and the faces must equal them exactly. */
#include "hdt_test.h"

/* Relative margin below which a determinant counts as zero. The images carry
   errors near 1e-14; the margin is far above that and far below what random
   points produce. */
#define AMBIGUOUS 1e-10

/* ---- The neighbour set: words and matrices ---- */

typedef struct nset_t {
  int g;
  size_t count;
  word_t *words;  /* canonical words, by translation id */
  double (*m)[4]; /* SU(1,1) matrices, by translation id */
} nset_t;

static nset_t nset_make(int g) {
  nset_t n = {g, 0, NULL, NULL};
  ck_assert_int_eq(hdt_neighbour_count(g, &n.count), HDT_OK);
  n.words = calloc(n.count, sizeof *n.words);
  n.m = calloc(n.count, sizeof *n.m);
  ck_assert(n.words && n.m);
  for (size_t id = 0; id < n.count; ++id) {
    const hdt_status s = hdt_neighbour_word(g, id, n.words[id].a, TW_MAX, &n.words[id].n);
    expect(s == HDT_OK, "hdt_neighbour_word(%d, %zu): %s", g, id, hdt_last_error_message());
    word_matrix(g, &n.words[id], n.m[id]);
  }
  return n;
}

static void nset_free(nset_t *n) {
  free(n->words);
  free(n->m);
}

/* The translation id of the element with canonical word w, or -1. */
static long nset_find(const nset_t *n, const word_t *w) {
  for (size_t id = 0; id < n->count; ++id)
    if (word_eq(&n->words[id], w)) return (long)id;
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
    l->f = realloc(l->f, l->cap * sizeof *l->f);
    ck_assert_ptr_nonnull(l->f);
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
         4 rho^2 < cos(pi/2g) ((1 - s^2 - rho^2)^2 - 4 s^2 rho^2) (DESIGN.md). */
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

static vertex_set live_vertices(const hdt_triangulation *t) {
  vertex_set s = {0, NULL, NULL, NULL, 0};
  const size_t bound = hdt_vertex_id_bound(t);
  s.id = malloc(bound * sizeof *s.id);
  s.x = malloc(bound * sizeof *s.x);
  s.y = malloc(bound * sizeof *s.y);
  ck_assert(s.id && s.x && s.y);
  for (uint32_t v = 0; v < bound; ++v) {
    const int dummy = hdt_vertex_is_dummy(t, v);
    if (dummy < 0) continue;
    const hdt_status st = hdt_vertex_point(t, v, &s.x[s.n], &s.y[s.n]);
    expect(st == HDT_OK, "hdt_vertex_point(%u) of a live vertex: %s", v, hdt_last_error_message());
    s.id[s.n++] = v;
    s.dummies += (size_t)dummy;
  }
  expect(s.n == hdt_vertex_count(t), "%zu live ids, hdt_vertex_count says %zu", s.n, hdt_vertex_count(t));
  expect(s.dummies == hdt_dummy_count(t), "%zu dummy ids, hdt_dummy_count says %zu", s.dummies, hdt_dummy_count(t));
  return s;
}

static void vertex_set_free(vertex_set *s) {
  free(s->id);
  free(s->x);
  free(s->y);
}

static brute_t brute_force(const nset_t *ns, const vertex_set *vs) {
  brute_t b = {{NULL, 0, 0}, {NULL, 0, 0}, 0};
  const size_t nim = vs->n * ns->count;
  image_t *im = malloc(nim * sizeof *im), *near = malloc(nim * sizeof *near);
  ck_assert(im && near);
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
  qsort(b.strict.f, b.strict.n, sizeof *b.strict.f, face_cmp);
  qsort(b.weak.f, b.weak.n, sizeof *b.weak.f, face_cmp);
  return b;
}

/* The library's faces in normal form, sorted. */
static face_list library_faces(const hdt_triangulation *t) {
  size_t n = 0;
  ck_assert_int_eq(hdt_faces(t, NULL, NULL, 0, &n), HDT_OK);
  uint32_t *v = malloc(3 * n * sizeof *v + 1);
  int32_t *tr = malloc(3 * n * sizeof *tr + 1);
  ck_assert(v && tr);
  size_t got = 0;
  const hdt_status s = hdt_faces(t, v, tr, n, &got);
  expect(s == HDT_OK && got == n, "hdt_faces: %s, %zu faces of %zu", hdt_status_string(s), got, n);
  face_list l = {NULL, 0, 0};
  for (size_t f = 0; f < n; ++f) face_push(&l, face_normal(&v[3 * f], &tr[3 * f]));
  free(v);
  free(tr);
  qsort(l.f, l.n, sizeof *l.f, face_cmp);
  return l;
}

/* ---- The premise: balls of radius sys/2 about points of F lie in D_N ---- */

/* Every point p within sys/2 of a point a of F_g is h(rep) for some h in N:
   hdt_point_representative gives w with w(p) in F_g, so h = w^-1. */
START_TEST(half_systole_balls_lie_in_d_n) {
  uint64_t rng = 0x5eed;
  for (int g = 2; g <= 4; ++g) {
    nset_t ns = nset_make(g);
    const double sys = hdt_systole(g);
    double vx, vy;
    ck_assert_int_eq(hdt_polygon_vertex(g, 0, &vx, &vy), HDT_OK);
    const double rv = hypot(vx, vy);
    int tried = 0;
    while (tried < 600) {
      /* a: uniform in the disk of F's vertices, kept when in F; every third one
         just inside a vertex of F (on the ray from 0, F is star-shaped), where
         the ball reaches farthest out. */
      double ax, ay;
      if (tried % 3 == 0) {
        const double s = 1 - 1e-3 * (double)(rng_next(&rng) >> 11) * 0x1p-53;
        ck_assert_int_eq(hdt_polygon_vertex(g, rng_below(&rng, 4 * g), &ax, &ay), HDT_OK);
        ax *= s, ay *= s;
      } else {
        const double ang = 2 * acos(-1.0) * (double)(rng_next(&rng) >> 11) * 0x1p-53;
        const double r = rv * sqrt((double)(rng_next(&rng) >> 11) * 0x1p-53);
        ax = r * cos(ang), ay = r * sin(ang);
      }
      size_t len = 0;
      ck_assert_int_eq(hdt_point_representative(g, ax, ay, NULL, NULL, NULL, 0, &len), HDT_OK);
      if (len != 0) continue;
      ++tried;
      /* p at hyperbolic distance d < sys/2 from a: translate a point at
         Euclidean radius tanh(d/2) from 0 to a. */
      const double d = sys / 2 * (1 - 1e-6) * sqrt((double)(rng_next(&rng) >> 11) * 0x1p-53);
      const double phi = 2 * acos(-1.0) * (double)(rng_next(&rng) >> 11) * 0x1p-53;
      const double wx = tanh(d / 2) * cos(phi), wy = tanh(d / 2) * sin(phi);
      /* (w + a) / (1 + conj(a) w) */
      const double nr = wx + ax, ni = wy + ay, dr = 1 + ax * wx + ay * wy, di = ax * wy - ay * wx;
      const double px = (nr * dr + ni * di) / (dr * dr + di * di), py = (ni * dr - nr * di) / (dr * dr + di * di);
      word_t w = {0};
      const hdt_status s = hdt_point_representative(g, px, py, NULL, NULL, w.a, TW_MAX, &w.n);
      expect(s == HDT_OK, "hdt_point_representative: %s", hdt_last_error_message());
      const word_t inv = word_inverse(g, &w);
      const word_t h = reduce_word(g, &inv);
      char buf[512];
      expect(nset_find(&ns, &h) >= 0, "g=%d: p (%.17g, %.17g) at distance %g < sys/2 of a (%.17g, %.17g) in F lies in h(F), h = [%s] not in N",
             g, px, py, d, ax, ay, word_str(&h, buf, sizeof buf));
    }
    nset_free(&ns);
  }
}
END_TEST

/* The matrices the brute force uses agree with the triangulation's own
   table for ids 0..|N|-1 (hdt_translation_matrix). */
START_TEST(translation_ids_of_n_are_fixed) {
  for (int g = 2; g <= 3; ++g) {
    nset_t ns = nset_make(g);
    hdt_triangulation *t = NULL;
    ck_assert_int_eq(hdt_create(&t, g), HDT_OK);
    char b1[512], b2[512];
    for (size_t id = 0; id < ns.count; ++id) {
      double m[4];
      word_t w = {0};
      ck_assert_int_eq(hdt_translation_matrix(t, (int32_t)id, m), HDT_OK);
      expect(matrix_gap(m, ns.m[id]) < 1e-12, "g=%d id %zu: translation matrix differs from the word's", g, id);
      ck_assert_int_eq(hdt_translation_word(t, (int32_t)id, w.a, TW_MAX, &w.n), HDT_OK);
      expect(word_eq(&w, &ns.words[id]), "g=%d id %zu: translation word [%s], neighbour word [%s]", g, id,
             word_str(&w, b1, sizeof b1), word_str(&ns.words[id], b2, sizeof b2));
    }
    hdt_destroy(t);
    nset_free(&ns);
  }
}
END_TEST

/* ---- The cross-check ---- */

/* n random points uniform for hyperbolic area in F_g: uniform in the
   hyperbolic disk about 0 through F's vertices, kept when their
   representative is themselves. */
static void random_points_in_f(uint64_t *rng, int g, size_t n, double *xy) {
  double vx, vy;
  ck_assert_int_eq(hdt_polygon_vertex(g, 0, &vx, &vy), HDT_OK);
  const double rv = hypot(vx, vy);
  const double cosh_max = (1 + rv * rv) / (1 - rv * rv); /* cosh of the hyperbolic radius */
  for (size_t i = 0; i < n;) {
    const double u = (double)(rng_next(rng) >> 11) * 0x1p-53;
    const double ch = 1 + u * (cosh_max - 1);
    const double r = sqrt((ch - 1) / (ch + 1)); /* tanh(d/2) from cosh d */
    const double ang = 2 * acos(-1.0) * (double)(rng_next(rng) >> 11) * 0x1p-53;
    const double x = r * cos(ang), y = r * sin(ang);
    size_t len = 1;
    if (hdt_point_representative(g, x, y, NULL, NULL, NULL, 0, &len) != HDT_OK || len != 0) continue;
    xy[2 * i] = x, xy[2 * i + 1] = y;
    ++i;
  }
}

typedef struct tally_t {
  size_t runs, exact_runs, ambiguous_runs, ambiguous_generic_runs, generic_runs;
} tally_t;

/* Compares the brute force with the library on t; returns 1 when nothing was
   ambiguous (an exact equality check). */
static int cross_check(const nset_t *ns, const hdt_triangulation *t, const char *what) {
  const int g = ns->g;
  vertex_set vs = live_vertices(t);
  face_list lib = library_faces(t);
  brute_t bf = brute_force(ns, &vs);
  char b1[128], b2[128];
  const size_t expected = 2 * (vs.n + 2 * (size_t)g - 2);
  expect(hdt_face_count(t) == expected, "%s: hdt_face_count %zu, expected 2 (V + 2g - 2) = %zu", what,
         hdt_face_count(t), expected);
  expect(lib.n == expected, "%s: hdt_faces gave %zu faces, expected %zu", what, lib.n, expected);
  for (size_t i = 0; i < lib.n; ++i) {
    const face_t *f = &lib.f[i];
    expect(i == 0 || face_cmp(&lib.f[i - 1], f) != 0, "%s: face %s listed twice", what, face_str(f, b1, sizeof b1));
    expect(f->c[1] == 0, "%s: face %s: smallest vertex not at translation 0", what, face_str(f, b1, sizeof b1));
    for (int q = 1; q < 3; ++q)
      expect(f->c[2 * q + 1] >= 0 && (size_t)f->c[2 * q + 1] < ns->count,
             "%s: face %s uses translation %lld outside N (|N| = %zu)", what, face_str(f, b1, sizeof b1),
             (long long)f->c[2 * q + 1], ns->count);
  }
  /* Every face the brute force finds without doubt is a library face ... */
  for (size_t i = 0; i < bf.strict.n; ++i)
    expect(face_in(&lib, &bf.strict.f[i]), "%s: Delaunay face %s (brute force, %zu vertices) missing from hdt_faces",
           what, face_str(&bf.strict.f[i], b1, sizeof b1), vs.n);
  /* ... and every library face has an empty circle. */
  for (size_t i = 0; i < lib.n; ++i)
    expect(face_in(&bf.weak, &lib.f[i]),
           "%s: face %s of hdt_faces is not Delaunay by brute force (%zu vertices; first brute face %s)", what,
           face_str(&lib.f[i], b1, sizeof b1), vs.n, bf.weak.n ? face_str(&bf.weak.f[0], b2, sizeof b2) : "-");
  const int exact = bf.ambiguous == 0;
  if (exact) expect(bf.strict.n == lib.n, "%s: brute force found %zu faces, hdt_faces %zu", what, bf.strict.n, lib.n);
  free(lib.f);
  free(bf.strict.f);
  free(bf.weak.f);
  vertex_set_free(&vs);
  return exact;
}

static void run_cross_checks(int g, const size_t *sizes, size_t nsizes, int seeds, tally_t *tally) {
  nset_t ns = nset_make(g);
  for (int seed = 1; seed <= seeds; ++seed) {
    for (size_t si = 0; si < nsizes; ++si) {
      const size_t n = sizes[si];
      for (int remove = 0; remove <= 1; ++remove) {
        uint64_t rng = 0x9e3779b97f4a7c15ULL * (uint64_t)(1000 * g + 10 * seed + (int)si) + 1;
        double *xy = malloc(2 * n * sizeof *xy);
        uint32_t *ids = malloc(n * sizeof *ids);
        ck_assert(xy && ids);
        random_points_in_f(&rng, g, n, xy);
        hdt_triangulation *t = NULL;
        ck_assert_int_eq(hdt_create(&t, g), HDT_OK);
        /* Half through insert_many, half one by one. */
        const size_t half = n / 2;
        hdt_status s = hdt_insert_many(t, xy, half, ids);
        expect(s == HDT_OK, "insert_many: %s (%s)", hdt_status_string(s), hdt_last_error_message());
        for (size_t i = half; i < n; ++i) {
          s = hdt_insert(t, xy[2 * i], xy[2 * i + 1], &ids[i]);
          expect(s == HDT_OK, "insert (%.17g, %.17g): %s (%s)", xy[2 * i], xy[2 * i + 1], hdt_status_string(s),
                 hdt_last_error_message());
        }
        size_t remaining = hdt_dummy_count(t);
        if (remove) {
          s = hdt_remove_dummies(t, &remaining);
          expect(s == HDT_OK, "remove_dummies: %s (%s)", hdt_status_string(s), hdt_last_error_message());
        }
        char what[128];
        snprintf(what, sizeof what, "g=%d seed %d n=%zu %s (%zu dummies left)", g, seed, n,
                 remove ? "dummies removed" : "dummies kept", remaining);
        const int exact = cross_check(&ns, t, what);
        ++tally->runs;
        tally->exact_runs += (size_t)exact;
        tally->ambiguous_runs += (size_t)!exact;
        if (remaining == 0) {
          ++tally->generic_runs;
          tally->ambiguous_generic_runs += (size_t)!exact;
        }
        hdt_destroy(t);
        free(xy);
        free(ids);
      }
    }
  }
  nset_free(&ns);
}

static void report(int g, const tally_t *t) {
  printf("brute_force g=%d: %zu runs, %zu exact equalities, %zu with ambiguous (cocircular) tests; "
         "%zu runs without dummies, %zu of them ambiguous\n",
         g, t->runs, t->exact_runs, t->ambiguous_runs, t->generic_runs, t->ambiguous_generic_runs);
  fflush(stdout);
  /* Random points are in general position: once the dummies are gone an
     ambiguous run means trouble in the test's numerics, and must be rare.
     (The dummy sets seen so far are in general position too.) */
  expect(t->ambiguous_generic_runs * 10 <= t->generic_runs, "g=%d: %zu of %zu runs without dummies were ambiguous", g,
         t->ambiguous_generic_runs, t->generic_runs);
  expect(t->ambiguous_runs * 4 <= t->runs, "g=%d: %zu of %zu runs were ambiguous", g, t->ambiguous_runs, t->runs);
}

static const size_t sizes[] = {1, 5, 30, 100, 200};

START_TEST(genus2_matches_brute_force) {
  tally_t tally = {0, 0, 0, 0, 0};
  run_cross_checks(2, sizes, sizeof sizes / sizeof sizes[0], 10, &tally);
  report(2, &tally);
}
END_TEST

START_TEST(genus3_matches_brute_force) {
  tally_t tally = {0, 0, 0, 0, 0};
  run_cross_checks(3, sizes, sizeof sizes / sizeof sizes[0], 6, &tally);
  report(3, &tally);
}
END_TEST

/* Enough points that remove_dummies clears every dummy, so the equality is
   exact (no cocircular dummies left). */
START_TEST(large_sets_without_dummies) {
  const size_t big[] = {400, 800};
  for (int g = 2; g <= 3; ++g) {
    tally_t tally = {0, 0, 0, 0, 0};
    run_cross_checks(g, big, 2, 2, &tally);
    report(g, &tally);
  }
}
END_TEST

int main(void) {
  const TTest *const tests[] = {
      half_systole_balls_lie_in_d_n,
      translation_ids_of_n_are_fixed,
      genus2_matches_brute_force,
      genus3_matches_brute_force,
      large_sets_without_dummies,
  };
  return run_tests("brute_force", tests, sizeof tests / sizeof tests[0]);
}
