/* The Delaunay triangulation of random points on M_g, and its picture.
 *
 *   triangulate_demo [-g GENUS] [-n POINTS] [-s SEED] [--neighbours] [OUT.svg]
 *
 * Defaults: genus 3, 300 points, seed 1, output triangulation-gGENUS.svg.
 * The points are uniform for hyperbolic area in F_g. The program creates a
 * triangulation (it starts with the dummy points of its genus), inserts the
 * points with hdt_insert_many, removes the dummies it can, validates, prints
 * the counts and timings, and draws every face's canonical copy in the
 * Poincare disk (with --neighbours also its copies under the 4g generators).
 *
 * Uses only the public C API (C99 and POSIX clock_gettime).
 */
#define _POSIX_C_SOURCE 199309L

#include <hdt.h>

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define PICTURE_SIZE 800.0 /* width, and height of the disk's square */
#define TITLE_HEIGHT 56.0  /* a band above the disk for the caption */
#define DISK_SCALE 0.97    /* the unit circle's radius, in half picture widths */

/* ---- Errors and timing ---- */

static int check(hdt_status s, const char *what) {
  if (s == HDT_OK) return 1;
  fflush(stdout);
  fprintf(stderr, "triangulate_demo: %s failed: %s (%s)\n", what, hdt_status_string(s),
          hdt_last_error_message());
  return 0;
}

