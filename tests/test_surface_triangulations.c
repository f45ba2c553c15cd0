/* Triangulations of surfaces given by a polygon (HDT_0.8), through the
   public header. The triangulations are checked by computations of this
   file alone, in double precision, from what the API reports (vertex
   points, faces, their translations' matrices, neighbours): Euler's
   formula, the faces' hyperbolic areas summing to 4 pi (g - 1), the empty
   circle across every edge, the translation words against the pairings'
   matrices, point location against the located triangle. M_2 given as
   the Bolza octagon must give the built-in M_2's faces on the same points.
   Every call the polygon handle does not support yet must say so and
   change nothing. */
#include <complex.h>

#define PI 3.14159265358979323846

#include "hdt_test.h"

/* The Bolza surface's octagon (as in test_surfaces.c): v_k =
   2^(-1/4) e^(i (2k+1) pi/8) in Q(a), a = sqrt(sqrt2 + 1). */
#define BOLZA_VERTICES                                                              \
  "1/2*a 1/2*a^3-a\n1/2*a^3-a 1/2*a\n-1/2*a^3+a 1/2*a\n-1/2*a 1/2*a^3-a\n"          \
  "-1/2*a -1/2*a^3+a\n-1/2*a^3+a -1/2*a\n1/2*a^3-a -1/2*a\n1/2*a -1/2*a^3+a\n"
static const char bolza[] = "field a^4-2*a^2-1 a 1.5538+/-0.01\n8\n4 5 6 7 0 1 2 3\n" BOLZA_VERTICES;
/* The same octagon glued as a1 b1 a1^-1 b1^-1 a2 b2 a2^-1 b2^-1. */
static const char bolza_commutator[] = "field a^4-2*a^2-1 a 1.5538+/-0.01\n8\n2 3 0 1 6 7 4 5\n" BOLZA_VERTICES;

/* HDT_TEST_SCALE (a positive number, default 1) scales the points and the
   refinements' work: .ci/valgrind sets 0.25. */
static double test_scale(void) {
  const char *s = getenv("HDT_TEST_SCALE");
  const double v = s ? atof(s) : 1;
  return v > 0 && v <= 1 ? v : 1;
}
static size_t scaled(size_t n) { return (size_t)ceil((double)n * test_scale()); }

typedef struct mob_t {
  double complex a, b; /* z -> (a z + b) / (conj(b) z + conj(a)) */
} mob_t;

static double complex mob_apply(mob_t m, double complex z) { return (m.a * z + m.b) / (conj(m.b) * z + conj(m.a)); }
static mob_t mob_inverse(mob_t m) { return (mob_t){conj(m.a), -m.b}; }
static mob_t mob_compose(mob_t f, mob_t g) { /* f after g */
  return (mob_t){f.a * g.a + f.b * conj(g.b), f.a * g.b + f.b * conj(g.a)};
}
static int mob_close(mob_t f, mob_t g, double tol) {
  const double scale = cabs(f.a) + cabs(f.b);
  return (cabs(f.a - g.a) + cabs(f.b - g.b) < tol * scale) || (cabs(f.a + g.a) + cabs(f.b + g.b) < tol * scale);
}

static hdt_surface *random_surface(int sides, uint64_t seed) {
  hdt_surface *s = NULL;
  OK(hdt_surface_random_symmetric(&s, sides, seed));
  return s;
}

static hdt_triangulation *on_surface(const hdt_surface *s) {
  hdt_triangulation *t = NULL;
  const hdt_status st = hdt_create_on_surface(&t, s);
  expect(st == HDT_OK && t, "hdt_create_on_surface: %s (%s)", hdt_status_string(st), hdt_last_error_message());
  expect(hdt_genus(t) == hdt_surface_genus(s), "genus %d, the surface's %d", hdt_genus(t), hdt_surface_genus(s));
  return t;
}

/* Everything the checks read, copied out of a triangulation. */
typedef struct mesh_t {
  int genus;
  size_t V, F, id_bound;
  double complex *point; /* by vertex id (NAN for dead ids) */
  uint32_t *fv, *nf;     /* 3 per face: vertices, neighbour faces */
  int32_t *ft, *nt;      /* 3 per face: corner translations, neighbour translations */
} mesh_t;

static mob_t matrix_of(const hdt_triangulation *t, int32_t id) {
  double m[4];
  OK(hdt_translation_matrix(t, id, m));
  return (mob_t){m[0] + I * m[1], m[2] + I * m[3]};
}

static mesh_t read_mesh(const hdt_triangulation *t) {
  mesh_t m = {hdt_genus(t), hdt_vertex_count(t), hdt_face_count(t), hdt_vertex_id_bound(t), NULL, NULL, NULL, NULL, NULL};
  m.point = malloc(m.id_bound * sizeof *m.point);
  uint32_t *ids = malloc(m.V * sizeof *ids);
  double *xy = malloc(2 * m.V * sizeof *xy);
  m.fv = malloc(3 * m.F * sizeof *m.fv), m.nf = malloc(3 * m.F * sizeof *m.nf);
  m.ft = malloc(3 * m.F * sizeof *m.ft), m.nt = malloc(3 * m.F * sizeof *m.nt);
  ck_assert(m.point && ids && xy && m.fv && m.nf && m.ft && m.nt);
  size_t count;
  OK(hdt_vertices(t, ids, xy, NULL, m.V, &count));
  expect(count == m.V, "hdt_vertices gives %zu of %zu", count, m.V);
  for (size_t v = 0; v < m.id_bound; ++v) m.point[v] = NAN;
  for (size_t i = 0; i < m.V; ++i) m.point[ids[i]] = xy[2 * i] + I * xy[2 * i + 1];
  OK(hdt_faces(t, m.fv, m.ft, m.F, &count));
  OK(hdt_face_neighbours(t, m.nf, m.nt, m.F, &count));
  free(ids);
  free(xy);
  return m;
}

