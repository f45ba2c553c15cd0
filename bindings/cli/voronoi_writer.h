/* hdt-triangulate --voronoi: the Voronoi diagram in the text and JSON
 * outputs (hdt-triangulate.1, OUTPUT FORMATS):
 *   - per face, in hdt_faces order, its Voronoi vertex: the hyperbolic
 *     circumcentre (x, y) of the face's canonical copy and the circumradius;
 *   - per edge, in hdt_edges order, the Voronoi edge: the faces on the left
 *     and right of the Delaunay edge, and the geodesic segment from the left
 *     face's circumcentre to the right face's circumcentre placed beside it.
 * Fetched once through the public API (hdt_voronoi_vertices, hdt_edges,
 * hdt_voronoi_edges); numbers printed with %.17g. */
#ifndef HDT_CLI_VORONOI_WRITER_H
#define HDT_CLI_VORONOI_WRITER_H

#include <hdt.h>

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

typedef struct voronoi {
  size_t face_count, edge_count;
  double *centres;      /* 2 per face */
  double *radii;        /* 1 per face */
  uint32_t *edge_faces; /* 2 per edge: left, right */
  double *segments;     /* 4 per edge: x0 y0 x1 y1 */
} voronoi;

/* Fills v from t; 0 on a failure (reported on stderr; v is then freed). */
int voronoi_take(const hdt_triangulation *t, voronoi *v);
void voronoi_free(voronoi *v);
/* The sections "voronoi_vertices F" and "voronoi_edges E" of the text output. */
void voronoi_write_text(FILE *f, const voronoi *v);
/* The member "voronoi": {...} of the JSON object, indented by two spaces,
   without a separator before or after. */
void voronoi_write_json(FILE *f, const voronoi *v);

#endif
