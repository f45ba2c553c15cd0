/* hdt-triangulate: reading points, one per line, with line numbers.
 *
 * A line holds two numbers, "x y" or "x,y" (spaces and tabs around the comma
 * allowed); blank lines and everything from a '#' on are ignored; a trailing
 * carriage return (CRLF files) is ignored, and so is a UTF-8 byte order mark
 * at the start of the input. Numbers are read by strtod in the C locale (so
 * "1e-3", "0x1p-2", "nan" and "inf" are numbers; the last two are then
 * refused by libhdt's own domain check, as is any point with |z| >= 1). Any
 * other line is an error naming its line number; a line with a decimal
 * comma ("0,25") gets an error that says so.
 */
#ifndef HDT_CLI_POINT_READER_H
#define HDT_CLI_POINT_READER_H

#include <stddef.h>
#include <stdio.h>

/* Points in input order: point i is (xy[2i], xy[2i+1]), read from line
   lines[i] (1-based; 0 for generated points). */
typedef struct point_list {
  double *xy;
  unsigned long *lines;
  size_t count, capacity;
} point_list;

/* Errors tied to input lines, reported as "NAME:LINE: message". */
typedef struct line_error {
  unsigned long line;
  char *message;
} line_error;

typedef struct diagnostics {
  line_error *errors;
  size_t count, capacity;
} diagnostics;

void point_list_free(point_list *points);
void diagnostics_free(diagnostics *d);

/* Adds an error; 0 when out of memory. */
int diagnostics_add(diagnostics *d, unsigned long line, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Prints the errors in line order as "NAME:LINE: message" on stderr, at most
   `limit` of them, then how many were left out. */
void diagnostics_print(diagnostics *d, const char *name, size_t limit);

/* Reads every line of f into points; a bad line adds an error to d and
   reading goes on (so all of them are reported at once). Returns 0 only on
   a read error or out of memory (reported on stderr, naming `name`). */
int point_reader_read(FILE *f, const char *name, point_list *points, diagnostics *d);

/* libhdt's domain check of every point (hdt_point_representative): each
   point it refuses with HDT_EDOMAIN adds an error at its line, with
   libhdt's message. Returns 0 only on another library failure (reported). */
int point_reader_check_domain(int genus, const point_list *points, diagnostics *d);

#endif
