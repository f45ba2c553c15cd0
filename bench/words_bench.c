/* The word functions and hdt_point_representative, for the figures that
 * include/hdt.h no longer carries (docs/benchmarks.md, written by
 * bench/compare.py): the linear pass of hdt_word_matrix over long words,
 * a product at the top of what double holds at genus 2, and the first
 * calls at a large genus, which build that genus's tables (CPU time and
 * the growth of the peak resident size). One process, the large genus
 * first.
 *
 *   words_bench [--genus 1024] [--letters 1000000]
 *
 * Prints a Markdown table. */
#define _POSIX_C_SOURCE 200809L

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_common.h"
#include "hdt.h"

static const char *status_name(hdt_status s) {
  switch (s) {
    case HDT_OK: return "HDT_OK";
    case HDT_EDOMAIN: return "HDT_EDOMAIN";
    case HDT_ENOTSUP: return "HDT_ENOTSUP";
    default: return hdt_status_string(s);
  }
}

static void row(const char *what, hdt_status s, double ms, long kib) {
  printf("| %s | %s | %.3g | %s", what, status_name(s), ms, kib >= 0 ? "" : "- |\n");
  if (kib >= 0) printf("%.1f |\n", kib / 1024.0);
}

int main(int argc, char **argv) {
  int big = 1024;
  size_t letters = 1000000;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!strcmp(argv[i], "--genus")) big = atoi(argv[i + 1]);
    else if (!strcmp(argv[i], "--letters")) letters = (size_t)strtoull(argv[i + 1], NULL, 10);
    else return fprintf(stderr, "usage: words_bench [--genus G] [--letters L]\n"), 2;
  }
  int32_t *w = malloc(letters * sizeof *w);
  if (!w) return 1;
  double m[4];
  printf("libhdt %s: CPU ms of one call; MiB: growth of the peak resident size (words_bench)\n\n",
         hdt_version_string());
  printf("| call | status | ms | MiB |\n|---|---|---:|---:|\n");
  /* The large genus first, before the long words touch their pages, so
     that the peak's growth is the genus's tables. */
  char what[160];
  long k0 = bench_status_kib("VmHWM");
  double rx, ry;
  size_t length;
  double t0 = bench_cpu_ms();
  hdt_status s = hdt_point_representative(big, 0.999, 0.001, &rx, &ry, NULL, 0, &length);
  snprintf(what, sizeof what, "hdt_point_representative(%d, 0.999, 0.001), first call of the genus", big);
  row(what, s, bench_cpu_ms() - t0, bench_status_kib("VmHWM") - k0);
  k0 = bench_status_kib("VmHWM");
  const int32_t g0 = 0;
  t0 = bench_cpu_ms();
  s = hdt_word_matrix(big, &g0, 1, m);
  snprintf(what, sizeof what, "hdt_word_matrix(%d, [0]), first word call of the genus", big);
  row(what, s, bench_cpu_ms() - t0, bench_status_kib("VmHWM") - k0);
  /* Warm genus 2's tables first, so that the rows below time the calls. */
  hdt_word_matrix(2, NULL, 0, m);
  for (size_t i = 0; i < letters; ++i) w[i] = i % 2 ? 4 : 0; /* (g_0 g_0^-1)^(L/2): the identity */
  t0 = bench_cpu_ms();
  s = hdt_word_matrix(2, w, letters, m);
  snprintf(what, sizeof what, "hdt_word_matrix, genus 2, a word of the identity of %zu letters", letters);
  row(what, s, bench_cpu_ms() - t0, -1);
  uint64_t state = 1; /* splitmix64's increment: letters 0..7 without a fixed pattern */
  for (size_t i = 0; i < letters; ++i) {
    uint64_t z = (state += 0x9E3779B97F4A7C15u);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    w[i] = (int32_t)((z ^ (z >> 31)) % 8);
  }
  t0 = bench_cpu_ms();
  s = hdt_word_matrix(2, w, letters, m);
  snprintf(what, sizeof what, "hdt_word_matrix, genus 2, %zu random letters (the entries overflow)", letters);
  row(what, s, bench_cpu_ms() - t0, -1);
  for (size_t i = 0; i < 464; ++i) w[i] = 0;
  t0 = bench_cpu_ms();
  s = hdt_word_matrix(2, w, 464, m);
  row("hdt_word_matrix, genus 2, g_0^464 (the longest power that fits)", s, bench_cpu_ms() - t0, -1);
  free(w);
  return 0;
}
