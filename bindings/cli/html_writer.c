/* hdt-triangulate --html: the viewer page (html_writer.h). The JSON is
 * written as hdt.viewer.data_json writes it, byte for byte: members in a
 * fixed order, no spaces, one line per top-level member, each number with
 * the fewest of 15, 16 or 17 significant digits that read back as the same
 * double (Python's "%.*g" and C's printf give the same digits: both round
 * correctly). */
#define _POSIX_C_SOURCE 200809L

#include "html_writer.h"

#include "cli_util.h"
#include "viewer_template.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* The version of the JSON format (hdt.viewer.FORMAT_VERSION). */
#define VIEWER_FORMAT_VERSION 1

static void put_number(FILE *f, double x) {
  char text[40];
  for (int digits = 15; digits <= 17; ++digits) {
    snprintf(text, sizeof text, "%.*g", digits, x);
    if (digits == 17 || strtod(text, NULL) == x) break;
  }
  fputs(text, f);
}

static void put_numbers(FILE *f, const double *x, size_t n) {
  putc('[', f);
  for (size_t i = 0; i < n; ++i) {
    if (i) putc(',', f);
    put_number(f, x[i]);
  }
  putc(']', f);
}

static void put_word(FILE *f, const int32_t *letters, size_t n) {
  putc('[', f);
  for (size_t i = 0; i < n; ++i) fprintf(f, i ? ",%ld" : "%ld", (long)letters[i]);
  putc(']', f);
}

/* The length of the valid UTF-8 sequence at p (1 to 4 bytes), or 0 (as
   lib/picture/svg.cpp decides it). */
static int utf8_sequence(const unsigned char *p) {
  int n;
  unsigned int min;
  if (p[0] < 0x80) return 1;
  if ((p[0] & 0xe0) == 0xc0) n = 2, min = 0x80;
  else if ((p[0] & 0xf0) == 0xe0) n = 3, min = 0x800;
  else if ((p[0] & 0xf8) == 0xf0) n = 4, min = 0x10000;
  else return 0;
  unsigned int code = p[0] & (0x7fu >> n);
  for (int i = 1; i < n; ++i) {
    if ((p[i] & 0xc0) != 0x80) return 0; /* also stops at the terminating NUL */
    code = (code << 6) | (p[i] & 0x3f);
  }
  if (code < min || code > 0x10ffff || (code >= 0xd800 && code <= 0xdfff)) return 0;
  return n;
}

/* A JSON string safe inside a script element (hdt.viewer.string): quote,
   backslash, control characters, '<', '>' and '&' escaped; bytes that are
   not UTF-8 (as in a file name) as '?'. */
static void put_string(FILE *f, const char *text) {
  const unsigned char *p = (const unsigned char *)text;
  putc('"', f);
  while (*p) {
    const int n = utf8_sequence(p);
    if (n == 0) {
      putc('?', f);
      ++p;
    } else if (*p == '"' || *p == '\\') {
      putc('\\', f);
      putc(*p++, f);
    } else if (*p < 0x20 || *p == '<' || *p == '>' || *p == '&') {
      fprintf(f, "\\u%04x", *p++);
    } else {
      fwrite(p, 1, (size_t)n, f);
      p += n;
    }
  }
  putc('"', f);
}

/* A growing array of numbers (the matrices, before they are written). */
typedef struct doubles {
  double *x;
  size_t n, capacity;
} doubles;

static int push(doubles *d, const double *x, size_t n) {
  if (d->n + n > d->capacity) {
    const size_t capacity = 2 * (d->n + n);
    double *grown = cli_realloc(d->x, capacity, sizeof *grown);
    if (!grown) return 0;
    d->x = grown;
    d->capacity = capacity;
  }
  memcpy(d->x + d->n, x, n * sizeof *x);
  d->n += n;
  return 1;
}

static int compare_ids(const void *a, const void *b) {
  const int32_t x = *(const int32_t *)a, y = *(const int32_t *)b;
  return (x > y) - (x < y);
}

/* A canonical word by the two-call pattern: fills *letters (malloc'ed,
   freed by the caller) and *n. */
static int neighbour_word(int genus, size_t id, int32_t **letters, size_t *n) {
  if (!cli_check(hdt_neighbour_word(genus, id, NULL, 0, n), "hdt_neighbour_word")) return 0;
  *letters = cli_alloc(*n, sizeof **letters);
  return *letters && cli_check(hdt_neighbour_word(genus, id, *letters, *n, n), "hdt_neighbour_word");
}

static int translation_word(const hdt_triangulation *t, int32_t id, int32_t **letters, size_t *n) {
  if (!cli_check(hdt_translation_word(t, id, NULL, 0, n), "hdt_translation_word")) return 0;
  *letters = cli_alloc(*n, sizeof **letters);
  return *letters && cli_check(hdt_translation_word(t, id, *letters, *n, n), "hdt_translation_word");
}

