/* Adjacency, stars, edges, face corners and the Voronoi diagram (HDT_0.4),
   each checked against an independent computation: translation words
   reduced by the group functions (not by the triangulation's table), brute
   force over the neighbour set N (tests/brute_force.h), hyperbolic areas,
   and a 256-bit MPFR evaluation built here from the generators' formula. */
#define _DEFAULT_SOURCE

#include <mpfr.h>

#include "brute_force.h"
#include "hdt_test.h"

/* ---- A triangulation and everything the new functions say about it ---- */

typedef struct dual {
  hdt_triangulation *t;
  int g;
  size_t V, F, E, bound;
  uint32_t *ids;
  double *rep;       /* by vertex id: 2 per id (NaN for removed ids) */
  uint32_t *fv;      /* hdt_faces */
  int32_t *ft;
  uint32_t *nf;      /* hdt_face_neighbours */
  int32_t *nt;
  double *corners;   /* hdt_face_points */
  uint32_t *ev;      /* hdt_edges */
  int32_t *et;
  uint32_t *ef;
  double *length;
  double *centre;    /* hdt_voronoi_vertices */
  double *radius;
  double *vedge;     /* hdt_voronoi_edges */
} dual;

static void *need(void *p) {
  ck_assert_ptr_nonnull(p);
  return p;
}


static void read_dual(hdt_triangulation *t, dual *d) {
  memset(d, 0, sizeof *d);
  d->t = t;
  d->g = hdt_genus(t);
  d->V = hdt_vertex_count(t);
  d->F = hdt_face_count(t);
  d->E = hdt_edge_count(t);
  d->bound = hdt_vertex_id_bound(t);
  size_t n = 0;
  d->ids = need(malloc(d->V * sizeof *d->ids));
  double *xy = need(malloc(2 * d->V * sizeof *xy));
  OK(hdt_vertices(t, d->ids, xy, NULL, d->V, &n));
  d->rep = need(malloc(2 * d->bound * sizeof *d->rep));
  for (size_t i = 0; i < 2 * d->bound; ++i) d->rep[i] = NAN;
  for (size_t i = 0; i < d->V; ++i) d->rep[2 * d->ids[i]] = xy[2 * i], d->rep[2 * d->ids[i] + 1] = xy[2 * i + 1];
  free(xy);
  d->fv = need(malloc(3 * d->F * sizeof *d->fv));
  d->ft = need(malloc(3 * d->F * sizeof *d->ft));
  OK(hdt_faces(t, d->fv, d->ft, d->F, &n));
  d->nf = need(malloc(3 * d->F * sizeof *d->nf));
  d->nt = need(malloc(3 * d->F * sizeof *d->nt));
  OK(hdt_face_neighbours(t, d->nf, d->nt, d->F, &n));
  expect(n == d->F, "hdt_face_neighbours: %zu faces, hdt_face_count %zu", n, d->F);
  d->corners = need(malloc(6 * d->F * sizeof *d->corners));
  OK(hdt_face_points(t, d->corners, d->F, &n));
  d->ev = need(malloc(2 * d->E * sizeof *d->ev));
  d->et = need(malloc(d->E * sizeof *d->et));
  d->ef = need(malloc(2 * d->E * sizeof *d->ef));
  d->length = need(malloc(d->E * sizeof *d->length));
  OK(hdt_edges(t, d->ev, d->et, d->ef, d->length, d->E, &n));
  expect(n == d->E, "hdt_edges: %zu edges, hdt_edge_count %zu", n, d->E);
  d->centre = need(malloc(2 * d->F * sizeof *d->centre));
  d->radius = need(malloc(d->F * sizeof *d->radius));
  OK(hdt_voronoi_vertices(t, d->centre, d->radius, d->F, &n));
  d->vedge = need(malloc(4 * d->E * sizeof *d->vedge));
  OK(hdt_voronoi_edges(t, d->vedge, d->E, &n));
}

static void free_dual(dual *d) {
  free(d->ids), free(d->rep), free(d->fv), free(d->ft), free(d->nf), free(d->nt), free(d->corners);
  free(d->ev), free(d->et), free(d->ef), free(d->length), free(d->centre), free(d->radius), free(d->vedge);
  hdt_destroy(d->t);
}

/* ---- Group elements through the group functions ---- */

static word_t tword(const dual *d, int32_t id) {
  word_t w = {0};
  size_t n = 0;
  OK(hdt_translation_word(d->t, id, w.a, TW_MAX, &n));
  w.n = n;
  return w;
}

/* Whether the product of the elements of ids a, b, c (c applied first; -1
   for none) is the identity, decided by hdt_word_reduce. */
static int product_is_identity(const dual *d, int32_t a, int32_t b, int32_t c) {
  word_t w = tword(d, a), x = tword(d, b);
  word_append(&w, &x);
  if (c >= 0) {
    word_t y = tword(d, c);
    word_append(&w, &y);
  }
  return reduce_word(d->g, &w).n == 0;
}

static void matrix_of(const dual *d, int32_t id, double m[4]) { OK(hdt_translation_matrix(d->t, id, m)); }

static void apply(const double m[4], double x, double y, double *ox, double *oy) {
  const double ar = m[0], ai = m[1], br = m[2], bi = m[3];
  const double nr = ar * x - ai * y + br, ni = ar * y + ai * x + bi;
  const double dr = br * x + bi * y + ar, di = br * y - bi * x - ai;
  const double d2 = dr * dr + di * di;
  *ox = (nr * dr + ni * di) / d2;
  *oy = (ni * dr - nr * di) / d2;
}

/* (z - w) / (1 - conj(w) z): the isometry taking w to 0, applied to z. */
static void to_origin(double wx, double wy, double zx, double zy, double *ox, double *oy) {
  const double nr = zx - wx, ni = zy - wy, dr = 1 - (wx * zx + wy * zy), di = -(wx * zy - wy * zx);
  const double q = dr * dr + di * di;
  *ox = (nr * dr + ni * di) / q, *oy = (ni * dr - nr * di) / q;
}

/* Hyperbolic distance by the cosh formula, in long double (the library
   uses an asinh formula in double). */
static double hdist(double x1, double y1, double x2, double y2) {
  const long double dx = (long double)x1 - x2, dy = (long double)y1 - y2;
  const long double a = 1 - ((long double)x1 * x1 + (long double)y1 * y1);
  const long double b = 1 - ((long double)x2 * x2 + (long double)y2 * y2);
  return (double)acoshl(1 + 2 * (dx * dx + dy * dy) / (a * b));
}

/* The same for points very close together (an error measure): the asinh
   form, which keeps its relative accuracy there. */
static double hgap(double x1, double y1, double x2, double y2) {
  const long double a = 1 - ((long double)x1 * x1 + (long double)y1 * y1);
  const long double b = 1 - ((long double)x2 * x2 + (long double)y2 * y2);
  return (double)(2 * asinhl(hypotl((long double)x1 - x2, (long double)y1 - y2) / sqrtl(a * b)));
}

/* The triangulations every case looks at: with and without dummies, genus 2
   to 4; the last two with points all over the disk (radius 0.95), most of
   them away from F_g, so that vertices have homes other than the identity
   (the others' points lie in F_g). */
typedef struct setup {
  int g;
  size_t n;
  int remove_dummies;
  int wide;
} setup;
static const setup setups[] = {{2, 0, 0, 0},   {2, 150, 1, 0}, {3, 120, 0, 0}, {3, 200, 1, 0},
                               {4, 250, 1, 0}, {2, 200, 1, 1}, {3, 150, 0, 1}};
