/* Surfaces given by a fundamental polygon (HDT_0.7), through the public
   header: random CGAL-style genus-2 polygons, the Bolza surface's regular
   octagon in a number field, text round trips, and every refusal. The
   geometry is checked independently in double precision: the pairings
   against the vertices they must move, the group relation around each
   vertex cycle, and Gauss-Bonnet from angles measured at the vertices. */
#include <complex.h>

#include "hdt_test.h"

#define NMAX 32

typedef struct polygon_t {
  int n, genus, paired[NMAX];
  double complex v[NMAX];
  double complex a[NMAX], b[NMAX]; /* the pairings, z -> (a z + b) / (conj(b) z + conj(a)) */
  int cycle[NMAX];
  size_t cycles;
} polygon_t;

static hdt_surface *random_surface(int sides, uint64_t seed) {
  hdt_surface *s = NULL;
  const hdt_status st = hdt_surface_random_symmetric(&s, sides, seed);
  expect(st == HDT_OK && s, "hdt_surface_random_symmetric(%d, %llu): %s", sides, (unsigned long long)seed,
         hdt_last_error_message());
  return s;
}

static polygon_t read_back(const hdt_surface *s) {
  polygon_t p;
  p.n = hdt_surface_side_count(s);
  p.genus = hdt_surface_genus(s);
  expect(p.n >= 4 && p.n <= NMAX, "side count %d", p.n);
  for (int k = 0; k < p.n; ++k) {
    double x, y, m[4];
    OK(hdt_surface_vertex(s, k, &x, &y));
    p.v[k] = x + I * y;
    OK(hdt_surface_pairing(s, k, &p.paired[k], m));
    p.a[k] = m[0] + I * m[1], p.b[k] = m[2] + I * m[3];
  }
  OK(hdt_surface_vertex_cycles(s, p.cycle, (size_t)p.n, &p.cycles));
  return p;
}

static double complex apply(const polygon_t *p, int k, double complex z) {
  return (p->a[k] * z + p->b[k]) / (conj(p->b[k]) * z + conj(p->a[k]));
}

/* The pairing of side k sends side j = paired(k), from v_{j+1} to v_j, onto
   side k from v_k to v_{k+1}; its matrix has |a|^2 - |b|^2 = 1. */
static void expect_pairings(const polygon_t *p) {
  for (int k = 0; k < p->n; ++k) {
    const int j = p->paired[k], n = p->n;
    expect(j >= 0 && j < n && j != k && p->paired[j] == k, "side %d paired with %d, which pairs with %d", k, j,
           p->paired[j]);
    const double det = creal(p->a[k] * conj(p->a[k]) - p->b[k] * conj(p->b[k]));
    expect(fabs(det - 1) < 1e-12, "pairing %d: |a|^2 - |b|^2 = %.17g", k, det);
    expect(cabs(apply(p, k, p->v[(j + 1) % n]) - p->v[k]) < 1e-10, "pairing %d does not send v_%d to v_%d", k,
           (j + 1) % n, k);
    expect(cabs(apply(p, k, p->v[j]) - p->v[(k + 1) % n]) < 1e-10, "pairing %d does not send v_%d to v_%d", k, j,
           (k + 1) % n);
  }
}

/* The direction at v of the geodesic from v to w: T_v(w), T_v(z) =
   (z - v) / (1 - conj(v) z), has the same argument (T_v is conformal with a
   positive derivative at v). */
static double direction(double complex v, double complex w) { return carg((w - v) / (1 - conj(v) * w)); }

/* Interior angles from the vertices alone: their sum is 2 pi for each
   vertex cycle, and the area (n - 2) pi - sum is 4 pi (g - 1) (Gauss-Bonnet);
   the cycles also agree with Euler's formula. */
