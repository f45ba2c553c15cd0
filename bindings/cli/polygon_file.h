/* hdt-triangulate: --polygon, a surface given by a fundamental polygon in
   CGAL's text format (or libhdt's number-field extension; docs/polygons.md),
   read, checked exactly and described, or read to be triangulated. */
#ifndef HDT_CLI_POLYGON_FILE_H
#define HDT_CLI_POLYGON_FILE_H

#include <hdt.h>

/* The surface of the polygon in `path` ("-": standard input), or NULL, the
   failure reported. */
hdt_surface *polygon_file_read(const char *path);

/* Reads the polygon in `path` ("-": standard input), writes its description
   to `output` (NULL or "-": standard output) and, when `svg` is not NULL,
   the polygon drawn there. The exit status (CLI_EXIT_*); failures are
   reported, and nothing is written when anything fails. */
int polygon_file_describe(const char *path, const char *output, const char *svg);

#endif