#define SETUPS (sizeof setups / sizeof setups[0])

static void load(size_t k, dual *d) {
  const setup *s = &setups[k];
  read_dual(s->wide ? wide_disk_triangulation(s->g, s->n, 0x5eed + k, s->remove_dummies)
                    : small_disk_triangulation(s->g, s->n, 0x5eed + k, s->remove_dummies),
            d);
}

/* ---- Cases ---- */

/* Across an edge and back: the neighbour's neighbour is the face, the
   translations are inverse, and the shared edge's corners coincide exactly
   (as group elements: h c'_j = c_i for the corner translations). */
START_TEST(neighbours_are_an_involution) {
  for (size_t k = 0; k < SETUPS; ++k) {
    dual d;
    load(k, &d);
    for (size_t f = 0; f < d.F; ++f)
      for (int i = 0; i < 3; ++i) {
        const uint32_t n = d.nf[3 * f + i];
        const int32_t h = d.nt[3 * f + i];
        expect(n < d.F && n != f, "face %zu: neighbour %u", f, n);
        int back = -1;
        for (int j = 0; j < 3; ++j)
          if (d.nf[3 * n + j] == f) back = j;
        expect(back >= 0, "genus %d: face %u does not have face %zu as a neighbour", d.g, n, f);
        expect(product_is_identity(&d, h, d.nt[3 * n + back], -1), "face %zu edge %d: translations not inverse", f, i);
        /* The edge opposite corner i is (i+1, i+2); seen from n it runs the
           other way: corner back+1 of n is corner i+2 of f. */
        const int a = (i + 1) % 3, b = (i + 2) % 3, na = (back + 2) % 3, nb = (back + 1) % 3;
        expect(d.fv[3 * f + a] == d.fv[3 * n + na] && d.fv[3 * f + b] == d.fv[3 * n + nb],
               "face %zu edge %d: the neighbour's edge has other vertices", f, i);
        const word_t ca = tword(&d, d.ft[3 * f + a]);
        word_t w = tword(&d, h), x = tword(&d, d.ft[3 * n + na]);
        word_append(&w, &x);
        word_t r = reduce_word(d.g, &w);
        word_t cr = reduce_word(d.g, &ca);
        expect(word_eq(&r, &cr), "genus %d face %zu edge %d: h(neighbour's corner) is not the face's corner", d.g, f, i);
      }
    free_dual(&d);
  }
}
END_TEST

/* The stars: each (face, corner) once over all vertices (3F in total),
   consecutive faces share the edge from v, and each translation is the
   inverse of v's corner translation in that face. */
START_TEST(stars_cover_each_face_three_times) {
  for (size_t k = 0; k < SETUPS; ++k) {
    dual d;
    load(k, &d);
    unsigned char *seen = need(calloc(3 * d.F, 1));
    size_t total = 0;
    uint32_t *faces = need(malloc(d.F * sizeof *faces));
    uint8_t *corners = need(malloc(d.F));
    int32_t *tr = need(malloc(d.F * sizeof *tr));
    for (size_t i = 0; i < d.V; ++i) {
      const uint32_t v = d.ids[i];
      size_t n = 0;
      OK(hdt_vertex_star(d.t, v, NULL, NULL, NULL, 0, &n));
      expect(n >= 3, "vertex %u: a star of %zu faces", v, n);
      size_t m = 0;
      OK(hdt_vertex_star(d.t, v, faces, corners, tr, n, &m));
      expect(m == n, "vertex %u: star sizes %zu then %zu", v, n, m);
      for (size_t s = 0; s < n; ++s) {
        const uint32_t f = faces[s];
        const int c = corners[s];
        expect(f < d.F && c < 3 && d.fv[3 * f + c] == v, "vertex %u: star entry %zu is not one of its corners", v, s);
        expect(!seen[3 * f + c], "face %u corner %d twice in the stars", f, c);
        seen[3 * f + c] = 1;
        expect(product_is_identity(&d, tr[s], d.ft[3 * f + c], -1), "vertex %u: star translation %zu", v, s);
        /* The next face is across the edge from v to the corner after it. */
        const uint32_t next = faces[(s + 1) % n];
        expect(d.nf[3 * f + (c + 1) % 3] == next, "vertex %u: star faces %zu and %zu are not adjacent there", v, s,
               (s + 1) % n);
      }
      total += n;
    }
    expect(total == 3 * d.F, "genus %d: the stars hold %zu corners, 3F = %zu", d.g, total, 3 * d.F);
    free(seen), free(faces), free(corners), free(tr);
    free_dual(&d);
  }
}
END_TEST

/* Euler's formula, each face edge once, and each length against the brute
   force: the shortest distance from a's representative to the N-images of
   b's; that image's element is the edge's translation. */
START_TEST(edges_against_brute_force) {
  for (size_t k = 0; k < SETUPS; ++k) {
    dual d;
    load(k, &d);
    expect((long)d.V - (long)d.E + (long)d.F == 2 - 2 * d.g, "genus %d: V - E + F = %zu - %zu + %zu", d.g, d.V, d.E,
           d.F);
    bf_nset ns;
    char msg[256];
    expect(bf_nset_make(&ns, d.g, msg, sizeof msg) == 0, "%s", msg);
    unsigned char *seen = need(calloc(3 * d.F, 1));
    for (size_t e = 0; e < d.E; ++e) {
      const uint32_t a = d.ev[2 * e], b = d.ev[2 * e + 1], left = d.ef[2 * e], right = d.ef[2 * e + 1];
      expect(left < right, "edge %zu: faces %u, %u", e, left, right);
      int i = -1;
      for (int c = 0; c < 3; ++c)
        if (d.fv[3 * left + (c + 1) % 3] == a && d.fv[3 * left + (c + 2) % 3] == b) i = c;
      expect(i >= 0 && d.nf[3 * left + i] == right, "edge %zu is not an edge of its left face", e);
      expect(!seen[3 * left + i], "edge %zu listed twice", e);
      seen[3 * left + i] = 1;
      for (int j = 0; j < 3; ++j)
        if (d.nf[3 * right + j] == left) seen[3 * right + j] = 1;
      const double ax = d.rep[2 * a], ay = d.rep[2 * a + 1], bx = d.rep[2 * b], by = d.rep[2 * b + 1];
      double best = INFINITY;
      size_t arg = 0;
      for (size_t h = 0; h < ns.count; ++h) {
        double x, y;
        apply(ns.m[h], bx, by, &x, &y);
        const double dist = hdist(ax, ay, x, y);
        if (dist < best) best = dist, arg = h;
      }
      expect(fabs(d.length[e] - best) <= 1e-12 * best, "genus %d edge %zu: length %.17g, brute force %.17g", d.g, e,
             d.length[e], best);
      expect(best < hdt_systole(d.g) / 2, "edge %zu: length %g is not below sys/2", e, best);
      size_t len = 0;
      const int32_t *w = bf_nset_word(&ns, arg, &len);
      const word_t et = tword(&d, d.et[e]);
      expect(et.n == len && memcmp(et.a, w, len * sizeof *w) == 0,
             "genus %d edge %zu: its translation is not the nearest image's element", d.g, e);
    }
    for (size_t c = 0; c < 3 * d.F; ++c) expect(seen[c], "face %zu edge %zu is in no listed edge", c / 3, c % 3);
    free(seen);
    bf_nset_free(&ns);
    free_dual(&d);
  }
}
END_TEST

