// The polygon-surface Delaunay oracle (polygon_brute_force.hpp): against
// libhdt's own triangulation of M_2, the Bolza octagon given as a polygon;
// on other polygons its completeness checks, the orientation of its faces
// and the emptiness of their circles by PolygonKernel (a check of the kernel
// against the oracle too); and its refusal of a point set too sparse or a
// radius too small.
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <tuple>
#include <vector>

#include "domain/polygon_kernel.hpp"
#include "domain/random_octagon.hpp"
#include "domain/representative.hpp"
#include "dummies/dummy_points.hpp"
#include "mesh/triangulation.hpp"
#include "surface/polygon.hpp"

extern "C" {
#include <check.h>
}

#include "polygon_brute_force.hpp"
#include "random.hpp"
#include "run_suite.hpp"
#include "test_polygons.hpp"

using namespace hdt::domain;
using namespace hdt::domain::test;

namespace {

using Point = std::complex<double>;

double distance(Point a, Point b) {
  return std::acosh(1 + 2 * std::norm(a - b) / ((1 - std::norm(a)) * (1 - std::norm(b))));
}

// A face's comparison key: its vertex indices in the rotation whose triple
// is least, and its corners in the lift that puts that rotation's first
// corner at the identity (exactly where the oracle keeps it): the same key
// means the same face, with the same group elements, up to rounding.
using Key = std::tuple<std::array<int, 3>, std::array<double, 6>>;

int least_rotation(const std::array<int, 3> &v) {
  int best = 0;
  for (int r = 1; r < 3; ++r) {
    const std::array<int, 3> a{v[r], v[(r + 1) % 3], v[(r + 2) % 3]}, b{v[best], v[(best + 1) % 3], v[(best + 2) % 3]};
    if (a < b) best = r;
  }
  return best;
}

// v in its least rotation, w the corners with the first at the identity.
Key key(const std::array<int, 3> &v, const std::array<Point, 3> &w) {
  return {v, {w[0].real(), w[0].imag(), w[1].real(), w[1].imag(), w[2].real(), w[2].imag()}};
}

void compare_keys(std::vector<Key> a, std::vector<Key> b) {
  ck_assert_uint_eq(a.size(), b.size());
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  for (std::size_t f = 0; f < a.size(); ++f) {
    ck_assert_msg(std::get<0>(a[f]) == std::get<0>(b[f]), "face %zu: vertices (%d %d %d) and (%d %d %d)", f,
                  std::get<0>(a[f])[0], std::get<0>(a[f])[1], std::get<0>(a[f])[2], std::get<0>(b[f])[0],
                  std::get<0>(b[f])[1], std::get<0>(b[f])[2]);
    for (int s = 0; s < 6; ++s)
      ck_assert_msg(std::abs(std::get<1>(a[f])[s] - std::get<1>(b[f])[s]) < 1e-9, "face %zu coordinate %d: %.17g and %.17g",
                    f, s, std::get<1>(a[f])[s], std::get<1>(b[f])[s]);
  }
}

std::vector<Key> oracle_keys(const OracleResult &R) {
  std::vector<Key> keys;
  for (const OracleFace &f : R.faces) {
    ck_assert_int_eq(least_rotation(f.v), 0);
    keys.push_back(key(f.v, f.w));
  }
  return keys;
}

void print(const char *name, const OracleResult &R, int n) {
  std::printf("%s: n %d, tiles %zu, candidates %zu, lifts %zu, faces %zu, exact signs %zu, area %.15g %s\n", name, n,
              R.tiles.size(), R.candidates, R.lifts, R.faces.size(), R.exact_signs, R.area, R.why.c_str());
}

// The built-in M_2 after inserting z and removing the dummies: its faces'
// keys, vertex ids mapped to the indices of z.
std::vector<Key> built_in_keys(int genus, const std::vector<Point> &z) {
  hdt::mesh::Triangulation t = hdt::dummies::new_triangulation(genus);
  std::vector<double> xy;
  for (const Point &p : z) xy.insert(xy.end(), {p.real(), p.imag()});
  std::vector<uint32_t> ids(z.size());
  t.insert_many(xy.data(), z.size(), ids.data());
  ck_assert_uint_eq(t.remove_dummies(), 0);
  ck_assert_uint_eq(t.vertex_count(), z.size());
  std::vector<int> index(t.vertices().size(), -1);
  for (std::size_t i = 0; i < ids.size(); ++i) index[ids[i]] = int(i);
  std::vector<Key> keys;
  for (const hdt::mesh::Face &f : t.faces()) {
    std::array<int, 3> v;
    for (int c = 0; c < 3; ++c) {
      ck_assert_int_ge(index[f.v[c]], 0);
      v[c] = index[f.v[c]];
    }
    const int first = least_rotation(v);
    const auto back = t.table().inverse(f.t[first]);
    std::array<int, 3> u;
    std::array<Point, 3> w;
    for (int k = 0; k < 3; ++k) {
      const int c = (first + k) % 3;
      const hdt::mesh::Vertex &x = t.vertices()[f.v[c]];
      const auto image = t.table().moebius(t.table().compose(back, f.t[c])).apply({x.x, x.y});
      u[k] = v[c];
      w[k] = {image.re, image.im};
    }
    keys.push_back(key(u, w));
  }
  return keys;
}

// Each face counterclockwise for the kernel, and its circle empty of the
// images the kernel is shown: every tile's images of the face's own
// vertices and of a sample of the others, all those within 3r of a corner.
void check_with_kernel(const FundamentalPolygon &P, OracleResult &R, const std::vector<Point> &z, double r) {
  FieldLock lock(P.field() != nullptr);
  PolygonKernel K(P, *R.table);
  // Every tile's images in double, from its canonical matrix: a filter only.
  std::vector<std::vector<Point>> image(R.tiles.size());
  for (std::size_t u = 0; u < R.tiles.size(); ++u) {
    const Moebius &m = R.table->element(R.tiles[u]).matrix();
    auto d = [](const Complex &e) { return Point(static_cast<double>(e.re), static_cast<double>(e.im)); };
    for (const Point &p : z) image[u].push_back((d(m.a) * p + d(m.b)) / (d(m.c) * p + d(m.d)));
  }
  std::size_t tested = 0;
  for (const OracleFace &f : R.faces) {
    std::array<PolygonPoint, 3> c;
    for (int k = 0; k < 3; ++k) c[k] = {z[std::size_t(f.v[k])].real(), z[std::size_t(f.v[k])].imag(), f.t[k]};
    ck_assert_int_eq(K.orientation(c[0], c[1], c[2]), 1);
    for (std::size_t j = 0; j < z.size(); ++j) {
      const bool own = int(j) == f.v[0] || int(j) == f.v[1] || int(j) == f.v[2];
      if (!own && j % 4 != 0) continue;
      for (std::size_t u = 0; u < R.tiles.size(); ++u) {
        const ElementId h = R.tiles[u];
        bool corner = false;
        for (int k = 0; k < 3; ++k) corner |= int(j) == f.v[k] && h == f.t[k];
        if (corner || distance(image[u][j], f.w[0]) > 3 * r) continue;
        ck_assert_int_eq(K.in_circle(c[0], c[1], c[2], {z[j].real(), z[j].imag(), h}), -1);
        ++tested;
      }
    }
  }
  std::printf("kernel: %zu in_circle tests on %zu faces\n", tested, R.faces.size());
  ck_assert_uint_gt(tested, 10 * R.faces.size());
}

void check_polygon(const FundamentalPolygon &P, const char *name, int n, double reach, double r, uint64_t seed) {
  const std::vector<Point> z = fundamental_set_points(P, n, reach, seed);
  OracleResult R = polygon_delaunay(P, z, r);
  print(name, R, n);
  ck_assert_msg(R.status == OracleStatus::complete, "%s: %s", name, R.why.c_str());
  ck_assert_uint_eq(R.faces.size(), std::size_t(2 * n + 4 * (P.genus() - 1)));
  check_with_kernel(P, R, z, r);
}

}  // namespace

