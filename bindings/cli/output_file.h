/* hdt-triangulate: outputs that appear whole or not at all.
 *
 * An output to a regular file (new or existing) is written to a temporary
 * file in the destination's directory (".NAME.XXXXXX") and renamed onto the
 * destination by output_commit, so a failure never leaves a partial or
 * emptied file. Standard output ("-"), and an existing destination that is
 * not a regular file (/dev/null, a FIFO, a terminal), are buffered in memory
 * and written by output_commit. A symbolic link to a regular file is
 * followed (the file it names is replaced, the link stays). On SIGINT,
 * SIGTERM, SIGHUP and SIGPIPE the temporary files are removed before the
 * signal's default action.
 */
#ifndef HDT_CLI_OUTPUT_FILE_H
#define HDT_CLI_OUTPUT_FILE_H

#include <stddef.h>
#include <stdio.h>

typedef struct output_file {
  const char *name;   /* as given, for messages ("-": standard output) */
  char *destination;  /* the file replaced on commit; NULL for a stream */
  char *temp_path;    /* the temporary file, while it exists */
  int stream_to_path; /* a stream to `name` (not standard output) */
  char *buffer;       /* a stream's contents (open_memstream) */
  size_t size;
  int mode;           /* the permissions the file gets */
  FILE *f;            /* where to write, between open and finish */
} output_file;

/* Opens an output to `name` ("-" or NULL: standard output). 0 on failure
   (reported; nothing to discard). */
int output_open(output_file *o, const char *name);

/* Flushes and closes the writing side, checking every write. 0 on failure
   (reported); output_discard must follow. */
int output_finish(output_file *o);

/* Puts a finished output in place: renames the temporary file onto the
   destination, or writes the buffer. 0 on failure (reported). Releases
   everything either way. */
int output_commit(output_file *o);

/* Drops an output that is not to be committed (removes the temporary file);
   safe on an output that was never opened (all zero) or already released. */
void output_discard(output_file *o);

#endif
