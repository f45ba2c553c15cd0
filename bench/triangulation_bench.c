/* Triangulation benchmark of libhdt through the public C API.
 *
 * Sweep (the default): for each genus and each N = 10^3, 10^4, ... up to
 * --max: hdt_create (first in the process, then cached), hdt_insert_many of N
 * points uniform for hyperbolic area in F_g (bench/uniform_points.h, fixed
 * seed), hdt_remove_dummies, hdt_validate (up to --validate-max points), and
 * the peak resident memory added by the triangulation per vertex. Each
 * (genus, N) runs in its own child process, so the peak memory and the
 * first-creation time are its own.
 *
 *   triangulation_bench [--genus 2,3,4,8,16] [--max 1000000] [--validate-max 100000] [--mode range|one]
 *
 * Single run (what bench/compare.py calls, one process per run): prints one
 * RESULT line of key=value fields (see bench_common.h).
 *
 *   triangulation_bench --n N [--genus G] [--mode range|one] [--seed S] [--validate] [--faces FILE]
 *
 * range: one hdt_insert_many call; one: hdt_insert for each point in input
 * order. Then hdt_remove_dummies, timed apart. Memory: baseline is the
 * resident size once the input points exist (before hdt_create, whose
 * per-genus tables are counted); peak is VmHWM after the dummies are removed
 * (the validity check and the face export come later and are not counted);
 * bytes_per_vtx = (peak - baseline) / V.
 */
#define _GNU_SOURCE
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "bench_common.h"
#include "hdt.h"
#include "uniform_points.h"

static void check(hdt_status s, const char *what) {
  if (s != HDT_OK) {
    fprintf(stderr, "%s: %s: %s\n", what, hdt_status_string(s), hdt_last_error_message());
    exit(1);
  }
}

typedef struct run_result {
  double create_ms, create_cpu_ms, cached_ms, cached_cpu_ms, insert_ms, cpu_ms, remove_ms, remove_cpu_ms, validate_ms,
      validate_cpu_ms;
  size_t dummies, left, V, F;
  long baseline_kib, peak_kib;
  int valid, faces_written;
} run_result;

/* Writes the face set by input point index (see bench_write_faces);
   index_of[v] is the input index of vertex v. 0 on success. */
static int write_faces(const hdt_triangulation *t, const uint64_t *index_of, size_t id_bound, const char *path) {
  size_t count = 0;
  check(hdt_faces(t, NULL, NULL, 0, &count), "hdt_faces");
  uint32_t *v = malloc(3 * count * sizeof *v + 1);
  uint64_t *faces = malloc(3 * count * sizeof *faces + 1);
  check(hdt_faces(t, v, NULL, count, &count), "hdt_faces");
  int ok = 1;
  for (size_t i = 0; i < 3 * count; ++i) {
    if (v[i] >= id_bound || index_of[v[i]] == UINT64_MAX) ok = 0;
    faces[i] = v[i] < id_bound ? index_of[v[i]] : UINT64_MAX;
  }
  if (!ok) fprintf(stderr, "a face vertex is not an input point\n");
  const int status = ok ? bench_write_faces(path, faces, count) : -1;
  free(v);
  free(faces);
  return status;
}

static run_result run(const bench_options *o) {
  run_result r;
  memset(&r, 0, sizeof r);
  const size_t n = o->n;
  double *xy = malloc(2 * n * sizeof *xy);
  uint32_t *ids = malloc(n * sizeof *ids);
  bench_points_in_polygon(o->genus, n, o->seed, xy);
  memset(ids, 0, n * sizeof *ids);
  bench_reset_peak();
  r.baseline_kib = bench_status_kib("VmRSS");

  hdt_triangulation *t, *t2;
  double t0 = bench_now_ms(), c0 = bench_cpu_ms();
  check(hdt_create(&t, o->genus), "hdt_create");
  r.create_ms = bench_now_ms() - t0;
  r.create_cpu_ms = bench_cpu_ms() - c0;
  t0 = bench_now_ms(), c0 = bench_cpu_ms();
  check(hdt_create(&t2, o->genus), "hdt_create");
  r.cached_ms = bench_now_ms() - t0;
  r.cached_cpu_ms = bench_cpu_ms() - c0;
  hdt_destroy(t2);
  r.dummies = hdt_dummy_count(t);

  t0 = bench_now_ms();
  c0 = bench_cpu_ms();
  if (o->one_by_one) {
    for (size_t i = 0; i < n; ++i) check(hdt_insert(t, xy[2 * i], xy[2 * i + 1], &ids[i]), "hdt_insert");
  } else {
    check(hdt_insert_many(t, xy, n, ids), "hdt_insert_many");
  }
  r.insert_ms = bench_now_ms() - t0;
  r.cpu_ms = bench_cpu_ms() - c0;
  t0 = bench_now_ms(), c0 = bench_cpu_ms();
  check(hdt_remove_dummies(t, &r.left), "hdt_remove_dummies");
  r.remove_ms = bench_now_ms() - t0;
  r.remove_cpu_ms = bench_cpu_ms() - c0;
  r.peak_kib = bench_status_kib("VmHWM");
  r.V = hdt_vertex_count(t);
  r.F = hdt_face_count(t);

  r.validate_ms = r.validate_cpu_ms = -1;
  r.valid = -1;
  if (o->validate) {
    t0 = bench_now_ms(), c0 = bench_cpu_ms();
    const hdt_status s = hdt_validate(t);
    r.validate_ms = bench_now_ms() - t0;
    r.validate_cpu_ms = bench_cpu_ms() - c0;
    r.valid = s == HDT_OK;
    if (s != HDT_OK) fprintf(stderr, "hdt_validate: %s: %s\n", hdt_status_string(s), hdt_last_error_message());
  }

  if (o->faces) {
    if (r.left != 0) {
      fprintf(stderr, "%zu dummy vertices left: faces not written\n", r.left);
    } else {
      const size_t bound = hdt_vertex_id_bound(t);
      uint64_t *index_of = malloc(bound * sizeof *index_of + 1);
      for (size_t v = 0; v < bound; ++v) index_of[v] = UINT64_MAX;
      for (size_t i = 0; i < n; ++i)
        if (ids[i] < bound) index_of[ids[i]] = i;
      r.faces_written = write_faces(t, index_of, bound, o->faces) == 0;
      free(index_of);
    }
  }
  hdt_destroy(t);
  free(ids);
  free(xy);
  return r;
}

