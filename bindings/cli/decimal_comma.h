/* hdt-triangulate: recognising numbers written with a decimal comma.
 *
 * Spreadsheets in many locales write 0.25 as "0,25" and separate the columns
 * with ';' or a tab. Such a line either fails to parse or reads as the point
 * (0, 25), which the domain check refuses. The reader does not guess what
 * was meant (a comma also separates x from y); it only recognises the
 * pattern, so that the error can say so.
 */
#ifndef HDT_CLI_DECIMAL_COMMA_H
#define HDT_CLI_DECIMAL_COMMA_H

#include <stddef.h>

/* Finds in `line` (comment already cut off) the first field of the form
   [+-]DIGITS,DIGITS: bounded by the line's ends, blanks, ';' or quotes, so
   that "x,y" with blanks around the comma, and numbers with a '.' or an
   exponent, never match. Copies it to `field` (NUL-terminated; a field that
   does not fit is not matched) and returns 1; 0 when there is none. */
int decimal_comma_find(const char *line, char *field, size_t size);

#endif
