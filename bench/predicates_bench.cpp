// Microbenchmark of the exact predicates: nanoseconds per call of the
// filtered path (random, non-degenerate input: the filter decides) and of
// the exact path (the same calls forced through K_g), for g = 2, 4, 8, 16.
//
//   predicates_bench [CALLS]      (default 20000 filtered calls per predicate)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "predicates/kernel.hpp"
#include "predicates/stage_exact.hpp"
#include "surface/polygon.hpp"

using namespace hdt;
using predicates::TranslatedPoint;

namespace {

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Random points of the disk of radius 0.8 with random ids of N, fixed seed.
std::vector<TranslatedPoint> random_points(predicates::Kernel &kernel, std::size_t count) {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> coordinate(-0.8, 0.8);
  std::uniform_int_distribution<int> id(0, int(kernel.surface().table().neighbour_count()) - 1);
  std::vector<TranslatedPoint> points;
  while (points.size() < count) {
    const double x = coordinate(rng), y = coordinate(rng);
    if (x * x + y * y < 0.64) points.push_back({x, y, id(rng)});
  }
  return points;
}

template <class Call>
double nanoseconds_per_call(std::size_t calls, Call call) {
  int sink = 0;
  const double start = now();
  for (std::size_t i = 0; i < calls; ++i) sink += call(i);
  const double elapsed = now() - start;
  if (sink == 123456789) std::puts("");  // keep the calls
  return elapsed / double(calls) * 1e9;
}

}  // namespace

int main(int argc, char **argv) {
  const std::size_t calls = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 20000;
  std::printf("%-6s %-12s %14s %14s %10s\n", "genus", "predicate", "filtered ns", "exact ns", "exact/filt");
  for (int g : {2, 4, 8, 16}) {
    surface::Surface M(g);
    predicates::Kernel kernel{M};
    predicates::ExactStage exact_stage(M);  // the kernel's last stage, timed on its own
    const std::vector<TranslatedPoint> pts = random_points(kernel, calls + 4);
    // Exact calls cost far more: fewer of them, shrinking with the genus.
    const std::size_t exact_calls = std::max<std::size_t>(20, calls / (20 * std::size_t(g)));
    auto report = [&](const char *name, double filtered, double exact) {
      std::printf("%-6d %-12s %14.0f %14.0f %10.0f\n", g, name, filtered, exact, exact / filtered);
    };
    // Warm the caches: the rounded matrices of every id in use (computed on
    // first use, in multiprecision) and the exact ones of the first points.
    for (std::size_t i = 0; i < calls; ++i) kernel.beyond_side(pts[i], 0);
    for (std::size_t i = 0; i < exact_calls; ++i) exact_stage.orientation(pts[i], pts[i + 1], pts[i + 2]);
    kernel.reset_statistics();
    report("orientation",
           nanoseconds_per_call(calls, [&](std::size_t i) { return kernel.orientation(pts[i], pts[i + 1], pts[i + 2]); }),
           nanoseconds_per_call(exact_calls,
                                [&](std::size_t i) { return to_int(exact_stage.orientation(pts[i], pts[i + 1], pts[i + 2])); }));
    report("in_circle",
           nanoseconds_per_call(
               calls, [&](std::size_t i) { return kernel.in_circle(pts[i], pts[i + 1], pts[i + 2], pts[i + 3]); }),
           nanoseconds_per_call(exact_calls, [&](std::size_t i) {
             return to_int(exact_stage.in_circle(pts[i], pts[i + 1], pts[i + 2], pts[i + 3]));
           }));
    report("beyond_side",
           nanoseconds_per_call(calls, [&](std::size_t i) { return kernel.beyond_side(pts[i], int(i % (4 * g))); }),
           nanoseconds_per_call(exact_calls,
                                [&](std::size_t i) { return to_int(exact_stage.beyond_side(pts[i], int(i % (4 * g)))); }));
    const auto &s = kernel.statistics();
    std::printf("%-6d filter decided %lu of %lu calls (%.4f%%)\n", g, s.filtered(), s.calls(),
                100.0 * double(s.filtered()) / double(s.calls()));
  }
  return 0;
}