/* hdt_face_points: the corner translations applied to the representatives. */
START_TEST(face_points_are_the_translated_corners) {
  for (size_t k = 0; k < SETUPS; ++k) {
    dual d;
    load(k, &d);
    for (size_t c = 0; c < 3 * d.F; ++c) {
      double m[4], x, y;
      matrix_of(&d, d.ft[c], m);
      apply(m, d.rep[2 * d.fv[c]], d.rep[2 * d.fv[c] + 1], &x, &y);
      expect(hypot(x - d.corners[2 * c], y - d.corners[2 * c + 1]) < 1e-13, "face %zu corner %zu: (%g, %g) vs (%g, %g)",
             c / 3, c % 3, d.corners[2 * c], d.corners[2 * c + 1], x, y);
    }
    free_dual(&d);
  }
}
END_TEST

/* Each Voronoi vertex is at its radius from the three corners, and no
   N-image of any vertex is inside its circle (brute force: the circle lies
   within sys/2 of the face's smallest vertex, in F_g, so within D_N). */
START_TEST(voronoi_vertices_are_empty_circles) {
  for (size_t k = 0; k < SETUPS; ++k) {
    dual d;
    load(k, &d);
    bf_nset ns;
    char msg[256];
    expect(bf_nset_make(&ns, d.g, msg, sizeof msg) == 0, "%s", msg);
    /* Every N-image of every vertex, once. */
    double *images = need(malloc(2 * d.V * ns.count * sizeof *images));
    for (size_t i = 0; i < d.V; ++i)
      for (size_t h = 0; h < ns.count; ++h)
        apply(ns.m[h], d.rep[2 * d.ids[i]], d.rep[2 * d.ids[i] + 1], &images[2 * (i * ns.count + h)],
              &images[2 * (i * ns.count + h) + 1]);
    for (size_t f = 0; f < d.F; ++f) {
      const double cx = d.centre[2 * f], cy = d.centre[2 * f + 1], r = d.radius[f];
      expect(r > 0 && r < hdt_systole(d.g) / 4, "face %zu: radius %g", f, r);
      for (int i = 0; i < 3; ++i) {
        const double di = hdist(cx, cy, d.corners[6 * f + 2 * i], d.corners[6 * f + 2 * i + 1]);
        expect(fabs(di - r) <= 1e-11 * r, "genus %d face %zu corner %d: at %.17g from the centre, radius %.17g", d.g,
               f, i, di, r);
      }
      /* d(c, w) >= r' iff |c - w|^2 / ((1 - |c|^2)(1 - |w|^2)) >= sinh^2(r'/2):
         no acosh in the inner loop. */
      const double sh = sinh(r * (1 - 1e-11) / 2), bound = sh * sh, wc = 1 - (cx * cx + cy * cy);
      for (size_t i = 0; i < d.V * ns.count; ++i) {
        const double x = images[2 * i], y = images[2 * i + 1];
        const double u = ((cx - x) * (cx - x) + (cy - y) * (cy - y)) / (wc * (1 - (x * x + y * y)));
        expect(u >= bound, "genus %d face %zu: vertex %u (image %zu) at %.17g inside radius %.17g", d.g, f,
               d.ids[i / ns.count], i % ns.count, hdist(cx, cy, x, y), r);
      }
    }
    free(images);
    bf_nset_free(&ns);
    free_dual(&d);
  }
}
END_TEST

/* Signed hyperbolic area of the geodesic triangle (p, q, r): move p to 0,
   then the triangle (0, z1, z2) has area -2 arg(1 - conj(z1) z2). */
static double triangle_area(double px, double py, double qx, double qy, double rx, double ry) {
  const double m[4] = {1 / sqrt(1 - px * px - py * py), 0, -px / sqrt(1 - px * px - py * py),
                       -py / sqrt(1 - px * px - py * py)};
  double x1, y1, x2, y2;
  apply(m, qx, qy, &x1, &y1);
  apply(m, rx, ry, &x2, &y2);
  /* 1 - conj(z1) z2 */
  const double re = 1 - (x1 * x2 + y1 * y2), im = -(x1 * y2 - y1 * x2);
  return -2 * atan2(im, re);
}

/* The Voronoi cells: each the star's circumcentres around the
   representative, turning once counterclockwise about it; consecutive
   corners are the ends of the Voronoi edge dual to the star's edge between
   them; and the cells tile the surface: their areas add up to 4 pi (g-1). */
START_TEST(voronoi_cells_tile_the_surface) {
  for (size_t k = 0; k < SETUPS; ++k) {
    dual d;
    load(k, &d);
    /* The edge between two faces, by the pair. */
    double area = 0;
    uint32_t *faces = need(malloc(d.F * sizeof *faces));
    uint8_t *corners = need(malloc(d.F));
    int32_t *tr = need(malloc(d.F * sizeof *tr));
    double *cell = need(malloc(2 * d.F * sizeof *cell));
    for (size_t i = 0; i < d.V; ++i) {
      const uint32_t v = d.ids[i];
      const double vx = d.rep[2 * v], vy = d.rep[2 * v + 1];
      size_t n = 0, m = 0;
      OK(hdt_vertex_star(d.t, v, faces, corners, tr, d.F, &n));
      OK(hdt_voronoi_cell(d.t, v, NULL, 0, &m));
      expect(m == n, "vertex %u: cell of %zu corners, star of %zu", v, m, n);
      OK(hdt_voronoi_cell(d.t, v, cell, n, &m));
      double turn = 0;
      for (size_t s = 0; s < n; ++s) {
        double mt[4], x, y;
        matrix_of(&d, tr[s], mt);
        apply(mt, d.centre[2 * faces[s]], d.centre[2 * faces[s] + 1], &x, &y);
        expect(hypot(x - cell[2 * s], y - cell[2 * s + 1]) < 1e-12, "vertex %u: cell corner %zu is not its face's centre",
               v, s);
        const size_t t = (s + 1) % n;
        /* Seen with v moved to the origin, where the geodesics from v are
           diameters: the sides of the (geodesically convex) cell bow toward
           v, and Euclidean angles about (vx, vy) itself could miss a turn. */
        double ax, ay, bx, by;
        to_origin(vx, vy, cell[2 * s], cell[2 * s + 1], &ax, &ay);
        to_origin(vx, vy, cell[2 * t], cell[2 * t + 1], &bx, &by);
        turn += atan2(ax * by - ay * bx, ax * bx + ay * by);
        area += triangle_area(vx, vy, cell[2 * s], cell[2 * s + 1], cell[2 * t], cell[2 * t + 1]);
        /* The Voronoi edge dual to the edge from v between faces s and t. */
        const uint32_t f = faces[s], g = faces[t];
        size_t e = 0;
        while (e < d.E && !((d.ef[2 * e] == f && d.ef[2 * e + 1] == g) || (d.ef[2 * e] == g && d.ef[2 * e + 1] == f)))
          ++e;
        expect(e < d.E, "vertex %u: no edge between faces %u and %u", v, f, g);
        /* hdt_voronoi_edges places it in the left face's frame; the cell in
           the frame around v: map by the left face's star translation. */
        const int left_is_s = d.ef[2 * e] == f;
        matrix_of(&d, tr[left_is_s ? s : t], mt);
        double p[2][2];
        for (int j = 0; j < 2; ++j) apply(mt, d.vedge[4 * e + 2 * j], d.vedge[4 * e + 2 * j + 1], &p[j][0], &p[j][1]);
        const double *mine = left_is_s ? p[0] : p[1], *theirs = left_is_s ? p[1] : p[0];
        expect(hypot(mine[0] - cell[2 * s], mine[1] - cell[2 * s + 1]) < 1e-12 &&
                   hypot(theirs[0] - cell[2 * t], theirs[1] - cell[2 * t + 1]) < 1e-12,
               "genus %d vertex %u: cell side %zu is not Voronoi edge %zu", d.g, v, s, e);
      }
      expect(fabs(turn - 2 * M_PI) < 1e-9, "vertex %u: the cell turns %g about it", v, turn);
    }
    const double want = 4 * M_PI * (d.g - 1);
    expect(fabs(area - want) < 1e-9 * want, "genus %d: the cells' areas add up to %.15g, 4 pi (g-1) = %.15g", d.g,
           area, want);
    free(faces), free(corners), free(tr), free(cell);
    free_dual(&d);
  }
}
END_TEST

