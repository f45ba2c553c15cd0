/* hdt-triangulate: recognising numbers written with a decimal comma. */
#include "decimal_comma.h"

#include <string.h>

static int is_digit(char c) { return c >= '0' && c <= '9'; }

/* What may surround a field: ';' and quotes are the CSV of spreadsheets
   whose decimal separator is the comma ("0,1;0,2", "\"0,1\",\"0,2\""). */
static int is_boundary(char c) {
  return c == '\0' || c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f' || c == ';' || c == '"' ||
         c == '\'';
}

/* Length of a [+-]DIGITS,DIGITS field at s, or 0. */
static size_t field_length(const char *s) {
  size_t n = (*s == '+' || *s == '-') ? 1 : 0;
  const size_t integer_start = n;
  while (is_digit(s[n])) ++n;
  if (n == integer_start || s[n] != ',') return 0;
  const size_t fraction_start = ++n;
  while (is_digit(s[n])) ++n;
  if (n == fraction_start || !is_boundary(s[n])) return 0;
  return n;
}

int decimal_comma_find(const char *line, char *field, size_t size) {
  for (const char *s = line; *s; ++s) {
    if (s != line && !is_boundary(s[-1])) continue;
    const size_t n = field_length(s);
    if (n > 0 && n < size) {
      memcpy(field, s, n);
      field[n] = '\0';
      return 1;
    }
  }
  return 0;
}
