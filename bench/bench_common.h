/* Helpers shared by the benchmark programs (C and C++): wall-clock time,
 * the process's memory from /proc/self/status, command-line parsing of the
 * single-run options, and the face-set export used to compare the
 * triangulations of two programs.
 *
 * Every single-run program prints exactly one line starting with "RESULT "
 * followed by key=value fields (no spaces inside values); bench/compare.py
 * reads those. Fields common to all programs:
 *   prog mode g n seed insert_ms us_per_pt cpu_ms cpu_us_per_pt remove_ms dummies_left
 *   validate_ms valid V E F baseline_kib peak_kib bytes_per_vtx failed
 * (insert_ms, us_per_pt: wall clock; cpu_ms, cpu_us_per_pt: the process's
 * CPU time over the same insertion; valid: 1 passed, 0 failed, -1 not run; validate_ms -1 when not run).
 */
#ifndef HDT_BENCH_COMMON_H
#define HDT_BENCH_COMMON_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static inline double bench_now_ms(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

/* CPU time of the process (all its threads), in ms. */
static inline double bench_cpu_ms(void) {
  struct timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

/* A field of /proc/self/status in KiB (VmRSS: resident now; VmHWM: peak
   resident since the process started), -1 when unreadable. */
static inline long bench_status_kib(const char *field) {
  FILE *f = fopen("/proc/self/status", "r");
  char line[256];
  long value = -1;
  const size_t n = strlen(field);
  while (f && fgets(line, sizeof line, f))
    if (strncmp(line, field, n) == 0 && line[n] == ':') value = atol(line + n + 1);
  if (f) fclose(f);
  return value;
}

/* Resets the process's peak resident size (VmHWM) to its current resident
   size (Linux >= 4.0: "5" to /proc/self/clear_refs), so that a forked child
   measures its own peak. Silently does nothing where unsupported. */
static inline void bench_reset_peak(void) {
  FILE *f = fopen("/proc/self/clear_refs", "w");
  if (f) {
    fputs("5", f);
    fclose(f);
  }
}

/* Options of one run. */
typedef struct bench_options {
  int genus;          /* --genus G (2) */
  size_t n;           /* --n N (required) */
  int one_by_one;     /* --mode one (else --mode range, the default) */
  uint64_t seed;      /* --seed S (1) */
  int validate;       /* --validate: run the validity check */
  const char *faces;  /* --faces FILE: write the face set (see bench_write_faces) */
} bench_options;

/* Parses the single-run options from argv[first..argc); 0 on success, -1
   (after a message on stderr) on a bad option. */
static inline int bench_parse_options(int argc, char **argv, int first, bench_options *o) {
  o->genus = 2, o->n = 0, o->one_by_one = 0, o->seed = 1, o->validate = 0, o->faces = NULL;
  for (int i = first; i < argc; ++i) {
    const char *a = argv[i];
    if (!strcmp(a, "--genus") && i + 1 < argc) {
      o->genus = atoi(argv[++i]);
    } else if (!strcmp(a, "--n") && i + 1 < argc) {
      o->n = (size_t)strtoull(argv[++i], NULL, 10);
    } else if (!strcmp(a, "--mode") && i + 1 < argc) {
      const char *m = argv[++i];
      if (!strcmp(m, "one")) o->one_by_one = 1;
      else if (!strcmp(m, "range")) o->one_by_one = 0;
      else {
        fprintf(stderr, "--mode: 'range' or 'one', not '%s'\n", m);
        return -1;
      }
    } else if (!strcmp(a, "--seed") && i + 1 < argc) {
      o->seed = (uint64_t)strtoull(argv[++i], NULL, 10);
    } else if (!strcmp(a, "--validate")) {
      o->validate = 1;
    } else if (!strcmp(a, "--faces") && i + 1 < argc) {
      o->faces = argv[++i];
    } else {
      fprintf(stderr, "unknown or incomplete option '%s'\n", a);
      return -1;
    }
  }
  if (o->n == 0) {
    fprintf(stderr, "--n N is required (N > 0)\n");
    return -1;
  }
  return 0;
}

/* Rotates a face (a, b, c), given counterclockwise as input point indices,
   so that its smallest index comes first; the orientation is kept. */
static inline void bench_canonical_face(uint64_t f[3]) {
  while (f[0] > f[1] || f[0] > f[2]) {
    const uint64_t t = f[0];
    f[0] = f[1], f[1] = f[2], f[2] = t;
  }
}

static int bench_face_less(const void *pa, const void *pb) {
  const uint64_t *a = (const uint64_t *)pa, *b = (const uint64_t *)pb;
  for (int k = 0; k < 3; ++k)
    if (a[k] != b[k]) return a[k] < b[k] ? -1 : 1;
  return 0;
}

/* Writes the faces (3 input point indices each, counterclockwise) as text,
   one face a line, each rotated to start at its smallest index, the lines
   sorted: two programs that triangulated the same points the same way write
   the same file. faces is modified (rotated and sorted). 0 on success. */
static inline int bench_write_faces(const char *path, uint64_t *faces, size_t count) {
  for (size_t i = 0; i < count; ++i) bench_canonical_face(faces + 3 * i);
  qsort(faces, count, 3 * sizeof *faces, bench_face_less);
  FILE *f = fopen(path, "w");
  if (!f) {
    perror(path);
    return -1;
  }
  for (size_t i = 0; i < count; ++i)
    fprintf(f, "%llu %llu %llu\n", (unsigned long long)faces[3 * i], (unsigned long long)faces[3 * i + 1],
            (unsigned long long)faces[3 * i + 2]);
  return fclose(f) == 0 ? 0 : -1;
}

#endif
