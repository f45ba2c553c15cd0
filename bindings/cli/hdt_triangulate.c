/* hdt-triangulate: the Delaunay triangulation of a point set on M_g.
 *
 *   hdt-triangulate [OPTIONS] [FILE]
 *
 * Reads points (or draws random ones), triangulates them with libhdt's
 * public C API, and writes the faces as text or JSON, optionally an SVG
 * picture and an interactive viewer (HTML). Outputs appear whole or not at all. See usage() below and the
 * manual page, hdt-triangulate.1.
 *
 * This file: the options and the run. point_reader.c parses the input
 * (decimal_comma.c recognises "0,25" for its errors), random_points.c
 * samples, snapshot.c fetches the triangulation, face_writer.c writes it,
 * libhdt's hdt_svg draws the picture, html_writer.c writes the viewer,
 * saved_file.c loads and saves
 * (hdt_load, hdt_save), output_file.c makes the writes all-or-nothing.
 */
#define _POSIX_C_SOURCE 200809L

#include "cli_util.h"
#include "face_writer.h"
#include "mesh_writer.h"
#include "html_writer.h"
#include "output_file.h"
#include "point_reader.h"
#include "progress_bar.h"
#include "random_points.h"
#include "polygon_file.h"
#include "saved_file.h"
#include "snapshot.h"

#include <hdt.h>

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* The cap of --random (in --help and its error): 10^8 points are 1.6 GB of
   coordinates already, before the triangulation. */
#define MAX_RANDOM_POINTS 100000000ULL
#define MAX_RANDOM_POINTS_SHOWN "10^8"
#define MAX_REPORTED_LINES 20
#define PICTURE_SIZE 800.0 /* the SVG's width in pixels */

static void usage(FILE *f) {
  fprintf(f,
          "usage: " CLI_NAME " [OPTIONS] [FILE]\n"
          "\n"
          "Delaunay triangulation of points on the symmetric hyperbolic surface M_g\n"
          "(libhdt). Reads points \"x y\" or \"x,y\" of the open unit disk (Poincare\n"
          "disk), one per line, from FILE or standard input (FILE absent or \"-\");\n"
          "blank lines, '#' comments and a UTF-8 byte order mark are ignored; the\n"
          "decimal point is '.'. Writes the vertices, faces and translation words;\n"
          "nothing is written when anything fails. No points (an empty input warns)\n"
          "give the triangulation of the dummy point set.\n"
          "\n"
          "  -g, --genus G       genus of M_g, 2..%d (default 2)\n"
          "      --random N      triangulate N random points, uniform for hyperbolic\n"
          "                      area in F_g, instead of reading points; N <= " MAX_RANDOM_POINTS_SHOWN "\n"
          "      --seed S        seed of --random (default 1)\n"
          "  -f, --format FMT    text (default) or json; or a mesh file: vtu, msh (Gmsh\n"
          "                      2.2), obj or off, each face in its canonical copy\n"
          "  -o, --output FILE   write the triangulation to FILE (default standard output)\n"
          "      --svg FILE      also draw it in the Poincare disk, as SVG\n"
          "      --html FILE     also write an interactive viewer: one self-contained\n"
          "                      HTML page (drag to move across the surface)\n"
          "      --save FILE     also save it in libhdt's format (hdt_save), for --load\n"
          "      --load FILE     start from the triangulation saved in FILE (its genus),\n"
          "                      then insert the points of an input FILE or --random, if\n"
          "                      given (standard input is then read only as \"-\")\n"
          "      --neighbours    with --svg: also the copies across the 4g sides of F_g\n"
          "                      (also spelled --neighbors)\n"
          "      --polygon FILE  the surface of the fundamental polygon in FILE (CGAL's\n"
          "                      text format), checked exactly, instead of M_g: with\n"
          "                      points (an input FILE or --random) triangulate them on\n"
          "                      it (not with -g, --load, --html); alone,\n"
          "                      write its genus, pairing, cycles, |N| and systole (with\n"
          "                      -o, and --svg for a picture of it)\n"
          "      --side-labels   with --svg: label the sides of F_g, s_k with g_k (which\n"
          "                      maps s_(k+2g) onto it) and s_(k+2g) with g_k^-1\n"
          "      --voronoi       also the Voronoi diagram: in the output, drawn with\n"
          "                      --svg, and in the viewer of --html\n"
          "      --refine R[,B]  then refine: circumradius <= R, circumradius / shortest\n"
          "                      edge <= B (>= 1; default no bound; R or B may be inf)\n"
          "      --epsilon E     then refine into an epsilon-net: every point of M_g\n"
          "                      within E of a vertex\n"
          "      --keep-dummies  keep the dummy points (default: remove those that can go)\n"
          "      --validate      check every invariant with exact predicates first\n"
          "      --stats         counts, quality and timings on standard error\n"
          "  -h, --help          this text\n"
          "  -V, --version       versions of the tool and of libhdt\n"
          "\n"
          "Exit status: 0 success, 1 bad input data or a failure (reported as\n"
          "FILE:LINE: message for a bad line), 2 bad usage.\n"
          "\n"
          "See hdt-triangulate(1).\n",
          HDT_CREATE_GENUS_MAX);
}

