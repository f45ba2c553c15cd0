/* The surface facts of M_g, and a picture of F_g with the tiles of its
 * neighbour set N (the region D_N the triangulation works in).
 *
 *   surface_demo [GENUS [OUT.svg]]      (defaults: 3, surface-g3.svg)
 *
 * Uses only the public C API. Until triangulations exist this is the
 * library's demo; it becomes the triangulation demo later.
 */
#include <hdt.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define PICTURE_SIZE 800.0
#define TITLE_HEIGHT 40.0 /* a band above the disk for the title */

static int check(hdt_status s, const char *what) {
  if (s == HDT_OK) return 1;
  fprintf(stderr, "%s: %s (%s)\n", what, hdt_status_string(s), hdt_last_error_message());
  return 0;
}

/* Disk coordinates to SVG coordinates (y points down in SVG). */
static double sx(double x) { return PICTURE_SIZE / 2 * (1 + 0.97 * x); }
static double sy(double y) { return TITLE_HEIGHT + PICTURE_SIZE / 2 * (1 - 0.97 * y); }

/* An SVG path command drawing the geodesic from p to q: an arc of the
 * circle orthogonal to the unit circle, or a segment through the centre. */
static void geodesic_to(FILE *f, double px, double py, double qx, double qy) {
  const double cross = px * qy - py * qx;
  if (fabs(cross) < 1e-12) {
    fprintf(f, " L %.3f %.3f", sx(qx), sy(qy));
    return;
  }
  /* Centre c with c.p = (1 + |p|^2)/2 and c.q = (1 + |q|^2)/2. */
  const double bp = (1 + px * px + py * py) / 2, bq = (1 + qx * qx + qy * qy) / 2;
  const double cx = (bp * qy - bq * py) / cross, cy = (px * bq - qx * bp) / cross;
  const double r = sqrt(cx * cx + cy * cy - 1) * PICTURE_SIZE / 2 * 0.97;
  const int counterclockwise = (px - cx) * (qy - cy) - (py - cy) * (qx - cx) > 0;
  fprintf(f, " A %.3f %.3f 0 0 %d %.3f %.3f", r, r, counterclockwise ? 0 : 1, sx(qx), sy(qy));
}

/* The polygon h(F_g) for the word of translation id `id`. */
static int draw_tile(FILE *f, int genus, size_t id, const char *style) {
  int32_t word[256];
  size_t length = 0;
  if (!check(hdt_neighbour_word(genus, id, word, 256, &length), "hdt_neighbour_word")) return 0;
  const int n = 4 * genus;
  double x0 = 0, y0 = 0, px = 0, py = 0;
  fprintf(f, "<path %s d=\"", style);
  for (int k = 0; k <= n; ++k) {
    double vx, vy, x, y;
    if (!check(hdt_polygon_vertex(genus, k, &vx, &vy), "hdt_polygon_vertex")) return 0;
    if (!check(hdt_word_apply(genus, word, length, vx, vy, &x, &y), "hdt_word_apply")) return 0;
    if (k == 0) {
      fprintf(f, "M %.3f %.3f", sx(x), sy(y));
      x0 = x;
      y0 = y;
    } else {
      geodesic_to(f, px, py, k == n ? x0 : x, k == n ? y0 : y);
    }
    px = x;
    py = y;
  }
  fprintf(f, " Z\"/>\n");
  return 1;
}

static int write_picture(const char *path, int genus, size_t neighbours) {
  FILE *f = fopen(path, "w");
  if (!f) {
    perror(path);
    return 0;
  }
  fprintf(f, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%g\" height=\"%g\" viewBox=\"0 0 %g %g\">\n",
          PICTURE_SIZE, PICTURE_SIZE + TITLE_HEIGHT, PICTURE_SIZE, PICTURE_SIZE + TITLE_HEIGHT);
  fprintf(f, "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n");
  fprintf(f, "<circle cx=\"%g\" cy=\"%g\" r=\"%g\" fill=\"#f4f6fb\" stroke=\"#333\" stroke-width=\"1.5\"/>\n",
          PICTURE_SIZE / 2, TITLE_HEIGHT + PICTURE_SIZE / 2, PICTURE_SIZE / 2 * 0.97);
  int ok = 1;
  for (size_t id = 1; ok && id < neighbours; ++id)
    ok = draw_tile(f, genus, id, "fill=\"none\" stroke=\"#7a8bb0\" stroke-width=\"0.6\"");
  if (ok) ok = draw_tile(f, genus, 0, "fill=\"#ffd98a\" fill-opacity=\"0.6\" stroke=\"#b35900\" stroke-width=\"2\"");
  fprintf(f, "<text x=\"12\" y=\"24\" font-family=\"sans-serif\" font-size=\"16\">F_%d and its %zu neighbours "
             "(D_N), Poincare disk</text>\n</svg>\n", genus, neighbours - 1);
  if (fclose(f) != 0) ok = 0;
  return ok;
}

int main(int argc, char **argv) {
  const int genus = argc > 1 ? atoi(argv[1]) : 3;
  char default_path[64];
  snprintf(default_path, sizeof default_path, "surface-g%d.svg", genus);
  const char *path = argc > 2 ? argv[2] : default_path;

  size_t neighbours = 0;
  if (!check(hdt_neighbour_count(genus, &neighbours), "hdt_neighbour_count")) return 1;
  const double pi = acos(-1.0);
  double vx, vy, mx, my;
  if (!check(hdt_polygon_vertex(genus, 0, &vx, &vy), "hdt_polygon_vertex")) return 1;
  if (!check(hdt_polygon_side_midpoint(genus, 0, &mx, &my), "hdt_polygon_side_midpoint")) return 1;

  printf("libhdt %s: the symmetric hyperbolic surface M_%d\n", hdt_version_string(), genus);
  printf("  fundamental polygon F_g : regular %d-gon, interior angles pi/%d, area 4 pi (g-1) = %.6f\n",
         4 * genus, 2 * genus, 4 * pi * (genus - 1));
  printf("  vertex radius (disk)    : %.15f\n", hypot(vx, vy));
  printf("  side midpoint radius    : %.15f\n", hypot(mx, my));
  printf("  systole                 : %.15f\n", hdt_systole(genus));
  printf("  neighbour set |N|       : %zu = (4g-1)^2\n", neighbours);

  /* The relator reduces to the empty word; a chain of half relators shows
     why canonical words need more than Dehn's algorithm. */
  int32_t relator[4 * HDT_GENUS_MAX];
  for (int j = 0; j < 4 * genus; ++j) relator[j] = (int32_t)((j * (2 * genus + 1)) % (4 * genus));
  size_t length = 0;
  if (!check(hdt_word_reduce(genus, relator, (size_t)(4 * genus), NULL, 0, &length), "hdt_word_reduce")) return 1;
  printf("  relator (%d letters)    : reduces to %zu letters\n", 4 * genus, length);

  if (!write_picture(path, genus, neighbours)) {
    fprintf(stderr, "could not write %s\n", path);
    return 1;
  }
  printf("  picture                 : %s\n", path);
  return 0;
}