static int single(const bench_options *o) {
  const run_result r = run(o);
  printf("RESULT prog=libhdt mode=%s g=%d n=%zu seed=%llu create_ms=%.3f create_cpu_ms=%.3f cached_ms=%.3f "
         "cached_cpu_ms=%.3f dummies=%zu insert_ms=%.3f us_per_pt=%.4f cpu_ms=%.3f cpu_us_per_pt=%.4f remove_ms=%.3f "
         "remove_cpu_ms=%.3f dummies_left=%zu validate_ms=%.3f validate_cpu_ms=%.3f valid=%d V=%zu E=%zu F=%zu "
         "baseline_kib=%ld peak_kib=%ld bytes_per_vtx=%.1f failed=%zu faces_written=%d\n",
         o->one_by_one ? "one" : "range", o->genus, o->n, (unsigned long long)o->seed, r.create_ms, r.create_cpu_ms,
         r.cached_ms, r.cached_cpu_ms, r.dummies, r.insert_ms, r.insert_ms * 1e3 / (double)o->n, r.cpu_ms,
         r.cpu_ms * 1e3 / (double)o->n, r.remove_ms, r.remove_cpu_ms, r.left, r.validate_ms, r.validate_cpu_ms,
         r.valid, r.V, 3 * r.F / 2, r.F, r.baseline_kib, r.peak_kib,
         (double)(r.peak_kib - r.baseline_kib) * 1024.0 / (double)r.V, o->n + r.left - r.V, r.faces_written);
  return r.valid == 0;
}

static int sweep(int argc, char **argv) {
  int genera[64] = {2, 3, 4, 8, 16}, ng = 5, one_by_one = 0;
  size_t max = 1000000, validate_max = 100000;
  for (int i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "--genus") && i + 1 < argc) {
      ng = 0;
      for (char *s = strtok(argv[++i], ","); s && ng < 64; s = strtok(NULL, ",")) genera[ng++] = atoi(s);
    } else if (!strcmp(argv[i], "--max") && i + 1 < argc) {
      max = strtoull(argv[++i], NULL, 10);
    } else if (!strcmp(argv[i], "--validate-max") && i + 1 < argc) {
      validate_max = strtoull(argv[++i], NULL, 10);
    } else if (!strcmp(argv[i], "--mode") && i + 1 < argc) {
      one_by_one = !strcmp(argv[++i], "one");
    } else {
      fprintf(stderr,
              "usage: %s [--genus 2,3,4,8,16] [--max N] [--validate-max N] [--mode range|one]\n"
              "       %s --n N [--genus G] [--mode range|one] [--seed S] [--validate] [--faces FILE]\n",
              argv[0], argv[0]);
      return 2;
    }
  }
  printf("libhdt %s triangulation benchmark: points uniform in F_g, %s\n", hdt_version_string(),
         one_by_one ? "hdt_insert one by one" : "hdt_insert_many");
  printf("  g        N dummy create_ms cached_ms insert_us/pt remove_ms validate_ms bytes/vtx left\n");
  for (int i = 0; i < ng; ++i)
    for (size_t n = 1000; n <= max; n *= 10) {
      fflush(stdout);
      const pid_t pid = fork();
      if (pid == 0) {
        bench_options o = {genera[i], n, one_by_one, 1, n <= validate_max, NULL};
        const run_result r = run(&o);
        printf("%3d %8zu %5zu %9.2f %9.3f %12.3f %9.2f %11.1f %9.1f %4zu\n", o.genus, n, r.dummies, r.create_ms,
               r.cached_ms, r.insert_ms * 1e3 / (double)n, r.remove_ms, r.validate_ms,
               (double)(r.peak_kib - r.baseline_kib) * 1024.0 / (double)r.V, r.left);
        fflush(stdout);
        _exit(r.valid == 0);
      }
      int status = 0;
      waitpid(pid, &status, 0);
      if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return 1;
    }
  return 0;
}

int main(int argc, char **argv) {
  for (int i = 1; i < argc; ++i)
    if (!strcmp(argv[i], "--n")) {
      bench_options o;
      if (bench_parse_options(argc, argv, 1, &o) != 0) return 2;
      return single(&o);
    }
  return sweep(argc, argv);
}
