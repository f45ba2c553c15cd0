/* hdt-triangulate: messages, checked allocation, timing. */
#define _POSIX_C_SOURCE 200809L

#include "cli_util.h"

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

void cli_error(const char *format, ...) {
  va_list args;
  va_start(args, format);
  fflush(stdout);
  fputs(CLI_NAME ": ", stderr);
  vfprintf(stderr, format, args);
  fputc('\n', stderr);
  va_end(args);
}

void cli_warning(const char *format, ...) {
  va_list args;
  va_start(args, format);
  fflush(stdout);
  fputs(CLI_NAME ": warning: ", stderr);
  vfprintf(stderr, format, args);
  fputc('\n', stderr);
  va_end(args);
}

int cli_check(hdt_status s, const char *what) {
  if (s == HDT_OK) return 1;
  const char *detail = hdt_last_error_message();
  if (detail && *detail)
    cli_error("%s: %s (%s)", what, hdt_status_string(s), detail);
  else
    cli_error("%s: %s", what, hdt_status_string(s));
  return 0;
}

void *cli_alloc(size_t n, size_t size) {
  if (size != 0 && n > SIZE_MAX / size) {
    cli_error("out of memory (%zu elements of %zu bytes)", n, size);
    return NULL;
  }
  const size_t bytes = n * size;
  void *p = malloc(bytes ? bytes : 1);
  if (!p) cli_error("out of memory (%zu elements of %zu bytes)", n, size);
  return p;
}

void *cli_realloc(void *p, size_t n, size_t size) {
  if (size != 0 && n > SIZE_MAX / size) {
    cli_error("out of memory (%zu elements of %zu bytes)", n, size);
    return NULL;
  }
  const size_t bytes = n * size;
  void *q = realloc(p, bytes ? bytes : 1);
  if (!q) cli_error("out of memory (%zu elements of %zu bytes)", n, size);
  return q;
}

double cli_now_ms(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}
