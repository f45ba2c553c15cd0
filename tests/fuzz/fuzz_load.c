/* libFuzzer target: hdt_load on hostile bytes. Each input is loaded twice:
 * as it is (the checksum then refuses almost everything) and with its last
 * 4 bytes replaced by the right CRC-32, so that mutations reach the parser,
 * the range checks and the validation behind the checksum. A finding:
 *
 *   - a crash, a hang or a sanitizer report;
 *   - a refusal that is not HDT_EINVAL (HDT_ENOMEM aside), names no byte
 *     offset in its message, or writes *out;
 *   - an accepted input whose triangulation hdt_validate refuses, or that
 *     hdt_save does not write back byte for byte (a load keeps everything).
 *
 * The seeds (corpus-load/) are small saved triangulations; make_seeds.py
 * writes them with the library of a build. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hdt.h"

#define SENTINEL ((hdt_triangulation *)(uintptr_t)0x5a5a5a5a)

static void finding(const char *what, const uint8_t *data, size_t size) {
  fprintf(stderr, "\nfuzz_load: finding: %s (%zu bytes; %s)\n", what, size, hdt_last_error_message());
  (void)data;
  abort();
}

static uint32_t crc32_of(const uint8_t *p, size_t n) {
  uint32_t c = 0xFFFFFFFFu;
  for (size_t i = 0; i < n; ++i) {
    c ^= p[i];
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
  }
  return ~c;
}

static void try_load(const uint8_t *data, size_t size) {
  hdt_triangulation *t = SENTINEL;
  const hdt_status s = hdt_load(&t, size ? data : NULL, size);
  if (s != HDT_OK) {
    if (t != SENTINEL) finding("*out written on failure", data, size);
    if (s == HDT_ENOMEM) return;
    if (s != HDT_EINVAL) finding("a refusal other than HDT_EINVAL", data, size);
    const char *m = hdt_last_error_message();
    if (size > 0 && (!strstr(m, "hdt_load") || !strstr(m, "byte "))) finding("the message names no byte", data, size);
    return;
  }
  if (t == SENTINEL || t == NULL) finding("HDT_OK without a handle", data, size);
  /* Saved before hdt_validate, which may give translation ids to the
     products it meets (hdt.h): the loaded table is the saved one. */
  size_t n = 0;
  if (hdt_save(t, NULL, 0, &n) != HDT_OK) finding("hdt_save sizing fails", data, size);
  uint8_t *again = malloc(n ? n : 1);
  if (!again) abort();
  if (hdt_save(t, again, n, &n) != HDT_OK) finding("hdt_save fails", data, size);
  if (n != size || memcmp(again, data, size) != 0) finding("saving the loaded triangulation gives other bytes", data, size);
  free(again);
  if (hdt_validate(t) != HDT_OK) finding("an accepted input breaks an invariant", data, size);
  hdt_destroy(t);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  try_load(data, size);
  if (size >= 8) {
    uint8_t *sealed = malloc(size);
    if (!sealed) abort();
    memcpy(sealed, data, size);
    const uint32_t c = crc32_of(sealed, size - 4);
    for (int i = 0; i < 4; ++i) sealed[size - 4 + i] = (uint8_t)(c >> 8 * i);
    try_load(sealed, size);
    free(sealed);
  }
  return 0;
}