/* ---- The MPFR evaluation ---- */

#define PREC 256
/* hdt.h's relative bound on lengths, radii and hdt_quality's figures. */
#define TINY_BOUND 1e-14

typedef struct mcomplex {
  mpfr_t re, im;
} mcomplex;
typedef struct mmatrix {
  mcomplex a, b;
} mmatrix;

static void mc_init(mcomplex *z) { mpfr_inits2(PREC, z->re, z->im, (mpfr_ptr)0); }
static void mc_clear(mcomplex *z) { mpfr_clears(z->re, z->im, (mpfr_ptr)0); }
static void mm_init(mmatrix *m) { mc_init(&m->a), mc_init(&m->b); }
static void mm_clear(mmatrix *m) { mc_clear(&m->a), mc_clear(&m->b); }

/* r = p q, r = p conj(q) (r may not alias). */
static void mc_mul(mcomplex *r, const mcomplex *p, const mcomplex *q, int conj_q) {
  mpfr_t s;
  mpfr_init2(s, PREC);
  const int sg = conj_q ? -1 : 1;
  mpfr_mul(r->re, p->re, q->re, MPFR_RNDN), mpfr_mul(s, p->im, q->im, MPFR_RNDN);
  if (sg > 0) mpfr_sub(r->re, r->re, s, MPFR_RNDN);
  else mpfr_add(r->re, r->re, s, MPFR_RNDN);
  mpfr_mul(r->im, p->im, q->re, MPFR_RNDN), mpfr_mul(s, p->re, q->im, MPFR_RNDN);
  if (sg > 0) mpfr_add(r->im, r->im, s, MPFR_RNDN);
  else mpfr_sub(r->im, r->im, s, MPFR_RNDN);
  mpfr_clear(s);
}

/* g_k = [[A, B e^{i k pi / 2g}], [conj, A]], A = cot(pi/4g), B = sqrt(A^2 - 1):
   written from the formula, not read from the library. */
static void generator(int g, int k, mmatrix *m) {
  mpfr_t pi, t;
  mpfr_inits2(PREC, pi, t, (mpfr_ptr)0);
  mpfr_const_pi(pi, MPFR_RNDN);
  mpfr_div_ui(t, pi, 4 * g, MPFR_RNDN);
  mpfr_cot(m->a.re, t, MPFR_RNDN);
  mpfr_set_ui(m->a.im, 0, MPFR_RNDN);
  mpfr_sqr(t, m->a.re, MPFR_RNDN);
  mpfr_sub_ui(t, t, 1, MPFR_RNDN);
  mpfr_sqrt(t, t, MPFR_RNDN);
  mpfr_mul_ui(pi, pi, k, MPFR_RNDN);
  mpfr_div_ui(pi, pi, 2 * g, MPFR_RNDN);
  mpfr_sin_cos(m->b.im, m->b.re, pi, MPFR_RNDN);
  mpfr_mul(m->b.re, m->b.re, t, MPFR_RNDN), mpfr_mul(m->b.im, m->b.im, t, MPFR_RNDN);
  mpfr_clears(pi, t, (mpfr_ptr)0);
}

/* m = m * g_k (apply g_k first). */
static void times_generator(int g, mmatrix *m, int k) {
  mmatrix q, r;
  mm_init(&q), mm_init(&r);
  generator(g, k, &q);
  mcomplex s;
  mc_init(&s);
  /* [[a, b], [b~, a~]] [[a', b'], [b'~, a'~]]: a a' + b conj(b'), a b' + b conj(a'). */
  mc_mul(&r.a, &m->a, &q.a, 0), mc_mul(&s, &m->b, &q.b, 1);
  mpfr_add(r.a.re, r.a.re, s.re, MPFR_RNDN), mpfr_add(r.a.im, r.a.im, s.im, MPFR_RNDN);
  mc_mul(&r.b, &m->a, &q.b, 0), mc_mul(&s, &m->b, &q.a, 1);
  mpfr_add(r.b.re, r.b.re, s.re, MPFR_RNDN), mpfr_add(r.b.im, r.b.im, s.im, MPFR_RNDN);
  mpfr_set(m->a.re, r.a.re, MPFR_RNDN), mpfr_set(m->a.im, r.a.im, MPFR_RNDN);
  mpfr_set(m->b.re, r.b.re, MPFR_RNDN), mpfr_set(m->b.im, r.b.im, MPFR_RNDN);
  mm_clear(&q), mm_clear(&r), mc_clear(&s);
}

/* The hyperboloid point (t, u, v) of h(x + iy), h the element of word w. */
static void lift(int g, const word_t *w, double x, double y, mpfr_t p[3]) {
  mmatrix m;
  mm_init(&m);
  mpfr_set_ui(m.a.re, 1, MPFR_RNDN), mpfr_set_ui(m.a.im, 0, MPFR_RNDN);
  mpfr_set_ui(m.b.re, 0, MPFR_RNDN), mpfr_set_ui(m.b.im, 0, MPFR_RNDN);
  for (size_t i = 0; i < w->n; ++i) times_generator(g, &m, w->a[i]);
  mcomplex z, num, den, s;
  mc_init(&z), mc_init(&num), mc_init(&den), mc_init(&s);
  mpfr_set_d(z.re, x, MPFR_RNDN), mpfr_set_d(z.im, y, MPFR_RNDN);
  mc_mul(&num, &m.a, &z, 0);
  mpfr_add(num.re, num.re, m.b.re, MPFR_RNDN), mpfr_add(num.im, num.im, m.b.im, MPFR_RNDN);
  /* conj(b) z + conj(a) = conj(b conj(z) + a) */
  mc_mul(&s, &m.b, &z, 1);
  mpfr_add(den.re, s.re, m.a.re, MPFR_RNDN), mpfr_add(den.im, s.im, m.a.im, MPFR_RNDN);
  mpfr_neg(den.im, den.im, MPFR_RNDN);
  /* z' = num / den */
  mpfr_t n2, q;
  mpfr_inits2(PREC, n2, q, (mpfr_ptr)0);
  mpfr_sqr(n2, den.re, MPFR_RNDN), mpfr_sqr(q, den.im, MPFR_RNDN), mpfr_add(n2, n2, q, MPFR_RNDN);
  mc_mul(&s, &num, &den, 1);
  mpfr_div(s.re, s.re, n2, MPFR_RNDN), mpfr_div(s.im, s.im, n2, MPFR_RNDN);
  /* (1 + |z|^2, 2x, 2y) / (1 - |z|^2) */
  mpfr_sqr(n2, s.re, MPFR_RNDN), mpfr_sqr(q, s.im, MPFR_RNDN), mpfr_add(n2, n2, q, MPFR_RNDN);
  mpfr_ui_sub(q, 1, n2, MPFR_RNDN);
  mpfr_add_ui(p[0], n2, 1, MPFR_RNDN), mpfr_div(p[0], p[0], q, MPFR_RNDN);
  mpfr_mul_2ui(p[1], s.re, 1, MPFR_RNDN), mpfr_div(p[1], p[1], q, MPFR_RNDN);
  mpfr_mul_2ui(p[2], s.im, 1, MPFR_RNDN), mpfr_div(p[2], p[2], q, MPFR_RNDN);
  mpfr_clears(n2, q, (mpfr_ptr)0);
  mm_clear(&m), mc_clear(&z), mc_clear(&num), mc_clear(&den), mc_clear(&s);
}

