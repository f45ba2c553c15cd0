/* hdt-triangulate: a copy of what the text and JSON outputs need from a
 * triangulation (vertices, faces, and the words of the translation ids the
 * faces use), fetched once through the public API. (The picture is drawn by
 * libhdt itself: hdt_svg.) */
#ifndef HDT_CLI_SNAPSHOT_H
#define HDT_CLI_SNAPSHOT_H

#include <hdt.h>

#include <stddef.h>
#include <stdint.h>

typedef struct snapshot {
  int genus;
  /* 0 on the built-in M_g; else the number of sides of the polygon the
     surface is given by (hdt_create_on_surface), whose translation words
     are words in its pairings. */
  int sides;
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
     canonical words (letters word_letters[word_start[i] .. word_start[i+1]-1]). */
  size_t translation_count;
  int32_t *translation_ids;
  size_t *word_start;
  int32_t *word_letters;
  /* slot[id] = index i of translation id `id` (ids up to max_translation). */
  int32_t max_translation;
  size_t *slot;
} snapshot;

/* Fills s from t; 0 on a failure (reported on stderr; s is then freed). */
int snapshot_take(const hdt_triangulation *t, snapshot *s);
void snapshot_free(snapshot *s);

#endif
