/* hdt-triangulate --voronoi: the Voronoi diagram as text or JSON. */
#include "voronoi_writer.h"

#include <stdlib.h>
#include <string.h>

#include "cli_util.h"

int voronoi_take(const hdt_triangulation *t, voronoi *v) {
  memset(v, 0, sizeof *v);
  const size_t F = hdt_face_count(t), E = hdt_edge_count(t);
  v->centres = cli_alloc(2 * F, sizeof *v->centres);
  v->radii = cli_alloc(F, sizeof *v->radii);
  v->edge_faces = cli_alloc(2 * E, sizeof *v->edge_faces);
  v->segments = cli_alloc(4 * E, sizeof *v->segments);
  size_t n = 0, m = 0, k = 0;
  if (!v->centres || !v->radii || !v->edge_faces || !v->segments ||
      !cli_check(hdt_voronoi_vertices(t, v->centres, v->radii, F, &n), "hdt_voronoi_vertices") ||
      !cli_check(hdt_edges(t, NULL, NULL, v->edge_faces, NULL, E, &m), "hdt_edges") ||
      !cli_check(hdt_voronoi_edges(t, v->segments, E, &k), "hdt_voronoi_edges")) {
    voronoi_free(v);
    return 0;
  }
  v->face_count = n, v->edge_count = m;
  return 1;
}

void voronoi_free(voronoi *v) {
  free(v->centres), free(v->radii), free(v->edge_faces), free(v->segments);
  memset(v, 0, sizeof *v);
}

void voronoi_write_text(FILE *f, const voronoi *v) {
  fprintf(f, "voronoi_vertices %zu\n", v->face_count);
  for (size_t i = 0; i < v->face_count; ++i)
    fprintf(f, "%.17g %.17g %.17g\n", v->centres[2 * i], v->centres[2 * i + 1], v->radii[i]);
  fprintf(f, "voronoi_edges %zu\n", v->edge_count);
  for (size_t e = 0; e < v->edge_count; ++e) {
    const double *s = v->segments + 4 * e;
    fprintf(f, "%lu %lu %.17g %.17g %.17g %.17g\n", (unsigned long)v->edge_faces[2 * e],
            (unsigned long)v->edge_faces[2 * e + 1], s[0], s[1], s[2], s[3]);
  }
}

void voronoi_write_json(FILE *f, const voronoi *v) {
  fputs("  \"voronoi\": {\n    \"vertices\": [", f);
  const char *sep = "\n";
  for (size_t i = 0; i < v->face_count; ++i) {
    fprintf(f, "%s      {\"x\": %.17g, \"y\": %.17g, \"radius\": %.17g}", sep, v->centres[2 * i],
            v->centres[2 * i + 1], v->radii[i]);
    sep = ",\n";
  }
  fputs(v->face_count ? "\n    ],\n" : "],\n", f);
  fputs("    \"edges\": [", f);
  sep = "\n";
  for (size_t e = 0; e < v->edge_count; ++e) {
    const double *s = v->segments + 4 * e;
    fprintf(f, "%s      {\"faces\": [%lu, %lu], \"from\": [%.17g, %.17g], \"to\": [%.17g, %.17g]}", sep,
            (unsigned long)v->edge_faces[2 * e], (unsigned long)v->edge_faces[2 * e + 1], s[0], s[1], s[2], s[3]);
    sep = ",\n";
  }
  fputs(v->edge_count ? "\n    ]\n  }" : "]\n  }", f);
}