/* <p, q> = t t' - u u' - v v' (cosh of the distance for hyperboloid points). */
static void minkowski(mpfr_t r, mpfr_t p[3], mpfr_t q[3]) {
  mpfr_t s;
  mpfr_init2(s, PREC);
  mpfr_mul(r, p[0], q[0], MPFR_RNDN);
  for (int i = 1; i < 3; ++i) mpfr_mul(s, p[i], q[i], MPFR_RNDN), mpfr_sub(r, r, s, MPFR_RNDN);
  mpfr_clear(s);
}

/* A hyperboloid point in the disk: (u, v) / (1 + t), rounded. */
static void to_disk(mpfr_t p[3], double *x, double *y) {
  mpfr_t s;
  mpfr_init2(s, PREC);
  mpfr_add_ui(s, p[0], 1, MPFR_RNDN);
  mpfr_t q;
  mpfr_init2(q, PREC);
  mpfr_div(q, p[1], s, MPFR_RNDN), *x = mpfr_get_d(q, MPFR_RNDN);
  mpfr_div(q, p[2], s, MPFR_RNDN), *y = mpfr_get_d(q, MPFR_RNDN);
  mpfr_clears(s, q, (mpfr_ptr)0);
}

/* Every corner, circumcentre, circumradius and edge length recomputed at
   256 bits from the representatives and the translations' words: the
   circumcentre is the Minkowski normal of the plane through the three
   hyperboloid points (another formula than the library's). The worst
   errors found are printed for docs/dual.md. */
START_TEST(constructions_against_mpfr) {
  const setup cases[] = {{2, 200, 1, 0}, {3, 300, 1, 0}, {5, 400, 1, 0}, {2, 0, 0, 0}, {4, 0, 0, 0}};
  double worst_point = 0, worst_radius = 0, worst_length = 0, worst_corner_h = 0, worst_centre_h = 0;
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
    dual d;
    read_dual(small_disk_triangulation(cases[k].g, cases[k].n, 77 + k, cases[k].remove_dummies), &d);
    /* Only representatives that are the stored points (every user point
       here; the dummies' are checked by hdt_point_representative) give an
       exact input; faces with another vertex are left out. */
    unsigned char *exact = need(calloc(d.bound, 1));
    for (size_t i = 0; i < d.V; ++i) {
      size_t len = 1;
      int32_t w[8];
      const uint32_t v = d.ids[i];
      if (hdt_vertex_is_dummy(d.t, v) == 0) exact[v] = 1;
      else if (hdt_point_representative(d.g, d.rep[2 * v], d.rep[2 * v + 1], NULL, NULL, w, 8, &len) == HDT_OK &&
               len == 0)
        exact[v] = 1;
    }
    mpfr_t p[3][3], c[3], e1[3], e2[3], s, r;
    for (int i = 0; i < 3; ++i) mpfr_inits2(PREC, p[i][0], p[i][1], p[i][2], c[i], e1[i], e2[i], (mpfr_ptr)0);
    mpfr_inits2(PREC, s, r, (mpfr_ptr)0);
    size_t checked = 0;
    for (size_t f = 0; f < d.F; ++f) {
      if (!exact[d.fv[3 * f]] || !exact[d.fv[3 * f + 1]] || !exact[d.fv[3 * f + 2]]) continue;
      ++checked;
      for (int i = 0; i < 3; ++i) {
        const word_t w = tword(&d, d.ft[3 * f + i]);
        const uint32_t v = d.fv[3 * f + i];
        lift(d.g, &w, d.rep[2 * v], d.rep[2 * v + 1], p[i]);
        double x, y;
        to_disk(p[i], &x, &y);
        worst_point = fmax(worst_point, hypot(x - d.corners[6 * f + 2 * i], y - d.corners[6 * f + 2 * i + 1]));
        worst_corner_h = fmax(worst_corner_h, hgap(x, y, d.corners[6 * f + 2 * i], d.corners[6 * f + 2 * i + 1]));
      }
      /* The plane's normal n = (p1 - p0) x (p2 - p0) with the Minkowski
         metric: n = J (e1 x e2), J = diag(-1, 1, 1) up to sign; the centre
         is n / sqrt(<n, n>) with t > 0. */
      for (int j = 0; j < 3; ++j)
        mpfr_sub(e1[j], p[1][j], p[0][j], MPFR_RNDN), mpfr_sub(e2[j], p[2][j], p[0][j], MPFR_RNDN);
      for (int j = 0; j < 3; ++j) {
        const int a = (j + 1) % 3, b = (j + 2) % 3;
        mpfr_mul(c[j], e1[a], e2[b], MPFR_RNDN), mpfr_mul(s, e1[b], e2[a], MPFR_RNDN);
        mpfr_sub(c[j], c[j], s, MPFR_RNDN);
      }
      mpfr_neg(c[0], c[0], MPFR_RNDN);
      minkowski(s, c, c);
      mpfr_sqrt(s, s, MPFR_RNDN);
      if (mpfr_sgn(c[0]) < 0) mpfr_neg(s, s, MPFR_RNDN);
      for (int j = 0; j < 3; ++j) mpfr_div(c[j], c[j], s, MPFR_RNDN);
      double x, y;
      to_disk(c, &x, &y);
      worst_point = fmax(worst_point, hypot(x - d.centre[2 * f], y - d.centre[2 * f + 1]));
      worst_centre_h = fmax(worst_centre_h, hgap(x, y, d.centre[2 * f], d.centre[2 * f + 1]));
      minkowski(r, c, p[0]);
      mpfr_acosh(r, r, MPFR_RNDN);
      const double radius = mpfr_get_d(r, MPFR_RNDN);
      worst_radius = fmax(worst_radius, fabs(radius - d.radius[f]) / radius);
      /* The edges whose left face this is: their lengths. */
      for (int i = 0; i < 3; ++i) {
        if (d.nf[3 * f + i] < f) continue;
        size_t e = 0;
        while (e < d.E && !(d.ef[2 * e] == f && d.ef[2 * e + 1] == d.nf[3 * f + i])) ++e;
        expect(e < d.E, "face %zu: edge %d not listed", f, i);
        minkowski(r, p[(i + 1) % 3], p[(i + 2) % 3]);
        mpfr_acosh(r, r, MPFR_RNDN);
        const double length = mpfr_get_d(r, MPFR_RNDN);
        worst_length = fmax(worst_length, fabs(length - d.length[e]) / length);
      }
    }
    /* More than half when there are points; a third with the dummies alone:
       the thinned dummy sets are small, and half of genus 4's 72 faces touch
       a site (v_0, m_k) whose rounding is not its own representative. */
    expect(cases[k].n > 0 ? 2 * checked > d.F : 3 * checked > d.F, "genus %d: only %zu of %zu faces had exact corners",
           d.g, checked, d.F);
    printf("dual: genus %d, %zu points%s: %zu faces; worst so far: points %.3g, hyperbolic %.3g / %.3g, radii %.3g, "
           "lengths %.3g\n",
           d.g, cases[k].n, cases[k].remove_dummies ? "" : " and the dummies", checked, worst_point, worst_corner_h,
           worst_centre_h, worst_radius, worst_length);
    for (int i = 0; i < 3; ++i) mpfr_clears(p[i][0], p[i][1], p[i][2], c[i], e1[i], e2[i], (mpfr_ptr)0);
    mpfr_clears(s, r, (mpfr_ptr)0);
    free(exact);
    free_dual(&d);
  }
  printf("dual: worst errors against MPFR: points %.3g (hyperbolic: corners %.3g, centres %.3g), radii %.3g "
         "relative, edge lengths %.3g relative\n",
         worst_point, worst_corner_h, worst_centre_h, worst_radius, worst_length);
  fflush(stdout);
  /* docs/dual.md states the measured values; these bounds leave a factor 2. */
  expect(worst_point < 1e-13 && worst_corner_h < 1e-12 && worst_centre_h < 1e-12,
         "a point is %.3g (hyperbolic: %.3g, %.3g) from its MPFR value", worst_point, worst_corner_h, worst_centre_h);
  expect(worst_radius < 1e-12 && worst_length < 1e-12, "radius error %.3g, length error %.3g", worst_radius,
         worst_length);
  mpfr_free_cache();
}
END_TEST