/* ---- Options ---- */

typedef struct options {
  int genus;
  int random;
  unsigned long long n_random;
  int seed_given;
  unsigned long long seed;
  face_format format;
  int mesh;               /* 1: a mesh format (mesh_format), not text or JSON */
  mesh_format mesh_format;
  const char *output;
  const char *svg;
  const char *html;
  const char *save;
  const char *load;
  const char *polygon;
  const char *input;
  int genus_given;
  int keep_dummies, neighbours, side_labels, voronoi, validate, stats, help, version;
  int refine;              /* 1: --refine, 2: --epsilon */
  double max_radius, max_ratio;
} options;

enum { OPT_GENUS, OPT_RANDOM, OPT_SEED, OPT_FORMAT, OPT_OUTPUT, OPT_SVG, OPT_NEIGHBOURS, OPT_VORONOI, OPT_KEEP,
       OPT_VALIDATE, OPT_STATS, OPT_HELP, OPT_VERSION, OPT_SAVE, OPT_LOAD, OPT_REFINE, OPT_EPSILON, OPT_HTML,
       OPT_SIDE_LABELS, OPT_POLYGON };

typedef struct option_spec {
  const char *long_name; /* without "--" */
  char short_name;       /* 0: none */
  int takes_value;
  int id;
} option_spec;

static const option_spec option_table[] = {
    {"genus", 'g', 1, OPT_GENUS},        {"random", 0, 1, OPT_RANDOM},
    {"seed", 0, 1, OPT_SEED},            {"format", 'f', 1, OPT_FORMAT},
    {"output", 'o', 1, OPT_OUTPUT},      {"svg", 0, 1, OPT_SVG},
    {"neighbours", 0, 0, OPT_NEIGHBOURS}, {"neighbors", 0, 0, OPT_NEIGHBOURS},
    {"keep-dummies", 0, 0, OPT_KEEP},    {"validate", 0, 0, OPT_VALIDATE},
    {"stats", 0, 0, OPT_STATS},          {"help", 'h', 0, OPT_HELP},
    {"version", 'V', 0, OPT_VERSION},    {"save", 0, 1, OPT_SAVE},
    {"load", 0, 1, OPT_LOAD},            {"voronoi", 0, 0, OPT_VORONOI},
    {"refine", 0, 1, OPT_REFINE},        {"epsilon", 0, 1, OPT_EPSILON},
    {"html", 0, 1, OPT_HTML},            {"side-labels", 0, 0, OPT_SIDE_LABELS},
    {"polygon", 0, 1, OPT_POLYGON},
};
#define N_OPTIONS (sizeof option_table / sizeof option_table[0])

