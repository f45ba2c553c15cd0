/* hdt-triangulate: the triangulation drawn in the Poincare disk, as SVG.
 *
 * Each face is drawn once, in its canonical copy (the copy meeting F_g), with
 * geodesic arcs; F_g is filled lightly and outlined; user vertices are dark
 * dots at their representatives, dummy vertices red dots. With
 * `neighbours`, the 4g copies of F_g across its sides (images under the
 * generators g_k) and the faces' copies in them are drawn lighter.
 */
#ifndef HDT_CLI_SVG_PICTURE_H
#define HDT_CLI_SVG_PICTURE_H

#include "snapshot.h"

#include <stdio.h>

typedef struct svg_options {
  const char *title;    /* first line of the caption (plain text, escaped here) */
  int neighbours;       /* also draw the copies across the 4g sides */
} svg_options;

/* Writes the picture to f. 0 on a library failure (reported); the stream's
   error state is left for the caller to check. */
int svg_picture_write(FILE *f, const snapshot *s, const svg_options *options);

#endif