/* ---- Tiny edges (issue 33): copies of distinct vertices 1e-16 apart ---- */

/* The exact corner of vertex v under the face translation id tr: the stored
   point (a double, exact) under tr h, h the word taking it to its
   representative (hdt_point_representative). */
static void exact_corner(const dual *d, const double *stored, int32_t tr, uint32_t v, mpfr_t P[3]) {
  word_t w = tword(d, tr), home = {0};
  size_t len = 0;
  OK(hdt_point_representative(d->g, stored[2 * v], stored[2 * v + 1], NULL, NULL, home.a, TW_MAX, &len));
  home.n = len;
  word_append(&w, &home);
  lift(d->g, &w, stored[2 * v], stored[2 * v + 1], P);
}

/* acosh(<P, Q>) in MPFR, as a double. */
static double exact_distance(mpfr_t P[3], mpfr_t Q[3]) {
  mpfr_t r;
  mpfr_init2(r, PREC);
  minkowski(r, P, Q);
  if (mpfr_cmp_ui(r, 1) < 0) mpfr_set_ui(r, 1, MPFR_RNDN);
  mpfr_acosh(r, r, MPFR_RNDN);
  const double x = mpfr_get_d(r, MPFR_RNDN);
  mpfr_clear(r);
  return x;
}

/* The unit tangent at O towards P: (P - <P, O> O) / |.| (space-like). */
static void unit_tangent(mpfr_t O[3], mpfr_t P[3], mpfr_t T[3]) {
  mpfr_t s;
  mpfr_init2(s, PREC);
  minkowski(s, P, O);
  for (int j = 0; j < 3; ++j) mpfr_mul(T[j], s, O[j], MPFR_RNDN), mpfr_sub(T[j], P[j], T[j], MPFR_RNDN);
  minkowski(s, T, T);
  mpfr_neg(s, s, MPFR_RNDN), mpfr_sqrt(s, s, MPFR_RNDN);
  for (int j = 0; j < 3; ++j) mpfr_div(T[j], T[j], s, MPFR_RNDN);
  mpfr_clear(s);
}

/* The angle at O of the triangle O, P, Q: 2 atan2(|T - U|, |T + U|) for
   the unit tangents, which keeps small angles and tiny faces accurate. */
static double exact_angle(mpfr_t O[3], mpfr_t P[3], mpfr_t Q[3]) {
  mpfr_t T[3], U[3], D[3], S[3], a, b;
  for (int j = 0; j < 3; ++j) mpfr_inits2(PREC, T[j], U[j], D[j], S[j], (mpfr_ptr)0);
  mpfr_inits2(PREC, a, b, (mpfr_ptr)0);
  unit_tangent(O, P, T), unit_tangent(O, Q, U);
  for (int j = 0; j < 3; ++j) mpfr_sub(D[j], T[j], U[j], MPFR_RNDN), mpfr_add(S[j], T[j], U[j], MPFR_RNDN);
  minkowski(a, D, D), minkowski(b, S, S);
  mpfr_neg(a, a, MPFR_RNDN), mpfr_neg(b, b, MPFR_RNDN);
  mpfr_sqrt(a, a, MPFR_RNDN), mpfr_sqrt(b, b, MPFR_RNDN);
  mpfr_atan2(a, a, b, MPFR_RNDN);
  mpfr_mul_2ui(a, a, 1, MPFR_RNDN);
  const double x = mpfr_get_d(a, MPFR_RNDN);
  for (int j = 0; j < 3; ++j) mpfr_clears(T[j], U[j], D[j], S[j], (mpfr_ptr)0);
  mpfr_clears(a, b, (mpfr_ptr)0);
  return x;
}

/* The circumradius of P0, P1, P2: the Minkowski normal of their plane, as
   in constructions_against_mpfr. */
static double exact_radius(mpfr_t p[3][3]) {
  mpfr_t c[3], e1[3], e2[3], s;
  for (int j = 0; j < 3; ++j) mpfr_inits2(PREC, c[j], e1[j], e2[j], (mpfr_ptr)0);
  mpfr_init2(s, PREC);
  for (int j = 0; j < 3; ++j) mpfr_sub(e1[j], p[1][j], p[0][j], MPFR_RNDN), mpfr_sub(e2[j], p[2][j], p[0][j], MPFR_RNDN);
  for (int j = 0; j < 3; ++j) {
    const int a = (j + 1) % 3, b = (j + 2) % 3;
    mpfr_mul(c[j], e1[a], e2[b], MPFR_RNDN), mpfr_mul(s, e1[b], e2[a], MPFR_RNDN);
    mpfr_sub(c[j], c[j], s, MPFR_RNDN);
  }
  mpfr_neg(c[0], c[0], MPFR_RNDN);
  minkowski(s, c, c);
  mpfr_sqrt(s, s, MPFR_RNDN);
  if (mpfr_sgn(c[0]) < 0) mpfr_neg(s, s, MPFR_RNDN);
  for (int j = 0; j < 3; ++j) mpfr_div(c[j], c[j], s, MPFR_RNDN);
  const double r = exact_distance(c, p[0]);
  for (int j = 0; j < 3; ++j) mpfr_clears(c[j], e1[j], e2[j], (mpfr_ptr)0);
  mpfr_clear(s);
  return r;
}

/* Random points of the disk of radius 0.95 (homes other than the identity) and, near every side's midpoint
   m_k (0.999 m_k, moved along the side), a point p and the rounded image
   of p under the generator that maps side s_k away (a second user point,
   whose copy beside p is an ulp or so from p: an edge of length 1e-16
   between a stored point and a translated one), and p moved by two ulps
   (an edge between two stored points). Every hdt_edges length, Voronoi
   radius and hdt_quality figure is compared with the 256-bit value of the
   exact points (the stored doubles under the faces' translations and the
   vertices' homes). */