static void expect_gauss_bonnet(const polygon_t *p) {
  const double pi = acos(-1.0);
  double sum[NMAX] = {0}, total = 0;
  for (int k = 0; k < p->n; ++k) {
    const double complex v = p->v[k], before = p->v[(k + p->n - 1) % p->n], after = p->v[(k + 1) % p->n];
    double angle = direction(v, before) - direction(v, after);
    while (angle <= 0) angle += 2 * pi;
    expect(angle < pi, "the angle at v_%d is %.17g, not convex", k, angle);
    sum[p->cycle[k]] += angle, total += angle;
  }
  for (size_t c = 0; c < p->cycles; ++c)
    expect(fabs(sum[c] - 2 * pi) < 1e-9, "cycle %zu: the angle sum is %.17g, not 2 pi", c, sum[c]);
  const double area = (p->n - 2) * pi - total;
  expect(fabs(area - 4 * pi * (p->genus - 1)) < 1e-9, "area %.17g, not 4 pi (g - 1) for g = %d", area, p->genus);
  expect(2 - 2 * p->genus == (int)p->cycles - p->n / 2 + 1, "Euler: %zu cycles, %d sides, genus %d", p->cycles, p->n,
         p->genus);
}

/* Around a vertex cycle the pairings compose to the identity: from v_k the
   copy across side k is g_k(P), whose corner at v_k is v_{j+1}, j =
   paired(k); the next copy is across the side after that corner, side
   j + 1, and so on, until the walk is back at v_k. The product
   g_{k_1} g_{k_2} ... g_{k_m} is then +-1 (one turn around the vertex), and
   the vertices walked are those of one cycle of hdt_surface_vertex_cycles. */
static void expect_cycle_relations(const polygon_t *p) {
  for (int start = 0; start < p->n; ++start) {
    double complex A = 1, B = 0; /* the product so far, as (a, b) */
    int k = start, length = 0;
    do {
      expect(p->cycle[k] == p->cycle[start], "v_%d and v_%d are one point but in cycles %d and %d", k, start,
             p->cycle[k], p->cycle[start]);
      const double complex a = A * p->a[k] + B * conj(p->b[k]), b = A * p->b[k] + B * conj(p->a[k]);
      A = a, B = b;
      k = (p->paired[k] + 1) % p->n;
      ++length;
    } while (k != start && length <= p->n);
    expect(k == start, "the walk from v_%d does not come back", start);
    int members = 0;
    for (int v = 0; v < p->n; ++v) members += p->cycle[v] == p->cycle[start];
    expect(members == length, "cycle of v_%d: %d vertices walked, %d listed", start, length, members);
    expect(cabs(B) < 1e-9 && fabs(cabs(A) - 1) < 1e-9 && fabs(cimag(A)) < 1e-9,
           "around v_%d the pairings give (%.3g%+.3gi, %.3g%+.3gi), not +-1", start, creal(A), cimag(A), creal(B),
           cimag(B));
  }
}

/* The text the library writes reads back as the same surface, and the text
   of that is the same again (exact coordinates). */
static void expect_text_round_trip(const hdt_surface *s) {
  size_t length = 0;
  OK(hdt_surface_polygon_text(s, NULL, 0, &length));
  char *text = malloc(length + 1);
  ck_assert_ptr_nonnull(text);
  expect(hdt_surface_polygon_text(s, text, length, &length) == HDT_EBUFS, "no HDT_EBUFS without room for the NUL");
  OK(hdt_surface_polygon_text(s, text, length + 1, &length));
  expect(strlen(text) == length, "the text's length is %zu, not %zu", strlen(text), length);
  hdt_surface *t = surface_from_text(text);
  size_t again_length = 0;
  OK(hdt_surface_polygon_text(t, NULL, 0, &again_length));
  char *again = malloc(again_length + 1);
  ck_assert_ptr_nonnull(again);
  OK(hdt_surface_polygon_text(t, again, again_length + 1, &again_length));
  expect(strcmp(text, again) == 0, "the text of the text differs:\n%s\n%s", text, again);
  free(text), free(again);
  hdt_surface_destroy(t);
}

/* Random polygons with `sides` sides, seeds 1..seeds: genus 2, `cycles`
   vertex cycles, sides opposite paired, and every geometric check. */
static void expect_random_surfaces(int sides, uint64_t seeds, size_t cycles) {
  for (uint64_t seed = 1; seed <= seeds; ++seed) {
    hdt_surface *s = random_surface(sides, seed);
    const polygon_t p = read_back(s);
    expect(p.n == sides && p.genus == 2 && p.cycles == cycles, "seed %llu: %d sides, genus %d, %zu cycles",
           (unsigned long long)seed, p.n, p.genus, p.cycles);
    for (int k = 0; k < sides; ++k)
      expect(p.paired[k] == (k + sides / 2) % sides, "side %d paired with %d", k, p.paired[k]);
    expect_pairings(&p);
    expect_gauss_bonnet(&p);
    expect_cycle_relations(&p);
    expect_text_round_trip(s);
    hdt_surface_destroy(s);
  }
}