static void free_mesh(mesh_t *m) {
  free(m->point), free(m->fv), free(m->nf), free(m->ft), free(m->nt);
}

/* Corner i of face f of the canonical copy, in the disk. */
static double complex corner(const hdt_triangulation *t, const mesh_t *m, size_t f, int i) {
  return mob_apply(matrix_of(t, m->ft[3 * f + i]), m->point[m->fv[3 * f + i]]);
}

/* The direction at v of the geodesic from v to w (conformal at v). */
static double direction(double complex v, double complex w) { return carg((w - v) / (1 - conj(v) * w)); }

/* The interior angle at a of the geodesic triangle a b c (counterclockwise). */
static double angle(double complex a, double complex b, double complex c) {
  double d = direction(a, c) - direction(a, b);
  while (d < 0) d += 2 * PI;
  while (d >= 2 * PI) d -= 2 * PI;
  return d;
}

/* Whether q lies strictly inside the Euclidean circle through a, b, c of
   the disk (a hyperbolic circle, horocycle or hypercycle: the one of the
   empty-circle property), beyond a relative margin for rounding. */
static int inside_circle(double complex a, double complex b, double complex c, double complex q) {
  const double complex ab = b - a, ac = c - a;
  const double d = 2 * cimag(conj(ab) * ac);
  const double complex centre = a + I * (ab * cabs(ac) * cabs(ac) - ac * cabs(ab) * cabs(ab)) / d;
  const double r = cabs(a - centre);
  return cabs(q - centre) < r * (1 - 1e-9);
}

/* Euler's formula, the area, and the empty circle across every edge. */
static void expect_delaunay(const hdt_triangulation *t) {
  OK(hdt_validate(t));
  mesh_t m = read_mesh(t);
  expect(m.F == 2 * (m.V + 2 * (size_t)m.genus - 2), "F = %zu, V = %zu at genus %d", m.F, m.V, m.genus);
  expect(hdt_edge_count(t) == 3 * m.F / 2, "%zu edges for %zu faces", hdt_edge_count(t), m.F);
  double area = 0;
  for (size_t f = 0; f < m.F; ++f) {
    double complex z[3];
    for (int i = 0; i < 3; ++i) z[i] = corner(t, &m, f, i);
    const double a = PI - angle(z[0], z[1], z[2]) - angle(z[1], z[2], z[0]) - angle(z[2], z[0], z[1]);
    expect(a > 0, "face %zu has area %g", f, a);
    area += a;
    for (int i = 0; i < 3; ++i) {
      /* The neighbour's copy across the edge opposite corner i, and its
         corner off that edge. */
      const size_t g = m.nf[3 * f + i];
      const mob_t h = matrix_of(t, m.nt[3 * f + i]);
      const double complex p = z[(i + 1) % 3], q = z[(i + 2) % 3];
      double complex far = 0;
      double far_d = -1;
      int on_edge = 0;
      for (int j = 0; j < 3; ++j) {
        const double complex w = mob_apply(h, corner(t, &m, g, j));
        const double d = fmin(cabs(w - p), cabs(w - q));
        if (d < 1e-9) ++on_edge;
        if (d > far_d) far_d = d, far = w;
      }
      expect(on_edge == 2, "face %zu, corner %d: the neighbour's copy shares %d corners", f, i, on_edge);
      expect(!inside_circle(z[0], z[1], z[2], far), "face %zu: its neighbour %zu's vertex is inside its circle", f, g);
    }
  }
  const double expected = 4 * PI * (m.genus - 1);
  expect(fabs(area - expected) < 1e-9 * expected, "the faces' areas sum to %.17g, not 4 pi (g - 1) = %.17g", area,
         expected);
  free_mesh(&m);
}

/* Every translation of the faces and neighbours: its word's product of the
   surface's pairings is its matrix. */
static void expect_translation_words(const hdt_triangulation *t, const hdt_surface *s) {
  mesh_t m = read_mesh(t);
  for (size_t k = 0; k < 6 * m.F; ++k) {
    const int32_t id = k < 3 * m.F ? m.ft[k] : m.nt[k - 3 * m.F];
    int32_t word[64];
    size_t length;
    OK(hdt_translation_word(t, id, word, 64, &length));
    mob_t product = {1, 0};
    for (size_t i = 0; i < length; ++i) {
      double q[4];
      OK(hdt_surface_pairing(s, word[i], NULL, q));
      product = mob_compose(product, (mob_t){q[0] + I * q[1], q[2] + I * q[3]});
    }
    expect(mob_close(product, matrix_of(t, id), 1e-10), "translation %d: its word's product is not its matrix", id);
    expect((id == 0) == (length == 0), "translation %d has a word of %zu letters", id, length);
  }
  size_t length;
  expect(hdt_translation_word(t, -1, NULL, 0, &length) == HDT_EINVAL, "translation id -1 accepted");
  free_mesh(&m);
}

/* Whether z lies in the closed geodesic triangle a b c (counterclockwise),
   up to a margin: geodesics are straight in the Klein model. */
static int in_triangle(double complex a, double complex b, double complex c, double complex z) {
  const double complex k[4] = {2 * a / (1 + a * conj(a)), 2 * b / (1 + b * conj(b)), 2 * c / (1 + c * conj(c)),
                               2 * z / (1 + z * conj(z))};
  for (int i = 0; i < 3; ++i)
    if (cimag(conj(k[(i + 1) % 3] - k[i]) * (k[3] - k[i])) < -1e-12) return 0;
  return 1;
}

