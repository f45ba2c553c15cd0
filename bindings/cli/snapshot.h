/* hdt-triangulate: a copy of what the outputs need from a triangulation
 * (vertices, faces, and the words and matrices of the translation ids the
 * faces use), fetched once through the public API. */
#ifndef HDT_CLI_SNAPSHOT_H
#define HDT_CLI_SNAPSHOT_H

#include <hdt.h>

#include <stddef.h>
#include <stdint.h>

typedef struct snapshot {
  int genus;
  /* Vertices by id, 0 .. vertex_bound-1: kind[v] is -1 for a removed id,
     0 for a user vertex, 1 for a dummy; (x[v], y[v]) is the representative
     of a live vertex in the half-open F_g. */
  size_t vertex_bound, vertex_count, dummy_count;
  signed char *kind;
  double *x, *y;
  /* Faces in hdt_faces order: 3 vertex ids (counterclockwise) and 3
     translation ids per face. */
  size_t face_count;
  uint32_t *face_vertices;
  int32_t *face_translations;
  /* The distinct translation ids the faces use, increasing, with their
     canonical words (letters word_letters[word_start[i] .. word_start[i+1]-1])
     and SU(1,1) matrices (layout of hdt_word_matrix). */
  size_t translation_count;
  int32_t *translation_ids;
  size_t *word_start;
  int32_t *word_letters;
  double (*matrices)[4];
  /* slot[id] = index i of translation id `id` (ids up to max_translation). */
  int32_t max_translation;
  size_t *slot;
} snapshot;

/* Fills s from t; 0 on a failure (reported on stderr; s is then freed). */
int snapshot_take(const hdt_triangulation *t, snapshot *s);
void snapshot_free(snapshot *s);

/* The matrix of a translation id used by some face. */
const double *snapshot_matrix(const snapshot *s, int32_t id);

/* z -> (a z + b) / (conj(b) z + conj(a)) for m = (Re a, Im a, Re b, Im b). */
void moebius_apply(const double m[4], double x, double y, double *ox, double *oy);

/* The corner c (0..2) of face f in the face's canonical copy: the corner's
   translation applied to its vertex's representative. */
void snapshot_corner(const snapshot *s, size_t f, int c, double *x, double *y);

#endif
