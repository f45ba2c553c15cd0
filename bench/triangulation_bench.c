/* Triangulation benchmark through the public C API.
 *
 * For each genus and each N: hdt_create (first in the process, then cached),
 * hdt_insert_many of N points uniform for hyperbolic area in F_g (fixed
 * seed), hdt_remove_dummies, hdt_validate (up to --validate-max points), and
 * the peak resident memory added by the insertion per vertex. Each (genus, N)
 * runs in its own child process, so peak memory and the first-creation time
 * are its own.
 *
 *   triangulation_bench [--genus 2,3,4,8,16] [--max 1000000] [--validate-max 100000]
 */
#define _GNU_SOURCE
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "hdt.h"

static double now_ms(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

/* A field of /proc/self/status in kB (VmRSS, VmHWM). */
static long status_kb(const char *field) {
  FILE *f = fopen("/proc/self/status", "r");
  char line[256];
  long value = -1;
  size_t n = strlen(field);
  while (f && fgets(line, sizeof line, f))
    if (strncmp(line, field, n) == 0 && line[n] == ':') value = atol(line + n + 1);
  if (f) fclose(f);
  return value;
}

static uint64_t rng_state = 0x853c49e6748fea9bULL;
static double uniform01(void) {
  rng_state ^= rng_state >> 12, rng_state ^= rng_state << 25, rng_state ^= rng_state >> 27;
  return (double)((rng_state * 2685821657736338717ULL) >> 11) * 0x1p-53;
}

/* N points uniform for hyperbolic area in F_g: uniform in the hyperbolic
   disk of F_g's circumradius R (cosh r uniform in [1, cosh R]), kept when
   no side line of F_g separates them from 0 (a double test; the library maps
   any point to its representative anyway). */
static void sample(int g, size_t n, double *xy) {
  const double A = 1.0 / tan(M_PI / (4.0 * g));
  const double cosh_R = A * A, cosh_l = 2 * A * A - 1, sinh_l = sqrt(cosh_l * cosh_l - 1);
  for (size_t i = 0; i < n;) {
    const double c = 1 + (cosh_R - 1) * uniform01(), a = 2 * M_PI * uniform01();
    const double rho = tanh(acosh(c) / 2), x = rho * cos(a), y = rho * sin(a);
    const double w = 1 - x * x - y * y, t = (1 + x * x + y * y) / w, u = 2 * x / w, v = 2 * y / w;
    int inside = 1;
    for (int k = 0; k < 4 * g && inside; ++k) {
      const double th = k * M_PI / (2.0 * g);
      /* <N, O> - <N, g_k O> with g_k O = (cosh l, sinh l cos th, sinh l sin th). */
      if (t - (t * cosh_l - u * sinh_l * cos(th) - v * sinh_l * sin(th)) > 0) inside = 0;
    }
    if (inside) xy[2 * i] = x, xy[2 * i + 1] = y, ++i;
  }
}

static void check(hdt_status s, const char *what) {
  if (s != HDT_OK) {
    fprintf(stderr, "%s: %s: %s\n", what, hdt_status_string(s), hdt_last_error_message());
    exit(1);
  }
}

static void run(int g, size_t n, size_t validate_max) {
  double *xy = malloc(2 * n * sizeof *xy);
  sample(g, n, xy);
  hdt_triangulation *t, *t2;
  double t0 = now_ms();
  check(hdt_create(&t, g), "hdt_create");
  const double first = now_ms() - t0;
  t0 = now_ms();
  check(hdt_create(&t2, g), "hdt_create");
  const double cached = now_ms() - t0;
  hdt_destroy(t2);
  const size_t dummies = hdt_dummy_count(t);
  const long rss_before = status_kb("VmRSS");
  t0 = now_ms();
  check(hdt_insert_many(t, xy, n, NULL), "hdt_insert_many");
  const double insert = now_ms() - t0;
  const long peak = status_kb("VmHWM");
  size_t left;
  t0 = now_ms();
  check(hdt_remove_dummies(t, &left), "hdt_remove_dummies");
  const double removal = now_ms() - t0;
  double validate = -1;
  if (n <= validate_max) {
    t0 = now_ms();
    check(hdt_validate(t), "hdt_validate");
    validate = now_ms() - t0;
  }
  printf("%3d %8zu %5zu %9.2f %8.3f %9.3f %8.2f %9.1f %8.1f %6zu\n", g, n, dummies, first, cached, insert * 1e3 / n,
         removal, validate, (peak - rss_before) * 1024.0 / n, left);
  fflush(stdout);
  hdt_destroy(t);
  free(xy);
}

int main(int argc, char **argv) {
  int genera[64] = {2, 3, 4, 8, 16}, ng = 5;
  size_t max = 1000000, validate_max = 100000;
  for (int i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "--genus") && i + 1 < argc) {
      ng = 0;
      for (char *s = strtok(argv[++i], ","); s && ng < 64; s = strtok(NULL, ",")) genera[ng++] = atoi(s);
    } else if (!strcmp(argv[i], "--max") && i + 1 < argc) {
      max = strtoull(argv[++i], NULL, 10);
    } else if (!strcmp(argv[i], "--validate-max") && i + 1 < argc) {
      validate_max = strtoull(argv[++i], NULL, 10);
    } else {
      fprintf(stderr, "usage: %s [--genus 2,3,4,8,16] [--max N] [--validate-max N]\n", argv[0]);
      return 2;
    }
  }
  printf("libhdt %s triangulation benchmark: points uniform in F_g, hdt_insert_many\n", hdt_version_string());
  printf("  g        N dummy create_ms cached_ms insert_us/pt remove_ms validate_ms bytes/vtx left\n");
  for (int i = 0; i < ng; ++i)
    for (size_t n = 1000; n <= max; n *= 10) {
      fflush(stdout);
      const pid_t pid = fork();
      if (pid == 0) {
        run(genera[i], n, validate_max);
        _exit(0);
      }
      int status = 0;
      waitpid(pid, &status, 0);
      if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return 1;
    }
  return 0;
}
