// How the triangulation's storage grows: geometrically, whatever the calls.
// Inserting N points in calls of a few points each used to reserve exactly
// the room of each call, so that every call copied all the faces: N^2 / k
// work (200,000 points in calls of 100 took 74 s, against 0.25 s in one
// call). Timing has no place in a test; the number of times the faces move
// to new storage does: about log2 N when growth is geometric, one per call
// when it is not.
#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "mesh/triangulation.hpp"

#include <check.h>

#include "dummies/dummy_points.hpp"
#include "run_suite.hpp"

using namespace hdt::mesh;

namespace {

// n random points of the disk of Euclidean radius 0.5 (inside F_2 and F_3).
std::vector<double> points(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  std::vector<double> xy;
  while (xy.size() < 2 * n) {
    const double x = u(rng), y = u(rng);
    if (x * x + y * y < 0.25) xy.push_back(x), xy.push_back(y);
  }
  return xy;
}

// How many times the faces' storage moves while n points go in through
// insert_many, k at a time (k = 0: one insert() a point).
int moves_while_inserting(int genus, std::size_t n, std::size_t k, std::size_t *faces) {
  Triangulation t = hdt::dummies::new_triangulation(genus);
  const std::vector<double> xy = points(n, 11);
  std::vector<uint32_t> ids(n);
  const Face *storage = t.faces().data();
  int moves = 0;
  for (std::size_t i = 0; i < n; i += (k == 0 ? 1 : k)) {
    if (k == 0) t.insert(xy[2 * i], xy[2 * i + 1]);
    else t.insert_many(xy.data() + 2 * i, std::min(k, n - i), ids.data());
    if (t.faces().data() != storage) storage = t.faces().data(), ++moves;
  }
  t.validate();
  *faces = t.faces().size();
  return moves;
}

}  // namespace

START_TEST(faces_move_logarithmically_often_in_many_small_calls) {
  const int genus = 2 + _i;
  const std::size_t n = 4000;
  std::size_t one_call = 0;
  moves_while_inserting(genus, n, n, &one_call);
  for (const std::size_t k : {std::size_t(0), std::size_t(1), std::size_t(7), std::size_t(100)}) {
    std::size_t faces = 0;
    const int moves = moves_while_inserting(genus, n, k, &faces);
    // Every call of a series moved them before: 4000, 572 and 40 moves
    // for 1, 7 and 100 points a call.
    // Doubling from the dummies' few dozen faces to 8000: under 10.
    ck_assert_msg(moves <= 12, "genus %d, %zu points a call: the faces moved %d times", genus, k, moves);
    // Euler: F = 2V + 4(g - 1) whatever the order.
    ck_assert_uint_eq(faces, one_call);
  }
}
END_TEST

int main() {
  return run_suite("storage_growth", 300, [](TCase *tc) {
    tcase_add_loop_test(tc, faces_move_logarithmically_often_in_many_small_calls, 0, 2);
  });
}