int html_writer_write(FILE *f, const hdt_triangulation *t, const char *title, int voronoi) {
  const int genus = hdt_genus(t), sides = 4 * genus;
  int ok = 0;
  uint32_t *ids = NULL, *face_vertices = NULL;
  double *xy = NULL, *segments = NULL;
  uint8_t *dummy = NULL;
  int32_t *translations = NULL, *used = NULL, *letters = NULL;
  doubles numbers = {0};
  size_t vertices = 0, faces = 0, edges = 0, neighbours = 0, used_count = 0, length = 0;

  if (!cli_check(hdt_vertices(t, NULL, NULL, NULL, 0, &vertices), "hdt_vertices") ||
      !cli_check(hdt_faces(t, NULL, NULL, 0, &faces), "hdt_faces") ||
      !cli_check(hdt_neighbour_count(genus, &neighbours), "hdt_neighbour_count"))
    goto done;
  ids = cli_alloc(vertices, sizeof *ids);
  xy = cli_alloc(vertices, 2 * sizeof *xy);
  dummy = cli_alloc(vertices, sizeof *dummy);
  face_vertices = cli_alloc(faces, 3 * sizeof *face_vertices);
  translations = cli_alloc(faces, 3 * sizeof *translations);
  used = cli_alloc(faces, 3 * sizeof *used);
  if (!ids || !xy || !dummy || !face_vertices || !translations || !used) goto done;
  if ((vertices && !cli_check(hdt_vertices(t, ids, xy, dummy, vertices, &vertices), "hdt_vertices")) ||
      (faces && !cli_check(hdt_faces(t, face_vertices, translations, faces, &faces), "hdt_faces")))
    goto done;
  if (voronoi) {
    if (!cli_check(hdt_voronoi_edges(t, NULL, 0, &edges), "hdt_voronoi_edges")) goto done;
    segments = cli_alloc(edges, 4 * sizeof *segments);
    if (!segments || (edges && !cli_check(hdt_voronoi_edges(t, segments, edges, &edges), "hdt_voronoi_edges")))
      goto done;
  }
  /* The distinct translation ids of the corners, increasing. */
  memcpy(used, translations, 3 * faces * sizeof *used);
  qsort(used, 3 * faces, sizeof *used, compare_ids);
  for (size_t i = 0; i < 3 * faces; ++i)
    if (i == 0 || used[i] != used[i - 1]) used[used_count++] = used[i];

  fwrite(viewer_head, 1, sizeof viewer_head, f);
  fprintf(f, "{\"format\":\"hdt-viewer\",\"version\":%d,\"genus\":%d,\"title\":", VIEWER_FORMAT_VERSION, genus);
  if (title) put_string(f, title);
  else fputs("null", f);
  fputs(",\n\"polygon\":", f);
  for (int k = 0; k < sides; ++k) {
    double v[2];
    if (!cli_check(hdt_polygon_vertex(genus, k, &v[0], &v[1]), "hdt_polygon_vertex") || !push(&numbers, v, 2))
      goto done;
  }
  put_numbers(f, numbers.x, numbers.n);
  numbers.n = 0;
  fputs(",\n\"generators\":", f);
  for (int k = 0; k < sides; ++k) {
    const int32_t letter = k;
    double m[4];
    if (!cli_check(hdt_word_matrix(genus, &letter, 1, m), "hdt_word_matrix") || !push(&numbers, m, 4)) goto done;
  }
  put_numbers(f, numbers.x, numbers.n);
  numbers.n = 0;
  fputs(",\n\"neighbours\":{\"words\":[", f);
  for (size_t id = 0; id < neighbours; ++id) {
    double m[4];
    if (!neighbour_word(genus, id, &letters, &length) ||
        !cli_check(hdt_word_matrix(genus, letters, length, m), "hdt_word_matrix") || !push(&numbers, m, 4))
      goto done;
    if (id) putc(',', f);
    put_word(f, letters, length);
    free(letters);
    letters = NULL;
  }
  fputs("],\"matrices\":", f);
  put_numbers(f, numbers.x, numbers.n);
  numbers.n = 0;
  fputs("},\n\"vertices\":{\"ids\":[", f);
  for (size_t i = 0; i < vertices; ++i) fprintf(f, i ? ",%lu" : "%lu", (unsigned long)ids[i]);
  fputs("],\"xy\":", f);
  put_numbers(f, xy, 2 * vertices);
  fputs(",\"dummy\":[", f);
  for (size_t i = 0; i < vertices; ++i) fputs(i ? (dummy[i] ? ",1" : ",0") : (dummy[i] ? "1" : "0"), f);
  fputs("]},\n\"faces\":{\"vertices\":[", f);
  for (size_t i = 0; i < 3 * faces; ++i) fprintf(f, i ? ",%lu" : "%lu", (unsigned long)face_vertices[i]);
  fputs("],\"translations\":", f);
  put_word(f, translations, 3 * faces);
  fputs("},\n\"translations\":{\"ids\":", f);
  put_word(f, used, used_count);
  fputs(",\"words\":[", f);
  for (size_t i = 0; i < used_count; ++i) {
    double m[4];
    if (!translation_word(t, used[i], &letters, &length) ||
        !cli_check(hdt_translation_matrix(t, used[i], m), "hdt_translation_matrix") || !push(&numbers, m, 4))
      goto done;
    if (i) putc(',', f);
    put_word(f, letters, length);
    free(letters);
    letters = NULL;
  }
  fputs("],\"matrices\":", f);
  put_numbers(f, numbers.x, numbers.n);
  fputs("},\n\"voronoi\":", f);
  if (voronoi) {
    fputs("{\"edges\":", f);
    put_numbers(f, segments, 4 * edges);
    putc('}', f);
  } else {
    fputs("null", f);
  }
  putc('}', f);
  fwrite(viewer_tail, 1, sizeof viewer_tail, f);
  ok = 1;

done:
  free(letters);
  free(numbers.x);
  free(used);
  free(segments);
  free(translations);
  free(face_vertices);
  free(dummy);
  free(xy);
  free(ids);
  return ok;
}
