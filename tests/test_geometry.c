/* Geometry through the public header: the polygon F_g, the action of words
   (Moebius and Lorentz), and the systole. */
#include <complex.h>
#include <limits.h>
#include <mpfr.h>

#include "hdt_test.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

static double rel_diff(double x, double y) { return fabs(x - y) / fmax(fabs(x), fabs(y)); }

static void polygon_point(int g, int k, int vertex, double p[2]) {
  const hdt_status s = vertex ? hdt_polygon_vertex(g, k, &p[0], &p[1]) : hdt_polygon_side_midpoint(g, k, &p[0], &p[1]);
  ck_assert_int_eq(s, HDT_OK);
}

/* ---- The polygon ---- */

START_TEST(polygon_points_are_where_documented) {
  for (int g = 2; g <= 12; ++g) {
    const int n = 4 * g;
    const double cosh_d = 1 / tan(M_PI / n); /* distance d from 0 to a side midpoint */
    const double r_mid = sqrt((cosh_d - 1) / (cosh_d + 1));
    const double r_vertex = sqrt(cos(M_PI / (2 * g)));
    for (int k = 0; k < n; ++k) {
      double v[2], m[2];
      polygon_point(g, k, 1, v);
      polygon_point(g, k, 0, m);
      const double tv = (2 * k + 1) * M_PI / n, tm = k * M_PI / (2 * g);
      ck_assert_double_lt(hypot(v[0] - r_vertex * cos(tv), v[1] - r_vertex * sin(tv)), 1e-13);
      ck_assert_double_lt(hypot(m[0] - r_mid * cos(tm), m[1] - r_mid * sin(tm)), 1e-13);
      /* Indices are taken mod 4g, for any int. */
      const int shifted[] = {k - n, k + n, k - 7 * n, k + 5 * n};
      for (size_t i = 0; i < sizeof shifted / sizeof shifted[0]; ++i) {
        double w[2];
        polygon_point(g, shifted[i], 1, w);
        ck_assert(w[0] == v[0] && w[1] == v[1]);
        polygon_point(g, shifted[i], 0, w);
        ck_assert(w[0] == m[0] && w[1] == m[1]);
      }
    }
    const int extremes[] = {INT_MIN, INT_MAX, INT_MIN + 1};
    for (size_t i = 0; i < sizeof extremes / sizeof extremes[0]; ++i) {
      const int k = (int)(((long long)extremes[i] % n + n) % n);
      double a[2], b[2];
      for (int vertex = 0; vertex < 2; ++vertex) {
        polygon_point(g, extremes[i], vertex, a);
        polygon_point(g, k, vertex, b);
        expect(a[0] == b[0] && a[1] == b[1], "genus %d: index %d is not %d mod 4g", g, extremes[i], k);
      }
    }
  }
}
END_TEST

/* g_k maps side s_{k+2g} onto s_k: midpoint to midpoint, v_{k+2g-1} to v_k
   and v_{k+2g} to v_{k-1} (a translation keeps each side of its axis). */
START_TEST(generators_pair_the_sides) {
  for (int g = 2; g <= 12; ++g)
    for (int k = 0; k < 4 * g; ++k) {
      const word_t w = {1, {k}};
      const int from[3][2] = {{k + 2 * g, 0}, {k + 2 * g - 1, 1}, {k + 2 * g, 1}};
      const int to[3][2] = {{k, 0}, {k, 1}, {k - 1, 1}};
      for (int i = 0; i < 3; ++i) {
        double p[2], q[2], img[2];
        polygon_point(g, from[i][0], from[i][1], p);
        polygon_point(g, to[i][0], to[i][1], q);
        apply_word(g, &w, p[0], p[1], &img[0], &img[1]);
        expect(hypot(img[0] - q[0], img[1] - q[1]) < 1e-12, "genus %d, g_%d: point %d goes to (%.17g, %.17g)", g, k, i,
               img[0], img[1]);
      }
      /* g_k g_k^-1 is the identity. */
      const word_t pair = {2, {k, inv_letter(g, k)}};
      double m[4];
      word_matrix(g, &pair, m);
      const double id[4] = {1, 0, 0, 0};
      ck_assert_double_lt(matrix_gap(m, id), 1e-12);
    }
}
END_TEST

