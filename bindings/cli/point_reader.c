/* hdt-triangulate: reading points, one per line, with line numbers. */
#define _POSIX_C_SOURCE 200809L

#include "point_reader.h"

#include "cli_util.h"
#include "decimal_comma.h"

#include <hdt.h>

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

void point_list_free(point_list *points) {
  free(points->xy);
  free(points->lines);
  points->xy = NULL;
  points->lines = NULL;
  points->count = points->capacity = 0;
}

void diagnostics_free(diagnostics *d) {
  for (size_t i = 0; i < d->count; ++i) free(d->errors[i].message);
  free(d->errors);
  d->errors = NULL;
  d->count = d->capacity = 0;
}

int diagnostics_add(diagnostics *d, unsigned long line, const char *format, ...) {
  if (d->count == d->capacity) {
    const size_t capacity = d->capacity ? 2 * d->capacity : 16;
    line_error *errors = cli_realloc(d->errors, capacity, sizeof *errors);
    if (!errors) return 0;
    d->errors = errors;
    d->capacity = capacity;
  }
  va_list args;
  va_start(args, format);
  const int length = vsnprintf(NULL, 0, format, args);
  va_end(args);
  if (length < 0) return 0;
  char *message = cli_alloc((size_t)length + 1, 1);
  if (!message) return 0;
  va_start(args, format);
  vsnprintf(message, (size_t)length + 1, format, args);
  va_end(args);
  d->errors[d->count].line = line;
  d->errors[d->count].message = message;
  ++d->count;
  return 1;
}

static int by_line(const void *a, const void *b) {
  const line_error *p = a, *q = b;
  return (p->line > q->line) - (p->line < q->line);
}

void diagnostics_print(diagnostics *d, const char *name, size_t limit) {
  /* Parse errors and domain errors are added in two passes, each in line
     order; a stable order is all that matters for equal lines (one error
     per line at most), so qsort is enough. */
  qsort(d->errors, d->count, sizeof *d->errors, by_line);
  fflush(stdout);
  for (size_t i = 0; i < d->count && i < limit; ++i)
    fprintf(stderr, "%s:%lu: %s\n", name, d->errors[i].line, d->errors[i].message);
  if (d->count > limit)
    fprintf(stderr, "%s: %zu more bad lines not shown (%zu in all)\n", name, d->count - limit, d->count);
}

static int add_point(point_list *points, double x, double y, unsigned long line) {
  if (points->count == points->capacity) {
    const size_t capacity = points->capacity ? 2 * points->capacity : 1024;
    double *xy = cli_realloc(points->xy, capacity, 2 * sizeof *xy);
    if (!xy) return 0;
    points->xy = xy;
    unsigned long *lines = cli_realloc(points->lines, capacity, sizeof *lines);
    if (!lines) return 0;
    points->lines = lines;
    points->capacity = capacity;
  }
  points->xy[2 * points->count] = x;
  points->xy[2 * points->count + 1] = y;
  points->lines[points->count] = line;
  ++points->count;
  return 1;
}

static int is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

static const char *skip_blanks(const char *s) {
  while (is_blank(*s)) ++s;
  return s;
}

/* The token at s (up to a blank or a comma), quoted for a message:
   at most 24 bytes, other than printable ASCII shown as '?'. */
static void quote_token(const char *s, char out[32]) {
  size_t n = 0;
  while (s[n] && !is_blank(s[n]) && s[n] != ',' && n < 24) ++n;
  for (size_t i = 0; i < n; ++i) out[i] = (s[i] >= 0x20 && s[i] < 0x7f) ? s[i] : '?';
  const int more = s[n] && !is_blank(s[n]) && s[n] != ',';
  strcpy(out + n, more ? "..." : "");
}

/* One number at *s; on success *s moves past it. The number must end at a
   blank, a comma or the end of the line ("1.5abc" is not a number). */
static int read_number(const char **s, double *value) {
  char *end = NULL;
  const char *start = *s;
  if (*start == '\0' || is_blank(*start) || *start == ',') return 0;
  errno = 0;
  *value = strtod(start, &end); /* overflow gives +-inf, refused later by the domain check */
  if (end == start) return 0;
  if (*end != '\0' && !is_blank(*end) && *end != ',') return 0;
  *s = end;
  return 1;
}

/* Parses one line (comment and line end already cut off). 1: a point,
   0: blank, -1: an error was added (or, with *oom, out of memory). */
