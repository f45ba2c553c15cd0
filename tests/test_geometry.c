/* Geometry through the public header: the polygon F_g, the action of words
   (Moebius and Lorentz), and the systole. */
#include <complex.h>
#include <limits.h>

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
        apply_word(g, &w, points[i][0], points[i][1], &ax, &ay);
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

int main(void) {
  const TTest *const tests[] = {
      polygon_points_are_where_documented, generators_pair_the_sides, actions_agree,
      lorentz_preserves_the_form,          systole_closed_form,       systole_is_least_translation_length,
  };
  return run_tests("geometry", tests, sizeof tests / sizeof tests[0]);
}