// The built-in F_g has v_k at angle (2k+1) pi/4g, radius sqrt(cos(pi/2g)):
// at genus 2 the vertices of test_polygons.hpp's Bolza octagon, at genus 3
// those of its regular 12-gon, no rotation; its side s_k (v_{k-1} to v_k)
// is the polygon's side k - 1, and its generator g_k (s_{k+2g} onto s_k)
// the polygon's pairing(k - 1): the same group, compared as canonical
// matrices [[1, b], [c, d]].
void check_built_in_vertices(const FundamentalPolygon &P, int genus) {
  hdt::mesh::Triangulation t = hdt::dummies::new_triangulation(genus);
  FieldLock lock(true);
  auto d = [](const Complex &e) { return Point(static_cast<double>(e.re), static_cast<double>(e.im)); };
  const int n = 4 * genus;
  for (int k = 0; k < n; ++k) {
    const auto v = hdt::surface::vertex(t.surface().presentation(), k);
    ck_assert(std::abs(P.vertex_double(k) - Point(v.re, v.im)) < 1e-15);
    const auto &g = t.table().moebius(t.table().intern(hdt::group::Word{k}));
    const Point a(g.a.re, g.a.im), b(g.b.re, g.b.im);
    const Element e(P.pairing((k + n - 1) % n));
    const Moebius &m = e.matrix();
    ck_assert(std::abs(d(m.b) - b / a) < 1e-12 && std::abs(d(m.c) - std::conj(b) / a) < 1e-12 &&
              std::abs(d(m.d) - std::conj(a) / a) < 1e-12);
  }
}

