/* hdt-triangulate: the triangulation as text or JSON. */
#define _POSIX_C_SOURCE 200809L

#include "face_writer.h"

#include <hdt.h>

static void write_text(FILE *f, const snapshot *s, const uint32_t *point_vertex, size_t n_points,
                       const voronoi *vd) {
  if (s->sides)
    fprintf(f,
            "# hdt-triangulate %s (libhdt %s): Delaunay triangulation on a surface of genus %d given by a "
            "%d-sided polygon\n",
            HDT_CLI_VERSION, hdt_version_string(), s->genus, s->sides);
  else
    fprintf(f, "# hdt-triangulate %s (libhdt %s): Delaunay triangulation on M_%d\n", HDT_CLI_VERSION,
            hdt_version_string(), s->genus);
  fputs("# Sections: a line \"NAME COUNT\", then COUNT lines.\n", f);
  fputs(s->sides ? "#   vertices:     id x y dummy   (x, y: representative in the polygon; dummy: 1 or 0)\n"
                 : "#   vertices:     id x y dummy   (x, y: representative in F_g; dummy: 1 or 0)\n",
        f);
  fputs("#   faces:        v0 v1 v2 t0 t1 t2   (vertices counterclockwise; corner i is\n"
        "#                 translation t_i applied to the point of vertex v_i)\n",
        f);
  fputs(s->sides ? "#   translations: id length letter...   (word in the pairings; letter k pairs side k)\n"
                 : "#   translations: id length letter...   (canonical word; letter k is g_k)\n",
        f);
  fputs("#   points:       index vertex   (the vertex of each input point, input order)\n", f);
  if (vd)
    fputs("#   voronoi_vertices: x y radius   (per face: circumcentre of its canonical copy)\n"
          "#   voronoi_edges:    left right x0 y0 x1 y1   (per edge: its faces; the Voronoi edge)\n",
          f);
  fprintf(f, "genus %d\n", s->genus);
  fprintf(f, "vertices %zu\n", s->vertex_count);
  for (size_t v = 0; v < s->vertex_bound; ++v)
    if (s->kind[v] >= 0) fprintf(f, "%zu %.17g %.17g %d\n", v, s->x[v], s->y[v], s->kind[v]);
  fprintf(f, "faces %zu\n", s->face_count);
  for (size_t i = 0; i < s->face_count; ++i) {
    const uint32_t *v = s->face_vertices + 3 * i;
    const int32_t *t = s->face_translations + 3 * i;
    fprintf(f, "%lu %lu %lu %ld %ld %ld\n", (unsigned long)v[0], (unsigned long)v[1], (unsigned long)v[2],
            (long)t[0], (long)t[1], (long)t[2]);
  }
  fprintf(f, "translations %zu\n", s->translation_count);
  for (size_t i = 0; i < s->translation_count; ++i) {
    const size_t begin = s->word_start[i], end = s->word_start[i + 1];
    fprintf(f, "%ld %zu", (long)s->translation_ids[i], end - begin);
    for (size_t k = begin; k < end; ++k) fprintf(f, " %ld", (long)s->word_letters[k]);
    fputc('\n', f);
  }
  fprintf(f, "points %zu\n", n_points);
  for (size_t i = 0; i < n_points; ++i) fprintf(f, "%zu %lu\n", i, (unsigned long)point_vertex[i]);
  if (vd) voronoi_write_text(f, vd);
}

static void write_json(FILE *f, const snapshot *s, const uint32_t *point_vertex, size_t n_points,
                       const voronoi *vd) {
  fprintf(f, "{\n  \"genus\": %d,\n  \"libhdt\": \"%s\",\n", s->genus, hdt_version_string());
  if (s->sides) fprintf(f, "  \"polygon_sides\": %d,\n", s->sides);
  fputs("  \"vertices\": [", f);
  const char *sep = "\n";
  for (size_t v = 0; v < s->vertex_bound; ++v) {
    if (s->kind[v] < 0) continue;
    fprintf(f, "%s    {\"id\": %zu, \"x\": %.17g, \"y\": %.17g, \"dummy\": %s}", sep, v, s->x[v], s->y[v],
            s->kind[v] ? "true" : "false");
    sep = ",\n";
  }
  fputs(s->vertex_count ? "\n  ],\n" : "],\n", f);
  fputs("  \"faces\": [", f);
  sep = "\n";
  for (size_t i = 0; i < s->face_count; ++i) {
    const uint32_t *v = s->face_vertices + 3 * i;
    const int32_t *t = s->face_translations + 3 * i;
    fprintf(f, "%s    {\"vertices\": [%lu, %lu, %lu], \"translations\": [%ld, %ld, %ld]}", sep,
            (unsigned long)v[0], (unsigned long)v[1], (unsigned long)v[2], (long)t[0], (long)t[1], (long)t[2]);
    sep = ",\n";
  }
  fputs(s->face_count ? "\n  ],\n" : "],\n", f);
  fputs("  \"translations\": {", f);
  sep = "\n";
  for (size_t i = 0; i < s->translation_count; ++i) {
    const size_t begin = s->word_start[i], end = s->word_start[i + 1];
    fprintf(f, "%s    \"%ld\": [", sep, (long)s->translation_ids[i]);
    for (size_t k = begin; k < end; ++k) fprintf(f, k > begin ? ", %ld" : "%ld", (long)s->word_letters[k]);
    fputc(']', f);
    sep = ",\n";
  }
  fputs(s->translation_count ? "\n  },\n" : "},\n", f);
  fputs("  \"points\": [", f);
  for (size_t i = 0; i < n_points; ++i) {
    if (i % 16 == 0) fputs(i ? ",\n    " : "\n    ", f);
    else fputs(", ", f);
    fprintf(f, "%lu", (unsigned long)point_vertex[i]);
  }
  fputs(n_points ? "\n  ]" : "]", f);
  if (vd) {
    fputs(",\n", f);
    voronoi_write_json(f, vd);
  }
  fputs("\n}\n", f);
}

void face_writer_write(FILE *f, face_format format, const snapshot *s, const uint32_t *point_vertex,
                       size_t n_points, const voronoi *v) {
  if (format == FACE_FORMAT_JSON)
    write_json(f, s, point_vertex, n_points, v);
  else
    write_text(f, s, point_vertex, n_points, v);
}
