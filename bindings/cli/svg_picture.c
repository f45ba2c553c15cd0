/* hdt-triangulate: the triangulation drawn in the Poincare disk, as SVG. */
#define _POSIX_C_SOURCE 200809L

#include "svg_picture.h"

#include "cli_util.h"

#include <hdt.h>

#include <math.h>
#include <stdlib.h>

#define PICTURE_SIZE 800.0 /* width, and height of the disk's square */
#define TITLE_HEIGHT 56.0  /* a band above the disk for the caption */
#define DISK_SCALE 0.97    /* the unit circle's radius, in half picture widths */

/* Disk coordinates to SVG coordinates (y points down in SVG), rounded to
   0.01 px when printed (about 3e-5 in the disk): enough for the eye and
   for zooming in, and it keeps the files small. */
static double sx(double x) { return PICTURE_SIZE / 2 * (1 + DISK_SCALE * x); }
static double sy(double y) { return TITLE_HEIGHT + PICTURE_SIZE / 2 * (1 - DISK_SCALE * y); }

/* ---- Geodesics ---- */

/* Path data for the geodesic from p to q: an arc of the circle orthogonal to
 * the unit circle through both, or a segment when p, q and 0 are collinear
 * (within a rounding-size margin, where the arc's radius would exceed any
 * visible curvature). Inside the disk that arc is less than a half circle
 * (large-arc flag 0). The sweep flag follows the turn from p to q about the
 * circle's centre c: counterclockwise in the disk (y up) is flag 0 in SVG's
 * y-down coordinates. */