START_TEST(bolza_vertices_are_the_built_in_ones) { check_built_in_vertices(bolza(), 2); }
END_TEST

START_TEST(bolza_polygon_equals_the_built_in_m2) {
  const FundamentalPolygon P = bolza();
  std::size_t faces = 0;
  for (const auto &[n, seed] : {std::pair<int, uint64_t>{40, 1}, {60, 2}, {80, 3}}) {
    const std::vector<Point> z = fundamental_set_points(P, n, 0.85, seed);
    const OracleResult R = polygon_delaunay(P, z, 1.0);
    print("bolza vs M_2", R, n);
    ck_assert_msg(R.status == OracleStatus::complete, "%s", R.why.c_str());
    compare_keys(built_in_keys(2, z), oracle_keys(R));
    faces += R.faces.size();
  }
  std::printf("bolza vs M_2: %zu faces equal\n", faces);
}
END_TEST

START_TEST(commutator_bolza) { check_polygon(bolza("2 3 0 1 6 7 4 5"), "commutator bolza", 50, 0.85, 1.0, 4); }
END_TEST

START_TEST(random_rational_octagon) {
  const CompactOctagon O = compact_random_octagon();
  std::printf("random octagon: seed %llu, vertex radius %.3f\n", (unsigned long long)O.seed, O.reach);
  check_polygon(O.polygon, "random octagon", 50, O.reach, 1.0, 5);
}
END_TEST

START_TEST(regular_12_gon_of_genus_3) { check_polygon(FundamentalPolygon(genus_3_12_gon()), "12-gon", 60, 0.94, 1.2, 6); }
END_TEST