static int parse_line(const char *text, unsigned long line, int first_content, double *x, double *y,
                      diagnostics *d, int *oom) {
  char token[32];
  const char *s = skip_blanks(text);
  if (*s == '\0') return 0;
  const char *hint = first_content ? " (a header line? comment it out with '#')" : "";
  if (!read_number(&s, x)) {
    quote_token(s, token);
    if (*s == ',')
      *oom = !diagnostics_add(d, line, "expected a number before the comma");
    else
      *oom = !diagnostics_add(d, line, "not a number: '%s'%s", token, hint);
    return -1;
  }
  /* The separator: blanks, or a comma with blanks around it. */
  const char *after_x = s;
  s = skip_blanks(s);
  if (*s == ',') s = skip_blanks(s + 1);
  if (*s == '\0') {
    *oom = !diagnostics_add(d, line, "%s", after_x[strspn(after_x, " \t\r\v\f")] == ','
                                              ? "expected a second number after the comma"
                                              : "only one number; expected two, \"x y\" or \"x,y\"");
    return -1;
  }
  if (!read_number(&s, y)) {
    quote_token(s, token);
    if (*s == ',')
      *oom = !diagnostics_add(d, line, "expected a number between the commas");
    else
      *oom = !diagnostics_add(d, line, "not a number: '%s'%s", token, hint);
    return -1;
  }
  s = skip_blanks(s);
  if (*s != '\0') {
    quote_token(*s == ',' ? skip_blanks(s + 1) : s, token);
    *oom = !diagnostics_add(d, line, "more than two columns (found '%s%s' after the second number)",
                            *s == ',' ? "," : "", token);
    return -1;
  }
  return 1;
}

/* A line holding a number with a decimal comma ("0,25") gets an error that
   says so, in place of parse_line's (one per bad line): that is the likely
   cause. Such a line reads, if at all, as integer coordinates, outside the
   disk but for "0,0", which stays a point. Returns the line's kind as
   parse_line does; *oom when out of memory. */
static int check_decimal_comma(const char *text, unsigned long line, int kind, double x, double y,
                               diagnostics *d, int *oom) {
  char field[64], dotted[64];
  if (kind == 0 || (kind == 1 && x == 0 && y == 0) || !decimal_comma_find(text, field, sizeof field))
    return kind;
  if (kind == -1) {
    --d->count;
    free(d->errors[d->count].message);
  }
  strcpy(dotted, field);
  dotted[strcspn(dotted, ",")] = '.';
  *oom = !diagnostics_add(d, line, "not a number: '%s' (a decimal comma? write %s)", field, dotted);
  return -1;
}

/* A UTF-8 byte order mark, which some editors and spreadsheets put at the
   start of a text file; it is not part of the first line's text. */
static const char utf8_bom[] = "\xEF\xBB\xBF";

int point_reader_read(FILE *f, const char *name, point_list *points, diagnostics *d) {
  char *buffer = NULL;
  size_t size = 0;
  unsigned long line = 0;
  int ok = 1, seen_content = 0;
  for (;;) {
    errno = 0;
    const ssize_t length = getline(&buffer, &size, f);
    if (length < 0) {
      if (ferror(f)) {
        cli_error("%s: read error: %s", name, strerror(errno ? errno : EIO));
        ok = 0;
      } else if (errno == ENOMEM) {
        cli_error("%s: out of memory reading line %lu", name, line + 1);
        ok = 0;
      }
      break;
    }
    ++line;
    if (strlen(buffer) != (size_t)length) {
      if (!diagnostics_add(d, line, "a NUL byte in the line (is this a text file?)")) {
        ok = 0;
        break;
      }
      seen_content = 1;
      continue;
    }
    char *text = buffer;
    if (line == 1 && strncmp(text, utf8_bom, 3) == 0) text += 3;
    text[strcspn(text, "#\n")] = '\0';
    double x = 0, y = 0;
    int oom = 0;
    int kind = parse_line(text, line, !seen_content, &x, &y, d, &oom);
    if (!oom) kind = check_decimal_comma(text, line, kind, x, y, d, &oom);
    if (oom || (kind == 1 && !add_point(points, x, y, line))) {
      ok = 0;
      break;
    }
    if (kind != 0) seen_content = 1;
  }
  free(buffer);
  return ok;
}

int point_reader_check_domain(int genus, const point_list *points, diagnostics *d) {
  for (size_t i = 0; i < points->count; ++i) {
    size_t length = 0;
    const hdt_status s =
        hdt_point_representative(genus, points->xy[2 * i], points->xy[2 * i + 1], NULL, NULL, NULL, 0, &length);
    if (s == HDT_EDOMAIN) {
      /* libhdt's detail, without the function name it may start with. */
      const char *message = hdt_last_error_message();
      const char *colon = strstr(message, ": ");
      if (strncmp(message, "hdt_", 4) == 0 && colon) message = colon + 2;
      if (!diagnostics_add(d, points->lines[i], "%s", message)) return 0;
    } else if (!cli_check(s, "hdt_point_representative")) {
      return 0;
    }
  }
  return 1;
}
