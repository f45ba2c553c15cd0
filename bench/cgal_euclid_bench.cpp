// Euclidean reference: CGAL's Delaunay_triangulation_2 with
// Exact_predicates_inexact_constructions_kernel on N points uniform in the
// unit square (the shared generator, same seed as the other programs).
//
//   cgal_euclid_bench --n N [--mode range|one] [--seed S] [--validate]
//
// range: insert(first, last) (CGAL's spatial sort, each point located from
// the previous one). one: insert(p) for each point in input order, no hint.
// The validity check is CGAL's is_valid() (combinatorics, orientation, and
// the empty-circle property across every edge). V, E, F count the finite
// elements (the infinite vertex and its faces are CGAL's artefact).
// Prints one RESULT line (see bench_common.h).
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstdio>
#include <vector>

#include "bench_common.h"
#include "uniform_points.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Delaunay_triangulation_2<Kernel> Triangulation;
typedef Kernel::Point_2 Point;

int main(int argc, char **argv) {
  bench_options o;
  if (bench_parse_options(argc, argv, 1, &o) != 0) return 2;
  std::vector<double> xy(2 * o.n);
  bench_points_in_square(o.n, o.seed, xy.data());
  bench_reset_peak();
  const long baseline = bench_status_kib("VmRSS");

  double t0 = bench_now_ms();
  const double c3 = bench_cpu_ms();
  Triangulation tr;
  const double create_ms = bench_now_ms() - t0, create_cpu_ms = bench_cpu_ms() - c3;
  std::vector<Point> points;
  points.reserve(o.n);
  for (std::size_t i = 0; i < o.n; ++i) points.push_back(Point(xy[2 * i], xy[2 * i + 1]));

  t0 = bench_now_ms();
  const double c0 = bench_cpu_ms();
  if (o.one_by_one) {
    for (const Point &p : points) tr.insert(p);
  } else {
    tr.insert(points.begin(), points.end());
  }
  const double insert_ms = bench_now_ms() - t0;
  const double cpu_ms = bench_cpu_ms() - c0;
  const long peak = bench_status_kib("VmHWM");

  double validate_ms = -1, validate_cpu_ms = -1;
  int valid = -1;
  if (o.validate) {
    t0 = bench_now_ms();
    const double c1 = bench_cpu_ms();
    valid = tr.is_valid() ? 1 : 0;
    validate_ms = bench_now_ms() - t0;
    validate_cpu_ms = bench_cpu_ms() - c1;
  }
  const std::size_t V = tr.number_of_vertices();
  const std::size_t failed = o.n - V;
  std::size_t E = 0;
  for (auto e = tr.finite_edges_begin(); e != tr.finite_edges_end(); ++e) ++E;
  std::printf(
      "RESULT prog=cgal-euclid mode=%s g=0 n=%zu seed=%llu create_ms=%.3f create_cpu_ms=%.3f dummies=0 "
      "insert_ms=%.3f us_per_pt=%.4f cpu_ms=%.3f cpu_us_per_pt=%.4f remove_ms=0 remove_cpu_ms=0 dummies_left=0 "
      "validate_ms=%.3f validate_cpu_ms=%.3f valid=%d V=%zu E=%zu F=%zu baseline_kib=%ld peak_kib=%ld "
      "bytes_per_vtx=%.1f failed=%zu faces_written=0\n",
      o.one_by_one ? "one" : "range", o.n, (unsigned long long)o.seed, create_ms, create_cpu_ms, insert_ms,
      insert_ms * 1e3 / double(o.n), cpu_ms, cpu_ms * 1e3 / double(o.n), validate_ms, validate_cpu_ms, valid, V,
      E, std::size_t(tr.number_of_faces()), baseline, peak, double(peak - baseline) * 1024.0 / double(V), failed);
  return (failed == 0 && valid != 0) ? 0 : 1;
}
