/* hdt-triangulate: the triangulation as text or JSON.
 *
 * Both formats hold the same things (hdt-triangulate.1, OUTPUT FORMATS):
 *   - the genus;
 *   - the live vertices by increasing id: id, the representative (x, y) in
 *     the half-open F_g, and whether the vertex is a dummy point;
 *   - the faces in hdt_faces order: three vertex ids counterclockwise and
 *     the three corners' translation ids (corner c of the face's canonical
 *     copy is translation t_c applied to the point of vertex v_c);
 *   - the translation ids the faces use, each with its canonical word (the
 *     letters k of the generators g_k, product written left to right);
 *   - for each input point, in input order, the vertex that holds it (ids
 *     are given in the order of insertion, rounds of Hilbert order, not input order);
 *   - with --voronoi, the Voronoi diagram last (voronoi_writer.h).
 * Numbers are printed with %.17g, so that they read back to the same
 * doubles.
 */
#ifndef HDT_CLI_FACE_WRITER_H
#define HDT_CLI_FACE_WRITER_H

#include "snapshot.h"
#include "voronoi_writer.h"

#include <stdint.h>
#include <stdio.h>

typedef enum { FACE_FORMAT_TEXT, FACE_FORMAT_JSON } face_format;

/* point_vertex[i] is the vertex of input point i (n_points of them); v is
   the Voronoi diagram, or NULL when not asked for. The stream's error state
   is left for the caller to check. */
void face_writer_write(FILE *f, face_format format, const snapshot *s, const uint32_t *point_vertex,
                       size_t n_points, const voronoi *v);

#endif
