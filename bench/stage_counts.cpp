// Which stage of the predicate pipeline decides each predicate's calls, on
// the benchmark's workload: the points of triangulation_bench (uniform in
// F_g, fixed seed), then points near F_g's corners and sides (within
// 10^-3 .. 10^-15, on either side: those outside are mapped in), where the
// filters see the most cancellation, then nearest-vertex queries at all of
// those. What docs/design.md's choice of stages per predicate was measured
// with.
//
//   stage_counts [--genus G] [--n N] [--corners M]   (defaults 2, 100000, 2000)
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <algorithm>
#include <vector>

#include "dummies/dummy_points.hpp"
#include "mesh/triangulation.hpp"
#include "uniform_points.h"

using namespace hdt;
using predicates::Predicate;
using predicates::Stage;

namespace {

// m points within 10^-3 .. 10^-15 (relative, log-uniform) of F_g's
// corners v_k (even i) or of its sides' midpoints (odd i), inside or
// outside, a little off the ray from O.
std::vector<double> boundary_points(int g, std::size_t m, uint64_t seed) {
  bench_rng r = bench_rng_seed(seed);
  const double A = 1.0 / std::tan(M_PI / (4.0 * g));
  const double corner_radius = std::tanh(std::acosh(A * A) / 2);
  const double side_radius = std::tanh(std::acosh(2 * A * A - 1) / 4);
  std::vector<double> xy;
  for (std::size_t i = 0; i < m; ++i) {
    const int k = int(bench_rng_next(&r) % uint64_t(4 * g));
    const double gap = std::pow(10.0, -3 - 12 * bench_uniform01(&r));
    const double sign = bench_uniform01(&r) < 0.5 ? -1 : 1;
    const bool corner = i % 2 == 0;
    const double angle = (corner ? 2 * k + 1 : 2 * k) * M_PI / (4.0 * g) + gap * (bench_uniform01(&r) - 0.5);
    const double radius = corner ? corner_radius : side_radius;
    const double rho = radius + sign * gap * (1 - radius);  // below 1 outside too
    xy.push_back(rho * std::cos(angle));
    xy.push_back(rho * std::sin(angle));
  }
  return xy;
}

}  // namespace

int main(int argc, char **argv) {
  int genus = 2;
  std::size_t n = 100000, corners = 2000;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--genus")) genus = std::atoi(argv[i + 1]);
    if (!std::strcmp(argv[i], "--n")) n = std::strtoul(argv[i + 1], nullptr, 10);
    if (!std::strcmp(argv[i], "--corners")) corners = std::strtoul(argv[i + 1], nullptr, 10);
  }
  std::vector<double> xy(2 * n);
  bench_points_in_polygon(genus, n, 1, xy.data());
  const std::vector<double> near = boundary_points(genus, corners, 2);
  xy.insert(xy.end(), near.begin(), near.end());

  mesh::Triangulation t = dummies::new_triangulation(genus);
  t.kernel().reset_statistics();
  t.insert_many(xy.data(), xy.size() / 2, nullptr);
  t.remove_dummies();
  for (std::size_t i = 0; i < near.size(); i += 2) t.nearest_vertex(near[i], near[i + 1]);
  for (std::size_t i = 0; i < std::min<std::size_t>(2 * n, 20000); i += 2) t.nearest_vertex(xy[i], xy[i + 1]);
  const predicates::FilterStatistics &s = t.kernel().statistics();

  std::printf("genus %d, %zu uniform points, %zu near the corners\n", genus, n, corners);
  std::printf("%-20s %10s %10s %10s %10s %10s %10s %10s %10s\n", "predicate", "calls", "disk", "double",
              "structural", "dd", "mpfr", "exact", "reach_mpfr");
  for (std::size_t p = 0; p < predicates::kPredicateCount; ++p) {
    const Predicate q = Predicate(p);
    std::printf("%-20s %10lu", predicates::predicate_name(q), s.calls(q));
    for (std::size_t st = 0; st < predicates::kStageCount; ++st) std::printf(" %10lu", s.decided_by(q, Stage(st)));
    std::printf(" %10lu\n", s.reached_mpfr[p]);
  }
  return 0;
}
