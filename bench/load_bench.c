/* What hdt_load costs on crafted files: a saved triangulation of n points
 * uniform in F_g, then the same file with W extra translation words (new
 * canonical words no face uses, the checksum rewritten: what a hostile file
 * can hold and still be valid), and with K words g_0^L (as far from O as L
 * letters go). Prints each file's size and load time, and the time a byte
 * of the words costs beyond the plain file's load.
 *
 *   load_bench --genus G --n N --words W --length L [--powers K --power-length P] [--seed S]
 *
 * --length is the random word's length before hdt_word_reduce; the words
 * kept are those longer than 2g after it (outside N). One line per file,
 * starting with "LOAD ". */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../tests/crafted_words.h"
#include "bench_common.h"
#include "hdt.h"
#include "uniform_points.h"

static double load_ms(const unsigned char *b, size_t n, int *ok) {
  hdt_triangulation *t = NULL;
  const double t0 = bench_now_ms();
  const hdt_status s = hdt_load(&t, b, n);
  const double ms = bench_now_ms() - t0;
  *ok = s == HDT_OK;
  if (s != HDT_OK) fprintf(stderr, "load_bench: hdt_load: %s\n", hdt_last_error_message());
  hdt_destroy(t);
  return ms;
}

static void report(const char *what, const unsigned char *b, size_t n, size_t plain_n, double plain_ms,
                   size_t words, size_t letters) {
  int ok = 0;
  const double ms = load_ms(b, n, &ok);
  const double extra = (double)(n - plain_n);
  printf("LOAD file=%s bytes=%zu words=%zu letters=%zu load_ms=%.1f loaded=%d ns_per_extra_byte=%.0f\n", what, n, words,
         letters, ms, ok, extra > 0 ? (ms - plain_ms) * 1e6 / extra : 0.0);
  fflush(stdout);
}

int main(int argc, char **argv) {
  int genus = 2;
  size_t n = 100, words = 0, length = 100, powers = 0, power_length = 0;
  uint64_t seed = 1;
  for (int i = 1; i + 1 < argc; i += 2) {
    const char *a = argv[i], *v = argv[i + 1];
    if (!strcmp(a, "--genus")) genus = atoi(v);
    else if (!strcmp(a, "--n")) n = (size_t)strtoull(v, NULL, 10);
    else if (!strcmp(a, "--words")) words = (size_t)strtoull(v, NULL, 10);
    else if (!strcmp(a, "--length")) length = (size_t)strtoull(v, NULL, 10);
    else if (!strcmp(a, "--powers")) powers = (size_t)strtoull(v, NULL, 10);
    else if (!strcmp(a, "--power-length")) power_length = (size_t)strtoull(v, NULL, 10);
    else if (!strcmp(a, "--seed")) seed = (uint64_t)strtoull(v, NULL, 10);
    else {
      fprintf(stderr, "load_bench: unknown option %s\n", a);
      return 2;
    }
  }
  hdt_triangulation *t = NULL;
  if (hdt_create(&t, genus) != HDT_OK) return fprintf(stderr, "%s\n", hdt_last_error_message()), 1;
  double *xy = malloc(2 * n * sizeof *xy + 16);
  bench_points_in_polygon(genus, n, seed, xy);
  if (hdt_insert_many(t, xy, n, NULL) != HDT_OK) return fprintf(stderr, "%s\n", hdt_last_error_message()), 1;
  size_t size = 0;
  hdt_save(t, NULL, 0, &size);
  unsigned char *plain = malloc(size);
  if (hdt_save(t, plain, size, &size) != HDT_OK) return fprintf(stderr, "%s\n", hdt_last_error_message()), 1;
  hdt_destroy(t);
  int ok = 0;
  load_ms(plain, size, &ok); /* the genus's tables, built once a process */
  const double plain_ms = load_ms(plain, size, &ok);
  printf("LOAD file=plain genus=%d n=%zu bytes=%zu load_ms=%.1f loaded=%d\n", genus, n, size, plain_ms, ok);
  fflush(stdout);
  const size_t max_length = 64 + 32 * (size_t)genus;
  if (words > 0) {
    crafted_words_t w = {0};
    const double t0 = bench_now_ms();
    if (!crafted_canonical_words(genus, words, length, max_length, seed, &w)) return fprintf(stderr, "words\n"), 1;
    fprintf(stderr, "load_bench: %zu words made in %.0f ms\n", w.count, bench_now_ms() - t0);
    size_t m = 0;
    unsigned char *c = crafted_file(plain, size, &w, &m);
    report("random-words", c, m, size, plain_ms, w.count, w.letter_count);
    free(c);
    crafted_words_free(&w);
  }
  if (powers > 0) {
    crafted_words_t w = {0};
    for (size_t k = 0; k < powers; ++k) crafted_power(genus, power_length + k, &w);
    size_t m = 0;
    unsigned char *c = crafted_file(plain, size, &w, &m);
    report("powers", c, m, size, plain_ms, w.count, w.letter_count);
    free(c);
    crafted_words_free(&w);
  }
  free(plain);
  free(xy);
  return 0;
}
