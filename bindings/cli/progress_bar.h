/* hdt-triangulate: a progress bar on stderr for the long calls
 * (hdt_insert_many, hdt_refine), through hdt_set_progress. Shown only when
 * stderr is a terminal, and only once the call has run for a second, so
 * that short runs and redirected output look as before.
 */
#ifndef HDT_CLI_PROGRESS_BAR_H
#define HDT_CLI_PROGRESS_BAR_H

#include <hdt.h>

typedef struct progress_bar {
  const char *what; /* "insert", "refine" */
  double start_ms;
  int shown;        /* something was drawn: end the line on detach */
} progress_bar;

/* Reports t's next long call to the bar (a no-op unless stderr is a terminal). */
void progress_bar_attach(hdt_triangulation *t, progress_bar *bar, const char *what);
/* Stops reporting; ends the bar's line when one was drawn. */
void progress_bar_detach(hdt_triangulation *t, progress_bar *bar);

#endif