static void expect_locate(const hdt_triangulation *t, uint64_t seed) {
  mesh_t m = read_mesh(t);
  for (int n = 0; n < 200; ++n) {
    const double r = 0.97 * sqrt(uniform01(&seed)), phi = 2 * PI * uniform01(&seed);
    const double complex q = r * cexp(I * phi);
    size_t f;
    int32_t h;
    OK(hdt_locate(t, creal(q), cimag(q), &f, &h));
    expect(f < m.F, "located face %zu of %zu", f, m.F);
    const mob_t H = matrix_of(t, h);
    expect(in_triangle(mob_apply(H, corner(t, &m, f, 0)), mob_apply(H, corner(t, &m, f, 1)),
                       mob_apply(H, corner(t, &m, f, 2)), q),
           "(%g, %g) is not in the located copy of face %zu", creal(q), cimag(q), f);
  }
  /* The nearest vertex to a point next to a vertex is that vertex. */
  for (size_t v = 0; v < m.id_bound; v += 7) {
    if (isnan(creal(m.point[v]))) continue;
    uint32_t nearest;
    OK(hdt_nearest_vertex(t, creal(m.point[v]) + 1e-9, cimag(m.point[v]), &nearest));
    expect(nearest == v, "the vertex nearest to vertex %zu's point is %u", v, nearest);
  }
  free_mesh(&m);
}

/* n points uniform in the disk of radius 0.95 (most outside the polygon). */
static double *wide_points(size_t n, uint64_t seed) { return uniform_disk_points(n, seed, 0.95); }

/* The checks on the dummy set, after insertions, and after removals. */
static void expect_triangulations_of(const hdt_surface *s, size_t n, uint64_t seed) {
  hdt_triangulation *t = on_surface(s);
  expect(hdt_vertex_count(t) == hdt_dummy_count(t) && hdt_dummy_count(t) > 0, "%zu vertices, %zu dummies",
         hdt_vertex_count(t), hdt_dummy_count(t));
  expect_delaunay(t);
  double *xy = wide_points(n, seed);
  uint32_t *ids = malloc(n * sizeof *ids);
  ck_assert_ptr_nonnull(ids);
  OK(hdt_insert_many(t, xy, n / 2, ids));
  for (size_t i = n / 2; i < n; ++i) OK(hdt_insert(t, xy[2 * i], xy[2 * i + 1], &ids[i]));
  expect_delaunay(t);
  expect_translation_words(t, s);
  expect_locate(t, seed + 1);
  /* A vertex's point is its representative: the same point of the surface
     as the one inserted. */
  for (size_t i = 0; i < n; i += 11) {
    double x, y, rx, ry;
    size_t length;
    OK(hdt_vertex_point(t, ids[i], &x, &y));
    OK(hdt_surface_representative(s, xy[2 * i], xy[2 * i + 1], &rx, &ry, NULL, 0, &length));
    expect(fabs(x - rx) < 1e-12 && fabs(y - ry) < 1e-12, "vertex %u at (%.17g, %.17g), its representative (%.17g, %.17g)",
           ids[i], x, y, rx, ry);
    expect(hdt_vertex_is_dummy(t, ids[i]) == 0, "vertex %u is called a dummy", ids[i]);
  }
  uint32_t again;
  expect(hdt_insert(t, xy[0], xy[1], &again) == HDT_EEXISTS && again == ids[0], "a point inserted twice");
  size_t left;
  OK(hdt_remove_dummies(t, &left));
  expect(left == hdt_dummy_count(t), "%zu dummies left, the count says %zu", left, hdt_dummy_count(t));
  for (size_t i = 0; i < n; i += 5) {
    const hdt_status st = hdt_remove_vertex(t, ids[i]);
    expect(st == HDT_OK || st == HDT_ENOTSUP, "hdt_remove_vertex: %s", hdt_last_error_message());
  }
  expect_delaunay(t);
  free(ids);
  free(xy);
  hdt_destroy(t);
}

START_TEST(bolza_octagon) {
  hdt_surface *s = surface_from_text(bolza);
  expect_triangulations_of(s, scaled(400), 11);
  hdt_surface_destroy(s);
}
END_TEST

START_TEST(bolza_commutator_octagon) {
  hdt_surface *s = surface_from_text(bolza_commutator);
  expect_triangulations_of(s, scaled(400), 12);
  hdt_surface_destroy(s);
}
END_TEST

START_TEST(random_octagons) {
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    hdt_surface *s = random_surface(8, seed);
    expect_triangulations_of(s, scaled(400), 20 + seed);
    hdt_surface_destroy(s);
  }
}
END_TEST

START_TEST(random_decagon) {
  hdt_surface *s = random_surface(10, 4);
  expect_triangulations_of(s, scaled(400), 30);
  hdt_surface_destroy(s);
}
END_TEST

/* A face as the points' indices from the smallest, and the other two
   corners' points seen from the first corner's copy: the same for every
   copy of the face, whichever path computed it. */
typedef struct face_key_t {
  size_t v[3];
  double complex w[2];
} face_key_t;

static int key_order(const void *a, const void *b) {
  const face_key_t *x = a, *y = b;
  for (int i = 0; i < 3; ++i)
    if (x->v[i] != y->v[i]) return x->v[i] < y->v[i] ? -1 : 1;
  return 0;
}

/* The keys of t's faces, its vertex ids mapped to the indices of the
   points inserted (ids[i] is point i's vertex). */
