/* hdt-triangulate: the progress bar (progress_bar.h). */
#include "progress_bar.h"

#include <stdio.h>
#include <unistd.h>

#include "cli_util.h"

/* Seconds before the first drawing, and between two. */
#define PROGRESS_DELAY_MS 1000.0
#define PROGRESS_INTERVAL_S 0.1
#define PROGRESS_WIDTH 30

static int draw(void *user, size_t done, size_t total) {
  progress_bar *bar = user;
  if (cli_now_ms() - bar->start_ms < PROGRESS_DELAY_MS) return 0;
  if (total == 0) {
    /* Refinement does not know its total in advance: a count. */
    fprintf(stderr, "\r%s: %s %zu points", CLI_NAME, bar->what, done);
  } else {
    const int filled = (int)((double)done / (double)total * PROGRESS_WIDTH);
    char cells[PROGRESS_WIDTH + 1];
    for (int i = 0; i < PROGRESS_WIDTH; ++i) cells[i] = i < filled ? '#' : '.';
    cells[PROGRESS_WIDTH] = '\0';
    fprintf(stderr, "\r%s: %s [%s] %3d%% (%zu/%zu)", CLI_NAME, bar->what, cells,
            (int)(100.0 * (double)done / (double)total), done, total);
  }
  fflush(stderr);
  bar->shown = 1;
  return 0; /* never stops the call: Ctrl-C ends the tool (output_file.h) */
}

void progress_bar_attach(hdt_triangulation *t, progress_bar *bar, const char *what) {
  bar->what = what;
  bar->start_ms = cli_now_ms();
  bar->shown = 0;
  if (isatty(STDERR_FILENO)) hdt_set_progress(t, draw, bar, PROGRESS_INTERVAL_S);
}

void progress_bar_detach(hdt_triangulation *t, progress_bar *bar) {
  hdt_set_progress(t, NULL, NULL, 0);
  if (bar->shown) fputc('\n', stderr);
  bar->shown = 0;
}
