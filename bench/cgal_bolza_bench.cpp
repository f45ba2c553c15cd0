// Peer benchmark: CGAL's Periodic_4_hyperbolic_Delaunay_triangulation_2 (the
// Bolza surface, genus 2) with its default traits
// (Periodic_4_hyperbolic_Delaunay_triangulation_traits_2<>: the kernel
// Exact_predicates_exact_constructions_kernel_with_sqrt, whose number type is
// CORE::Expr), on the same points as triangulation_bench --genus 2 (same
// generator, same seed). CGAL's octagon is libhdt's F_2 (vertices at the odd
// multiples of pi/8, side midpoints at the multiples of pi/4), so the points
// are used as they are.
//
//   cgal_bolza_bench --n N [--mode range|one] [--seed S] [--validate] [--faces FILE]
//
// range: insert(first, last, false) (CGAL's spatial sort, each point located
// from the previous one; dummies kept), then try_to_remove_dummy_vertices()
// timed apart. one: insert(p) for each point in input order, no hint, then
// try_to_remove_dummy_vertices(). The validity check is CGAL's is_valid().
// Prints one RESULT line (see bench_common.h).
#include <CGAL/Periodic_4_hyperbolic_Delaunay_triangulation_2.h>
#include <CGAL/Periodic_4_hyperbolic_Delaunay_triangulation_traits_2.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <unordered_map>
#include <vector>

#include "bench_common.h"
#include "uniform_points.h"

typedef CGAL::Periodic_4_hyperbolic_Delaunay_triangulation_traits_2<> Traits;
typedef CGAL::Periodic_4_hyperbolic_Delaunay_triangulation_2<Traits> Triangulation;
typedef Traits::Hyperbolic_point_2 Point;

namespace {

// The input index of a point, by its two doubles (CGAL's points were made
// from these doubles exactly, and to_double gives them back exactly).
struct Key {
  uint64_t x, y;
  bool operator==(const Key &o) const { return x == o.x && y == o.y; }
};
struct KeyHash {
  std::size_t operator()(const Key &k) const { return std::size_t(k.x * 0x9e3779b97f4a7c15ULL ^ (k.y + (k.x >> 7))); }
};
Key key_of(double x, double y) {
  Key k;
  std::memcpy(&k.x, &x, sizeof x);
  std::memcpy(&k.y, &y, sizeof y);
  return k;
}

}  // namespace

int main(int argc, char **argv) {
  bench_options o;
  if (bench_parse_options(argc, argv, 1, &o) != 0) return 2;
  if (o.genus != 2) {
    std::fprintf(stderr, "CGAL's periodic hyperbolic triangulation is genus 2 only\n");
    return 2;
  }
  std::vector<double> xy(2 * o.n);
  bench_points_in_polygon(2, o.n, o.seed, xy.data());
  bench_reset_peak();
  const long baseline = bench_status_kib("VmRSS");

  double t0 = bench_now_ms();
  const double c3 = bench_cpu_ms();
  Triangulation tr;
  const double create_ms = bench_now_ms() - t0, create_cpu_ms = bench_cpu_ms() - c3;
  const std::size_t dummies = std::size_t(tr.number_of_dummy_points());

  std::vector<Point> points;
  points.reserve(o.n);
  for (std::size_t i = 0; i < o.n; ++i) points.push_back(Point(xy[2 * i], xy[2 * i + 1]));

  std::size_t failed = 0;
  t0 = bench_now_ms();
  const double c0 = bench_cpu_ms();
  if (o.one_by_one) {
    for (const Point &p : points)
      if (tr.insert(p) == Triangulation::Vertex_handle()) ++failed;
  } else {
    const std::ptrdiff_t added = tr.insert(points.begin(), points.end(), false);
    failed = o.n - std::size_t(added);
  }
  const double insert_ms = bench_now_ms() - t0;
  const double cpu_ms = bench_cpu_ms() - c0;
  t0 = bench_now_ms();
  const double c2 = bench_cpu_ms();
  const int left = tr.try_to_remove_dummy_vertices();
  const double remove_ms = bench_now_ms() - t0, remove_cpu_ms = bench_cpu_ms() - c2;
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

  int faces_written = 0;
  if (o.faces) {
    if (left != 0) {
      std::fprintf(stderr, "%d dummy vertices left: faces not written\n", left);
    } else {
      std::unordered_map<Key, uint64_t, KeyHash> index;
      index.reserve(2 * o.n);
      for (std::size_t i = 0; i < o.n; ++i) index.emplace(key_of(xy[2 * i], xy[2 * i + 1]), uint64_t(i));
      std::vector<uint64_t> faces;
      faces.reserve(3 * tr.number_of_faces());
      bool ok = true;
      for (Triangulation::Face_iterator f = tr.faces_begin(); f != tr.faces_end(); ++f)
        for (int k = 0; k < 3; ++k) {
          const Point &p = f->vertex(k)->point();
          auto it = index.find(key_of(CGAL::to_double(p.x()), CGAL::to_double(p.y())));
          if (it == index.end()) ok = false;
          faces.push_back(it == index.end() ? UINT64_MAX : it->second);
        }
      if (!ok) std::fprintf(stderr, "a face vertex is not an input point\n");
      faces_written = ok && bench_write_faces(o.faces, faces.data(), faces.size() / 3) == 0;
    }
  }

  const std::size_t V = tr.number_of_vertices();
  std::printf(
      "RESULT prog=cgal-bolza mode=%s g=2 n=%zu seed=%llu create_ms=%.3f create_cpu_ms=%.3f dummies=%zu "
      "insert_ms=%.3f us_per_pt=%.4f cpu_ms=%.3f cpu_us_per_pt=%.4f remove_ms=%.3f remove_cpu_ms=%.3f "
      "dummies_left=%d validate_ms=%.3f validate_cpu_ms=%.3f valid=%d V=%zu E=%zu F=%zu baseline_kib=%ld "
      "peak_kib=%ld bytes_per_vtx=%.1f failed=%zu faces_written=%d\n",
      o.one_by_one ? "one" : "range", o.n, (unsigned long long)o.seed, create_ms, create_cpu_ms, dummies, insert_ms,
      insert_ms * 1e3 / double(o.n), cpu_ms, cpu_ms * 1e3 / double(o.n), remove_ms, remove_cpu_ms, left,
      validate_ms, validate_cpu_ms, valid, V, std::size_t(tr.number_of_edges()), std::size_t(tr.number_of_faces()),
      baseline, peak, double(peak - baseline) * 1024.0 / double(V), failed, faces_written);
  return (failed == 0 && valid != 0) ? 0 : 1;
}
