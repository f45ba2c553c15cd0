// Triangulation::insert_in_circle, the refinement's insertion with no walk:
// the same triangulation as the ordinary insert() of the same point (the
// Delaunay triangulation of a point set is unique under the kernel's
// perturbation) when the point is inside the given face's circle (the
// cavity grows from that face), nothing changed when it is not; and the
// faces it reports created are exactly the new vertex's star.
#include <algorithm>
#include <random>
#include <set>
#include <vector>

#include "dual/adjacency.hpp"
#include "dual/constructions.hpp"
#include "mesh/triangulation.hpp"

#include <check.h>

#include "dummies/dummy_points.hpp"
#include "run_suite.hpp"

using namespace hdt::mesh;
using namespace hdt::dual;

namespace {

// Random points of the disk of Euclidean radius 0.6 (all inside the
// Dirichlet domains of the genera tested, none near the unit circle).
void fill(Triangulation &a, Triangulation &b, int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-0.6, 0.6);
  for (int k = 0; k < n;) {
    const double x = u(rng), y = u(rng);
    if (x * x + y * y >= 0.36) continue;
    a.insert(x, y), b.insert(x, y), ++k;
  }
}

std::multiset<std::vector<uint32_t>> vertex_sets(const Triangulation &t) {
  std::multiset<std::vector<uint32_t>> out;
  for (const Face &f : t.faces()) {
    std::vector<uint32_t> v(f.v.begin(), f.v.end());
    std::sort(v.begin(), v.end());
    out.insert(v);
  }
  return out;
}

// Inserts p (in face f's canonical frame) with insert_in_circle into a and
// with insert into b, and compares.
void insert_both(Triangulation &a, Triangulation &b, uint32_t f, const Point &p) {
  std::vector<uint32_t> created;
  const Triangulation::Inserted in = a.insert_in_circle(p.re, p.im, f, &created);
  const Triangulation::Inserted ref = b.insert(p.re, p.im);
  ck_assert_uint_eq(in.vertex, ref.vertex);
  ck_assert(in.existed == ref.existed);
  a.validate();
  ck_assert(vertex_sets(a) == vertex_sets(b));
  std::vector<StarEntry> star;
  vertex_star(a, in.vertex, &star);
  std::vector<uint32_t> expected;
  for (const StarEntry &s : star) expected.push_back(s.face);
  std::sort(expected.begin(), expected.end());
  std::sort(created.begin(), created.end());
  ck_assert(created == expected);
}

}  // namespace

START_TEST(circumcentre_inserted_from_its_face_as_by_insert) {
  const int genus = _i == 0 ? 2 : 3;
  Triangulation a = hdt::dummies::new_triangulation(genus), b = hdt::dummies::new_triangulation(genus);
  fill(a, b, 60, 7 + unsigned(_i));
  std::mt19937_64 rng(11);
  for (int k = 0; k < 200; ++k) {
    const auto f = uint32_t(rng() % a.faces().size());
    const Face &F = a.faces()[f];
    const Point p[3] = {face_corner(a, F, 0), face_corner(a, F, 1), face_corner(a, F, 2)};
    const Circle c = circumcircle(a, F, p);
    insert_both(a, b, f, c.centre);
  }
}
END_TEST

// A point on or outside the face's circle is refused with nothing changed
// (refinement then leaves the face); one inside is inserted as by insert().
START_TEST(point_outside_the_circle_is_refused) {
  Triangulation a = hdt::dummies::new_triangulation(2), b = hdt::dummies::new_triangulation(2);
  fill(a, b, 60, 5);
  std::mt19937_64 rng(13);
  int outside = 0, inside = 0;
  for (int k = 0; k < 100; ++k) {
    // Another face's circumcentre, given for face f: in general outside f's circle.
    const auto f = uint32_t(rng() % a.faces().size()), g = uint32_t(rng() % a.faces().size());
    const Face &G = a.faces()[g];
    const Point p[3] = {face_corner(a, G, 0), face_corner(a, G, 1), face_corner(a, G, 2)};
    const Circle cg = circumcircle(a, G, p);
    const Face &F = a.faces()[f];
    const Point q[3] = {face_corner(a, F, 0), face_corner(a, F, 1), face_corner(a, F, 2)};
    const Circle cf = circumcircle(a, F, q);
    if (distance(cf.centre, cg.centre) > 2 * cf.radius) {
      ++outside;
      const std::size_t faces = a.faces().size(), vertices = a.vertices().size();
      std::vector<uint32_t> created{7};
      const Triangulation::Inserted in = a.insert_in_circle(cg.centre.re, cg.centre.im, f, &created);
      ck_assert_uint_eq(in.vertex, kNone);
      ck_assert(created.empty());
      ck_assert_uint_eq(a.faces().size(), faces);
      ck_assert_uint_eq(a.vertices().size(), vertices);
      ck_assert(vertex_sets(a) == vertex_sets(b));
    } else if (distance(cf.centre, cg.centre) < 0.5 * cf.radius) {
      ++inside;
      insert_both(a, b, f, cg.centre);
    }
  }
  ck_assert_int_gt(outside, 50);  // refused, many times
  a.validate();
}
END_TEST

START_TEST(unknown_face_is_refused) {
  Triangulation t = hdt::dummies::new_triangulation(2);
  std::vector<uint32_t> created;
  const std::size_t faces = t.faces().size();
  bool thrown = false;
  try {
    t.insert_in_circle(0.1, 0.1, uint32_t(faces), &created);
  } catch (const std::invalid_argument &) {
    thrown = true;
  }
  ck_assert(thrown);
  ck_assert_uint_eq(t.faces().size(), faces);
}
END_TEST

int main(void) {
  return run_suite("insert_in_circle", 300, [](TCase *tc) {
    tcase_add_loop_test(tc, circumcentre_inserted_from_its_face_as_by_insert, 0, 2);
    tcase_add_test(tc, point_outside_the_circle_is_refused);
    tcase_add_test(tc, unknown_face_is_refused);
  });
}