static double now_ms(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

/* ---- A small, portable random generator (splitmix64) ---- */

static uint64_t rng_state;

static uint64_t rng_next(void) {
  uint64_t z = (rng_state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/* Uniform in [0, 1), 53 random bits. */
static double rng_uniform(void) { return (double)(rng_next() >> 11) * 0x1.0p-53; }

/* ---- Random points uniform for hyperbolic area in F_g ----
 * F_g lies in the disk of hyperbolic radius R about 0, cosh R = cot^2(pi/4g)
 * (its vertices are at distance R). On that disk the area element is
 * sinh r dr dtheta, so cosh r uniform in [1, cosh R] and theta uniform give
 * the uniform distribution; a point is kept when it lies in F_g, i.e. when
 * its canonical representative is itself (hdt_point_representative gives
 * the empty word). The Poincare radius is tanh(r/2) = sqrt((cosh r - 1) /
 * (cosh r + 1)).
 *
 * Most rejected candidates are far beyond a side, and the library call is
 * not free, so a double-precision test rejects those first: side s_k lies on
 * the circle of centre c_k = |c| e^{ik pi/2g}, |c| = (mu + 1/mu)/2 with mu the
 * midpoints' radius, orthogonal to the unit circle, and z is beyond it when
 * its power |z - c_k|^2 - (|c|^2 - 1) = 1 + |z|^2 - 2 c_k.z is negative. Only
 * the side nearest in angle matters. Candidates that are not clearly beyond
 * it are decided by the library. */
static int sample_points(int genus, size_t n, double *xy, size_t *tried) {
  const double pi = acos(-1.0);
  const double cot = 1.0 / tan(pi / (4.0 * genus));
  const double cosh_R = cot * cot;
  double mx, my;
  if (!check(hdt_polygon_side_midpoint(genus, 0, &mx, &my), "hdt_polygon_side_midpoint")) return 0;
  const double mu = hypot(mx, my), c = (mu + 1.0 / mu) / 2.0, step = pi / (2.0 * genus);
  size_t kept = 0;
  *tried = 0;
  while (kept < n) {
    const double ch = 1.0 + rng_uniform() * (cosh_R - 1.0);
    const double rho = sqrt((ch - 1.0) / (ch + 1.0));
    const double theta = 2.0 * pi * rng_uniform();
    const double x = rho * cos(theta), y = rho * sin(theta);
    ++*tried;
    const double side_angle = step * floor(theta / step + 0.5);
    if (1.0 + rho * rho - 2.0 * c * rho * cos(theta - side_angle) < -1e-9) continue; /* clearly outside */
    size_t length = 0;
    if (!check(hdt_point_representative(genus, x, y, NULL, NULL, NULL, 0, &length),
               "hdt_point_representative"))
      return 0;
    if (length != 0) continue; /* outside the half-open F_g */
    xy[2 * kept] = x;
    xy[2 * kept + 1] = y;
    ++kept;
  }
  return 1;
}

/* ---- Moebius maps ---- */

/* SU(1,1) matrix as in hdt_word_matrix: m[0] + i m[1] = a, m[2] + i m[3] = b;
   z -> (a z + b) / (conj(b) z + conj(a)). */
static void moebius(const double m[4], double x, double y, double *ox, double *oy) {
  const double ar = m[0], ai = m[1], br = m[2], bi = m[3];
  const double nr = ar * x - ai * y + br, ni = ar * y + ai * x + bi;  /* a z + b */
  const double dr = br * x + bi * y + ar, di = br * y - bi * x - ai;  /* conj(b) z + conj(a) */
  const double d2 = dr * dr + di * di;
  *ox = (nr * dr + ni * di) / d2;
  *oy = (ni * dr - nr * di) / d2;
}

/* Matrices of translation ids, fetched once each (ids of a triangulation
   may exceed |N|; the table grows as needed). */
typedef struct {
  const hdt_triangulation *t;
  double (*m)[4];
  unsigned char *have;
  size_t size;
} matrix_cache;

static const double *cached_matrix(matrix_cache *cache, int32_t id) {
  if (id < 0) {
    fprintf(stderr, "triangulate_demo: negative translation id %ld\n", (long)id);
    return NULL;
  }
  const size_t i = (size_t)id;
  if (i >= cache->size) {
    size_t size = cache->size ? cache->size : 64;
    while (size <= i) size *= 2;
    double(*m)[4] = realloc(cache->m, size * sizeof *m);
    if (!m) return NULL;
    cache->m = m;
    unsigned char *have = realloc(cache->have, size);
    if (!have) return NULL;
    memset(have + cache->size, 0, size - cache->size);
    cache->have = have;
    cache->size = size;
  }
  if (!cache->have[i]) {
    if (!check(hdt_translation_matrix(cache->t, id, cache->m[i]), "hdt_translation_matrix")) return NULL;
    cache->have[i] = 1;
  }
  return cache->m[i];
}

/* ---- SVG ---- */

/* Disk coordinates to SVG coordinates (y points down in SVG). */
static double sx(double x) { return PICTURE_SIZE / 2 * (1 + DISK_SCALE * x); }
static double sy(double y) { return TITLE_HEIGHT + PICTURE_SIZE / 2 * (1 - DISK_SCALE * y); }

/* An SVG path command drawing the geodesic from p to q: an arc of the circle
 * orthogonal to the unit circle through both, or a segment when p, q and 0
 * are collinear. Inside the disk that arc is always less than a half circle
 * (large-arc flag 0); the sweep flag follows the turn from p to q about the
 * circle's centre (counterclockwise in the disk is 0 in SVG's y-down
 * coordinates, where flag 1 is the visually clockwise direction). */
static void geodesic_to(FILE *f, double px, double py, double qx, double qy) {
  const double cross = px * qy - py * qx;
  const double scale = (1 + px * px + py * py) * (1 + qx * qx + qy * qy);
  if (fabs(cross) <= 1e-9 * scale) {
    fprintf(f, "L%.2f %.2f", sx(qx), sy(qy));
    return;
  }
  /* The centre c solves c.p = (1 + |p|^2)/2, c.q = (1 + |q|^2)/2. */
  const double bp = (1 + px * px + py * py) / 2, bq = (1 + qx * qx + qy * qy) / 2;
  const double cx = (bp * qy - bq * py) / cross, cy = (px * bq - qx * bp) / cross;
  const double r = sqrt(fmax(cx * cx + cy * cy - 1, 0)) * PICTURE_SIZE / 2 * DISK_SCALE;
  const int counterclockwise = (px - cx) * (qy - cy) - (py - cy) * (qx - cx) > 0;
  fprintf(f, "A%.2f %.2f 0 0 %d %.2f %.2f", r, r, counterclockwise ? 0 : 1, sx(qx), sy(qy));
}

/* A closed geodesic polygon through n disk points, as path data. */
static void geodesic_polygon(FILE *f, const double *x, const double *y, int n) {
  fprintf(f, "M%.2f %.2f", sx(x[0]), sy(y[0]));
  for (int k = 0; k < n; ++k) geodesic_to(f, x[k], y[k], x[(k + 1) % n], y[(k + 1) % n]);
  fputc('Z', f);
}

/* A triangle whose corners are all within a pixel of each other. */
static int too_small(const double x[3], const double y[3]) {
  const double pixel = 2.0 / (PICTURE_SIZE * DISK_SCALE);
  for (int a = 0; a < 3; ++a)
    if (hypot(x[a] - x[(a + 1) % 3], y[a] - y[(a + 1) % 3]) > pixel) return 0;
  return 1;
}

/* The polygon F_g, or its image under the matrix m (NULL: identity). */
static int fundamental_polygon(FILE *f, int genus, const double *m) {
  double x[4 * HDT_GENUS_MAX], y[4 * HDT_GENUS_MAX];
  for (int k = 0; k < 4 * genus; ++k) {
    if (!check(hdt_polygon_vertex(genus, k, &x[k], &y[k]), "hdt_polygon_vertex")) return 0;
    if (m) moebius(m, x[k], y[k], &x[k], &y[k]);
  }
  geodesic_polygon(f, x, y, 4 * genus);
  return 1;
}

typedef struct {
  int genus;
  size_t face_count;
  const uint32_t *vertices;     /* 3 per face */
  const int32_t *translations;  /* 3 per face */
  const double *points;         /* representative of vertex v at 2v, 2v+1 */
  size_t vertex_bound;
  const hdt_triangulation *t;
  matrix_cache *cache;
} picture_data;

/* The corners of face i in its canonical copy, then mapped by h (may be NULL). */
static int face_corners(const picture_data *d, size_t i, const double *h, double x[3], double y[3]) {
  for (size_t c = 0; c < 3; ++c) {
    const uint32_t v = d->vertices[3 * i + c];
    const double *m = cached_matrix(d->cache, d->translations[3 * i + c]);
    if (!m) return 0;
    moebius(m, d->points[2 * v], d->points[2 * v + 1], &x[c], &y[c]);
    if (h) moebius(h, x[c], y[c], &x[c], &y[c]);
  }
  return 1;
}

static int write_picture(const char *path, const picture_data *d, int neighbours, size_t n_points) {
  FILE *f = fopen(path, "w");
  if (!f) {
    fprintf(stderr, "triangulate_demo: cannot open %s: %s\n", path, strerror(errno));
    return 0;
  }
  const int genus = d->genus;
  const double height = PICTURE_SIZE + TITLE_HEIGHT, r = PICTURE_SIZE / 2 * DISK_SCALE;
  int ok = 1;
  fprintf(f, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%g\" height=\"%g\" viewBox=\"0 0 %g %g\">\n",
          PICTURE_SIZE, height, PICTURE_SIZE, height);
  fprintf(f, "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n");
  fprintf(f, "<circle cx=\"%g\" cy=\"%g\" r=\"%g\" fill=\"#f4f6fb\" stroke=\"#333\" stroke-width=\"1.5\"/>\n",
          sx(0), sy(0), r);

  /* F_g, lightly filled under everything. */
  fprintf(f, "<path fill=\"#ffd98a\" fill-opacity=\"0.35\" stroke=\"none\" d=\"");
  ok = ok && fundamental_polygon(f, genus, NULL);
  fprintf(f, "\"/>\n");

  /* The copies under the one-letter translations (ids 1..4g), lighter. */
  if (ok && neighbours) {
    fprintf(f, "<g fill=\"none\" stroke-linejoin=\"round\">\n");
    fprintf(f, "<path stroke=\"#e0b070\" stroke-width=\"0.8\" d=\"");
    for (int32_t id = 1; ok && id <= 4 * genus; ++id) {
      const double *h = cached_matrix(d->cache, id);
      ok = h && fundamental_polygon(f, genus, h);
    }
    fprintf(f, "\"/>\n");
    fprintf(f, "<path stroke=\"#9aa8c8\" stroke-width=\"0.4\" d=\"");
    for (int32_t id = 1; ok && id <= 4 * genus; ++id) {
      double h[4];
      const double *hm = cached_matrix(d->cache, id);
      if (!hm) {
        ok = 0;
        break;
      }
      memcpy(h, hm, sizeof h); /* the cache may move while filling */
      for (size_t i = 0, drawn = 0; ok && i < d->face_count; ++i) {
        double x[3], y[3];
        ok = face_corners(d, i, h, x, y);
        if (!ok || too_small(x, y)) continue; /* near the circle: below a pixel */
        geodesic_polygon(f, x, y, 3);
        if (++drawn % 8 == 0) fputc('\n', f);
      }
    }
    fprintf(f, "\"/>\n</g>\n");
  }

  /* Every face's canonical copy. */
  fprintf(f, "<path fill=\"none\" stroke=\"#1f2a44\" stroke-width=\"0.6\" stroke-linejoin=\"round\" d=\"");
  for (size_t i = 0; ok && i < d->face_count; ++i) {
    double x[3], y[3];
    ok = face_corners(d, i, NULL, x, y);
    if (ok) geodesic_polygon(f, x, y, 3);
    if (ok && i % 8 == 7) fputc('\n', f);
  }
  fprintf(f, "\"/>\n");

  /* F_g's boundary on top. */
  fprintf(f, "<path fill=\"none\" stroke=\"#c05a00\" stroke-width=\"1.8\" stroke-opacity=\"0.85\" d=\"");
  ok = ok && fundamental_polygon(f, genus, NULL);
  fprintf(f, "\"/>\n");

  /* The vertices at their representatives: user points dark, dummies red. */
  fprintf(f, "<g fill=\"#1f2a44\">\n");
  for (size_t v = 0; ok && v < d->vertex_bound; ++v)
    if (hdt_vertex_is_dummy(d->t, (uint32_t)v) == 0)
      fprintf(f, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"1.6\"/>\n", sx(d->points[2 * v]), sy(d->points[2 * v + 1]));
  fprintf(f, "</g>\n<g fill=\"#d62728\">\n");
  for (size_t v = 0; ok && v < d->vertex_bound; ++v)
    if (hdt_vertex_is_dummy(d->t, (uint32_t)v) == 1)
      fprintf(f, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"2.6\"/>\n", sx(d->points[2 * v]), sy(d->points[2 * v + 1]));
  fprintf(f, "</g>\n");

  fprintf(f, "<text x=\"12\" y=\"22\" font-family=\"sans-serif\" font-size=\"16\">Delaunay triangulation "
             "of %zu random points on M_%d</text>\n", n_points, genus);
  fprintf(f, "<text x=\"12\" y=\"42\" font-family=\"sans-serif\" font-size=\"13\" fill=\"#555\">"
             "%zu vertices%s, %zu faces (canonical copies)%s; Poincare disk, F_%d outlined</text>\n",
          hdt_vertex_count(d->t), hdt_dummy_count(d->t) ? " (dummies in red)" : "", d->face_count,
          neighbours ? " and their images under the generators" : "", genus);
  fprintf(f, "</svg>\n");
  if (ferror(f)) ok = 0;
  if (fclose(f) != 0) ok = 0;
  if (!ok) fprintf(stderr, "triangulate_demo: could not write %s\n", path);
  return ok;
}

/* ---- Command line ---- */

static void usage(FILE *f) {
  fprintf(f, "usage: triangulate_demo [-g GENUS] [-n POINTS] [-s SEED] [--neighbours] [OUT.svg]\n"
             "  -g GENUS      genus of the surface M_g, >= 2 (default 3)\n"
             "  -n POINTS     number of random points, uniform for area in F_g (default 300)\n"
             "  -s SEED       seed of the random generator (default 1)\n"
             "  --neighbours  also draw the faces' copies under the 4g generators\n"
             "  OUT.svg       the picture (default triangulation-gGENUS.svg)\n");
}

static int parse_ull(const char *text, unsigned long long max, unsigned long long *out) {
  char *end = NULL;
  if (!text || !*text || *text == '-') return 0;
  errno = 0;
  const unsigned long long value = strtoull(text, &end, 10);
  if (errno != 0 || *end != '\0' || value > max) return 0;
  *out = value;
  return 1;
}

int main(int argc, char **argv) {
  unsigned long long genus_arg = 3, n_arg = 300, seed = 1;
  int neighbours = 0;
  const char *path = NULL;
  for (int i = 1; i < argc; ++i) {
    const char *a = argv[i];
    if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) {
      usage(stdout);
      return 0;
    } else if (strcmp(a, "--neighbours") == 0 || strcmp(a, "--neighbors") == 0) {
      neighbours = 1;
    } else if (strcmp(a, "-g") == 0 || strcmp(a, "-n") == 0 || strcmp(a, "-s") == 0) {
      const char *value = i + 1 < argc ? argv[++i] : NULL;
      int ok;
      if (a[1] == 'g') ok = parse_ull(value, HDT_GENUS_MAX, &genus_arg) && genus_arg >= 2;
      else if (a[1] == 'n') ok = parse_ull(value, 100000000ULL, &n_arg);
      else ok = parse_ull(value, UINT64_MAX, &seed);
      if (!ok) {
        fprintf(stderr, "triangulate_demo: bad or missing value for %s\n", a);
        usage(stderr);
        return 2;
      }
    } else if (a[0] == '-' && a[1] != '\0') {
      fprintf(stderr, "triangulate_demo: unknown option %s\n", a);
      usage(stderr);
      return 2;
    } else if (!path) {
      path = a;
    } else {
      fprintf(stderr, "triangulate_demo: more than one output file\n");
      usage(stderr);
      return 2;
    }
  }
  const int genus = (int)genus_arg;
  const size_t n = (size_t)n_arg;
  char default_path[64];
  snprintf(default_path, sizeof default_path, "triangulation-g%d.svg", genus);
  if (!path) path = default_path;

  int status = 1;
  hdt_triangulation *t = NULL;
  double *xy = NULL, *points = NULL;
  uint32_t *face_vertices = NULL;
  int32_t *face_translations = NULL;
  matrix_cache cache = {NULL, NULL, NULL, 0};

  printf("libhdt %s: Delaunay triangulation of %zu random points on M_%d (seed %llu)\n",
         hdt_version_string(), n, genus, seed);

  /* Sample. */
  rng_state = seed;
  xy = malloc((n ? n : 1) * 2 * sizeof *xy);
  if (!xy) {
    fprintf(stderr, "triangulate_demo: out of memory\n");
    goto done;
  }
  size_t tried = 0;
  double t0 = now_ms();
  if (!sample_points(genus, n, xy, &tried)) goto done;
  const double ms_sample = now_ms() - t0;

  /* Create, insert, remove the dummies, validate. */
  t0 = now_ms();
  if (!check(hdt_create(&t, genus), "hdt_create")) goto done;
  const double ms_create = now_ms() - t0;
  const size_t dummies = hdt_dummy_count(t);

  t0 = now_ms();
  if (!check(hdt_insert_many(t, xy, n, NULL), "hdt_insert_many")) goto done;
  const double ms_insert = now_ms() - t0;
  const size_t dummies_after_insert = hdt_dummy_count(t);

  size_t remaining = 0;
  t0 = now_ms();
  if (!check(hdt_remove_dummies(t, &remaining), "hdt_remove_dummies")) goto done;
  const double ms_remove = now_ms() - t0;

  /* A failed validation still gets its counts and picture (they help to
     see what broke), but the exit status is 1. */
  t0 = now_ms();
  const int valid = check(hdt_validate(t), "hdt_validate");
  const double ms_validate = now_ms() - t0;

  /* Counts. */
  const size_t V = hdt_vertex_count(t), F = hdt_face_count(t), E = 3 * F / 2;
  const size_t dummies_left = hdt_dummy_count(t);
  const long euler = (long)V - (long)E + (long)F;
  printf("  sampled        : %zu points uniform for area in F_%d (%zu tried, %.1f%% kept)\n", n, genus,
         tried, tried ? 100.0 * (double)n / (double)tried : 0.0);
  printf("  dummies        : %zu at creation, %zu after insertion, %zu left after removal\n", dummies,
         dummies_after_insert, dummies_left);
  printf("  counts         : %zu vertices, %zu faces, %zu edges, %zu dummies left\n", V, F, E, dummies_left);
  printf("  Euler char.    : V - E + F = %ld (2 - 2g = %d)\n", euler, 2 - 2 * genus);
  printf("  validate       : %s\n", valid ? "ok" : "FAILED");
  printf("  timings (ms)   : create %.2f, insert %.2f, remove dummies %.2f, validate %.2f (sampling %.2f)\n",
         ms_create, ms_insert, ms_remove, ms_validate, ms_sample);
  fflush(stdout);
  if (remaining != dummies_left)
    fprintf(stderr, "triangulate_demo: warning: hdt_remove_dummies reported %zu remaining, "
                    "hdt_dummy_count says %zu\n", remaining, dummies_left);
  if (euler != 2 - 2 * (long)genus || 2 * E != 3 * F)
    fprintf(stderr, "triangulate_demo: warning: counts break V - E + F = 2 - 2g\n");

  /* The faces and the vertices' representatives. */
  size_t face_count = 0;
  if (!check(hdt_faces(t, NULL, NULL, 0, &face_count), "hdt_faces (count)")) goto done;
  face_vertices = malloc((face_count ? face_count : 1) * 3 * sizeof *face_vertices);
  face_translations = malloc((face_count ? face_count : 1) * 3 * sizeof *face_translations);
  if (!face_vertices || !face_translations) {
    fprintf(stderr, "triangulate_demo: out of memory\n");
    goto done;
  }
  if (!check(hdt_faces(t, face_vertices, face_translations, face_count, &face_count), "hdt_faces")) goto done;
  if (face_count != F)
    fprintf(stderr, "triangulate_demo: warning: hdt_faces gives %zu faces, hdt_face_count %zu\n", face_count, F);

  const size_t bound = hdt_vertex_id_bound(t);
  points = malloc((bound ? bound : 1) * 2 * sizeof *points);
  if (!points) {
    fprintf(stderr, "triangulate_demo: out of memory\n");
    goto done;
  }
  for (size_t v = 0; v < bound; ++v) {
    points[2 * v] = points[2 * v + 1] = 0;
    if (hdt_vertex_is_dummy(t, (uint32_t)v) < 0) continue; /* removed */
    if (!check(hdt_vertex_point(t, (uint32_t)v, &points[2 * v], &points[2 * v + 1]), "hdt_vertex_point"))
      goto done;
  }
  for (size_t i = 0; i < 3 * face_count; ++i)
    if (face_vertices[i] >= bound || hdt_vertex_is_dummy(t, face_vertices[i]) < 0) {
      fprintf(stderr, "triangulate_demo: face %zu names vertex %lu, which is not live\n", i / 3,
              (unsigned long)face_vertices[i]);
      goto done;
    }

  cache.t = t;
  picture_data data = {genus, face_count, face_vertices, face_translations, points, bound, t, &cache};
  if (!write_picture(path, &data, neighbours, n)) goto done;
  printf("  picture        : %s\n", path);
  status = valid ? 0 : 1;

done:
  free(cache.m);
  free(cache.have);
  free(points);
  free(face_translations);
  free(face_vertices);
  free(xy);
  hdt_destroy(t);
  return status;
}