// M_3 as a polygon: the regular 12-gon's vertices and pairings are the
// built-in F_3's, and the oracle's faces the built-in triangulation's.
START_TEST(regular_12_gon_equals_the_built_in_m3) {
  const FundamentalPolygon P(genus_3_12_gon());
  check_built_in_vertices(P, 3);
  // Uniform points of the disk are sparse, hyperbolically, in the corners,
  // where the built-in vertex site v_0 stays unless points come near it.
  std::vector<Point> z = fundamental_set_points(P, 100, 0.94, 11);
  for (const Point &c : near_vertex_points(P, 12)) z.push_back(c);
  const OracleResult R = polygon_delaunay(P, z, 1.2);
  print("12-gon vs M_3", R, int(z.size()));
  ck_assert_msg(R.status == OracleStatus::complete, "%s", R.why.c_str());
  compare_keys(built_in_keys(3, z), oracle_keys(R));
}
END_TEST

// Four points on one circle about 0 and none inside it: the circle of
// three of them is empty but for the fourth on it, which only the exact
// stage can tell (the balls of exact doubles hold 0 exactly).
START_TEST(cocircular_points_are_degenerate) {
  const FundamentalPolygon P = bolza();
  std::vector<Point> z{{0.25, 0}, {0, 0.25}, {-0.25, 0}, {0, -0.25}};
  for (const Point &p : fundamental_set_points(P, 120, 0.85, 9))
    if (std::abs(p) > 0.35 && z.size() < 50) z.push_back(p);
  const OracleResult R = polygon_delaunay(P, z, 1.0);
  print("cocircular", R, int(z.size()));
  ck_assert(R.status == OracleStatus::degenerate);
  ck_assert_uint_eq(R.faces.size(), 0);
  ck_assert_uint_gt(R.exact_signs, 0);
}
END_TEST

// Every sign exact: the same faces as the staged run, on a rational
// octagon (the seed random_rational_octagon finds) and on the Bolza
// octagon's field.
START_TEST(exact_signs_give_the_same_faces) {
  for (const FundamentalPolygon &P : {random_octagon(153), bolza()}) {
    const std::vector<Point> z = fundamental_set_points(P, 40, 0.87, 10);
    const OracleResult staged = polygon_delaunay(P, z, 1.0), exact = polygon_delaunay(P, z, 1.0, true);
    print("staged", staged, 40);
    print("exact", exact, 40);
    ck_assert(staged.status == OracleStatus::complete && exact.status == OracleStatus::complete);
    ck_assert_uint_gt(exact.exact_signs, exact.candidates);
    compare_keys(oracle_keys(staged), oracle_keys(exact));
  }
}
END_TEST

// Three points on M_2 have no Delaunay faces of circumradius <= 1; 60 points
// have faces larger than 0.2: both are failures, with no faces.
START_TEST(too_sparse_or_too_small_fails) {
  const FundamentalPolygon P = bolza();
  const OracleResult sparse = polygon_delaunay(P, fundamental_set_points(P, 3, 0.85, 7), 1.0);
  print("sparse", sparse, 3);
  ck_assert(sparse.status == OracleStatus::incomplete);
  ck_assert_uint_eq(sparse.faces.size(), 0);
  const OracleResult small = polygon_delaunay(P, fundamental_set_points(P, 60, 0.85, 8), 0.2);
  print("small r", small, 60);
  ck_assert(small.status == OracleStatus::incomplete);
  ck_assert_uint_eq(small.faces.size(), 0);
}
END_TEST

int main() {
  return run_suite("polygon_brute_force", 300, [](TCase *tc) {
    tcase_add_test(tc, bolza_vertices_are_the_built_in_ones);
    tcase_add_test(tc, bolza_polygon_equals_the_built_in_m2);
    tcase_add_test(tc, commutator_bolza);
    tcase_add_test(tc, random_rational_octagon);
    tcase_add_test(tc, regular_12_gon_of_genus_3);
    tcase_add_test(tc, regular_12_gon_equals_the_built_in_m3);
    tcase_add_test(tc, too_sparse_or_too_small_fails);
    tcase_add_test(tc, cocircular_points_are_degenerate);
    tcase_add_test(tc, exact_signs_give_the_same_faces);
  });
}