static void tiny_edges_case(int g, uint64_t seed, double worst[4]) {
  hdt_triangulation *t = new_triangulation(g);
  size_t cap = 4096;
  double *stored = need(malloc(2 * cap * sizeof *stored));
  for (size_t i = 0; i < 2 * cap; ++i) stored[i] = NAN;
  const size_t random_points = 300;
  double *xy = uniform_disk_points(random_points, seed, 0.95);
  for (size_t i = 0; i < random_points; ++i) {
    uint32_t v;
    OK(hdt_insert(t, xy[2 * i], xy[2 * i + 1], &v));
    expect(v < cap, "vertex id %u", v);
    stored[2 * v] = xy[2 * i], stored[2 * v + 1] = xy[2 * i + 1];
  }
  free(xy);
  for (int k = 0; k < 4 * g; ++k) {
    double mx, my;
    OK(hdt_polygon_side_midpoint(g, k, &mx, &my));
    const double along = (k % 3 - 1) * 0.05;
    double px[3], py[3];
    px[0] = 0.999 * mx - along * my, py[0] = 0.999 * my + along * mx;
    /* g_{k + 2g} = g_k^-1 maps side s_k onto s_{k + 2g}: the image lies
       outside F_g, its representative next to p. */
    const word_t w = {1, {(k + 2 * g) % (4 * g)}};
    mpfr_t P[3];
    mpfr_inits2(PREC, P[0], P[1], P[2], (mpfr_ptr)0);
    lift(g, &w, px[0], py[0], P);
    to_disk(P, &px[1], &py[1]);
    mpfr_clears(P[0], P[1], P[2], (mpfr_ptr)0);
    px[2] = nextafter(nextafter(px[0], 0), 0), py[2] = py[0];
    for (int j = 0; j < 3; ++j) {
      uint32_t v;
      OK(hdt_insert(t, px[j], py[j], &v));
      expect(v < cap, "vertex id %u", v);
      stored[2 * v] = px[j], stored[2 * v + 1] = py[j];
    }
  }
  /* Some dummies may stay (the guarantee): faces with one are left out. */
  OK(hdt_remove_dummies(t, NULL));
  double q[4];
  OK(hdt_quality(t, &q[0], &q[1], &q[2], &q[3]));
  dual d;
  read_dual(t, &d);
  mpfr_t p[3][3];
  for (int i = 0; i < 3; ++i) mpfr_inits2(PREC, p[i][0], p[i][1], p[i][2], (mpfr_ptr)0);
  double min_angle = INFINITY, max_ratio = 0, max_radius = 0, min_edge = INFINITY;
  double worst_length = 0, worst_radius = 0;
  size_t tiny = 0;
  size_t checked = 0;
  for (size_t f = 0; f < d.F; ++f) {
    if (hdt_vertex_is_dummy(t, d.fv[3 * f]) || hdt_vertex_is_dummy(t, d.fv[3 * f + 1]) ||
        hdt_vertex_is_dummy(t, d.fv[3 * f + 2]))
      continue;
    ++checked;
    for (int i = 0; i < 3; ++i) exact_corner(&d, stored, d.ft[3 * f + i], d.fv[3 * f + i], p[i]);
    const double radius = exact_radius(p);
    worst_radius = fmax(worst_radius, fabs(d.radius[f] - radius) / radius);
    double shortest = INFINITY;
    for (int i = 0; i < 3; ++i) {
      const double length = exact_distance(p[(i + 1) % 3], p[(i + 2) % 3]);
      expect(length > 0, "face %zu: two corners coincide", f);
      shortest = fmin(shortest, length);
      min_angle = fmin(min_angle, exact_angle(p[i], p[(i + 1) % 3], p[(i + 2) % 3]));
      if (d.nf[3 * f + i] < f) continue;
      /* Edge i of f, listed with f: its first vertex is corner i + 1. */
      size_t e = 0;
      while (e < d.E && !(d.ef[2 * e] == f && d.ev[2 * e] == d.fv[3 * f + (i + 1) % 3] &&
                          d.ev[2 * e + 1] == d.fv[3 * f + (i + 2) % 3]))
        ++e;
      expect(e < d.E, "face %zu: edge %d not listed", f, i);
      expect(d.length[e] > 0, "genus %d: edge %zu between vertices %u and %u has length %g (exact %.3g)", g, e,
             d.ev[2 * e], d.ev[2 * e + 1], d.length[e], length);
      worst_length = fmax(worst_length, fabs(d.length[e] - length) / length);
      tiny += length < 1e-12;
    }
    min_edge = fmin(min_edge, shortest);
    max_radius = fmax(max_radius, radius);
    max_ratio = fmax(max_ratio, radius / shortest);
  }
  expect(2 * checked > d.F, "genus %d: only %zu of %zu faces without dummies", g, checked, d.F);
  expect(tiny >= (size_t)(4 * g), "genus %d: only %zu edges shorter than 1e-12", g, tiny);
  const double want[4] = {min_angle, max_ratio, max_radius, min_edge};
  const char *names[4] = {"min angle", "max ratio", "max radius", "min edge"};
  double worst_quality = 0;
  for (int j = 0; j < 4; ++j) {
    expect(q[j] > 0 && isfinite(q[j]), "genus %d: hdt_quality's %s is %g (exact %.3g)", g, names[j], q[j], want[j]);
    /* Compared where every face was (hdt_quality's are all faces). */
    if (checked == d.F) worst_quality = fmax(worst_quality, fabs(q[j] - want[j]) / want[j]);
  }
  printf("tiny edges: genus %d, %zu vertices, %zu of %zu faces, %zu edges shorter than 1e-12 (shortest %.3g): worst relative errors: "
         "lengths %.3g, radii %.3g, hdt_quality %.3g\n",
         g, d.V, checked, d.F, tiny, min_edge, worst_length, worst_radius, worst_quality);
  fflush(stdout);
  worst[0] = fmax(worst[0], worst_length), worst[1] = fmax(worst[1], worst_radius);
  worst[2] = fmax(worst[2], worst_quality);
  for (int i = 0; i < 3; ++i) mpfr_clears(p[i][0], p[i][1], p[i][2], (mpfr_ptr)0);
  free(stored);
  free_dual(&d);
}

START_TEST(tiny_edges_against_mpfr) {
  double worst[4] = {0, 0, 0, 0};
  tiny_edges_case(2, 0x71e1, worst);
  tiny_edges_case(3, 0x71e2, worst);
  tiny_edges_case(5, 0x71e3, worst);
  /* hdt.h's bound (docs/dual.md). */
  expect(worst[0] < TINY_BOUND && worst[1] < TINY_BOUND && worst[2] < TINY_BOUND,
         "relative errors: lengths %.3g, radii %.3g, hdt_quality %.3g", worst[0], worst[1], worst[2]);
  mpfr_free_cache();
}
END_TEST

/* The contract: NULL handle and count, a too small buffer (count set,
   nothing written), a dead vertex, the size query. */
/* The handle keeps the circumcentres (and radii) it computed, for
   hdt_voronoi_cell, hdt_voronoi_vertices and hdt_voronoi_edges, and the
   faces change under it: after insertions and removals, the Voronoi
   vertices and edges must be, to the bit, those of a fresh handle with the
   same faces (hdt_save, hdt_load: an empty cache), and every cell its
   star's circumcentres, mapped by the star's translations. Each round reads
   everything first, so that the next round's changes leave stale entries
   behind. */
