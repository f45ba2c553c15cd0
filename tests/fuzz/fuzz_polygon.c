/* libFuzzer target: hdt_surface_from_polygon on hostile text. A finding:
 *
 *   - a crash, a hang or a sanitizer report (a leak included: e-antic's own
 *     error paths leak, so libhdt must refuse before they run);
 *   - a refusal that is not HDT_EINVAL (HDT_ENOMEM aside), with no message,
 *     or with *out not NULL;
 *   - an accepted polygon that breaks what a surface is: genus < 2, Euler's
 *     formula (cycles - n/2 + 1 = 2 - 2g) false, a pairing that is not a
 *     matching, or a text that does not read back as the same text.
 *
 * The seeds (corpus-polygon/) are polygons that pass (random octagons and
 * decagons, the Bolza octagon in Q(a)) and a few that fail. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hdt.h"

#define SENTINEL ((hdt_surface *)(uintptr_t)0x5a5a5a5a)

static void finding(const char *what, size_t size) {
  fprintf(stderr, "\nfuzz_polygon: finding: %s (%zu bytes; %s)\n", what, size, hdt_last_error_message());
  abort();
}

static char *text_of(const hdt_surface *s, size_t size) {
  size_t length = 0;
  if (hdt_surface_polygon_text(s, NULL, 0, &length) != HDT_OK) finding("no text for an accepted polygon", size);
  char *text = malloc(length + 1);
  if (!text) abort();
  if (hdt_surface_polygon_text(s, text, length + 1, &length) != HDT_OK) finding("the text is not written", size);
  return text;
}

static void check_surface(const hdt_surface *s, size_t size) {
  const int n = hdt_surface_side_count(s), g = hdt_surface_genus(s);
  size_t cycles = 0;
  if (g < 2 || n < 4 || n % 2) finding("an accepted polygon with genus < 2 or odd n", size);
  if (hdt_surface_vertex_cycles(s, NULL, 0, &cycles) != HDT_OK) finding("no vertex cycles", size);
  if ((long)cycles - n / 2 + 1 != 2 - 2 * g) finding("Euler's formula fails", size);
  for (int k = 0; k < n; ++k) {
    int j = -1, back = -1;
    if (hdt_surface_pairing(s, k, &j, NULL) != HDT_OK || hdt_surface_pairing(s, j, &back, NULL) != HDT_OK)
      finding("a pairing is refused", size);
    if (j == k || back != k) finding("the pairing is not a matching", size);
  }
  char *text = text_of(s, size);
  hdt_surface *again = SENTINEL;
  if (hdt_surface_from_polygon(&again, text, strlen(text)) != HDT_OK) finding("the written text is refused", size);
  char *text_again = text_of(again, size);
  if (strcmp(text, text_again) != 0) finding("the text does not read back as itself", size);
  free(text), free(text_again);
  hdt_surface_destroy(again);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  hdt_surface *s = SENTINEL;
  const hdt_status status = hdt_surface_from_polygon(&s, size ? (const char *)data : NULL, size);
  if (status != HDT_OK) {
    if (s != NULL) finding("*out not NULL on failure", size);
    if (status == HDT_ENOMEM) return 0;
    if (status != HDT_EINVAL) finding("a refusal other than HDT_EINVAL", size);
    if (!strstr(hdt_last_error_message(), "hdt_surface_from_polygon")) finding("the message is missing", size);
    return 0;
  }
  check_surface(s, size);
  hdt_surface_destroy(s);
  return 0;
}
