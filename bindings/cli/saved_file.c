/* hdt-triangulate: --load and --save. The file is read whole, then
   hdt_load checks and validates it; the bytes of --save come from hdt_save. */
#define _POSIX_C_SOURCE 200809L

#include "saved_file.h"

#include "cli_util.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

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
