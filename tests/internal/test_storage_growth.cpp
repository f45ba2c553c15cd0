// How the triangulation's storage grows: geometrically, whatever the calls.
// Inserting N points in calls of a few points each used to reserve exactly
// the room of each call, so that every call copied all the faces: N^2 / k
// work (200,000 points in calls of 100 took 74 s, against 0.25 s in one
// call). Timing has no place in a test; the number of times the faces move
// to new storage does: about log2 N when growth is geometric, one per call
// when it is not. And the helper that moves them (huge_pages.hpp) keeps
// every element and, when it cannot allocate, changes nothing.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <new>
#include <random>
#include <stdexcept>
#include <vector>

#include "triangulation/huge_pages.hpp"
#include "triangulation/triangulation.hpp"

#include <check.h>

#include "run_suite.hpp"

using namespace hdt::triangulation;

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
  Triangulation t(genus);
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

START_TEST(reserve_on_huge_pages_keeps_every_element) {
  // 6 MB: large enough for the advice (two huge pages and more).
  std::vector<uint64_t> v;
  for (uint64_t i = 0; i < 1000; ++i) v.push_back(i * 2654435761u);
  reserve_on_huge_pages(v, 800000);
  ck_assert_uint_ge(v.capacity(), 800000);
  ck_assert_uint_eq(v.size(), 1000);
  for (uint64_t i = 0; i < 1000; ++i) ck_assert_uint_eq(v[i], i * 2654435761u);
  const uint64_t *before = v.data();
  reserve_on_huge_pages(v, 10);  // already room: nothing moves
  ck_assert_ptr_eq(v.data(), before);
  std::vector<bool> bits(77, true);
  reserve_on_huge_pages(bits, 1 << 20);
  ck_assert_uint_eq(bits.size(), 77);
  for (std::size_t i = 0; i < bits.size(); ++i) ck_assert(bits[i]);
  const std::vector<double> zeros = sized_on_huge_pages<std::vector<double>>(700000);
  ck_assert_uint_eq(zeros.size(), 700000);
  for (const double z : zeros) ck_assert(z == 0);
}
END_TEST

// An allocator that refuses more than 1000 elements, as memory running out.
template <class T>
struct Refusing {
  using value_type = T;
  Refusing() = default;
  template <class U>
  Refusing(const Refusing<U> &) {}
  T *allocate(std::size_t n) {
    if (n > 1000) throw std::bad_alloc();
    return std::allocator<T>().allocate(n);
  }
  void deallocate(T *p, std::size_t n) { std::allocator<T>().deallocate(p, n); }
  bool operator==(const Refusing &) const { return true; }
  bool operator!=(const Refusing &) const { return false; }
};

START_TEST(reserve_on_huge_pages_changes_nothing_when_it_cannot_allocate) {
  std::vector<uint64_t, Refusing<uint64_t>> v(100, 7);
  const uint64_t *before = v.data();
  bool refused = false;
  try {
    reserve_on_huge_pages(v, 5000);
  } catch (const std::bad_alloc &) {
    refused = true;
  }
  ck_assert(refused);
  ck_assert_ptr_eq(v.data(), before);
  ck_assert_uint_eq(v.size(), 100);
  for (const uint64_t x : v) ck_assert_uint_eq(x, 7);
  reserve_on_huge_pages(v, 900);  // within the limit: moved, kept
  ck_assert_uint_ge(v.capacity(), 900);
  for (const uint64_t x : v) ck_assert_uint_eq(x, 7);
}
END_TEST

int main() {
  return run_suite("storage_growth", 300, [](TCase *tc) {
    tcase_add_loop_test(tc, faces_move_logarithmically_often_in_many_small_calls, 0, 2);
    tcase_add_test(tc, reserve_on_huge_pages_keeps_every_element);
    tcase_add_test(tc, reserve_on_huge_pages_changes_nothing_when_it_cannot_allocate);
  });
}