static void geodesic_to(FILE *f, double px, double py, double qx, double qy) {
  const double cross = px * qy - py * qx;
  const double bp = (1 + px * px + py * py) / 2, bq = (1 + qx * qx + qy * qy) / 2;
  if (fabs(cross) <= 1e-9 * bp * bq) {
    fprintf(f, "L%.2f %.2f", sx(qx), sy(qy));
    return;
  }
  /* c solves c.p = (1 + |p|^2)/2 and c.q = (1 + |q|^2)/2. */
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

/* ---- The surface's pieces in F_g ----
 *
 * The picture shows M_g as F_g with its sides paired: every copy h(T) of a
 * face T that meets F_g, cut at F_g's sides by a clip path, so that F_g is
 * tiled exactly and an edge leaving through side s_k comes back through
 * s_{k+2g}. The canonical copy T of a face has its smallest vertex in F_g
 * and lies in D_N, the union of the tiles n(F_g), n in N; so a tile
 * h^{-1}(F_g) meeting T is one of those, and the copies to look at are h(T),
 * h in N (N = N^{-1}). A copy is dropped when its three corners lie beyond
 * one side of F_g (then all of it does: half-planes are convex); the few
 * others that miss F_g are cut away by the clip path.
 */

typedef struct geometry {
  int genus, n;           /* n = 4g sides */
  double *vx, *vy;        /* F_g's vertices v_0 .. v_{n-1} */
  double *cx, *cy;        /* centres of the sides' circles (orthogonal to the unit circle) */
  double (*generator)[4]; /* g_0 .. g_{n-1} */
  double (*neighbour)[4]; /* the elements of N, by translation id */
  size_t neighbour_count;
} geometry;

static void geometry_free(geometry *g) {
  free(g->vx);
  free(g->vy);
  free(g->cx);
  free(g->cy);
  free(g->generator);
  free(g->neighbour);
}

static int geometry_init(geometry *g, int genus) {
  const int n = 4 * genus;
  g->genus = genus;
  g->n = n;
  g->vx = cli_alloc((size_t)n, sizeof *g->vx);
  g->vy = cli_alloc((size_t)n, sizeof *g->vy);
  g->cx = cli_alloc((size_t)n, sizeof *g->cx);
  g->cy = cli_alloc((size_t)n, sizeof *g->cy);
  g->generator = cli_alloc((size_t)n, sizeof *g->generator);
  if (!g->vx || !g->vy || !g->cx || !g->cy || !g->generator) return 0;
  for (int k = 0; k < n; ++k) {
    const int32_t letter = k;
    double mx, my;
    if (!cli_check(hdt_polygon_vertex(genus, k, &g->vx[k], &g->vy[k]), "hdt_polygon_vertex") ||
        !cli_check(hdt_polygon_side_midpoint(genus, k, &mx, &my), "hdt_polygon_side_midpoint") ||
        !cli_check(hdt_word_matrix(genus, &letter, 1, g->generator[k]), "hdt_word_matrix"))
      return 0;
    /* The circle through m_k orthogonal to the unit circle has its centre on
       the ray through m_k, at |c| = (|m| + 1/|m|) / 2. */
    const double m2 = mx * mx + my * my, scale = (1 + m2) / (2 * m2);
    g->cx[k] = mx * scale;
    g->cy[k] = my * scale;
  }
  if (!cli_check(hdt_neighbour_count(genus, &g->neighbour_count), "hdt_neighbour_count")) return 0;
  g->neighbour = cli_alloc(g->neighbour_count, sizeof *g->neighbour);
  if (!g->neighbour) return 0;
  int32_t word[2 * HDT_GENUS_MAX + 1]; /* the words of N have at most 2g letters */
  for (size_t id = 0; id < g->neighbour_count; ++id) {
    size_t length = 0;
    if (!cli_check(hdt_neighbour_word(genus, id, word, sizeof word / sizeof *word, &length), "hdt_neighbour_word") ||
        !cli_check(hdt_word_matrix(genus, word, length, g->neighbour[id]), "hdt_word_matrix"))
      return 0;
  }
  return 1;
}

/* The power of the disk point (x, y) with respect to the circle of side k:
   negative beyond the side's geodesic (outside F_g's half-plane), zero on it. */
static double side_power(const geometry *g, int k, double x, double y) {
  return 1 + x * x + y * y - 2 * (g->cx[k] * x + g->cy[k] * y);
}

static int beyond(const geometry *g, int k, double x, double y) { return side_power(g, k, x, y) < 0; }

/* Whether the triangle with corners x, y can meet F_g. */
static int may_meet_polygon(const geometry *g, const double x[3], const double y[3]) {
  for (int k = 0; k < g->n; ++k)
    if (beyond(g, k, x[0], y[0]) && beyond(g, k, x[1], y[1]) && beyond(g, k, x[2], y[2])) return 0;
  return 1;
}

/* Path data for the copies h(T) meeting F_g, each then mapped by `then`
   (NULL: the identity); with `skip_small`, copies below a pixel are left out. */
static void pieces(FILE *f, const snapshot *s, const geometry *g, const double *then, int skip_small) {
  size_t drawn = 0;
  for (size_t i = 0; i < s->face_count; ++i) {
    double tx[3], ty[3];
    for (int c = 0; c < 3; ++c) snapshot_corner(s, i, c, &tx[c], &ty[c]);
    for (size_t h = 0; h < g->neighbour_count; ++h) {
      double x[3], y[3];
      for (int c = 0; c < 3; ++c) {
        x[c] = tx[c];
        y[c] = ty[c];
        if (h != 0) moebius_apply(g->neighbour[h], tx[c], ty[c], &x[c], &y[c]);
      }
      if (!may_meet_polygon(g, x, y)) continue;
      if (then)
        for (int c = 0; c < 3; ++c) moebius_apply(then, x[c], y[c], &x[c], &y[c]);
      if (skip_small && too_small(x, y)) continue;
      geodesic_polygon(f, x, y, 3);
      if (++drawn % 8 == 0) fputc('\n', f);
    }
  }
}

/* The polygon F_g, or its image under m (NULL: the identity). */
static void polygon_copy(FILE *f, const geometry *g, const double *m) {
  double x[4 * HDT_GENUS_MAX], y[4 * HDT_GENUS_MAX];
  for (int k = 0; k < g->n; ++k) {
    x[k] = g->vx[k];
    y[k] = g->vy[k];
    if (m) moebius_apply(m, g->vx[k], g->vy[k], &x[k], &y[k]);
  }
  geodesic_polygon(f, x, y, g->n);
}

/* ---- The picture ---- */

/* The length of the valid UTF-8 sequence at p (1 to 4 bytes), or 0. */
static int utf8_sequence(const unsigned char *p) {
  int n;
  unsigned int min;
  if (p[0] < 0x80) return 1;
  if ((p[0] & 0xe0) == 0xc0) n = 2, min = 0x80;
  else if ((p[0] & 0xf0) == 0xe0) n = 3, min = 0x800;
  else if ((p[0] & 0xf8) == 0xf0) n = 4, min = 0x10000;
  else return 0;
  unsigned int code = p[0] & (0x7f >> n);
  for (int i = 1; i < n; ++i) {
    if ((p[i] & 0xc0) != 0x80) return 0; /* also stops at the terminating NUL */
    code = (code << 6) | (p[i] & 0x3f);
  }
  if (code < min || code > 0x10ffff || (code >= 0xd800 && code <= 0xdfff)) return 0;
  return n;
}

/* Plain text as SVG character data: markup escaped, and what XML 1.0 does
   not allow (control characters, bytes that are not UTF-8, as in a file
   name) shown as '?'. */
static void put_escaped(FILE *f, const char *text) {
  const unsigned char *p = (const unsigned char *)text;
  while (*p) {
    const int n = utf8_sequence(p);
    if (n == 0 || (*p < 0x20 && *p != '\t')) {
      fputc('?', f);
      ++p;
    } else if (*p == '&') {
      fputs("&amp;", f), ++p;
    } else if (*p == '<') {
      fputs("&lt;", f), ++p;
    } else if (*p == '>') {
      fputs("&gt;", f), ++p;
    } else {
      fwrite(p, 1, (size_t)n, f);
      p += n;
    }
  }
}

/* A dot at each place vertex v appears in the closed F_g: its representative,
   and for a vertex on F_g's boundary its other copies there (on the paired
   side; at every corner for a vertex at v_0). */
static void vertex_dots(FILE *f, const snapshot *s, const geometry *g, int kind, const char *colour,
                        double radius) {
  const double eps = 1e-9;
  fprintf(f, "<g fill=\"%s\">\n", colour);
  for (size_t v = 0; v < s->vertex_bound; ++v) {
    if (s->kind[v] != kind) continue;
    fprintf(f, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%g\"/>\n", sx(s->x[v]), sy(s->y[v]), radius);
    int on_boundary = 0;
    for (int k = 0; k < g->n && !on_boundary; ++k) on_boundary = fabs(side_power(g, k, s->x[v], s->y[v])) < eps;
    for (size_t h = 1; on_boundary && h < g->neighbour_count; ++h) {
      double x, y;
      moebius_apply(g->neighbour[h], s->x[v], s->y[v], &x, &y);
      int inside = 1;
      for (int k = 0; k < g->n && inside; ++k) inside = side_power(g, k, x, y) > -eps;
      if (inside) fprintf(f, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%g\"/>\n", sx(x), sy(y), radius);
    }
  }
  fputs("</g>\n", f);
}

int svg_picture_write(FILE *f, const snapshot *s, const svg_options *options) {
  const int genus = s->genus;
  const double height = PICTURE_SIZE + TITLE_HEIGHT, r = PICTURE_SIZE / 2 * DISK_SCALE;
  /* Thinner lines and smaller dots for large triangulations. */
  const double line = s->face_count > 6000 ? 0.3 : 0.6;
  const double dot = s->vertex_count > 3000 ? 0.9 : 1.6;

  geometry g = {0};
  if (!geometry_init(&g, genus)) {
    geometry_free(&g);
    return 0;
  }

  fprintf(f, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%g\" height=\"%g\" viewBox=\"0 0 %g %g\">\n",
          PICTURE_SIZE, height, PICTURE_SIZE, height);
  fputs("<defs><clipPath id=\"hdt-polygon\"><path d=\"", f);
  polygon_copy(f, &g, NULL);
  fputs("\"/></clipPath></defs>\n", f);
  fputs("<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n", f);
  fprintf(f, "<circle cx=\"%g\" cy=\"%g\" r=\"%g\" fill=\"#f4f6fb\" stroke=\"#333\" stroke-width=\"1.5\"/>\n",
          sx(0), sy(0), r);

  /* F_g, lightly filled under everything. */
  fputs("<path fill=\"#ffd98a\" fill-opacity=\"0.35\" stroke=\"none\" d=\"", f);
  polygon_copy(f, &g, NULL);
  fputs("\"/>\n", f);

  /* Across the sides, lighter: the tiles g_k(F_g), each with the
     triangulation drawn in it (F_g's pieces mapped by g_k, cut at the tile). */
  if (options->neighbours) {
    fputs("<defs>\n", f);
    for (int k = 0; k < g.n; ++k) {
      fprintf(f, "<clipPath id=\"hdt-tile-%d\"><path d=\"", k);
      polygon_copy(f, &g, g.generator[k]);
      fputs("\"/></clipPath>\n", f);
    }
    fputs("</defs>\n<g fill=\"none\" stroke-linejoin=\"round\">\n", f);
    for (int k = 0; k < g.n; ++k) {
      fprintf(f, "<path clip-path=\"url(#hdt-tile-%d)\" stroke=\"#8a9ac0\" stroke-width=\"%g\" d=\"", k,
              line * 2 / 3);
      pieces(f, s, &g, g.generator[k], 1);
      fputs("\"/>\n", f);
    }
    fputs("<path stroke=\"#e0b070\" stroke-width=\"1\" d=\"", f);
    for (int k = 0; k < g.n; ++k) polygon_copy(f, &g, g.generator[k]);
    fputs("\"/>\n</g>\n", f);
  }

  /* The triangulation in F_g, cut at its sides. */
  fprintf(f, "<path clip-path=\"url(#hdt-polygon)\" fill=\"none\" stroke=\"#1f2a44\" stroke-width=\"%g\" "
             "stroke-linejoin=\"round\" d=\"", line);
  pieces(f, s, &g, NULL, 0);
  fputs("\"/>\n", f);

  /* F_g's boundary on top. */
  fputs("<path fill=\"none\" stroke=\"#c05a00\" stroke-width=\"1.8\" stroke-opacity=\"0.85\" d=\"", f);
  polygon_copy(f, &g, NULL);
  fputs("\"/>\n", f);

  /* The vertices: user points dark, dummies red. */
  vertex_dots(f, s, &g, 0, "#1f2a44", dot);
  vertex_dots(f, s, &g, 1, "#d62728", dot + 1.0);

  fputs("<text x=\"12\" y=\"22\" font-family=\"sans-serif\" font-size=\"16\">", f);
  put_escaped(f, options->title);
  fputs("</text>\n", f);
  fprintf(f, "<text x=\"12\" y=\"42\" font-family=\"sans-serif\" font-size=\"13\" fill=\"#555\">%zu vertices",
          s->vertex_count);
  if (s->dummy_count) fprintf(f, " (%zu dumm%s, red)", s->dummy_count, s->dummy_count == 1 ? "y" : "ies");
  fprintf(f, ", %zu faces, drawn in F_%d and cut at its sides", s->face_count, genus);
  if (options->neighbours) fprintf(f, ", and in the %d tiles across them", g.n);
  fputs("; Poincare disk</text>\n", f);
  fputs("</svg>\n", f);

  geometry_free(&g);
  return 1;
}
