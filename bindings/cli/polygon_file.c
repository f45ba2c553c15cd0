#include "polygon_file.h"

#include <errno.h>
#include <hdt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli_util.h"
#include "output_file.h"

#define POLYGON_FILE_MAX (64u << 20) /* bytes: far more than any polygon text needs */

/* The whole file (NUL-terminated, *size bytes before it), or NULL (reported). */
static char *read_text(const char *path, size_t *size) {
  const int from_stdin = strcmp(path, "-") == 0;
  FILE *f = from_stdin ? stdin : fopen(path, "rb");
  if (!f) {
    cli_error("cannot open %s: %s", path, strerror(errno));
    return NULL;
  }
  char *text = NULL;
  size_t capacity = 0;
  *size = 0;
  for (;;) {
    if (*size + 1 >= capacity) {
      char *grown = capacity < POLYGON_FILE_MAX ? cli_realloc(text, capacity ? 2 * capacity : 4096, 1) : NULL;
      if (!grown) {
        if (capacity >= POLYGON_FILE_MAX) cli_error("%s: more than %u bytes: not a polygon", path, POLYGON_FILE_MAX);
        free(text);
        text = NULL;
        break;
      }
      text = grown, capacity = capacity ? 2 * capacity : 4096;
    }
    const size_t got = fread(text + *size, 1, capacity - *size - 1, f);
    *size += got;
    if (got == 0) break;
  }
  if (text && ferror(f)) {
    cli_error("cannot read %s: %s", path, strerror(errno));
    free(text);
    text = NULL;
  }
  if (f != stdin) fclose(f);
  if (text) text[*size] = '\0';
  return text;
}

/* The description: genus, sides, pairing, cycles, |N| and the systole. */
static void describe(FILE *f, const char *path, const hdt_surface *s) {
  const int n = hdt_surface_side_count(s);
  fprintf(f, "# %s: a closed surface from the fundamental polygon in %s (checked exactly)\n", CLI_NAME, path);
  fprintf(f, "genus %d\nsides %d\npairing", hdt_surface_genus(s), n);
  for (int k = 0; k < n; ++k) {
    int j = 0;
    hdt_surface_pairing(s, k, &j, NULL);
    fprintf(f, " %d", j);
  }
  int *cycle = cli_realloc(NULL, (size_t)n, sizeof *cycle);
  size_t cycles = 0, count = 0;
  if (cycle && hdt_surface_vertex_cycles(s, cycle, (size_t)n, &cycles) == HDT_OK) {
    fprintf(f, "\nvertex_cycles %zu:", cycles);
    for (size_t c = 0; c < cycles; ++c) {
      fputs(c ? " |" : "", f);
      for (int k = 0; k < n; ++k)
        if (cycle[k] == (int)c) fprintf(f, " %d", k);
    }
  }
  free(cycle);
  if (hdt_surface_neighbour_count(s, &count) == HDT_OK) fprintf(f, "\nneighbours %zu", count);
  double lo, hi;
  if (hdt_surface_systole(s, &lo, &hi) == HDT_OK)
    fprintf(f, "\nsystole %.17g %.17g\n", lo, hi);
  else
    fprintf(f, "\n# systole not computed: %s\n", hdt_last_error_message());
}

/* The picture written to an opened output and finished (committed later,
   with the description). */
static int draw_svg(output_file *out, const char *name, const hdt_surface *s) {
  size_t length = 0;
  if (hdt_surface_svg(s, 800, NULL, 0, &length) != HDT_OK) return 0;
  char *text = cli_realloc(NULL, length + 1, 1);
  int ok = text && hdt_surface_svg(s, 800, text, length + 1, &length) == HDT_OK && output_open(out, name);
  if (ok) {
    fputs(text, out->f);
    ok = output_finish(out);
  }
  free(text);
  return ok;
}

hdt_surface *polygon_file_read(const char *path) {
  size_t size = 0;
  char *text = read_text(path, &size);
  if (!text) return NULL;
  hdt_surface *s = NULL;
  const hdt_status status = hdt_surface_from_polygon(&s, text, size);
  free(text);
  if (status != HDT_OK)
    cli_error("%s: not a fundamental polygon of a closed surface: %s", strcmp(path, "-") ? path : "<stdin>",
              hdt_last_error_message());
  return s;
}

int polygon_file_describe(const char *path, const char *output, const char *svg) {
  hdt_surface *s = polygon_file_read(path);
  if (!s) return CLI_EXIT_FAILURE;
  output_file out = {0}, picture = {0};
  int ok = output_open(&out, output);
  if (ok) {
    describe(out.f, path, s);
    ok = output_finish(&out) && (!svg || draw_svg(&picture, svg, s)) && (!svg || output_commit(&picture)) &&
         output_commit(&out);
  }
  if (!ok) output_discard(&out), output_discard(&picture);
  hdt_surface_destroy(s);
  return ok ? CLI_EXIT_OK : CLI_EXIT_FAILURE;
}