/* ---- Matrices: Moebius, Lorentz and hdt_word_apply agree ---- */

static double complex moebius(const double m[4], double complex z) {
  const double complex a = m[0] + I * m[1], b = m[2] + I * m[3];
  return (a * z + b) / (conj(b) * z + conj(a));
}

/* The hyperboloid point ((1 + |z|^2), 2x, 2y) / (1 - |z|^2). */
static void to_hyperboloid(double complex z, double p[3]) {
  const double r2 = creal(z) * creal(z) + cimag(z) * cimag(z);
  p[0] = (1 + r2) / (1 - r2);
  p[1] = 2 * creal(z) / (1 - r2);
  p[2] = 2 * cimag(z) / (1 - r2);
}

/* The hyperboloid point of the image of z under the SU(1,1) matrix, without
   the cancellation in 1 - |f(z)|^2 = (1 - |z|^2) / |conj(b) z + conj(a)|^2. */
static void image_on_hyperboloid(const double m[4], double complex z, double p[3]) {
  const double complex a = m[0] + I * m[1], b = m[2] + I * m[3];
  const double complex num = a * z + b, den = conj(b) * z + conj(a);
  const double one_minus = 1 - creal(z) * creal(z) - cimag(z) * cimag(z);
  const double complex uv = 2 * num * conj(den) / one_minus;
  p[0] = (creal(num * conj(num)) + creal(den * conj(den))) / one_minus;
  p[1] = creal(uv);
  p[2] = cimag(uv);
}

static double max_abs(const double *v, size_t n) {
  double r = 0;
  for (size_t i = 0; i < n; ++i) r = fmax(r, fabs(v[i]));
  return r;
}

START_TEST(actions_agree) {
  static const double points[][2] = {{0, 0}, {0.3, -0.2}, {-0.5, 0.4}, {0.1, 0.85}, {-0.97, 0.01}};
  uint64_t rng = 12345;
  for (int g = 2; g <= 5; ++g)
    for (int trial = 0; trial < 60; ++trial) {
      const word_t w = random_word(&rng, g, 8);
      double m[4], L[9];
      word_matrix(g, &w, m);
      ck_assert_int_eq(hdt_word_lorentz(g, w.a, w.n, L), HDT_OK);
      /* SU(1,1): |a|^2 - |b|^2 = 1. */
      const double size = max_abs(m, 4);
      ck_assert_double_lt(fabs(m[0] * m[0] + m[1] * m[1] - m[2] * m[2] - m[3] * m[3] - 1), 1e-12 * size * size);
      for (size_t i = 0; i < sizeof points / sizeof points[0]; ++i) {
        const double complex z = points[i][0] + I * points[i][1];
        const double complex fz = moebius(m, z);
        double ax, ay, p[3], lp[3] = {0, 0, 0};
        const hdt_status s = hdt_word_apply(g, w.a, w.n, points[i][0], points[i][1], &ax, &ay);
        if (s == HDT_EDOMAIN) {
          /* Refused only when the image rounds onto the circle. */
          expect(1 - cabs(fz) < 1e-15, "genus %d: image %.17g from the circle refused: %s", g, 1 - cabs(fz),
                 hdt_last_error_message());
          continue;
        }
        expect(s == HDT_OK, "hdt_word_apply(genus %d): %s", g, hdt_last_error_message());
        ck_assert_double_lt(hypot(ax - creal(fz), ay - cimag(fz)), 1e-9);
        to_hyperboloid(z, p);
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) lp[r] += L[3 * r + c] * p[c];
        /* Compared on the hyperboloid, and back in the disk. */
        double q[3];
        image_on_hyperboloid(m, z, q);
        for (int r = 0; r < 3; ++r)
          expect(fabs(lp[r] - q[r]) < 1e-9 * max_abs(q, 3), "genus %d: Lorentz and Moebius images differ", g);
        const double complex back = (lp[1] + I * lp[2]) / (1 + lp[0]);
        expect(cabs(back - fz) < 1e-9, "genus %d: Lorentz and Moebius images differ by %g", g, cabs(back - fz));
      }
    }
}
END_TEST

