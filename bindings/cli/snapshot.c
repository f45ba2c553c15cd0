/* hdt-triangulate: a copy of what the outputs need from a triangulation. */
#define _POSIX_C_SOURCE 200809L

#include "snapshot.h"

#include "cli_util.h"

#include <stdlib.h>
#include <string.h>

void snapshot_free(snapshot *s) {
  free(s->kind);
  free(s->x);
  free(s->y);
  free(s->face_vertices);
  free(s->face_translations);
  free(s->translation_ids);
  free(s->word_start);
  free(s->word_letters);
  free(s->slot);
  memset(s, 0, sizeof *s);
}

static int take_vertices(const hdt_triangulation *t, snapshot *s) {
  const size_t bound = hdt_vertex_id_bound(t);
  if (bound > (size_t)UINT32_MAX + 1) {
    cli_error("hdt_vertex_id_bound: %zu ids do not fit in uint32_t", bound);
    return 0;
  }
  s->vertex_bound = bound;
  s->kind = cli_alloc(bound, sizeof *s->kind);
  s->x = cli_alloc(bound, sizeof *s->x);
  s->y = cli_alloc(bound, sizeof *s->y);
  if (!s->kind || !s->x || !s->y) return 0;
  for (size_t v = 0; v < bound; ++v) {
    const int kind = hdt_vertex_is_dummy(t, (uint32_t)v);
    s->kind[v] = (signed char)(kind < 0 ? -1 : kind);
    s->x[v] = s->y[v] = 0;
    if (kind < 0) continue;
    ++s->vertex_count;
    if (kind == 1) ++s->dummy_count;
    if (!cli_check(hdt_vertex_point(t, (uint32_t)v, &s->x[v], &s->y[v]), "hdt_vertex_point")) return 0;
  }
  return 1;
}

static int take_faces(const hdt_triangulation *t, snapshot *s) {
  size_t count = 0;
  if (!cli_check(hdt_faces(t, NULL, NULL, 0, &count), "hdt_faces")) return 0;
  if (count > SIZE_MAX / 3) {
    cli_error("hdt_faces: %zu faces", count);
    return 0;
  }
  s->face_vertices = cli_alloc(3 * count, sizeof *s->face_vertices);
  s->face_translations = cli_alloc(3 * count, sizeof *s->face_translations);
  if (!s->face_vertices || !s->face_translations) return 0;
  if (!cli_check(hdt_faces(t, s->face_vertices, s->face_translations, count, &count), "hdt_faces")) return 0;
  s->face_count = count;
  for (size_t i = 0; i < 3 * count; ++i) {
    const uint32_t v = s->face_vertices[i];
    if (v >= s->vertex_bound || s->kind[v] < 0) {
      cli_error("hdt_faces: face %zu names vertex %lu, which is not live", i / 3, (unsigned long)v);
      return 0;
    }
    if (s->face_translations[i] < 0) {
      cli_error("hdt_faces: face %zu has the translation id %ld", i / 3, (long)s->face_translations[i]);
      return 0;
    }
  }
  return 1;
}

/* The words of the translation ids in use (id 0, the identity,
   always: the outputs list it even for a triangulation without faces). */
static int take_translations(const hdt_triangulation *t, snapshot *s) {
  int32_t max = 0;
  for (size_t i = 0; i < 3 * s->face_count; ++i)
    if (s->face_translations[i] > max) max = s->face_translations[i];
  s->max_translation = max;
  s->slot = cli_alloc((size_t)max + 1, sizeof *s->slot);
  if (!s->slot) return 0;
  const size_t none = (size_t)-1;
  for (size_t id = 0; id <= (size_t)max; ++id) s->slot[id] = none;
  s->slot[0] = 0;
  for (size_t i = 0; i < 3 * s->face_count; ++i) s->slot[s->face_translations[i]] = 0;
  size_t count = 0;
  for (size_t id = 0; id <= (size_t)max; ++id)
    if (s->slot[id] != none) s->slot[id] = count++;
  s->translation_count = count;
  s->translation_ids = cli_alloc(count, sizeof *s->translation_ids);
  s->word_start = cli_alloc(count + 1, sizeof *s->word_start);
  if (!s->translation_ids || !s->word_start) return 0;

  size_t letters = 0, capacity = 0;
  for (size_t id = 0; id <= (size_t)max; ++id) {
    if (s->slot[id] == none) continue;
    const size_t i = s->slot[id];
    s->translation_ids[i] = (int32_t)id;
    s->word_start[i] = letters;
    size_t length = 0;
    if (!cli_check(hdt_translation_word(t, (int32_t)id, NULL, 0, &length), "hdt_translation_word")) return 0;
    if (letters + length > capacity) {
      size_t grown = capacity ? 2 * capacity : 256;
      while (grown < letters + length) grown *= 2;
      int32_t *w = cli_realloc(s->word_letters, grown, sizeof *w);
      if (!w) return 0;
      s->word_letters = w;
      capacity = grown;
    }
    if (length > 0 &&
        !cli_check(hdt_translation_word(t, (int32_t)id, s->word_letters + letters, length, &length),
                   "hdt_translation_word"))
      return 0;
    letters += length;
  }
  s->word_start[count] = letters;
  return 1;
}

int snapshot_take(const hdt_triangulation *t, snapshot *s) {
  memset(s, 0, sizeof *s);
  s->genus = hdt_genus(t);
  hdt_surface *surface = NULL;
  if (hdt_triangulation_surface(t, &surface) != HDT_OK) return 0;
  s->sides = surface ? hdt_surface_side_count(surface) : 0;
  hdt_surface_destroy(surface);
  if (take_vertices(t, s) && take_faces(t, s) && take_translations(t, s)) return 1;
  snapshot_free(s);
  return 0;
}