static face_key_t *face_keys(const hdt_triangulation *t, const uint32_t *ids, size_t n, size_t *F) {
  mesh_t m = read_mesh(t);
  size_t *index = malloc(m.id_bound * sizeof *index);
  face_key_t *keys = malloc(m.F * sizeof *keys);
  ck_assert(index && keys);
  for (size_t v = 0; v < m.id_bound; ++v) index[v] = SIZE_MAX;
  for (size_t i = 0; i < n; ++i) index[ids[i]] = i;
  for (size_t f = 0; f < m.F; ++f) {
    int first = 0;
    for (int i = 1; i < 3; ++i)
      if (index[m.fv[3 * f + i]] < index[m.fv[3 * f + first]]) first = i;
    const mob_t back = mob_inverse(matrix_of(t, m.ft[3 * f + first]));
    for (int i = 0; i < 3; ++i) {
      const int c = (first + i) % 3;
      keys[f].v[i] = index[m.fv[3 * f + c]];
      expect(keys[f].v[i] != SIZE_MAX, "face %zu has a vertex that is no inserted point", f);
      if (i > 0) keys[f].w[i - 1] = mob_apply(back, corner(t, &m, f, c));
    }
  }
  qsort(keys, m.F, sizeof *keys, key_order);
  *F = m.F;
  free(index);
  free_mesh(&m);
  return keys;
}

/* M_2 given as the Bolza octagon and the built-in M_2, on the same points,
   dummies removed: the same faces, translation for translation (seen
   through the copies' corner points, as the two paths number translations
   differently). */
START_TEST(bolza_octagon_is_the_built_in_m2) {
  hdt_surface *s = surface_from_text(bolza);
  hdt_triangulation *p = on_surface(s), *b = new_triangulation(2);
  const size_t n = scaled(600);
  double *xy = wide_points(n, 41);
  uint32_t *pid = malloc(n * sizeof *pid), *bid = malloc(n * sizeof *bid);
  ck_assert(pid && bid);
  OK(hdt_insert_many(p, xy, n, pid));
  OK(hdt_insert_many(b, xy, n, bid));
  size_t left;
  OK(hdt_remove_dummies(p, &left));
  expect(left == 0, "%zu dummies left on the polygon", left);
  OK(hdt_remove_dummies(b, &left));
  expect(left == 0, "%zu dummies left on the built-in M_2", left);
  size_t pf, bf;
  face_key_t *pk = face_keys(p, pid, n, &pf), *bk = face_keys(b, bid, n, &bf);
  expect(pf == bf, "%zu faces on the polygon, %zu on the built-in M_2", pf, bf);
  for (size_t f = 0; f < pf; ++f) {
    int found = 0;
    for (size_t g = 0; g < bf && !found; ++g)
      found = key_order(&pk[f], &bk[g]) == 0 && cabs(pk[f].w[0] - bk[g].w[0]) < 1e-9 &&
              cabs(pk[f].w[1] - bk[g].w[1]) < 1e-9;
    expect(found, "the polygon's face (%zu, %zu, %zu) is no face of the built-in M_2", pk[f].v[0], pk[f].v[1],
           pk[f].v[2]);
  }
  free(pk), free(bk), free(pid), free(bid), free(xy);
  hdt_destroy(p), hdt_destroy(b);
  hdt_surface_destroy(s);
}
END_TEST

/* The hyperbolic radius of the circle through three disk points: the
   Euclidean circle (centre c, radius R) meets the ray from 0 through c at
   |c| - R and |c| + R, a diameter. */
static double circumradius(double complex a, double complex b, double complex c) {
  const double complex ab = b - a, ac = c - a;
  const double d = 2 * cimag(conj(ab) * ac);
  const double complex centre = a + I * (ab * cabs(ac) * cabs(ac) - ac * cabs(ab) * cabs(ab)) / d;
  const double R = cabs(a - centre), m = cabs(centre);
  return atanh(m + R) - atanh(m - R);
}

static double distance(double complex p, double complex q) { return 2 * atanh(cabs(p - q) / cabs(1 - conj(p) * q)); }

/* The Voronoi cells tile the surface: their areas ((k - 2) pi minus the
   angles of each convex cell) sum to 4 pi (g - 1); the stars of one call
   are those of one vertex at a time. */
static void expect_dual(const hdt_triangulation *t) {
  const size_t bound = hdt_vertex_id_bound(t), F = hdt_face_count(t);
  size_t *offsets = malloc((bound + 1) * sizeof *offsets), count;
  double *xy = malloc(6 * F * sizeof *xy);
  uint32_t *faces = malloc(3 * F * sizeof *faces), *one = malloc(3 * F * sizeof *one);
  ck_assert(offsets && xy && faces && one);
  OK(hdt_voronoi_cells(t, offsets, xy, 3 * F, &count));
  expect(count == 3 * F, "%zu cell corners for %zu faces", count, F);
  double area = 0;
  for (size_t v = 0; v < bound; ++v) {
    const size_t k = offsets[v + 1] - offsets[v];
    if (k == 0) continue;
    double sum = 0;
    for (size_t i = 0; i < k; ++i) {
      const double *p = xy + 2 * (offsets[v] + i), *a = xy + 2 * (offsets[v] + (i + k - 1) % k),
                   *b = xy + 2 * (offsets[v] + (i + 1) % k);
      sum += angle(p[0] + I * p[1], b[0] + I * b[1], a[0] + I * a[1]);
    }
    area += (double)(k - 2) * PI - sum;
  }
  const double expected = 4 * PI * (hdt_genus(t) - 1);
  expect(fabs(area - expected) < 1e-8 * expected, "the Voronoi cells' areas sum to %.17g, not %.17g", area, expected);
  OK(hdt_vertex_stars(t, offsets, faces, NULL, NULL, 3 * F, &count));
  for (size_t v = 0; v < bound; v += 3) {
    if (offsets[v + 1] == offsets[v]) continue;
    OK(hdt_vertex_star(t, (uint32_t)v, one, NULL, NULL, 3 * F, &count));
    expect(count == offsets[v + 1] - offsets[v] && memcmp(one, faces + offsets[v], count * sizeof *one) == 0,
           "vertex %zu's star differs between the two calls", v);
  }
  free(offsets), free(xy), free(faces), free(one);
}