START_TEST(random_octagons) { expect_random_surfaces(8, 10, 1); }
END_TEST

START_TEST(random_decagons) { expect_random_surfaces(10, 5, 2); }
END_TEST

/* The Bolza surface's octagon, v_k = 2^(-1/4) e^(i (2k+1) pi/8), in
   Q(a), a = sqrt(sqrt2 + 1) (a^4 - 2a^2 - 1 = 0): x = a/2, y = (a^3 - 2a)/2
   for v_0, the others by symmetry. */
static const char bolza[] =
    "field a^4-2*a^2-1 a 1.5538+/-0.01\n8\n4 5 6 7 0 1 2 3\n"
    "1/2*a 1/2*a^3-a\n1/2*a^3-a 1/2*a\n-1/2*a^3+a 1/2*a\n-1/2*a 1/2*a^3-a\n"
    "-1/2*a -1/2*a^3+a\n-1/2*a^3+a -1/2*a\n1/2*a^3-a -1/2*a\n1/2*a -1/2*a^3+a\n";

/* Given as a polygon, M_2 has the built-in F_2's vertices and, as its side
   pairings, the built-in generators (each pairing is one of hdt_word_matrix's
   letters, up to the sign of the matrix). */
START_TEST(bolza_octagon_is_the_built_in_m2) {
  hdt_surface *s = surface_from_text(bolza);
  const polygon_t p = read_back(s);
  expect(p.n == 8 && p.genus == 2 && p.cycles == 1, "%d sides, genus %d, %zu cycles", p.n, p.genus, p.cycles);
  for (int k = 0; k < 8; ++k) {
    double x, y;
    OK(hdt_polygon_vertex(2, k, &x, &y));
    expect(cabs(p.v[k] - (x + I * y)) < 1e-15, "v_%d differs from hdt_polygon_vertex", k);
    int found = 0;
    for (int32_t letter = 0; letter < 8 && !found; ++letter) {
      double m[4];
      OK(hdt_word_matrix(2, &letter, 1, m));
      const double complex a = m[0] + I * m[1], b = m[2] + I * m[3];
      found = (cabs(a - p.a[k]) < 1e-13 && cabs(b - p.b[k]) < 1e-13) ||
              (cabs(a + p.a[k]) < 1e-13 && cabs(b + p.b[k]) < 1e-13);
    }
    expect(found, "the pairing of side %d is no generator of the built-in M_2", k);
  }
  expect_pairings(&p);
  expect_gauss_bonnet(&p);
  expect_cycle_relations(&p);
  expect_text_round_trip(s);
  hdt_surface_destroy(s);
}
END_TEST

/* The least translation length of the pairings and their products of two,
   in double, from hdt_surface_pairing's SU(1,1) matrices [[a, b], [conj b,
   conj a]]: the product's top-left entry is a1 a2 + b1 conj(b2). */
static double shortest_of_two(const hdt_surface *s) {
  const int n = hdt_surface_side_count(s);
  double best = INFINITY;
  for (int i = 0; i < n; ++i)
    for (int j = -1; j < n; ++j) {
      double m[4], q[4];
      OK(hdt_surface_pairing(s, i, NULL, m));
      double complex a = m[0] + I * m[1];
      if (j >= 0) {
        OK(hdt_surface_pairing(s, j, NULL, q));
        a = a * (q[0] + I * q[1]) + (m[2] + I * m[3]) * conj(q[2] + I * q[3]);
      }
      const double c = fabs(creal(a));
      if (c > 1 + 1e-12) best = fmin(best, 2 * acosh(c));
    }
  return best;
}

/* The Bolza octagon's systole, neighbour set and representatives are the
   built-in M_2's, computed by the other path (the cyclotomic field, Dehn's
   algorithm, the canonical words). */
