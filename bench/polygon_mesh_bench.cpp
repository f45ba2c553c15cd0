// Polygon surfaces against the built-in M_2, side by side in one process:
// the same N points (uniform for hyperbolic area in F_2, bench/uniform_points.h)
// inserted with insert_many into (a) the built-in M_2's triangulation, (b) the
// Bolza octagon given as a polygon (the same surface, in a number field),
// (c) a random rational octagon (lib/domain/random_octagon.hpp, seed 1; the
// points are reduced into it). Each round creates the three triangulations
// (the dummy points: the built-in's from its process cache after the first
// round, the polygons' built every time) and times the creation and the
// insertion separately; then, on a fresh triangulation of each, an
// epsilon-net (dual::refine, the code of hdt_epsilon_net, creation not
// timed). The rounds alternate and the medians are reported with the
// ratios to the built-in path.
//
//   polygon_mesh_bench [--n N] [--rounds R] [--epsilon E] [--only built-in|bolza|octagon]
//   (defaults 100000, 3, 0.01, all three; --epsilon 0: no nets; --only:
//   one surface, for callgrind's --toggle-collect='*insert_many*')
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <tuple>
#include <vector>

#include "domain/field_lock.hpp"
#include "dual/refine.hpp"
#include "domain/random_octagon.hpp"
#include "dummies/dummy_points.hpp"
#include "test_polygons.hpp"
#include "uniform_points.h"

using namespace hdt;

namespace {

double seconds_of(const std::function<void()> &f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct Timings {
  const char *name;
  std::vector<double> create, insert, net;
  std::size_t net_points = 0;
};

// An epsilon-net on t, timed; the points it added into *added.
template <class Tri>
double net_seconds(Tri &t, double epsilon, std::size_t *added) {
  return seconds_of([&] { *added = dual::refine(t, {epsilon, HUGE_VAL}, SIZE_MAX).added; });
}

}  // namespace

int main(int argc, char **argv) {
  std::size_t n = 100000;
  int rounds = 3;
  double epsilon = 0.01;
  const char *only = "";
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--n")) n = std::strtoull(argv[i + 1], nullptr, 10);
    else if (!std::strcmp(argv[i], "--rounds")) rounds = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--only")) only = argv[i + 1];
    else if (!std::strcmp(argv[i], "--epsilon")) epsilon = std::atof(argv[i + 1]);
  }
  std::vector<double> xy(2 * n);
  bench_points_in_polygon(2, n, 1, xy.data());
  const domain::FundamentalPolygon bolza = domain::test::bolza(), octagon = domain::random_octagon(1);
  Timings built_in{"built-in M_2", {}, {}, {}}, bolza_polygon{"Bolza octagon as a polygon", {}, {}, {}},
      random{"random rational octagon (seed 1)", {}, {}, {}};
  if (*only) epsilon = 0;
  std::size_t faces[3] = {0, 0, 0};
  for (int r = 0; r < rounds; ++r) {
    if (!*only || !std::strcmp(only, "built-in")) {
      mesh::Triangulation *t = nullptr;
      built_in.create.push_back(seconds_of([&] { t = new mesh::Triangulation(dummies::new_triangulation(2)); }));
      built_in.insert.push_back(seconds_of([&] { t->insert_many(xy.data(), n, nullptr); }));
      faces[0] = t->faces().size();
      delete t;
      if (epsilon > 0) {
        mesh::Triangulation net(dummies::new_triangulation(2));
        built_in.net.push_back(net_seconds(net, epsilon, &built_in.net_points));
      }
    }
    for (auto [P, timings, slot, name] :
         {std::make_tuple(&bolza, &bolza_polygon, 1, "bolza"), std::make_tuple(&octagon, &random, 2, "octagon")}) {
      if (*only && std::strcmp(only, name)) continue;
      const domain::FieldLock lock(P->field() != nullptr);
      mesh::PolygonTriangulation *t = nullptr;
      timings->create.push_back(
          seconds_of([&] { t = new mesh::PolygonTriangulation(dummies::new_polygon_triangulation(*P)); }));
      timings->insert.push_back(seconds_of([&] { t->insert_many(xy.data(), n, nullptr); }));
      faces[slot] = t->faces().size();
      delete t;
      if (epsilon > 0) {
        mesh::PolygonTriangulation net(dummies::new_polygon_triangulation(*P));
        timings->net.push_back(net_seconds(net, epsilon, &timings->net_points));
      }
    }
  }
  if (*only) return 0;
  const double base = median(built_in.insert);
  std::printf("%zu points, %d rounds (medians)\n", n, rounds);
  std::printf("%-36s %12s %14s %10s %8s\n", "surface", "create ms", "insert us/pt", "vs M_2", "faces");
  int slot = 0;
  for (const Timings *t : {&built_in, &bolza_polygon, &random}) {
    const double ins = median(t->insert);
    std::printf("%-36s %12.1f %14.3f %9.2fx %8zu\n", t->name, 1e3 * median(t->create), 1e6 * ins / double(n),
                ins / base, faces[slot++]);
  }
  if (epsilon > 0) {
    const double net_base = median(built_in.net);
    std::printf("\nepsilon-net, epsilon = %g (medians)\n", epsilon);
    std::printf("%-36s %12s %14s %10s\n", "surface", "ms", "points added", "vs M_2");
    for (const Timings *t : {&built_in, &bolza_polygon, &random}) {
      const double net = median(t->net);
      std::printf("%-36s %12.1f %14zu %9.2fx\n", t->name, 1e3 * net, t->net_points, net / net_base);
    }
  }
  return 0;
}