/* Reports a usage error; returns 0 (for "return usage_error(...)"). */
static int usage_error(const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

static int usage_error(const char *format, ...) {
  va_list args;
  va_start(args, format);
  fflush(stdout);
  fputs(CLI_NAME ": ", stderr);
  vfprintf(stderr, format, args);
  fputs("\nTry '" CLI_NAME " --help'.\n", stderr);
  va_end(args);
  return 0;
}

/* A decimal number in [min, max], nothing else. */
static int parse_number(const char *text, unsigned long long min, unsigned long long max,
                        unsigned long long *out) {
  if (!text || *text < '0' || *text > '9') return 0;
  errno = 0;
  char *end = NULL;
  const unsigned long long value = strtoull(text, &end, 10);
  if (errno != 0 || *end != '\0' || value < min || value > max) return 0;
  *out = value;
  return 1;
}

/* A real number >= min (strictly > min when strict), or "inf"; nothing else. */
static int parse_bound(const char *text, size_t length, double min, int strict, double *out) {
  char buffer[64];
  if (length == 0 || length >= sizeof buffer) return 0;
  memcpy(buffer, text, length);
  buffer[length] = '\0';
  if (strcmp(buffer, "inf") == 0) {
    *out = INFINITY;
    return 1;
  }
  if (!((buffer[0] >= '0' && buffer[0] <= '9') || buffer[0] == '.')) return 0; /* no sign, nan, spaces */
  errno = 0;
  char *end = NULL;
  const double value = strtod(buffer, &end);
  if (errno != 0 || *end != '\0' || !isfinite(value) || value < min || (strict && value == min)) return 0;
  *out = value;
  return 1;
}

static int apply_option(options *o, const option_spec *spec, const char *shown, const char *value) {
  unsigned long long number = 0;
  switch (spec->id) {
    case OPT_GENUS:
      if (!parse_number(value, 2, HDT_CREATE_GENUS_MAX, &number))
        return usage_error("%s needs an integer from 2 to %d", shown, HDT_CREATE_GENUS_MAX);
      o->genus = (int)number;
      o->genus_given = 1;
      return 1;
    case OPT_RANDOM:
      /* All digits but too big (or beyond unsigned long long): name the cap. */
      if (value[0] >= '0' && value[0] <= '9' && value[strspn(value, "0123456789")] == '\0' &&
          !parse_number(value, 0, MAX_RANDOM_POINTS, &number))
        return usage_error("%s %s: more than the cap of " MAX_RANDOM_POINTS_SHOWN " (%llu) points", shown, value,
                           MAX_RANDOM_POINTS);
      if (!parse_number(value, 0, MAX_RANDOM_POINTS, &number))
        return usage_error("%s needs a count from 0 to " MAX_RANDOM_POINTS_SHOWN, shown);
      o->random = 1;
      o->n_random = number;
      return 1;
    case OPT_SEED:
      if (!parse_number(value, 0, UINT64_MAX, &number))
        return usage_error("%s needs an integer from 0 to 2^64 - 1", shown);
      o->seed_given = 1;
      o->seed = number;
      return 1;
    case OPT_FORMAT:
      if (strcmp(value, "text") == 0) o->format = FACE_FORMAT_TEXT;
      else if (strcmp(value, "json") == 0) o->format = FACE_FORMAT_JSON;
      else if (strcmp(value, "vtu") == 0) o->mesh = 1, o->mesh_format = MESH_FORMAT_VTU;
      else if (strcmp(value, "msh") == 0) o->mesh = 1, o->mesh_format = MESH_FORMAT_MSH;
      else if (strcmp(value, "obj") == 0) o->mesh = 1, o->mesh_format = MESH_FORMAT_OBJ;
      else if (strcmp(value, "off") == 0) o->mesh = 1, o->mesh_format = MESH_FORMAT_OFF;
      else return usage_error("unknown format '%s' (text, json, vtu, msh, obj or off)", value);
      return 1;
    case OPT_REFINE: {
      const char *comma = strchr(value, ',');
      const size_t length = comma ? (size_t)(comma - value) : strlen(value);
      o->max_ratio = INFINITY;
      if (!parse_bound(value, length, 0, 1, &o->max_radius) ||
          (comma && !parse_bound(comma + 1, strlen(comma + 1), 1, 0, &o->max_ratio)))
        return usage_error("%s needs R or R,B: a radius R > 0 and a ratio B >= 1 (either may be inf)", shown);
      o->refine = 1;
      return 1;
    }
    case OPT_EPSILON:
      if (!parse_bound(value, strlen(value), 0, 1, &o->max_radius) || isinf(o->max_radius))
        return usage_error("%s needs a finite number > 0", shown);
      o->max_ratio = INFINITY;
      o->refine = 2;
      return 1;
    case OPT_OUTPUT: o->output = value; return 1;
    case OPT_SVG: o->svg = value; return 1;
    case OPT_HTML: o->html = value; return 1;
    case OPT_SAVE: o->save = value; return 1;
    case OPT_LOAD: o->load = value; return 1;
    case OPT_POLYGON: o->polygon = value; return 1;
    case OPT_NEIGHBOURS: o->neighbours = 1; return 1;
    case OPT_SIDE_LABELS: o->side_labels = 1; return 1;
    case OPT_VORONOI: o->voronoi = 1; return 1;
    case OPT_KEEP: o->keep_dummies = 1; return 1;
    case OPT_VALIDATE: o->validate = 1; return 1;
    case OPT_STATS: o->stats = 1; return 1;
    case OPT_HELP: o->help = 1; return 1;
    case OPT_VERSION: o->version = 1; return 1;
  }
  return 0;
}

/* --polygon without points describes the surface given by its polygon: it
   goes with -o and --svg only. */
static int polygon_options_ok(const options *o, int refine_options) {
  if (o->load || o->genus_given || refine_options || o->voronoi || o->html || o->save || o->mesh ||
      o->format != FACE_FORMAT_TEXT || o->neighbours || o->side_labels || o->keep_dummies || o->validate || o->stats)
    return usage_error("--polygon without points (an input file or --random) describes the surface: it goes with "
                       "-o and --svg only");
  if (o->svg && strcmp(o->svg, "-") == 0 && (!o->output || strcmp(o->output, "-") == 0))
    return usage_error("--svg - and the description would both go to standard output");
  if (o->svg && o->output && strcmp(o->svg, o->output) == 0)
    return usage_error("-o and --svg name the same file ('%s')", o->svg);
  return 1;
}

static int parse_options(int argc, char **argv, options *o) {
  memset(o, 0, sizeof *o);
  o->genus = 2;
  o->seed = 1;
  o->format = FACE_FORMAT_TEXT;
  int only_files = 0, refine_options = 0;
  for (int i = 1; i < argc; ++i) {
    const char *a = argv[i];
    if (only_files || a[0] != '-' || strcmp(a, "-") == 0) {
      if (o->input) return usage_error("more than one input file ('%s' and '%s')", o->input, a);
      o->input = a;
      continue;
    }
    if (strcmp(a, "--") == 0) {
      only_files = 1;
      continue;
    }
    const option_spec *spec = NULL;
    const char *value = NULL;
    char shown[64];
    if (a[1] == '-') {
      const char *name = a + 2, *eq = strchr(name, '=');
      const size_t length = eq ? (size_t)(eq - name) : strlen(name);
      for (size_t k = 0; k < N_OPTIONS && !spec; ++k)
        if (strlen(option_table[k].long_name) == length && strncmp(option_table[k].long_name, name, length) == 0)
          spec = &option_table[k];
      if (!spec) return usage_error("unknown option '%s'", a);
      snprintf(shown, sizeof shown, "--%s", spec->long_name);
      if (eq && !spec->takes_value) return usage_error("%s takes no value", shown);
      if (eq) value = eq + 1;
    } else {
      for (size_t k = 0; k < N_OPTIONS && !spec; ++k)
        if (option_table[k].short_name == a[1]) spec = &option_table[k];
      if (!spec || (a[2] != '\0' && !spec->takes_value)) return usage_error("unknown option '%s'", a);
      snprintf(shown, sizeof shown, "-%c", a[1]);
      if (a[2] != '\0') value = a + 2; /* -g3, -ofile */
    }
    if (spec->takes_value && !value) {
      if (i + 1 >= argc) return usage_error("%s needs a value", shown);
      value = argv[++i];
    }
    if (!apply_option(o, spec, shown, value)) return 0;
    refine_options += spec->id == OPT_REFINE || spec->id == OPT_EPSILON;
  }
  if (o->help || o->version) return 1;
  if (o->polygon && !o->random && !o->input) return polygon_options_ok(o, refine_options);
  /* Triangulating on a polygon surface: what libhdt does not do there yet. */
  if (o->polygon && (o->genus_given || o->load))
    return usage_error("--polygon with points goes without %s: the surface is the polygon's",
                       o->genus_given ? "-g" : "--load (the file holds its surface)");
  if (o->polygon && o->html)
    return usage_error("--polygon with points goes without --html: the viewer of a polygon surface is not supported "
                       "yet");
  if (o->random && o->input) return usage_error("--random and an input file ('%s') exclude each other", o->input);
  if (o->seed_given && !o->random) return usage_error("--seed needs --random");
  if (refine_options > 1) return usage_error("--refine and --epsilon exclude each other, and each is given once");
  if (o->neighbours && !o->svg) return usage_error("--neighbours needs --svg");
  if (o->side_labels && !o->svg) return usage_error("--side-labels needs --svg");
  if (o->mesh && o->voronoi && !o->svg && !o->html)
    return usage_error("--voronoi goes with the text and json formats (or --svg, --html)");
  if (o->svg && strcmp(o->svg, "-") == 0 && (!o->output || strcmp(o->output, "-") == 0))
    return usage_error("--svg - and the triangulation would both go to standard output");
  if (o->svg && o->output && strcmp(o->svg, o->output) == 0)
    return usage_error("-o and --svg name the same file ('%s')", o->svg);
  if (o->svg && o->output) {
    struct stat a, b;
    if (stat(o->svg, &a) == 0 && stat(o->output, &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino &&
        S_ISREG(a.st_mode))
      return usage_error("-o '%s' and --svg '%s' are the same file", o->output, o->svg);
  }
  if (o->save) {
    const int to_stdout = strcmp(o->save, "-") == 0;
    if (to_stdout && (!o->output || strcmp(o->output, "-") == 0))
      return usage_error("--save - and the triangulation would both go to standard output");
    if (to_stdout && o->svg && strcmp(o->svg, "-") == 0)
      return usage_error("--save - and --svg - would both go to standard output");
    if (!to_stdout && ((o->output && strcmp(o->save, o->output) == 0) || (o->svg && strcmp(o->save, o->svg) == 0)))
      return usage_error("--save '%s' names the same file as another output", o->save);
  }
  if (o->html) {
    /* The viewer against each other output: not the same stream or file. */
    const char *other[] = {o->output ? o->output : "-", o->svg, o->save};
    const char *other_name[] = {"the triangulation", "--svg", "--save"};
    for (int k = 0; k < 3; ++k) {
      if (!other[k]) continue;
      if (strcmp(o->html, other[k]) == 0)
        return usage_error(strcmp(o->html, "-") == 0 ? "--html - and %s would both go to standard output"
                                                      : "--html and %s name the same file", other_name[k]);
      struct stat a, b;
      if (stat(o->html, &a) == 0 && stat(other[k], &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino &&
          S_ISREG(a.st_mode))
        return usage_error("--html '%s' and %s '%s' are the same file", o->html, other_name[k], other[k]);
    }
  }
  if (o->load && o->input && strcmp(o->load, "-") == 0 && strcmp(o->input, "-") == 0)
    return usage_error("--load - and the points would both be read from standard input");
  return 1;
}

/* ---- The run ---- */

typedef struct timings {
  double input, create, insert, remove, refine, validate, output;
} timings;

typedef struct counts {
  size_t points, tried, duplicates, dummies_created, dummies_after_insert, dummies_left, refined;
} counts;

static const char *input_name(const options *o) {
  return (!o->input || strcmp(o->input, "-") == 0) ? "<stdin>" : o->input;
}

/* The points: drawn, or read and checked line by line. 0 on failure
   (reported). */
/* surface: --polygon's (random points in its polygon), else NULL (in F_g). */
static int get_points(const options *o, const hdt_surface *surface, point_list *points, counts *c) {
  if (o->random) {
    const size_t n = (size_t)o->n_random;
    points->xy = cli_alloc(n, 2 * sizeof *points->xy);
    points->lines = cli_alloc(n, sizeof *points->lines);
    if (!points->xy || !points->lines) return 0;
    if (surface ? !random_surface_points(surface, (uint64_t)o->seed, n, points->xy, &c->tried)
                : !random_points(o->genus, (uint64_t)o->seed, n, points->xy, &c->tried))
      return 0;
    memset(points->lines, 0, n * sizeof *points->lines);
    points->count = points->capacity = n;
    return 1;
  }
  const char *name = input_name(o);
  FILE *f = stdin;
  if (o->input && strcmp(o->input, "-") != 0) {
    f = fopen(o->input, "r");
    if (!f) {
      cli_error("cannot open %s: %s", o->input, strerror(errno));
      return 0;
    }
  }
  diagnostics d = {0};
  int ok = point_reader_read(f, name, points, &d);
  if (f != stdin) fclose(f);
  /* With bad lines, the points that did parse get the domain check too, so
     that every bad line is reported at once. */
  if (ok && d.count > 0) ok = point_reader_check_domain(o->genus, points, &d);
  if (d.count > 0) {
    diagnostics_print(&d, name, MAX_REPORTED_LINES);
    ok = 0;
  }
  diagnostics_free(&d);
  /* Valid output, but more likely a wrong file or an empty pipe than the
     dummy set on purpose (which --random 0 asks for without a warning). */
  if (ok && points->count == 0)
    cli_warning("no points in %s; the output is the dummy point set's triangulation", name);
  return ok;
}

/* hdt_insert_many refuses the whole batch when one point is outside the
   disk; its index is only in the message, so every point is checked again
   with hdt_point_representative to name all the bad lines. */
static void report_domain_errors(const options *o, const point_list *points) {
  if (o->random) {
    cli_error("a random point was refused: %s", hdt_last_error_message());
    return;
  }
  char detail[256];
  snprintf(detail, sizeof detail, "%s", hdt_last_error_message()); /* the next call replaces it */
  diagnostics d = {0};
  if (point_reader_check_domain(o->genus, points, &d)) {
    if (d.count == 0) cli_error("hdt_insert_many: %s (%s)", hdt_status_string(HDT_EDOMAIN), detail);
    diagnostics_print(&d, input_name(o), MAX_REPORTED_LINES);
  }
  diagnostics_free(&d);
}

static void picture_title(const options *o, const counts *c, char *title, size_t size) {
  char surface[160]; /* M_g, or --polygon's surface by its file's name */
  if (o->polygon) {
    const char *slash = strrchr(o->polygon, '/');
    snprintf(surface, sizeof surface, "the genus-%d surface of %s", o->genus, slash ? slash + 1 : o->polygon);
  } else {
    snprintf(surface, sizeof surface, "M_%d", o->genus);
  }
  if (o->refine == 2)
    snprintf(title, size, "An epsilon-net of %s, eps = %g, refined from %s", surface, o->max_radius,
             c->points == 0 ? "the dummy points" : "the input points");
  else if (o->refine)
    snprintf(title, size, "Delaunay refinement on %s: circumradius <= %g, radius-edge ratio <= %g", surface,
             o->max_radius, o->max_ratio);
  else if (c->points == 0)
    snprintf(title, size, "The dummy point set of %s%s and its Delaunay triangulation", surface,
             o->keep_dummies ? ", before any insertion," : "");
  else if (o->random)
    snprintf(title, size, "Delaunay triangulation of %zu random point%s on %s (seed %llu)", c->points,
             c->points == 1 ? "" : "s", surface, o->seed);
  else if (o->input && strcmp(o->input, "-") != 0) {
    const char *slash = strrchr(o->input, '/');
    snprintf(title, size, "Delaunay triangulation of the %zu point%s of %s on %s", c->points,
             c->points == 1 ? "" : "s", slash ? slash + 1 : o->input, surface);
  }
  else
    snprintf(title, size, "Delaunay triangulation of %zu point%s on %s", c->points, c->points == 1 ? "" : "s",
             surface);
}

/* The picture, drawn by libhdt, written to f. 0 on a failure (reported);
   the stream's error state is left for the caller to check. */
static int write_picture(FILE *f, const hdt_triangulation *t, const char *title, int neighbours, int voronoi,
                         int side_labels) {
  const unsigned flags = (neighbours ? HDT_SVG_NEIGHBOURS : 0u) | (voronoi ? HDT_SVG_VORONOI : 0u) |
                         (side_labels ? HDT_SVG_SIDE_LABELS : 0u);
  /* A guess at the size (about 200 bytes a face, in F_g and in each tile),
     so that one call usually does (each call draws the whole picture); the
     exact size when it is too small. */
  const size_t faces = hdt_face_count(t), copies = neighbours ? 4 * (size_t)hdt_genus(t) + 1 : 1;
  size_t capacity = 0, length = 0;
  if (faces < SIZE_MAX / 1024 / copies) capacity = 4096 + 256 * copies * faces + 64 * hdt_vertex_count(t);
  char *text = capacity ? cli_alloc(capacity, 1) : NULL;
  if (capacity && !text) return 0;
  hdt_status status = hdt_svg(t, PICTURE_SIZE, title, flags, text, capacity, &length);
  if (status == HDT_EBUFS || (status == HDT_OK && capacity == 0)) {
    free(text);
    capacity = length + 1;
    text = cli_alloc(capacity, 1);
    if (!text) return 0;
    status = hdt_svg(t, PICTURE_SIZE, title, flags, text, capacity, &length);
  }
  if (!cli_check(status, "hdt_svg")) {
    free(text);
    return 0;
  }
  fwrite(text, 1, length, f);
  free(text);
  return 1;
}

static void print_stats(const options *o, const hdt_triangulation *tri, const snapshot *s, const counts *c,
                        const timings *t) {
  const size_t V = s->vertex_count, F = s->face_count, E = 3 * F / 2;
  const long euler = (long)V - (long)E + (long)F;
  fflush(stdout);
  if (o->polygon)
    fprintf(stderr, CLI_NAME " %s (libhdt %s): the genus-%d surface of %s\n", HDT_CLI_VERSION, hdt_version_string(),
            o->genus, o->polygon);
  else
    fprintf(stderr, CLI_NAME " %s (libhdt %s): M_%d\n", HDT_CLI_VERSION, hdt_version_string(), o->genus);
  if (o->random && o->polygon)
    fprintf(stderr, "  points       : %zu random, uniform for area in the polygon (seed %llu; %zu drawn, %.1f%% kept)\n",
            c->points, o->seed, c->tried, c->tried ? 100.0 * (double)c->points / (double)c->tried : 0.0);
  else if (o->random)
    fprintf(stderr, "  points       : %zu random, uniform for area in F_%d (seed %llu; %zu drawn, %.1f%% kept)\n",
            c->points, o->genus, o->seed, c->tried, c->tried ? 100.0 * (double)c->points / (double)c->tried : 0.0);
  else
    fprintf(stderr, "  points       : %zu read from %s (%zu repeat an earlier point)\n", c->points, input_name(o),
            c->duplicates);
  fprintf(stderr, "  dummies      : %zu %s, %zu after insertion, %zu left%s\n", c->dummies_created,
          o->load ? "loaded" : "at creation",
          c->dummies_after_insert, c->dummies_left, o->keep_dummies ? " (--keep-dummies)" : "");
  fprintf(stderr, "  counts       : %zu vertices, %zu edges, %zu faces; V - E + F = %ld (2 - 2g = %d)\n", V, E, F,
          euler, 2 - 2 * o->genus);
  if (o->refine)
    fprintf(stderr, "  refinement   : %zu points added (%s, radius <= %g, ratio <= %g)\n", c->refined,
            o->refine == 2 ? "--epsilon" : "--refine", o->max_radius, o->max_ratio);
  double angle, ratio, radius, edge;
  if (hdt_quality(tri, &angle, &ratio, &radius, &edge) == HDT_OK)
    fprintf(stderr,
            "  quality      : min angle %.4g deg, max radius-edge ratio %.6g, max circumradius %.6g, "
            "shortest edge %.6g\n",
            angle * 180 / 3.14159265358979323846, ratio, radius, edge);
  if (o->validate) fprintf(stderr, "  validate     : ok\n");
  fprintf(stderr, "  timings (ms) : %s %.2f, %s %.2f, insert %.2f, remove dummies %.2f", o->random ? "sample" : "read",
          t->input, o->load ? "load" : "create", t->create, t->insert, t->remove);
  if (o->refine) fprintf(stderr, ", refine %.2f", t->refine);
  if (o->validate) fprintf(stderr, ", validate %.2f", t->validate);
  fprintf(stderr, ", output %.2f\n", t->output);
}

static int run(const options *given) {
  options loaded = *given; /* with --load, the genus is the file's */
  const options *o = &loaded;
  int status = CLI_EXIT_FAILURE;
  point_list points = {0};
  hdt_triangulation *t = NULL;
  uint32_t *point_vertex = NULL;
  unsigned char *seen = NULL;
  snapshot s = {0};
  voronoi vd = {0};
  output_file out = {0}, svg = {0}, saved = {0}, html = {0};
  counts c = {0};
  timings tm = {0};
  hdt_surface *surface = NULL; /* --polygon's */

  double t0 = cli_now_ms();
  if (o->load) {
    if (!(t = saved_file_load(o->load))) goto done;
    tm.create = cli_now_ms() - t0;
    if (o->genus_given && o->genus != hdt_genus(t)) {
      cli_error("--genus %d, but %s holds a triangulation of genus %d", o->genus, o->load, hdt_genus(t));
      goto done;
    }
    loaded.genus = hdt_genus(t);
  }

  t0 = cli_now_ms();
  /* With --load, points come only from an input file or --random. */
  if (o->polygon && !(surface = polygon_file_read(o->polygon))) goto done;
  if (surface) loaded.genus = hdt_surface_genus(surface);
  if ((!o->load || o->input || o->random) && !get_points(o, surface, &points, &c)) goto done;
  tm.input = cli_now_ms() - t0;
  c.points = points.count;

  /* The outputs before the work, so that an unwritable destination fails
     fast; nothing appears there before the commit. */
  if (!output_open(&out, o->output)) goto done;
  if (o->svg && !output_open(&svg, o->svg)) goto done;
  if (o->html && !output_open(&html, o->html)) goto done;
  if (o->save && !output_open(&saved, o->save)) goto done;

  t0 = cli_now_ms();
  if (!t && surface && !cli_check(hdt_create_on_surface(&t, surface), "hdt_create_on_surface")) goto done;
  if (!t && !cli_check(hdt_create(&t, o->genus), "hdt_create")) goto done;
  if (!o->load) tm.create = cli_now_ms() - t0;
  c.dummies_created = hdt_dummy_count(t);

  point_vertex = cli_alloc(points.count, sizeof *point_vertex);
  if (!point_vertex) goto done;
  t0 = cli_now_ms();
  progress_bar bar;
  progress_bar_attach(t, &bar, "insert");
  const hdt_status inserted = hdt_insert_many(t, points.xy, points.count, point_vertex);
  progress_bar_detach(t, &bar);
  if (inserted == HDT_EDOMAIN) {
    report_domain_errors(o, &points);
    goto done;
  }
  if (!cli_check(inserted, "hdt_insert_many")) goto done;
  tm.insert = cli_now_ms() - t0;
  c.dummies_after_insert = hdt_dummy_count(t);

  t0 = cli_now_ms();
  if (!o->keep_dummies && !cli_check(hdt_remove_dummies(t, NULL), "hdt_remove_dummies")) goto done;
  tm.remove = cli_now_ms() - t0;
  c.dummies_left = hdt_dummy_count(t);

  /* After the dummies' removal, which could break the bounds again. */
  if (o->refine) {
    t0 = cli_now_ms();
    size_t unmet = 0;
    progress_bar_attach(t, &bar, "refine");
    const hdt_status refined = hdt_refine(t, o->max_radius, o->max_ratio, SIZE_MAX, &c.refined, &unmet);
    progress_bar_detach(t, &bar);
    if (!cli_check(refined, "hdt_refine")) goto done;
    tm.refine = cli_now_ms() - t0;
    c.dummies_left = hdt_dummy_count(t);
  }

  if (o->validate) {
    t0 = cli_now_ms();
    if (!cli_check(hdt_validate(t), "hdt_validate")) goto done;
    tm.validate = cli_now_ms() - t0;
  }

  /* Input points that landed on a vertex an earlier point made. */
  const size_t bound = hdt_vertex_id_bound(t);
  seen = cli_alloc(bound, 1);
  if (!seen) goto done;
  memset(seen, 0, bound);
  for (size_t i = 0; i < points.count; ++i) {
    if (point_vertex[i] < bound && seen[point_vertex[i]]) ++c.duplicates;
    if (point_vertex[i] < bound) seen[point_vertex[i]] = 1;
  }

  t0 = cli_now_ms();
  if (!snapshot_take(t, &s)) goto done;
  if (o->voronoi && !voronoi_take(t, &vd)) goto done;
  if (o->mesh) {
    if (!mesh_writer_write(out.f, o->mesh_format, t, &s)) goto done;
  } else {
    face_writer_write(out.f, o->format, &s, point_vertex, points.count, o->voronoi ? &vd : NULL);
  }
  if (o->svg || o->html) {
    char title[256];
    picture_title(o, &c, title, sizeof title);
    /* A loaded triangulation: libhdt's caption (and the viewer's default
       heading) counts all its user vertices. */
    if (o->svg && !write_picture(svg.f, t, o->load ? NULL : title, o->neighbours, o->voronoi, o->side_labels)) goto done;
    if (o->html && !html_writer_write(html.f, t, o->load ? NULL : title, o->voronoi)) goto done;
  }
  if (o->save && !saved_file_write(saved.f, t)) goto done;
  /* Everything written and checked before anything is put in place. */
  if (!output_finish(&out) || (o->svg && !output_finish(&svg)) || (o->html && !output_finish(&html)) ||
      (o->save && !output_finish(&saved)))
    goto done;
  /* The picture, the viewer and the saved file first: when one cannot be
     put in place, the triangulation is not written either. */
  if (o->svg && !output_commit(&svg)) goto done;
  if (o->html && !output_commit(&html)) goto done;
  if (o->save && !output_commit(&saved)) goto done;
  if (!output_commit(&out)) goto done;
  tm.output = cli_now_ms() - t0;

  if (o->stats) print_stats(o, t, &s, &c, &tm);
  status = CLI_EXIT_OK;

done:
  output_discard(&saved);
  output_discard(&svg);
  output_discard(&html);
  output_discard(&out);
  snapshot_free(&s);
  voronoi_free(&vd);
  free(seen);
  free(point_vertex);
  hdt_destroy(t);
  hdt_surface_destroy(surface);
  point_list_free(&points);
  return status;
}

int main(int argc, char **argv) {
  options o;
  if (!parse_options(argc, argv, &o)) return CLI_EXIT_USAGE;
  if (o.help) {
    usage(stdout);
    return fflush(stdout) == 0 ? CLI_EXIT_OK : CLI_EXIT_FAILURE;
  }
  if (o.version) {
    printf(CLI_NAME " %s\nlibhdt %s (ABI %d)\n", HDT_CLI_VERSION, hdt_version_string(), hdt_abi_version());
    return fflush(stdout) == 0 ? CLI_EXIT_OK : CLI_EXIT_FAILURE;
  }
  if (o.polygon && !o.random && !o.input) return polygon_file_describe(o.polygon, o.output, o.svg);
  return run(&o);
}