START_TEST(bolza_octagon_group_is_the_built_in_one) {
  hdt_surface *s = surface_from_text(bolza);
  double lo, hi;
  OK(hdt_surface_systole(s, &lo, &hi));
  expect(lo <= hdt_systole(2) && hdt_systole(2) <= hi && hi - lo < 1e-12, "systole in [%.17g, %.17g], M_2's %.17g",
         lo, hi, hdt_systole(2));
  size_t count, builtin;
  OK(hdt_surface_neighbour_count(s, &count));
  OK(hdt_neighbour_count(2, &builtin));
  expect(count == builtin, "|N| = %zu, the built-in M_2 has %zu", count, builtin);
  uint64_t seed = 5;
  for (int i = 0; i < 200; ++i) {
    const double r = 0.995 * sqrt(uniform01(&seed)), a = 2 * acos(-1.0) * uniform01(&seed);
    const double x = r * cos(a), y = r * sin(a);
    double rx, ry, bx, by;
    size_t length;
    OK(hdt_surface_representative(s, x, y, &rx, &ry, NULL, 0, &length));
    OK(hdt_point_representative(2, x, y, &bx, &by, NULL, 0, &length));
    expect(fabs(rx - bx) < 1e-12 && fabs(ry - by) < 1e-12, "(%.17g, %.17g): representative (%.17g, %.17g), M_2's (%.17g, %.17g)",
           x, y, rx, ry, bx, by);
  }
  hdt_surface_destroy(s);
}
END_TEST

/* The pairings' product along a word, applied to z in double. */
static double complex pairings_image(const polygon_t *p, const int32_t *w, size_t length, double complex z) {
  for (size_t i = length; i-- > 0;) z = apply(p, w[i], z);
  return z;
}

/* Inside the closed polygon, in double with a margin: left of every side's
   geodesic, taken in the Klein model where it is the chord. */
static int inside(const polygon_t *p, double complex z, double margin) {
  const double complex k = 2 * z / (1 + creal(z * conj(z)));
  for (int i = 0; i < p->n; ++i) {
    const double complex a = 2 * p->v[i] / (1 + creal(p->v[i] * conj(p->v[i])));
    const double complex b = 2 * p->v[(i + 1) % p->n] / (1 + creal(p->v[(i + 1) % p->n] * conj(p->v[(i + 1) % p->n])));
    if (cimag(conj(b - a) * (k - a)) < -margin) return 0;
  }
  return 1;
}

/* A random octagon: the systole against the least translation length of the
   words of up to three pairings in double (2 cosh(l/2) = |tr|, the trace
   2 Re a of the SU(1,1) form); representatives inside the polygon and the
   images of the points under their words. */
START_TEST(random_octagon_group) {
  hdt_surface *s = random_surface(8, 2); /* 1917 tiles for the systole (seed 1: 4315) */
  const polygon_t p = read_back(s);
  double lo, hi, least = INFINITY;
  OK(hdt_surface_systole(s, &lo, &hi));
  for (int i = 0; i < 8; ++i)
    for (int j = -1; j < 8; ++j)
      for (int k = -1; k < 8; ++k) {
        double complex A = p.a[i], B = p.b[i];
        const int more[2] = {j, k};
        for (int m = 0; m < 2; ++m) {
          if (more[m] < 0) continue;
          const double complex a = A * p.a[more[m]] + B * conj(p.b[more[m]]), b = A * p.b[more[m]] + B * conj(p.a[more[m]]);
          A = a, B = b;
        }
        const double t = fabs(2 * creal(A));
        if (t > 2 + 1e-6) least = fmin(least, 2 * acosh(t / 2));
      }
  expect(lo <= least + 1e-9 && fabs(least - lo) < 1e-9, "systole in [%.17g, %.17g], words of 3 pairings: %.17g", lo,
         hi, least);
  uint64_t seed = 9;
  for (int i = 0; i < 100; ++i) {
    const double r = 0.99 * sqrt(uniform01(&seed)), a = 2 * acos(-1.0) * uniform01(&seed);
    const double complex z = r * cos(a) + I * r * sin(a);
    int32_t word[256];
    size_t length;
    double rx, ry;
    OK(hdt_surface_representative(s, creal(z), cimag(z), &rx, &ry, word, 256, &length));
    const double complex image = pairings_image(&p, word, length, z);
    expect(cabs(image - (rx + I * ry)) < 1e-9, "the word does not take (%g, %g) to its representative", creal(z),
           cimag(z));
    expect(inside(&p, rx + I * ry, 1e-12), "the representative of (%g, %g) is outside the polygon", creal(z), cimag(z));
  }
  size_t count;
  OK(hdt_surface_neighbour_count(s, &count));
  expect(count == 49, "|N| = %zu: one cycle of 8 vertices gives 1 + 8 * 7 - 8 = 49", count);
  hdt_surface_destroy(s);
  /* a thin octagon (vertices 5.8 from 0): certified too, and no longer than
     any pairing or product of two pairings (their SU(1,1) matrices: cosh(l/2)
     = |Re tr| / 2) */
  s = random_surface(8, 3);
  OK(hdt_surface_systole(s, &lo, &hi));
  expect(lo <= hi && hi - lo < 1e-12, "the thin octagon's systole in [%.17g, %.17g]", lo, hi);
  expect(lo <= shortest_of_two(s) + 1e-9, "the thin octagon's systole %.17g above a word's %.17g", lo,
         shortest_of_two(s));
  hdt_surface_destroy(s);
}
END_TEST