/* The largest circumradius and ratio over the faces, and the shortest edge
   at a vertex of id >= from, all computed here from the corners. */
static void measure(const hdt_triangulation *t, uint32_t from, double *radius, double *ratio, double *shortest) {
  mesh_t m = read_mesh(t);
  *radius = *ratio = 0, *shortest = INFINITY;
  for (size_t f = 0; f < m.F; ++f) {
    double complex z[3];
    double edge = INFINITY;
    for (int i = 0; i < 3; ++i) z[i] = corner(t, &m, f, i);
    for (int i = 0; i < 3; ++i) {
      const double d = distance(z[(i + 1) % 3], z[(i + 2) % 3]);
      edge = fmin(edge, d);
      if (m.fv[3 * f + (i + 1) % 3] >= from || m.fv[3 * f + (i + 2) % 3] >= from) *shortest = fmin(*shortest, d);
    }
    const double r = circumradius(z[0], z[1], z[2]);
    *radius = fmax(*radius, r), *ratio = fmax(*ratio, r / edge);
  }
  free_mesh(&m);
}

/* Refinement and epsilon-nets meet their bounds, measured here. */
static void expect_refinement(const hdt_surface *s, uint64_t seed) {
  hdt_triangulation *t = on_surface(s);
  const size_t n = scaled(200);
  /* The bounds' work grows as 1 / radius^2: the radius grows as the scale shrinks. */
  const double r = 0.3 / sqrt(test_scale()), eps = 0.1 / sqrt(test_scale());
  double *xy = wide_points(n, seed);
  OK(hdt_insert_many(t, xy, n, NULL));
  expect_dual(t);
  size_t added, unmet;
  OK(hdt_refine(t, r, 1.2, SIZE_MAX, &added, &unmet));
  expect(unmet == 0 && added > 0, "refinement: %zu added, %zu unmet", added, unmet);
  double radius, ratio, shortest;
  measure(t, 0, &radius, &ratio, &shortest);
  expect(radius <= r * (1 + 1e-6) && ratio <= 1.2 * (1 + 1e-6), "after refinement: radius %.17g, ratio %.17g",
         radius, ratio);
  double qa, qr, qm, qe;
  OK(hdt_quality(t, &qa, &qr, &qm, &qe));
  expect(fabs(qm - radius) < 1e-9 && fabs(qr - ratio) < 1e-9 * ratio, "hdt_quality: radius %.17g, ratio %.17g", qm, qr);
  expect_delaunay(t);
  expect_dual(t);
  hdt_destroy(t);
  free(xy);

  t = on_surface(s);
  const uint32_t from = (uint32_t)hdt_vertex_id_bound(t);
  OK(hdt_epsilon_net(t, eps, SIZE_MAX, &added, &unmet));
  expect(unmet == 0 && added > 0, "epsilon-net: %zu added, %zu unmet", added, unmet);
  measure(t, from, &radius, &ratio, &shortest);
  expect(radius <= eps * (1 + 1e-6), "an epsilon-net with a face of circumradius %.17g", radius);
  expect(shortest >= eps * (1 - 1e-6), "an epsilon-net with points %.17g apart", shortest);
  expect_delaunay(t);
  expect_dual(t);
  hdt_destroy(t);
}

START_TEST(dual_and_refinement) {
  hdt_surface *s = random_surface(8, 1);
  expect_refinement(s, 50);
  hdt_surface_destroy(s);
  s = random_surface(10, 4);
  expect_refinement(s, 51);
  hdt_surface_destroy(s);
  s = surface_from_text(bolza_commutator);
  expect_refinement(s, 52);
  hdt_surface_destroy(s);
}
END_TEST

/* The saved bytes of t (malloc'ed, *size of them). */
static unsigned char *saved(const hdt_triangulation *t, size_t *size) {
  OK(hdt_save(t, NULL, 0, size));
  unsigned char *bytes = malloc(*size);
  ck_assert_ptr_nonnull(bytes);
  size_t written;
  OK(hdt_save(t, bytes, *size, &written));
  expect(written == *size, "hdt_save wrote %zu bytes of %zu", written, *size);
  return bytes;
}

static void expect_same_faces(const hdt_triangulation *a, const hdt_triangulation *b, const char *what) {
  mesh_t m = read_mesh(a), n = read_mesh(b);
  expect(m.V == n.V && m.F == n.F && m.id_bound == n.id_bound, "%s: other counts", what);
  expect(memcmp(m.fv, n.fv, 3 * m.F * sizeof *m.fv) == 0 && memcmp(m.ft, n.ft, 3 * m.F * sizeof *m.ft) == 0 &&
             memcmp(m.nf, n.nf, 3 * m.F * sizeof *m.nf) == 0 && memcmp(m.nt, n.nt, 3 * m.F * sizeof *m.nt) == 0,
         "%s: other faces", what);
  for (size_t v = 0; v < m.id_bound; ++v)
    expect(memcmp(&m.point[v], &n.point[v], sizeof m.point[v]) == 0, "%s: vertex %zu moved", what, v);
  free_mesh(&m), free_mesh(&n);
}

/* Saved and loaded: the same triangulation, byte for byte, the polygon
   kept exactly (its text given back), and the same later insertions;
   damaged files refused with the byte at fault. */
