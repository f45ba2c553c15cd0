/* hdt-triangulate --html: the interactive viewer, one self-contained HTML
 * page: the template bindings/python/hdt/viewer.html (embedded at build
 * time by embed_viewer.py) with the triangulation's data inlined as JSON,
 * the format of docs/viewer.md. Python's hdt.viewer writes the same bytes
 * for the same triangulation, title and Voronoi choice (a test checks it):
 * keep the two in step. */
#ifndef HDT_CLI_HTML_WRITER_H
#define HDT_CLI_HTML_WRITER_H

#include <hdt.h>

#include <stdio.h>

/* Writes the page for t to f; title (plain text, may be NULL: the page's
   default heading) and, with voronoi, the Voronoi edges. 0 on a failure
   (reported); the stream's error state is left for the caller to check. */
int html_writer_write(FILE *f, const hdt_triangulation *t, const char *title, int voronoi);

#endif