/* The text is refused, *out stays NULL, and the message says why. */
static void expect_refused(const char *text, const char *phrase) {
  hdt_surface *s = (hdt_surface *)&s; /* not NULL: the call must clear it */
  const hdt_status st = hdt_surface_from_polygon(&s, text, strlen(text));
  expect(st == HDT_EINVAL && s == NULL, "%s: %s, not refused", text, hdt_status_string(st));
  expect(strstr(hdt_last_error_message(), phrase) != NULL, "the message \"%s\" does not say \"%s\"",
         hdt_last_error_message(), phrase);
}

START_TEST(bad_polygons_are_refused_with_the_reason) {
  expect_refused("8\n4 5 6 7 0 1 2 x\n", "token 9");
  expect_refused("6\n3 4 5 0 1\n", "token 7");
  expect_refused("7\n1 0 3 2 6 5 4\n0 0 0 0 0 0 0 0 0 0 0 0 0 0\n", "an even number");
  expect_refused("4\n2 3 0 1\n1 0 0 1/2 -1/2 0 0 -1/2\n", "vertex 0 is not in the open unit disk");
  expect_refused("4\n1 0 3 2\n1/2 0 0 1/2 -1/2 0 0 -1/2\n", "angle sum");
  /* convex, opposite sides equal by symmetry, nearly Euclidean: 6 pi */
  expect_refused("8\n4 5 6 7 0 1 2 3\n1/5 1/10 1/10 1/5 -1/10 1/5 -1/5 1/10 "
                 "-1/5 -1/10 -1/10 -1/5 1/10 -1/5 1/5 -1/10\n",
                 "the angle sum must be 2 pi");
  /* the Bolza octagon with one vertex moved inwards: no longer convex */
  char text[sizeof bolza + 16];
  memcpy(text, bolza, sizeof bolza);
  char *v1 = strstr(text, "\n1/2*a^3-a 1/2*a\n");
  memcpy(v1, "\n1/4*a^3-a 1/4*a\n", 17);
  expect_refused(text, "not strictly convex");
  expect_refused("field a^2-4 a 2+/-0.1\n4\n", "not irreducible");
  /* refused before e-antic spends time on them */
  expect_refused("field a^300-2 a 1+/-0.1\n4\n", "the largest field degree");
  expect_refused("field a^100000-2 a 1+/-0.1\n4\n", "a power above 1024");
  expect_refused("field a^2-2 a 5+/-0.1\n4\n", "holds 0 real roots");
  expect_refused("field a^2-2 a 0+/-2\n4\n", "holds 2 real roots");
  expect_refused("field a^^2-2 a 1.4+/-0.1\n4\n", "expected a power after ^");
  expect_refused("field a^2-2 a 1.4+/-0.1\n4\n2 3 0 1\nb 0 0 1/2 -1/2 0 0 -1/2\n", "expected a at character 1");
  expect_refused("field a^2-2 a 1.4+/-0.1\n4\n2 3 0 1\na^99999999999 0 0 1/2 -1/2 0 0 -1/2\n", "a power above 1024");
  hdt_surface *s = NULL;
  expect(hdt_surface_from_polygon(NULL, bolza, strlen(bolza)) == HDT_EINVAL, "out NULL accepted");
  expect(hdt_surface_from_polygon(&s, NULL, 3) == HDT_EINVAL && s == NULL, "text NULL accepted");
  expect(hdt_surface_random_symmetric(&s, 12, 1) == HDT_EINVAL && s == NULL, "12 sides accepted");
}
END_TEST

/* The picture: an SVG document with one arc per side, each labelled with
   the side and the side glued to it, one dot per vertex, in as many dot
   colours as there are vertex cycles. */