static void expect_round_trip(const hdt_surface *s, uint64_t seed) {
  hdt_triangulation *t = on_surface(s), *u = NULL;
  const size_t n = scaled(300);
  double *xy = wide_points(2 * n, seed);
  OK(hdt_insert_many(t, xy, n, NULL));
  OK(hdt_remove_dummies(t, NULL));
  for (uint32_t v = 0; v < 40; v += 3) (void)hdt_remove_vertex(t, v);  /* gaps in the ids */
  size_t size, again;
  unsigned char *bytes = saved(t, &size);
  OK(hdt_load(&u, bytes, size));
  expect(hdt_genus(u) == hdt_genus(t), "genus %d loaded, %d saved", hdt_genus(u), hdt_genus(t));
  expect_same_faces(t, u, "loaded");
  unsigned char *twice = saved(u, &again);
  expect(again == size && memcmp(bytes, twice, size) == 0, "saving the loaded one gives other bytes");
  hdt_surface *back = NULL;
  char a[8192], b[8192];
  size_t la, lb;
  OK(hdt_triangulation_surface(u, &back));
  OK(hdt_surface_polygon_text(s, a, sizeof a, &la));
  OK(hdt_surface_polygon_text(back, b, sizeof b, &lb));
  expect(la == lb && strcmp(a, b) == 0, "the loaded polygon differs");
  hdt_surface_destroy(back);
  OK(hdt_insert_many(t, xy + 2 * n, n, NULL));
  OK(hdt_insert_many(u, xy + 2 * n, n, NULL));
  expect_same_faces(t, u, "after the same insertions");
  OK(hdt_validate(u));
  /* A damaged byte: the checksum; the polygon's text changed with the
     checksum made good again: its exact check. */
  bytes[size / 2] ^= 1;
  hdt_triangulation *none = (hdt_triangulation *)1;
  expect(hdt_load(&none, bytes, size) == HDT_EINVAL && strstr(hdt_last_error_message(), "checksum"),
         "a damaged file: %s", hdt_last_error_message());
  bytes[size / 2] ^= 1;
  const size_t text_at = 48;
  unsigned char *digit = memchr(bytes + text_at, '1', size - text_at);
  ck_assert_ptr_nonnull(digit);
  *digit = '3';
  uint32_t crc = 0xFFFFFFFFu;  /* CRC-32 (ISO-HDLC), bit by bit */
  for (size_t i = 0; i + 4 < size; ++i) {
    crc ^= bytes[i];
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1)));
  }
  crc ^= 0xFFFFFFFFu;
  for (int k = 0; k < 4; ++k) bytes[size - 4 + k] = (unsigned char)(crc >> (8 * k));
  expect(hdt_load(&none, bytes, size) == HDT_EINVAL && strstr(hdt_last_error_message(), "the polygon"),
         "a changed polygon: %s", hdt_last_error_message());
  free(bytes), free(twice), free(xy);
  hdt_destroy(t), hdt_destroy(u);
}

START_TEST(save_and_load) {
  hdt_surface *s = random_surface(8, 2);
  expect_round_trip(s, 60);
  hdt_surface_destroy(s);
  s = random_surface(10, 1);
  expect_round_trip(s, 61);
  hdt_surface_destroy(s);
  s = surface_from_text(bolza_commutator);
  expect_round_trip(s, 62);
  hdt_surface_destroy(s);
}
END_TEST

/* The gcd of the maximal minors of the 2g x m matrix c (columns c[j]):
   1 exactly when the columns span Z^{2g}. Cofactor expansion over column
   subsets: m is at most 6 here. */
static long long minor_gcd(long long c[][8], int rows, int m) {
  long long g = 0;
  for (unsigned mask = 0; mask < (1u << m); ++mask) {
    if (__builtin_popcount(mask) != rows) continue;
    long long a[8][8];
    int k = 0;
    for (int j = 0; j < m; ++j)
      if (mask >> j & 1) {
        for (int i = 0; i < rows; ++i) a[i][k] = c[j][i];
        ++k;
      }
    long long det = 1;  /* fraction-free Gaussian elimination (Bareiss) */
    long long prev = 1;
    for (int p = 0; p < rows && det != 0; ++p) {
      int q = p;
      while (q < rows && a[q][p] == 0) ++q;
      if (q == rows) { det = 0; break; }
      if (q != p) for (int j = 0; j < rows; ++j) { long long x = a[p][j]; a[p][j] = a[q][j]; a[q][j] = x; det = -det; }
      for (int i = p + 1; i < rows; ++i)
        for (int j = p + 1; j < rows; ++j) a[i][j] = (a[i][j] * a[p][p] - a[i][p] * a[p][j]) / prev;
      prev = a[p][p];
    }
    if (det != 0) det *= a[rows - 1][rows - 1];
    long long x = llabs(det), y = g;
    while (y) { const long long r = x % y; x = y; y = r; }
    g = x;
  }
  return g;
}

/* H_1 on a polygon surface, checked from words and cycles alone: each
   pairing's class c_k, c_paired(k) = -c_k, each vertex cycle's pairings
   summing to 0, every translation's class the sum of its letters' (a
   homomorphism), and the classes spanning Z^{2g}. */