START_TEST(lorentz_preserves_the_form) {
  static const double J[3] = {1, -1, -1};
  uint64_t rng = 777;
  for (int g = 2; g <= 6; ++g)
    for (int trial = 0; trial < 80; ++trial) {
      const word_t w = random_word(&rng, g, 8);
      double L[9];
      ck_assert_int_eq(hdt_word_lorentz(g, w.a, w.n, L), HDT_OK);
      const double size = fmax(1, max_abs(L, 9));
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          double s = 0; /* (L^T J L)_ij */
          for (int k = 0; k < 3; ++k) s += J[k] * L[3 * k + i] * L[3 * k + j];
          expect(fabs(s - (i == j ? J[i] : 0)) < 1e-12 * size * size, "genus %d: (L^T J L)_%d%d = %.17g", g, i, j, s);
        }
      /* Orthochronous, and orientation preserving (det checked where the
         rounding error of double, ~ size^3 eps, cannot reach 1). */
      ck_assert_double_ge(L[0], 1 - 1e-12);
      const double det_error = 1e-14 * size * size * size;
      if (det_error < 0.5) {
        const double det = L[0] * (L[4] * L[8] - L[5] * L[7]) - L[1] * (L[3] * L[8] - L[5] * L[6]) +
                           L[2] * (L[3] * L[7] - L[4] * L[6]);
        ck_assert_double_lt(fabs(det - 1), det_error);
      }
    }
}
END_TEST

/* ---- The systole ---- */

START_TEST(systole_closed_form) {
  const double expected = 2 * acosh(1 + sqrt(2.0));
  ck_assert_double_lt(rel_diff(hdt_systole(2), expected), 1e-14);
  const int bad[] = {1, 0, -5, INT_MIN};
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i)
    expect(isnan(hdt_systole(bad[i])), "hdt_systole(%d) = %g, not NaN", bad[i], hdt_systole(bad[i]));
  /* The documented formula, with no upper limit on the genus, increasing
     towards 2 arccosh 3. */
  double prev = 0;
  for (int g = 2; g <= 300; ++g) {
    const double s = hdt_systole(g);
    ck_assert_double_lt(rel_diff(s, 2 * acosh(1 + 2 * cos(M_PI / (2 * g)))), 1e-13);
    ck_assert_double_gt(s, prev);
    prev = s;
  }
  /* Towards 2 arccosh 3 (2g computed in double: no int overflow). */
  const int big[] = {HDT_GENUS_MAX, HDT_GENUS_MAX + 1, 1000000, INT_MAX / 2 + 1, INT_MAX};
  for (size_t i = 0; i < sizeof big / sizeof big[0]; ++i) {
    const double s = hdt_systole(big[i]);
    expect(rel_diff(s, 2 * acosh(1 + 2 * cos(M_PI / (2.0 * big[i])))) < 1e-13 && s >= prev &&
               s <= 2 * acosh(3.0) * (1 + 1e-15),
           "hdt_systole(%d) = %.17g", big[i], s);
    prev = s;
  }
}
END_TEST

/* Least translation length over the canonical words that extend w up to
   max_len letters (prefixes of canonical words are canonical). */
static double least_translation(int g, word_t *w, size_t max_len) {
  double best = INFINITY;
  if (w->n > 0) {
    double m[4];
    word_matrix(g, w, m);
    best = translation_length(m);
  }
  if (w->n == max_len) return best;
  for (int k = 0; k < 4 * g; ++k) {
    /* By the rotation symmetry (letter k -> k+1 is a conjugation) the least
       value is reached by a canonical word starting with letter 0. */
    if (w->n == 0 && k > 0) break;
    word_push(w, k);
    const word_t c = reduce_word(g, w);
    if (word_eq(&c, w)) best = fmin(best, least_translation(g, w, max_len));
    --w->n;
  }
  return best;
}

START_TEST(systole_is_least_translation_length) {
  for (int g = 2; g <= 6; ++g) {
    word_t w = {0};
    const double least = least_translation(g, &w, 4);
    expect(fabs(least - hdt_systole(g)) < 1e-9, "genus %d: least translation length %.17g, systole %.17g", g, least,
           hdt_systole(g));
  }
  /* Realised by g_0 (g = 2) and by g_0 g_{2g+1} (g >= 3). */
  for (int g = 2; g <= 32; ++g) {
    const word_t w = g == 2 ? (word_t){1, {0}} : (word_t){2, {0, 2 * g + 1}};
    double m[4];
    word_matrix(g, &w, m);
    expect(fabs(translation_length(m) - hdt_systole(g)) < 1e-9, "genus %d: %.17g vs systole %.17g", g,
           translation_length(m), hdt_systole(g));
  }
}
END_TEST