START_TEST(the_polygon_picture) {
  hdt_surface *s = random_surface(10, 2);
  const polygon_t p = read_back(s);
  size_t length = 0;
  OK(hdt_surface_svg(s, 800, NULL, 0, &length));
  char *svg = malloc(length + 1);
  ck_assert_ptr_nonnull(svg);
  expect(hdt_surface_svg(s, 800, svg, length, &length) == HDT_EBUFS, "no HDT_EBUFS without room for the NUL");
  OK(hdt_surface_svg(s, 800, svg, length + 1, &length));
  expect(strncmp(svg, "<svg ", 5) == 0 && strcmp(svg + length - 7, "</svg>\n") == 0, "not an SVG document");
  for (int k = 0; k < p.n; ++k) {
    char label[32];
    snprintf(label, sizeof label, ">%d~%d</text>", k, p.paired[k]);
    expect(strstr(svg, label) != NULL, "no label %s", label);
  }
  int arcs = 0, dots = 0;
  for (const char *q = svg; (q = strstr(q, "<path fill=\"none\"")) != NULL; ++q) ++arcs;
  for (const char *q = svg; (q = strstr(q, "<circle cx=")) != NULL; ++q) ++dots;
  expect(arcs == p.n && dots == p.n + 1, "%d side paths and %d circles (the disk and the vertices) for %d sides", arcs,
         dots, p.n);
  expect(hdt_surface_svg(s, 0, NULL, 0, &length) == HDT_EINVAL, "size 0 accepted");
  expect(hdt_surface_svg(s, NAN, NULL, 0, &length) == HDT_EINVAL, "size NaN accepted");
  expect(hdt_surface_svg(NULL, 800, NULL, 0, &length) == HDT_EINVAL, "NULL surface accepted");
  free(svg);
  hdt_surface_destroy(s);
}
END_TEST

/* NULL handles and buffers: a status, never a crash; nothing written on
   failure. */
START_TEST(null_and_small_buffers) {
  double x = 7, y = 7, m[4] = {7, 7, 7, 7};
  int paired = 7, cycle[8];
  size_t count = 7, length = 7;
  expect(hdt_surface_genus(NULL) == 0 && hdt_surface_side_count(NULL) == 0, "NULL handle has a genus");
  expect(hdt_surface_vertex(NULL, 0, &x, &y) == HDT_EINVAL && x == 7, "vertex of NULL");
  expect(hdt_surface_pairing(NULL, 0, &paired, m) == HDT_EINVAL && paired == 7, "pairing of NULL");
  expect(hdt_surface_vertex_cycles(NULL, cycle, 8, &count) == HDT_EINVAL && count == 7, "cycles of NULL");
  expect(hdt_surface_polygon_text(NULL, NULL, 0, &length) == HDT_EINVAL && length == 7, "text of NULL");
  hdt_surface_destroy(NULL);
  hdt_surface *s = random_surface(8, 3);
  expect(hdt_surface_vertex(s, 0, NULL, &y) == HDT_EINVAL, "x NULL accepted");
  expect(hdt_surface_vertex_cycles(s, cycle, 7, &count) == HDT_EBUFS && count == 1, "7 entries for 8 vertices");
  expect(hdt_surface_vertex_cycles(s, NULL, 8, &count) == HDT_EINVAL, "cycle NULL with capacity 8");
  OK(hdt_surface_vertex_cycles(s, NULL, 0, &count));
  expect(count == 1, "%zu cycles", count);
  char small[8];
  expect(hdt_surface_polygon_text(s, small, sizeof small, &length) == HDT_EBUFS && length > sizeof small,
         "the text fits in 8 bytes?");
  OK(hdt_surface_pairing(s, 9, &paired, NULL)); /* k mod n, like hdt_polygon_vertex */
  expect(paired == 5, "side 9 = side 1 is paired with %d", paired);
  hdt_surface_destroy(s);
}
END_TEST

int main(void) {
  const TTest *const tests[] = {random_octagons, random_decagons, bolza_octagon_is_the_built_in_m2,
                                bolza_octagon_group_is_the_built_in_one, random_octagon_group,
                                bad_polygons_are_refused_with_the_reason, the_polygon_picture, null_and_small_buffers};
  return run_tests("surfaces", tests, sizeof tests / sizeof tests[0]);
}