static void expect_homology(const hdt_surface *s, uint64_t seed) {
  hdt_triangulation *t = on_surface(s);
  double *xy = wide_points(scaled(200), seed);
  OK(hdt_insert_many(t, xy, scaled(200), NULL));
  const int n = hdt_surface_side_count(s), g2 = 2 * hdt_surface_genus(s);
  long long c[16][8];
  int known[16] = {0};
  int32_t word[64], h[8];
  size_t length, count;
  /* The ids in order until one is unknown: the pairings' single letters first. */
  int32_t ids = 0;
  for (;; ++ids) {
    if (hdt_translation_word(t, ids, word, 64, &length) != HDT_OK) break;
    OK(hdt_translation_homology(t, ids, h, 8, &count));
    expect(count == (size_t)g2, "%zu homology coordinates at genus %d", count, g2 / 2);
    if (length == 1) {
      for (int i = 0; i < g2; ++i) c[word[0]][i] = h[i];
      known[word[0]] = 1;
    }
  }
  for (int k = 0; k < n; ++k) expect(known[k], "no translation id is the pairing of side %d", k);
  int paired[16], cycle[16];
  size_t cycles;
  for (int k = 0; k < n; ++k) OK(hdt_surface_pairing(s, k, &paired[k], NULL));
  OK(hdt_surface_vertex_cycles(s, cycle, 16, &cycles));
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < g2; ++i) expect(c[paired[k]][i] == -c[k][i], "the classes of g_%d and g_%d do not cancel", k, paired[k]);
  for (size_t cy = 0; cy < cycles; ++cy)
    for (int i = 0; i < g2; ++i) {
      long long sum = 0;
      for (int v = 0; v < n; ++v) sum += cycle[v] == (int)cy ? c[paired[v]][i] : 0;
      expect(sum == 0, "vertex cycle %zu's relation has class %lld at coordinate %d", cy, sum, i);
    }
  for (int32_t id = 0; id < ids; ++id) {
    OK(hdt_translation_word(t, id, word, 64, &length));
    OK(hdt_translation_homology(t, id, h, 8, &count));
    for (int i = 0; i < g2; ++i) {
      long long sum = 0;
      for (size_t l = 0; l < length; ++l) sum += c[word[l]][i];
      expect(sum == h[i], "translation %d: class %d at coordinate %d, its letters sum to %lld", id, h[i], i, sum);
    }
  }
  long long columns[8][8];
  int m = 0;
  for (int k = 0; k < n; ++k)
    if (k < paired[k]) {
      for (int i = 0; i < g2; ++i) columns[m][i] = c[k][i];
      ++m;
    }
  expect(minor_gcd(columns, g2, m) == 1, "the pairings' classes do not span Z^%d", g2);
  free(xy);
  hdt_destroy(t);
}

START_TEST(homology) {
  hdt_surface *s = random_surface(8, 1);
  expect_homology(s, 80);
  hdt_surface_destroy(s);
  s = random_surface(10, 2);
  expect_homology(s, 81);
  hdt_surface_destroy(s);
  s = surface_from_text(bolza_commutator);
  expect_homology(s, 82);
  hdt_surface_destroy(s);
}
END_TEST

/* The picture: the polygon's sides drawn (its clip path holds one arc a
   side), the caption names the surface, the Voronoi diagram and the tiles
   across the sides come when asked. */
START_TEST(pictures) {
  hdt_surface *s = random_surface(10, 3);
  hdt_triangulation *t = on_surface(s);
  double *xy = wide_points(scaled(200), 70);
  OK(hdt_insert_many(t, xy, scaled(200), NULL));
  size_t length;
  OK(hdt_svg(t, 600, NULL, HDT_SVG_NEIGHBOURS | HDT_SVG_VORONOI | HDT_SVG_SIDE_LABELS, NULL, 0, &length));
  char *text = malloc(length + 1);
  ck_assert_ptr_nonnull(text);
  OK(hdt_svg(t, 600, NULL, HDT_SVG_NEIGHBOURS | HDT_SVG_VORONOI | HDT_SVG_SIDE_LABELS, text, length + 1, &length));
  expect(strncmp(text, "<svg ", 5) == 0 && strstr(text, "</svg>\n"), "not an SVG document");
  expect(strstr(text, "on a surface of genus 2") && strstr(text, "10-sided polygon"), "the caption: %.300s", text);
  const char *clip = strstr(text, "<clipPath id=\"hdt-polygon\"><path d=\"");
  ck_assert_ptr_nonnull(clip);
  size_t arcs = 0;
  for (const char *c = clip; *c && strncmp(c, "\"/>", 3) != 0; ++c) arcs += *c == 'A' || *c == 'L';
  expect(arcs == 10, "the polygon's outline has %zu sides", arcs);
  expect(strstr(text, "hdt-tile-9") && strstr(text, "#2a8a3a") && strstr(text, ">g_9<"), "tiles, Voronoi or labels missing");
  free(text), free(xy);
  hdt_destroy(t);
  hdt_surface_destroy(s);
}
END_TEST

/* The triangulation keeps its own polygon: the surface it gives back has
   the same text, and the one it was made from may go first. */
START_TEST(surface_round_trip) {
  hdt_surface *s = random_surface(8, 7), *back = NULL;
  hdt_triangulation *t = on_surface(s);
  char a[4096], b[4096];
  size_t la, lb;
  OK(hdt_surface_polygon_text(s, a, sizeof a, &la));
  hdt_surface_destroy(s);
  OK(hdt_triangulation_surface(t, &back));
  ck_assert_ptr_nonnull(back);
  OK(hdt_surface_polygon_text(back, b, sizeof b, &lb));
  expect(la == lb && strcmp(a, b) == 0, "the polygon given back differs:\n%s\n%s", a, b);
  OK(hdt_insert(t, 0.1, 0.2, NULL));
  OK(hdt_validate(t));
  hdt_surface_destroy(back);
  hdt_destroy(t);

  hdt_triangulation *m = new_triangulation(2);
  back = (hdt_surface *)1;
  OK(hdt_triangulation_surface(m, &back));
  expect(back == NULL, "a built-in M_2 gives a surface");
  expect(hdt_triangulation_surface(m, NULL) == HDT_EINVAL, "out NULL accepted");
  expect(hdt_triangulation_surface(NULL, &back) == HDT_EINVAL, "a NULL handle accepted");
  hdt_destroy(m);
}
END_TEST