static hdt_triangulation *fresh_copy(const hdt_triangulation *t) {
  size_t size = 0;
  OK(hdt_save(t, NULL, 0, &size));
  void *bytes = need(malloc(size));
  OK(hdt_save(t, bytes, size, &size));
  hdt_triangulation *u = NULL;
  OK(hdt_load(&u, bytes, size));
  free(bytes);
  return u;
}

static void check_cells_against_vertices(hdt_triangulation *t, int round) {
  const size_t V = hdt_vertex_count(t), F = hdt_face_count(t);
  uint32_t *ids = need(malloc(V * sizeof *ids)), *faces = need(malloc(F * sizeof *faces));
  int32_t *tr = need(malloc(F * sizeof *tr));
  double *centre = need(malloc(2 * F * sizeof *centre)), *cell = need(malloc(2 * F * sizeof *cell));
  size_t n = 0, m = 0;
  OK(hdt_vertices(t, ids, NULL, NULL, V, &n));
  hdt_triangulation *u = fresh_copy(t);
  const size_t E = hdt_edge_count(t);
  double *radius = need(malloc(F * sizeof *radius)), *mine = need(malloc(4 * E * sizeof *mine)),
         *fresh = need(malloc(4 * E * sizeof *fresh));
  OK(hdt_voronoi_vertices(u, centre, radius, F, &n));
  OK(hdt_voronoi_vertices(t, mine, mine + 2 * F, F, &n));
  expect(memcmp(mine, centre, 2 * F * sizeof *mine) == 0 && memcmp(mine + 2 * F, radius, F * sizeof *mine) == 0,
         "round %d: hdt_voronoi_vertices differs from a fresh handle's", round);
  OK(hdt_voronoi_edges(u, fresh, E, &n));
  OK(hdt_voronoi_edges(t, mine, E, &n));
  expect(memcmp(mine, fresh, 4 * E * sizeof *mine) == 0, "round %d: hdt_voronoi_edges differs from a fresh handle's",
         round);
  hdt_destroy(u);
  free(radius), free(mine), free(fresh);
  for (size_t i = 0; i < V; ++i) {
    OK(hdt_vertex_star(t, ids[i], faces, NULL, tr, F, &n));
    OK(hdt_voronoi_cell(t, ids[i], cell, F, &m));
    expect(m == n, "round %d, vertex %u: cell of %zu corners, star of %zu", round, ids[i], m, n);
    for (size_t k = 0; k < n; ++k) {
      double mt[4], x, y;
      OK(hdt_translation_matrix(t, tr[k], mt));
      apply(mt, centre[2 * faces[k]], centre[2 * faces[k] + 1], &x, &y);
      expect(hypot(x - cell[2 * k], y - cell[2 * k + 1]) < 1e-12,
             "round %d, vertex %u: cell corner %zu is not face %u's centre", round, ids[i], k, faces[k]);
    }
  }
  free(ids), free(faces), free(tr), free(centre), free(cell);
}

START_TEST(cells_follow_changes) {
  hdt_triangulation *t = wide_disk_triangulation(2, 150, 0xce11, 1);
  uint64_t seed = 0xce12;
  for (int round = 0; round < 4; ++round) {
    check_cells_against_vertices(t, round);
    /* Twenty new points (uniform in the disk of radius 0.95), then every
       seventh vertex removed where the guarantee allows it. */
    for (int k = 0; k < 20;) {
      const double x = 1.9 * uniform01(&seed) - 0.95, y = 1.9 * uniform01(&seed) - 0.95;
      if (x * x + y * y >= 0.95 * 0.95) continue;
      OK(hdt_insert(t, x, y, NULL));
      ++k;
    }
    const size_t V = hdt_vertex_count(t);
    uint32_t *ids = need(malloc(V * sizeof *ids));
    size_t n = 0;
    OK(hdt_vertices(t, ids, NULL, NULL, V, &n));
    size_t removed = 0;
    for (size_t i = round; i < V; i += 7) removed += hdt_remove_vertex(t, ids[i]) == HDT_OK;
    expect(removed > 0, "round %d: no vertex could be removed", round);
    free(ids);
  }
  check_cells_against_vertices(t, 4);
  hdt_destroy(t);
}
END_TEST

START_TEST(bad_arguments) {
  hdt_triangulation *t = small_disk_triangulation(2, 30, 9, 1);
  size_t n = 7;
  expect_failure(hdt_face_neighbours(NULL, NULL, NULL, 0, &n), HDT_EINVAL, "hdt_face_neighbours");
  expect_failure(hdt_face_neighbours(t, NULL, NULL, 0, NULL), HDT_EINVAL, "hdt_face_neighbours");
  expect_failure(hdt_edges(NULL, NULL, NULL, NULL, NULL, 0, &n), HDT_EINVAL, "hdt_edges");
  expect(hdt_edge_count(NULL) == 0, "hdt_edge_count(NULL)");
  const size_t F = hdt_face_count(t), E = hdt_edge_count(t);
  expect_failure(hdt_face_points(t, NULL, F, &n), HDT_EINVAL, "hdt_face_points");
  expect_failure(hdt_voronoi_edges(t, NULL, E, &n), HDT_EINVAL, "hdt_voronoi_edges");
  double *small = need(malloc(6 * F * sizeof *small));
  for (size_t i = 0; i < 6 * F; ++i) small[i] = -7;
  n = 0;
  expect_failure(hdt_face_points(t, small, F - 1, &n), HDT_EBUFS, "hdt_face_points");
  expect(n == F, "HDT_EBUFS: count %zu, F %zu", n, F);
  expect_failure(hdt_voronoi_vertices(t, small, small, F - 1, &n), HDT_EBUFS, "hdt_voronoi_vertices");
  expect_failure(hdt_voronoi_edges(t, small, E - 1, &n), HDT_EBUFS, "hdt_voronoi_edges");
  expect(n == E, "HDT_EBUFS: count %zu, E %zu", n, E);
  for (size_t i = 0; i < 6 * F; ++i) expect(small[i] == -7, "a failed call wrote entry %zu", i);
  const uint32_t dead = (uint32_t)hdt_vertex_id_bound(t);
  expect_failure(hdt_vertex_star(t, dead, NULL, NULL, NULL, 0, &n), HDT_EINVAL, "hdt_vertex_star");
  expect_failure(hdt_voronoi_cell(t, dead, NULL, 0, &n), HDT_EINVAL, "hdt_voronoi_cell");
  expect_failure(hdt_vertex_star(t, 40, NULL, NULL, NULL, 0, NULL), HDT_EINVAL, "hdt_vertex_star");
  /* Sizes: capacity 0 asks; every output may be NULL. */
  OK(hdt_edges(t, NULL, NULL, NULL, NULL, 0, &n));
  expect(n == E && E == 3 * F / 2, "hdt_edges size %zu, E %zu", n, E);
  OK(hdt_edges(t, NULL, NULL, NULL, NULL, E, &n));
  OK(hdt_voronoi_vertices(t, NULL, NULL, F, &n));
  expect(n == F, "hdt_voronoi_vertices: %zu", n);
  free(small);
  hdt_destroy(t);
}
END_TEST

int main(void) {
  const TTest *const tests[] = {neighbours_are_an_involution,       stars_cover_each_face_three_times,
                                edges_against_brute_force,          face_points_are_the_translated_corners,
                                voronoi_vertices_are_empty_circles, voronoi_cells_tile_the_surface,
                                cells_follow_changes,               constructions_against_mpfr,
                                tiny_edges_against_mpfr,            bad_arguments};
  return run_tests("dual", tests, sizeof tests / sizeof tests[0]);
}