/* ---- Correct rounding, against MPFR ----
   References at 200 bits by formulas other than the library's (which bounds
   mpfr_cosu and mpfr_tanu of exact arguments from both sides): pi rounded,
   each operation to nearest, then one rounding to double. A reference is
   within some 2^-180 (relative) of the exact value, so it could round to the
   wrong double only that close to a midpoint between doubles. */
#define REF_BITS 200

/* Bit equality: tells +0 from -0. */
static int same_double(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

/* 2 log(t + sqrt(t^2 - 1)) with t = 1 + 2 cos(pi/2g). */
static double reference_systole(int g) {
  mpfr_t t, u;
  mpfr_inits2(REF_BITS, t, u, (mpfr_ptr)0);
  mpfr_const_pi(t, MPFR_RNDN);
  mpfr_div_ui(t, t, 2 * (unsigned long)g, MPFR_RNDN);
  mpfr_cos(t, t, MPFR_RNDN);
  mpfr_mul_2ui(t, t, 1, MPFR_RNDN);
  mpfr_add_ui(t, t, 1, MPFR_RNDN);
  mpfr_sqr(u, t, MPFR_RNDN);
  mpfr_sub_ui(u, u, 1, MPFR_RNDN);
  mpfr_sqrt(u, u, MPFR_RNDN);
  mpfr_add(u, u, t, MPFR_RNDN);
  mpfr_log(u, u, MPFR_RNDN);
  mpfr_mul_2ui(u, u, 1, MPFR_RNDN);
  const double s = mpfr_get_d(u, MPFR_RNDN);
  mpfr_clears(t, u, (mpfr_ptr)0);
  return s;
}

/* The point of Euclidean radius sqrt((c - 1)/(c + 1)) at angle
   num pi / den; c is cosh of its distance from 0, cot(pi/4g)^cot_power. A
   coordinate that is exactly 0 (the angle a multiple of pi/2) is +0. */
static void reference_point(int g, int cot_power, long num, long den, double p[2]) {
  mpfr_t c, r, angle, x, y;
  mpfr_inits2(REF_BITS, c, r, angle, x, y, (mpfr_ptr)0);
  mpfr_const_pi(c, MPFR_RNDN);
  mpfr_div_ui(c, c, 4 * (unsigned long)g, MPFR_RNDN);
  mpfr_cot(c, c, MPFR_RNDN);
  mpfr_pow_ui(c, c, (unsigned long)cot_power, MPFR_RNDN);
  mpfr_sub_ui(r, c, 1, MPFR_RNDN);
  mpfr_add_ui(c, c, 1, MPFR_RNDN);
  mpfr_div(r, r, c, MPFR_RNDN);
  mpfr_sqrt(r, r, MPFR_RNDN);
  mpfr_const_pi(angle, MPFR_RNDN);
  mpfr_mul_si(angle, angle, num, MPFR_RNDN);
  mpfr_div_si(angle, angle, den, MPFR_RNDN);
  mpfr_sin_cos(y, x, angle, MPFR_RNDN);
  mpfr_mul(x, x, r, MPFR_RNDN);
  mpfr_mul(y, y, r, MPFR_RNDN);
  const int on_axis = (2 * num) % den == 0, odd = (2 * num / den) % 2 != 0;
  p[0] = on_axis && odd ? 0.0 : mpfr_get_d(x, MPFR_RNDN);
  p[1] = on_axis && !odd ? 0.0 : mpfr_get_d(y, MPFR_RNDN);
  mpfr_clears(c, r, angle, x, y, (mpfr_ptr)0);
}

/* v_k: cosh R = cot(pi/4g)^2 (the circumradius of the regular 4g-gon with
   angles pi/2g), at angle (2k+1) pi/4g. m_k: cosh d = cot(pi/4g), at angle
   k pi/2g (= 2k pi/4g). */
static void reference_vertex(int g, int k, double p[2]) { reference_point(g, 2, 2L * k + 1, 4L * g, p); }
static void reference_midpoint(int g, int k, double p[2]) { reference_point(g, 1, 2L * k, 4L * g, p); }

START_TEST(systole_is_correctly_rounded) {
  int genera[64 + 16];
  size_t n = 0;
  for (int g = 2; g <= 64; ++g) genera[n++] = g;
  const int larger[] = {65, 100, 127, 128, 255, 256, 511, 512, 777, 1000, 1023, HDT_GENUS_MAX, 1 << 20, INT_MAX};
  for (size_t i = 0; i < sizeof larger / sizeof larger[0]; ++i) genera[n++] = larger[i];
  for (size_t i = 0; i < n; ++i) {
    const double s = hdt_systole(genera[i]), ref = reference_systole(genera[i]);
    expect(same_double(s, ref), "hdt_systole(%d) = %a, correctly rounded %a", genera[i], s, ref);
  }
}
END_TEST

static void expect_rounded_points(int g, int k) {
  double v[2], m[2], rv[2], rm[2];
  polygon_point(g, k, 1, v);
  polygon_point(g, k, 0, m);
  reference_vertex(g, k, rv);
  reference_midpoint(g, k, rm);
  expect(same_double(v[0], rv[0]) && same_double(v[1], rv[1]),
         "genus %d: v_%d = (%a, %a), correctly rounded (%a, %a)", g, k, v[0], v[1], rv[0], rv[1]);
  expect(same_double(m[0], rm[0]) && same_double(m[1], rm[1]),
         "genus %d: m_%d = (%a, %a), correctly rounded (%a, %a)", g, k, m[0], m[1], rm[0], rm[1]);
}

START_TEST(polygon_points_are_correctly_rounded) {
  for (int g = 2; g <= 16; ++g)
    for (int k = 0; k < 4 * g; ++k) expect_rounded_points(g, k);
  /* Larger genus: around each quarter turn, and a random sample. */
  const int genera[] = {17, 31, 64, 100, 255, 512, 777, 1000, HDT_GENUS_MAX};
  uint64_t rng = 2024;
  for (size_t i = 0; i < sizeof genera / sizeof genera[0]; ++i) {
    const int g = genera[i];
    for (int q = 0; q < 4; ++q)
      for (int d = -2; d <= 2; ++d) expect_rounded_points(g, (q * g + d + 4 * g) % (4 * g));
    for (int j = 0; j < 24; ++j) expect_rounded_points(g, rng_below(&rng, 4 * g));
  }
}
END_TEST

/* The symmetries of F_g map its vertices and midpoints onto each other with
   exact coordinate changes, so the correctly rounded points follow them bit
   for bit: rotation by pi/2 (k -> k + g), reflection in the x-axis, and
   x = y at angle pi/4. */
START_TEST(polygon_points_keep_the_symmetries) {
  for (int g = 2; g <= 40; ++g) {
    const int n = 4 * g;
    for (int k = 0; k < n; ++k) {
      double v[2], vr[2], vc[2], m[2], mr[2], mc[2];
      polygon_point(g, k, 1, v);
      polygon_point(g, k + g, 1, vr);
      polygon_point(g, n - 1 - k, 1, vc); /* angle -(2k+1) pi/4g */
      polygon_point(g, k, 0, m);
      polygon_point(g, k + g, 0, mr);
      polygon_point(g, n - k, 0, mc);
      expect(same_double(vr[0], -v[1]) && same_double(vr[1], v[0]), "genus %d: v_%d is not v_%d turned by pi/2", g,
             k + g, k);
      expect(same_double(vc[0], v[0]) && same_double(vc[1], -v[1]), "genus %d: v_%d is not conj(v_%d)", g, n - 1 - k,
             k);
      /* Midpoints on an axis have a +0 coordinate, where -m[.] would be -0. */
      expect(same_double(mr[0], m[1] == 0 ? 0.0 : -m[1]) && same_double(mr[1], m[0]),
             "genus %d: m_%d is not m_%d turned by pi/2", g, k + g, k);
      expect(same_double(mc[0], m[0]) && same_double(mc[1], m[1] == 0 ? 0.0 : -m[1]),
             "genus %d: m_%d is not conj(m_%d)", g, (n - k) % n, k);
      if (2 * k + 1 == g) expect(same_double(v[0], v[1]), "genus %d: v_%d off the diagonal", g, k);
      if (2 * k == g) expect(same_double(m[0], m[1]), "genus %d: m_%d off the diagonal", g, k);
      if (k % g == 0) expect(same_double(m[(k / g) % 2 == 0 ? 1 : 0], 0.0), "genus %d: m_%d off its axis", g, k);
    }
  }
}
END_TEST

/* The dummy nearest to (x, y) (within 1e-9), as its id and point. */
static uint32_t nearest_dummy(hdt_triangulation *t, double x, double y, double p[2]) {
  size_t count = 0;
  ck_assert_int_eq(hdt_vertices(t, NULL, NULL, NULL, 0, &count), HDT_OK);
  uint32_t *ids = malloc(count * sizeof *ids);
  double *xy = malloc(2 * count * sizeof *xy);
  uint8_t *dummy = malloc(count);
  ck_assert(ids && xy && dummy);
  ck_assert_int_eq(hdt_vertices(t, ids, xy, dummy, count, &count), HDT_OK);
  uint32_t best = HDT_NO_VERTEX;
  double best_gap = 1e-9;
  for (size_t i = 0; i < count; ++i) {
    const double gap = hypot(xy[2 * i] - x, xy[2 * i + 1] - y);
    if (dummy[i] && gap < best_gap) best = ids[i], best_gap = gap, p[0] = xy[2 * i], p[1] = xy[2 * i + 1];
  }
  free(ids), free(xy), free(dummy);
  expect(best != HDT_NO_VERTEX, "no dummy vertex at (%.17g, %.17g)", x, y);
  return best;
}

/* The dummy vertex v_0 is the exact vertex; hdt_vertex_point rounds it, as
   hdt_polygon_vertex does. The rounded point is another point of the disk:
   inserting it makes a new vertex. */
START_TEST(v0_dummy_is_the_rounded_vertex) {
  for (int g = 2; g <= 6; ++g) {
    hdt_triangulation *t = NULL;
    ck_assert_int_eq(hdt_create(&t, g), HDT_OK);
    double v[2], d[2];
    polygon_point(g, 0, 1, v);
    const uint32_t id = nearest_dummy(t, v[0], v[1], d);
    expect(same_double(d[0], v[0]) && same_double(d[1], v[1]), "genus %d: the v_0 dummy is at (%a, %a), v_0 at (%a, %a)",
           g, d[0], d[1], v[0], v[1]);
    const size_t before = hdt_vertex_count(t);
    uint32_t inserted = HDT_NO_VERTEX;
    ck_assert_int_eq(hdt_insert(t, v[0], v[1], &inserted), HDT_OK);
    expect(inserted != id && hdt_vertex_count(t) == before + 1 && hdt_vertex_is_dummy(t, id) == 1,
           "genus %d: inserting the rounded v_0 did not make a new vertex", g);
    hdt_destroy(t);
  }
}
END_TEST

/* Likewise for the dummies m_0 .. m_{2g-1}. */
START_TEST(midpoint_dummies_are_the_rounded_midpoints) {
  for (int g = 2; g <= 6; ++g) {
    hdt_triangulation *t = NULL;
    ck_assert_int_eq(hdt_create(&t, g), HDT_OK);
    for (int k = 0; k < 2 * g; ++k) {
      double m[2], d[2];
      polygon_point(g, k, 0, m);
      nearest_dummy(t, m[0], m[1], d);
      expect(same_double(d[0], m[0]) && same_double(d[1], m[1]),
             "genus %d: the m_%d dummy is at (%a, %a), m_%d at (%a, %a)", g, k, d[0], d[1], k, m[0], m[1]);
    }
    hdt_destroy(t);
  }
}
END_TEST

int main(void) {
  const TTest *const tests[] = {
      polygon_points_are_where_documented, generators_pair_the_sides, actions_agree,
      lorentz_preserves_the_form,          systole_closed_form,       systole_is_least_translation_length,
      systole_is_correctly_rounded,        polygon_points_are_correctly_rounded,
      polygon_points_keep_the_symmetries,  v0_dummy_is_the_rounded_vertex,
      midpoint_dummies_are_the_rounded_midpoints,
  };
  return run_tests("geometry", tests, sizeof tests / sizeof tests[0]);
}