/* The faces and vertices, compared before and after a refused call. */
static void expect_unchanged(const hdt_triangulation *t, size_t V, size_t F, const uint32_t *fv, const char *call) {
  expect(hdt_vertex_count(t) == V && hdt_face_count(t) == F, "%s changed the counts", call);
  uint32_t *now = malloc(3 * F * sizeof *now);
  ck_assert_ptr_nonnull(now);
  size_t count;
  OK(hdt_faces(t, now, NULL, F, &count));
  expect(memcmp(now, fv, 3 * F * sizeof *now) == 0, "%s changed the faces", call);
  free(now);
}

/* Bad input: a status, a message, and nothing changed. */
START_TEST(refusals) {
  hdt_triangulation *t = (hdt_triangulation *)1;
  expect(hdt_create_on_surface(&t, NULL) == HDT_EINVAL && t == NULL, "a NULL surface accepted");
  hdt_surface *s = random_surface(8, 3);
  expect(hdt_create_on_surface(NULL, s) == HDT_EINVAL, "out NULL accepted");
  t = on_surface(s);
  double *xy = wide_points(100, 5);
  OK(hdt_insert_many(t, xy, 100, NULL));
  const size_t V = hdt_vertex_count(t), F = hdt_face_count(t);
  uint32_t *fv = malloc(3 * F * sizeof *fv);
  ck_assert_ptr_nonnull(fv);
  size_t count;
  OK(hdt_faces(t, fv, NULL, F, &count));

  expect(hdt_insert(t, NAN, 0, NULL) == HDT_EDOMAIN, "NaN accepted");
  expect(hdt_insert(t, 1, 0, NULL) == HDT_EDOMAIN, "a point on the circle accepted");
  const double bad[4] = {0.1, 0.1, 0.6, 0.9};
  expect(hdt_insert_many(t, bad, 2, NULL) == HDT_EDOMAIN, "a batch with a point outside the disk accepted");
  expect_unchanged(t, V, F, fv, "a refused insertion");
  expect(hdt_remove_vertex(t, 1u << 30) == HDT_EINVAL, "an unknown vertex removed");
  expect_unchanged(t, V, F, fv, "a refused removal");

  size_t added, unmet;
  double m[4];
  expect(hdt_refine(t, 0.5, 0.5, 1000, &added, &unmet) == HDT_EINVAL, "a ratio below 1 accepted");
  expect(hdt_epsilon_net(t, NAN, 1000, &added, &unmet) == HDT_EINVAL, "a NaN epsilon accepted");
  expect(hdt_refine(t, 1e-9, INFINITY, SIZE_MAX, &added, &unmet) == HDT_ENOMEM, "a refinement past memory accepted");
  expect(strstr(hdt_last_error_message(), "a surface of genus 2"), "the message: %s", hdt_last_error_message());
  expect_unchanged(t, V, F, fv, "the unsupported calls");
  OK(hdt_translation_matrix(t, 0, m));
  expect(m[0] == 1 && m[1] == 0 && m[2] == 0 && m[3] == 0, "translation 0 is not the identity");
  OK(hdt_validate(t));
  free(fv), free(xy);
  hdt_destroy(t);
  hdt_surface_destroy(s);
}
END_TEST

/* Progress reports come; a stopped batch keeps the points inserted so far,
   valid; a call on the handle from its own progress function is refused. */
static int count_reports(void *user, size_t done, size_t total) {
  (void)done, (void)total;
  ++*(int *)user;
  return 0;
}
static int stop_at_once(void *user, size_t done, size_t total) {
  (void)user, (void)done, (void)total;
  return 1;
}
static hdt_status reentry_status;
static int reenter(void *user, size_t done, size_t total) {
  (void)done, (void)total;
  reentry_status = hdt_insert((hdt_triangulation *)user, 0.01, 0.02, NULL);
  return 0;
}

START_TEST(progress) {
  hdt_surface *s = random_surface(10, 2);
  hdt_triangulation *t = on_surface(s);
  int reports = 0;
  OK(hdt_set_progress(t, count_reports, &reports, 0));
  double *xy = wide_points(3000, 9);  /* 1000 a batch: enough for progress reports at any scale */
  OK(hdt_insert_many(t, xy, 1000, NULL));
  expect(reports > 0, "no progress report");

  OK(hdt_set_progress(t, stop_at_once, NULL, 0));
  uint32_t ids[1000];
  OK(hdt_insert_many(t, xy + 2000, 1000, ids));
  size_t missing = 0;
  for (int i = 0; i < 1000; ++i) missing += ids[i] == HDT_NO_VERTEX;
  expect(missing > 0, "a stopped batch inserted every point");
  OK(hdt_validate(t));

  const size_t V = hdt_vertex_count(t);
  OK(hdt_set_progress(t, reenter, t, 0));
  OK(hdt_insert_many(t, xy + 4000, 1000, NULL));
  expect(reentry_status == HDT_EINVAL, "a call from the progress function: %s", hdt_status_string(reentry_status));
  expect(hdt_vertex_count(t) == V + 1000, "%zu vertices after 1000 more than %zu", hdt_vertex_count(t), V);
  OK(hdt_validate(t));
  free(xy);
  hdt_destroy(t);
  hdt_surface_destroy(s);
}
END_TEST

int main(void) {
  const TTest *const tests[] = {bolza_octagon,       bolza_commutator_octagon, random_octagons, random_decagon,
                                bolza_octagon_is_the_built_in_m2, dual_and_refinement,
                                save_and_load,       pictures,                homology,
                                surface_round_trip,
                                refusals,            progress};
  return run_tests("surface_triangulations", tests, sizeof tests / sizeof tests[0]);
}
