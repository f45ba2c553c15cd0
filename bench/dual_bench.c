/* The cost of the adjacency, edge, corner and Voronoi outputs (HDT_0.4)
 * next to hdt_faces on the same triangulation: N points uniform for area in
 * F_g, dummies removed; each output fetched whole (the stars and cells one
 * vertex at a time, every vertex), best of three warm runs.
 *
 *   dual_bench [--n 1000000] [--genus 2]
 *
 * Prints one line per output: milliseconds and the ratio to hdt_faces
 * (vertex ids and translations). docs/dual.md quotes it. */
#define _POSIX_C_SOURCE 200809L

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_common.h"
#include "hdt.h"
#include "uniform_points.h"

static void check(hdt_status s, const char *what) {
  if (s != HDT_OK) {
    fprintf(stderr, "%s: %s: %s\n", what, hdt_status_string(s), hdt_last_error_message());
    exit(1);
  }
}

typedef struct buffers {
  size_t V, F, E;
  uint32_t *ids, *u32a, *u32b;
  int32_t *i32a;
  uint8_t *u8;
  double *d1, *d2;
} buffers;

static hdt_triangulation *T;
static buffers B;

static void faces(void) { size_t n; check(hdt_faces(T, B.u32a, B.i32a, B.F, &n), "hdt_faces"); }
static void neighbours(void) { size_t n; check(hdt_face_neighbours(T, B.u32a, B.i32a, B.F, &n), "hdt_face_neighbours"); }
static void edges(void) { size_t n; check(hdt_edges(T, B.u32a, B.i32a, B.u32b, B.d1, B.E, &n), "hdt_edges"); }
static void face_points(void) { size_t n; check(hdt_face_points(T, B.d1, B.F, &n), "hdt_face_points"); }
static void voronoi_vertices(void) {
  size_t n;
  check(hdt_voronoi_vertices(T, B.d1, B.d2, B.F, &n), "hdt_voronoi_vertices");
}
static void voronoi_edges(void) { size_t n; check(hdt_voronoi_edges(T, B.d1, B.E, &n), "hdt_voronoi_edges"); }
static void stars(void) {
  for (size_t i = 0; i < B.V; ++i) {
    size_t n;
    check(hdt_vertex_star(T, B.ids[i], B.u32a, B.u8, B.i32a, B.F, &n), "hdt_vertex_star");
  }
}
static void cells(void) {
  for (size_t i = 0; i < B.V; ++i) {
    size_t n;
    check(hdt_voronoi_cell(T, B.ids[i], B.d1, B.F, &n), "hdt_voronoi_cell");
  }
}

static double best_ms(void (*f)(void)) {
  f(); /* warm: first use of translation products and matrices */
  double best = 1e300;
  for (int k = 0; k < 3; ++k) {
    const double t0 = bench_now_ms();
    f();
    const double dt = bench_now_ms() - t0;
    if (dt < best) best = dt;
  }
  return best;
}

int main(int argc, char **argv) {
  size_t n = 1000000;
  int genus = 2;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!strcmp(argv[i], "--n")) n = strtoull(argv[i + 1], NULL, 10);
    else if (!strcmp(argv[i], "--genus")) genus = atoi(argv[i + 1]);
  }
  double *xy = malloc(2 * n * sizeof *xy);
  bench_points_in_polygon(genus, n, 1, xy);
  check(hdt_create(&T, genus), "hdt_create");
  check(hdt_insert_many(T, xy, n, NULL), "hdt_insert_many");
  check(hdt_remove_dummies(T, NULL), "hdt_remove_dummies");
  free(xy);
  B.V = hdt_vertex_count(T), B.F = hdt_face_count(T), B.E = hdt_edge_count(T);
  B.ids = malloc(B.V * sizeof *B.ids);
  B.u32a = malloc(3 * B.F * sizeof *B.u32a);
  B.u32b = malloc(2 * B.E * sizeof *B.u32b);
  B.i32a = malloc(3 * B.F * sizeof *B.i32a);
  B.u8 = malloc(B.F);
  B.d1 = malloc(6 * B.F * sizeof *B.d1);
  B.d2 = malloc(B.F * sizeof *B.d2);
  size_t count;
  check(hdt_vertices(T, B.ids, NULL, NULL, B.V, &count), "hdt_vertices");
  printf("libhdt %s: genus %d, %zu vertices, %zu faces, %zu edges (best of 3 warm runs)\n", hdt_version_string(),
         genus, B.V, B.F, B.E);
  const struct {
    const char *name;
    void (*f)(void);
  } runs[] = {{"hdt_faces", faces},
              {"hdt_face_neighbours", neighbours},
              {"hdt_edges (all outputs)", edges},
              {"hdt_face_points", face_points},
              {"hdt_voronoi_vertices", voronoi_vertices},
              {"hdt_voronoi_edges", voronoi_edges},
              {"hdt_vertex_star, every vertex", stars},
              {"hdt_voronoi_cell, every vertex", cells}};
  double base = 0;
  for (size_t k = 0; k < sizeof runs / sizeof runs[0]; ++k) {
    const double ms = best_ms(runs[k].f);
    if (k == 0) base = ms;
    printf("  %-32s %9.1f ms  %5.2f x hdt_faces\n", runs[k].name, ms, ms / base);
  }
  free(B.ids), free(B.u32a), free(B.u32b), free(B.i32a), free(B.u8), free(B.d1), free(B.d2);
  hdt_destroy(T);
  return 0;
}
