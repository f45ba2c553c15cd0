/* hdt-triangulate: messages, checked allocation, timing. */
#ifndef HDT_CLI_UTIL_H
#define HDT_CLI_UTIL_H

#include <hdt.h>

#include <stddef.h>

#define CLI_NAME "hdt-triangulate"

/* Exit statuses. */
enum { CLI_EXIT_OK = 0, CLI_EXIT_FAILURE = 1, CLI_EXIT_USAGE = 2 };

/* "hdt-triangulate: <message>\n" on stderr. */
void cli_error(const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

/* "hdt-triangulate: warning: <message>\n" on stderr: the run goes on and
   succeeds, but the result may not be what was meant. */
void cli_warning(const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

/* 1 when s is HDT_OK; otherwise reports "hdt-triangulate: WHAT: <status> (<detail>)"
   and returns 0. */
int cli_check(hdt_status s, const char *what);

/* malloc of n elements of size bytes (at least one byte, so never NULL for
   n == 0), with the multiplication checked; reports "out of memory" and
   returns NULL on failure. */
void *cli_alloc(size_t n, size_t size);

/* realloc of p to n elements of size bytes, checked as cli_alloc; on
   failure NULL is returned and p is unchanged (and still to be freed). */
void *cli_realloc(void *p, size_t n, size_t size);

/* Milliseconds of a monotonic clock. */
double cli_now_ms(void);

#endif
