/* hdt-triangulate: --load and --save. The file is read whole, then
   hdt_load checks and validates it; the bytes of --save come from hdt_save. */
#define _POSIX_C_SOURCE 200809L

#include "saved_file.h"

#include "cli_util.h"

#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* The little-endian u32 at p. */
static uint32_t u32_at(const unsigned char *p) {
  return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* The most bytes a file with this 44-byte header can have (docs/format.md:
   48 + 2W + 2 (letters) + 25V + 48F, each word at most 65535 letters), or 0
   when it is no libhdt file: what --load reads at most, so that a stream
   with no end (/dev/zero) or a lying header stops at once. */
static double most_bytes(const unsigned char *header) {
  static const unsigned char signature[8] = {0x89, 'H', 'D', 'T', '\r', '\n', 0x1a, '\n'};
  if (memcmp(header, signature, 8) != 0) return 0;
  const double W = u32_at(header + 16), V = u32_at(header + 20), F = u32_at(header + 24);
  return 48 + 2 * W * (1 + 65535.0) + 25 * V + 48 * F;
}

hdt_triangulation *saved_file_load(const char *path) {
  const int from_stdin = strcmp(path, "-") == 0;
  const char *name = from_stdin ? "<stdin>" : path;
  FILE *f = from_stdin ? stdin : fopen(path, "rb");
  if (!f) {
    cli_error("cannot open %s: %s", path, strerror(errno));
    return NULL;
  }
  unsigned char *bytes = NULL;
  size_t size = 0, capacity = 0;
  double most = -1; /* known once the header is in */
  int ok = 1;
  for (;;) {
    if (size == capacity) {
      const size_t grown = capacity ? 2 * capacity : 65536;
      unsigned char *b = grown > capacity ? cli_realloc(bytes, grown, 1) : NULL;
      if (!b) {
        ok = 0;
        break;
      }
      bytes = b, capacity = grown;
    }
    const size_t got = fread(bytes + size, 1, capacity - size, f);
    size += got;
    if (most < 0 && size >= 44) {
      most = most_bytes(bytes);
      if (most == 0) {
        cli_error("%s: byte 0: no libhdt signature: not a file saved by libhdt", name);
        ok = 0;
        break;
      }
    }
    if (most >= 0 && (double)size > most) {
      cli_error("%s: byte %.0f: more bytes than its header allows: not a file saved by libhdt", name, most);
      ok = 0;
      break;
    }
    if (got == 0) break;
  }
  if (ok && ferror(f)) {
    cli_error("cannot read %s: %s", name, strerror(errno));
    ok = 0;
  }
  if (f != stdin) fclose(f);
  hdt_triangulation *t = NULL;
  if (ok) {
    const hdt_status s = hdt_load(&t, bytes, size);
    if (s != HDT_OK) {
      cli_error("%s: not a triangulation hdt-triangulate can load: %s (%s)", name, hdt_status_string(s),
                hdt_last_error_message());
      t = NULL;
    }
  }
  free(bytes);
  return t;
}

int saved_file_write(FILE *f, const hdt_triangulation *t) {
  size_t size = 0;
  if (!cli_check(hdt_save(t, NULL, 0, &size), "hdt_save")) return 0;
  unsigned char *bytes = cli_alloc(size, 1);
  if (!bytes) return 0;
  const int ok = cli_check(hdt_save(t, bytes, size, &size), "hdt_save");
  if (ok) fwrite(bytes, 1, size, f);
  free(bytes);
  return ok;
}
