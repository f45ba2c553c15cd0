/* hdt-triangulate: --load and --save, a triangulation in libhdt's saved
   format (hdt_save / hdt_load). */
#ifndef HDT_CLI_SAVED_FILE_H
#define HDT_CLI_SAVED_FILE_H

#include <hdt.h>

#include <stdio.h>

/* The triangulation saved in the file `path` ("-": standard input), or NULL
   on failure (reported: the file cannot be read, or hdt_load refuses it,
   naming the byte at fault). */
hdt_triangulation *saved_file_load(const char *path);

/* Writes t in the saved format to f. 0 on a failure (reported); the
   stream's error state is left for the caller to check. */
int saved_file_write(FILE *f, const hdt_triangulation *t);

#endif
