// The mesh's algorithms on a polygon surface (mesh/polygon_triangulation.hpp):
// a triangulation assembled from the brute-force oracle's faces
// (polygon_brute_force.hpp, which shares no predicate with the polygon
// kernel) must validate; after Bowyer-Watson insertions, one at a time and
// in a batch, its faces must be the oracle's on all the points, vertex for
// vertex and element for element. Points given outside the polygon must be
// reduced and inserted into a valid triangulation too, and located in a
// face copy that holds them.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "domain/field_lock.hpp"
#include "domain/random_octagon.hpp"
#include "domain/systole.hpp"
#include "dummies/dummy_points.hpp"
#include "mesh/assemble.hpp"
#include "mesh/polygon_triangulation.hpp"

extern "C" {
#include <check.h>
}

#include "polygon_brute_force.hpp"
#include "run_suite.hpp"
#include "test_polygons.hpp"

using namespace hdt::domain;
using namespace hdt::domain::test;
using hdt::mesh::PolygonGeometry;
using hdt::mesh::PolygonTriangulation;
using hdt::mesh::TranslationId;

namespace {

using Point = std::complex<double>;
// A face: its vertices (point indices) in the rotation whose triple is least,
// and the elements of its second and third corners relative to the first.
using Key = std::tuple<std::array<int, 3>, TranslationId, TranslationId>;

int least_rotation(const std::array<int, 3> &v) {
  int best = 0;
  for (int r = 1; r < 3; ++r)
    if (std::array<int, 3>{v[r], v[(r + 1) % 3], v[(r + 2) % 3]} <
        std::array<int, 3>{v[best], v[(best + 1) % 3], v[(best + 2) % 3]})
      best = r;
  return best;
}

// The oracle's faces with their elements interned in the mesh's table.
std::vector<Key> oracle_keys(const OracleResult &R, PolygonTriangulation &t) {
  std::vector<Key> keys;
  auto id = [&](ElementId e) { return TranslationId(t.surface().table().intern(R.table->element(e))); };
  for (const OracleFace &f : R.faces) {
    ck_assert_int_eq(least_rotation(f.v), 0);
    keys.emplace_back(f.v, id(f.t[1]), id(f.t[2]));
  }
  return keys;
}

// The mesh's faces, vertex ids mapped to point indices by index.
std::vector<Key> mesh_keys(PolygonTriangulation &t, const std::vector<int> &index) {
  std::vector<Key> keys;
  auto &T = t.table();
  for (const hdt::mesh::Face &f : t.faces()) {
    std::array<int, 3> v;
    for (int c = 0; c < 3; ++c) v[c] = index.at(f.v[c]);
    const int r = least_rotation(v);
    const TranslationId back = T.inverse(f.t[r]);
    keys.emplace_back(std::array<int, 3>{v[r], v[(r + 1) % 3], v[(r + 2) % 3]}, T.compose(back, f.t[(r + 1) % 3]),
                      T.compose(back, f.t[(r + 2) % 3]));
  }
  return keys;
}

void compare(std::vector<Key> a, std::vector<Key> b, const char *name) {
  ck_assert_msg(a.size() == b.size(), "%s: %zu faces, the oracle %zu", name, a.size(), b.size());
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  for (std::size_t f = 0; f < a.size(); ++f) {
    const auto &v = std::get<0>(a[f]), &w = std::get<0>(b[f]);
    ck_assert_msg(a[f] == b[f], "%s: face %zu: (%d %d %d | %d %d), the oracle (%d %d %d | %d %d)", name, f, v[0], v[1],
                  v[2], std::get<1>(a[f]), std::get<2>(a[f]), w[0], w[1], w[2], std::get<1>(b[f]), std::get<2>(b[f]));
  }
}

// The triangulation of z from the oracle's faces, vertex i is z[i]; nothing
// when the oracle cannot finish at radius r or a face has circumdiameter
// sys/2 or more (the mesh's invariant, which the dummy points will give).
std::optional<PolygonTriangulation> from_oracle(const FundamentalPolygon &P, const std::vector<Point> &z, double r) {
  const OracleResult R = polygon_delaunay(P, z, r);
  if (R.status != OracleStatus::complete) return std::nullopt;
  auto geometry = std::make_unique<PolygonGeometry>(P);
  ElementTable &table = geometry->surface().table();
  std::vector<hdt::mesh::Vertex> vertices;
  for (const Point &p : z) vertices.push_back({p.real(), p.imag(), 0, hdt::mesh::kNone});
  std::vector<hdt::mesh::CornerFace> given;
  for (const OracleFace &f : R.faces) {
    hdt::mesh::CornerFace c;
    for (int k = 0; k < 3; ++k)
      c.v[k] = uint32_t(f.v[k]), c.t[k] = TranslationId(table.intern(R.table->element(f.t[k])));
    given.push_back(c);
  }
  std::vector<hdt::mesh::Face> faces = hdt::mesh::assemble_faces(&vertices, given, geometry->table());
  std::vector<bool> dummy(z.size(), false);
  PolygonTriangulation t(std::move(geometry), std::move(vertices), std::move(dummy), std::move(faces));
  try {
    t.validate();
  } catch (const std::logic_error &e) {
    if (std::string(e.what()).find("circumdiameter") == std::string::npos) throw;
    return std::nullopt;
  }
  return t;
}

// A quarter of the systole, rounded up: the largest circumradius the mesh
// allows, so the oracle's search radius.
double quarter_systole(const FundamentalPolygon &P) { return systole(P).length.hi / 4 * (1 + 1e-9); }

// n0 points from the oracle (more while they leave a circle of diameter
// sys/2 or more), then n1 more inserted (half one by one, half in one
// batch), against the oracle on all of them.
void check_insertion(const FundamentalPolygon &P, const char *name, int n0, int n1, double reach, uint64_t seed) {
  const FieldLock lock(P.field() != nullptr);
  const double r = quarter_systole(P);
  std::vector<Point> z;
  std::optional<PolygonTriangulation> start;
  for (;; n0 += 30) {
    ck_assert_int_lt(n0, 400);
    z = fundamental_set_points(P, n0 + n1, reach, seed);
    if ((start = from_oracle(P, {z.begin(), z.begin() + n0}, r))) break;
  }
  PolygonTriangulation &t = *start;
  std::vector<int> index(static_cast<std::size_t>(n0));
  for (int i = 0; i < n0; ++i) index[std::size_t(i)] = i;
  const int single = n1 / 2;
  for (int i = n0; i < n0 + single; ++i) {
    const auto inserted = t.insert(z[std::size_t(i)].real(), z[std::size_t(i)].imag());
    ck_assert(!inserted.existed);
    ck_assert_uint_eq(inserted.vertex, index.size());
    index.push_back(i);
  }
  std::vector<double> xy;
  for (int i = n0 + single; i < n0 + n1; ++i) xy.insert(xy.end(), {z[std::size_t(i)].real(), z[std::size_t(i)].imag()});
  std::vector<uint32_t> ids(std::size_t(n1 - single));
  t.insert_many(xy.data(), ids.size(), ids.data());
  index.resize(t.vertices().size(), -1);
  for (std::size_t k = 0; k < ids.size(); ++k) index.at(ids[k]) = n0 + single + int(k);
  t.validate();
  ck_assert_uint_eq(t.vertex_count(), std::size_t(n0 + n1));
  const OracleResult R = polygon_delaunay(P, z, r);
  ck_assert_msg(R.status == OracleStatus::complete, "%s: oracle: %s", name, R.why.c_str());
  compare(mesh_keys(t, index), oracle_keys(R, t), name);
  std::printf("%s: %d + %d points, %zu faces as the oracle's, %zu elements\n", name, n0, n1, t.faces().size(),
              t.surface().table().size());
}

// A face's hyperbolic area, pi minus its angles, from its corners in double.
double face_area(PolygonTriangulation &t, const hdt::mesh::Face &F) {
  std::array<Point, 3> w;
  for (int i = 0; i < 3; ++i) {
    const hdt::mesh::Vertex &u = t.vertices()[F.v[i]];
    const auto z = t.geometry().image(u.x, u.y, F.t[i]);
    w[std::size_t(i)] = {z.re, z.im};
  }
  double angles = 0;
  for (int i = 0; i < 3; ++i) {
    // The angle at w_i between the geodesics to the other two: move w_i to
    // 0 (z -> (z - w) / (1 - conj(w) z)), where geodesics are diameters.
    const Point a = w[std::size_t(i)], b = w[std::size_t((i + 1) % 3)], c = w[std::size_t((i + 2) % 3)];
    const Point bb = (b - a) / (1.0 - std::conj(a) * b), cc = (c - a) / (1.0 - std::conj(a) * c);
    angles += std::abs(std::arg(cc / bb));
  }
  return M_PI - angles;
}

// The paper's Algorithm 1 on a polygon surface (dummies/dummy_points.hpp):
// certified inside by validate(); here again, with Euler's formula, the
// faces' areas summing to the surface's 4 pi (g - 1) (each face counted
// once, none missing: an independent check of the winding), and points
// inserted on top of the dummies into a valid triangulation.
void check_dummies(const FundamentalPolygon &P, const char *name) {
  const FieldLock lock(P.field() != nullptr);
  const auto t0 = std::chrono::steady_clock::now();
  PolygonTriangulation t = hdt::dummies::new_polygon_triangulation(P);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  t.validate();
  const std::size_t V = t.vertex_count();
  ck_assert_uint_eq(V, t.dummy_count());
  ck_assert_uint_eq(t.faces().size(), 2 * V + 4 * std::size_t(P.genus() - 1));
  double area = 0;
  for (const hdt::mesh::Face &F : t.faces()) area += face_area(t, F);
  const double expected = 4 * M_PI * (P.genus() - 1);
  ck_assert_msg(std::abs(area - expected) < 1e-9 * expected, "%s: area %.15g, 4 pi (g - 1) = %.15g", name, area,
                expected);
  std::printf("%s: genus %d, systole %.4f, %zu dummy points in %.3f s, %zu faces\n", name, P.genus(),
              t.surface().systole().length.lo, V, seconds, t.faces().size());
  uint64_t s = 29;
  std::vector<double> xy;
  for (int i = 0; i < 300; ++i) {
    const double rho = 0.99 * std::sqrt(uniform01(&s)), a = 2 * M_PI * uniform01(&s);
    xy.insert(xy.end(), {rho * std::cos(a), rho * std::sin(a)});
  }
  t.insert_many(xy.data(), 300, nullptr);
  t.validate();
  ck_assert_uint_eq(t.vertex_count(), V + 300);
}

// Dummies first, then n points of the fundamental set inserted; every dummy
// removed (remove_dummies) and then every seventh point: the faces must be
// the oracle's on the points left, which for the Bolza octagon are the
// built-in M_2's (test_polygon_brute_force).
void check_removal(const FundamentalPolygon &P, const char *name, int n, double reach, uint64_t seed,
                   bool corners = false) {
  const FieldLock lock(P.field() != nullptr);
  PolygonTriangulation t = hdt::dummies::new_polygon_triangulation(P);
  std::vector<Point> z = fundamental_set_points(P, n, reach, seed);
  if (corners)
    for (const Point &c : near_vertex_points(P, seed)) z.push_back(c);
  std::vector<double> xy;
  for (const Point &p : z) xy.insert(xy.end(), {p.real(), p.imag()});
  std::vector<uint32_t> ids(z.size());
  t.insert_many(xy.data(), z.size(), ids.data());
  ck_assert_msg(t.remove_dummies() == 0, "%s: %zu dummies stay", name, t.dummy_count());
  std::vector<Point> kept;
  std::vector<int> index(t.vertices().size(), -1);
  std::size_t removed = 0;
  for (std::size_t i = 0; i < z.size(); ++i) {
    if (i % 7 == 3 && t.remove(ids[i])) {
      ++removed;
      continue;
    }
    index[ids[i]] = int(kept.size());
    kept.push_back(z[i]);
  }
  t.validate();
  ck_assert_uint_gt(removed, z.size() / 10);
  const OracleResult R = polygon_delaunay(P, kept, quarter_systole(P));
  ck_assert_msg(R.status == OracleStatus::complete, "%s: oracle: %s", name, R.why.c_str());
  compare(mesh_keys(t, index), oracle_keys(R, t), name);
  std::printf("%s: dummies and %zu points removed, %zu faces as the oracle's on %zu points\n", name, removed,
              t.faces().size(), kept.size());
}

}  // namespace

START_TEST(dummy_points_on_polygons) {
  check_dummies(bolza(), "bolza");
  check_dummies(bolza("2 3 0 1 6 7 4 5"), "commutator bolza");
  for (uint64_t seed = 1; seed <= 3; ++seed) check_dummies(random_octagon(seed), "random octagon");
  check_dummies(random_symmetric_polygon(5, 4), "decagon, two cycles");
  check_dummies(FundamentalPolygon(genus_3_commutator_12_gon()), "commutator 12-gon");
}
END_TEST

START_TEST(removals) {
  check_removal(bolza(), "bolza", 80, 0.85, 6);
  check_removal(bolza("2 3 0 1 6 7 4 5"), "commutator bolza", 150, 0.85, 7);
  const CompactOctagon O = compact_random_octagon();
  check_removal(O.polygon, "random octagon", 220, O.reach, 8);
  // M_3 as a polygon (test_polygon_brute_force: its oracle's faces are the
  // built-in M_3's).
  check_removal(FundamentalPolygon(genus_3_12_gon()), "regular 12-gon", 100, 0.94, 11, true);
}
END_TEST

START_TEST(bolza_octagon) { check_insertion(bolza(), "bolza", 60, 40, 0.85, 3); }
END_TEST

START_TEST(commutator_bolza) { check_insertion(bolza("2 3 0 1 6 7 4 5"), "commutator bolza", 120, 40, 0.85, 4); }
END_TEST

START_TEST(random_rational_octagon) {
  const CompactOctagon O = compact_random_octagon();
  check_insertion(O.polygon, "random octagon", 190, 40, O.reach, 5);
}
END_TEST

// A polygon with two vertex cycles (five vertices each): CGAL's decagon.
START_TEST(random_decagon) {
  const CompactOctagon O = compact_random_octagon(0.9, 5);
  check_insertion(O.polygon, "random decagon, two cycles", 150, 40, O.reach, 9);
}
END_TEST

// Points anywhere in the disk, most outside P: reduced to their homes,
// inserted, each then located in a face copy that holds it (no corner on
// the wrong side of an edge) and found as a vertex by nearest_vertex.
START_TEST(points_outside_the_polygon) {
  const FundamentalPolygon P = bolza();
  const FieldLock lock(true);
  std::optional<PolygonTriangulation> start = from_oracle(P, fundamental_set_points(P, 60, 0.85, 3), quarter_systole(P));
  ck_assert(start);
  PolygonTriangulation &t = *start;
  uint64_t s = 11;
  std::vector<double> xy;
  for (int i = 0; i < 60; ++i) {
    const double rho = 0.98 * std::sqrt(uniform01(&s)), a = 2 * M_PI * uniform01(&s);
    xy.insert(xy.end(), {rho * std::cos(a), rho * std::sin(a)});
  }
  std::vector<uint32_t> ids(30);
  for (int i = 0; i < 30; ++i) ids[std::size_t(i)] = t.insert(xy[std::size_t(2 * i)], xy[std::size_t(2 * i + 1)]).vertex;
  std::vector<uint32_t> batch(30);
  t.insert_many(xy.data() + 60, 30, batch.data());
  ids.insert(ids.end(), batch.begin(), batch.end());
  t.validate();
  ck_assert_uint_eq(t.vertex_count(), 120);
  std::size_t away = 0;
  for (int i = 0; i < 60; ++i) {
    const double x = xy[std::size_t(2 * i)], y = xy[std::size_t(2 * i + 1)];
    away += t.vertices()[ids[std::size_t(i)]].home != 0;
    ck_assert_uint_eq(t.nearest_vertex(x, y), ids[std::size_t(i)]);
    const auto at = t.locate(x, y);
    const hdt::mesh::Face &F = t.faces()[at.face];
    const hdt::mesh::TranslatedPoint q{x, y, t.table().inverse(at.translation), -1};
    for (int e = 0; e < 3; ++e)
      ck_assert_int_ge(t.kernel().orientation(t.corner(F, (e + 1) % 3), t.corner(F, (e + 2) % 3), q), 0);
  }
  ck_assert_uint_gt(away, 20);
}
END_TEST

int main() {
  return run_suite("polygon_mesh", 300, [](TCase *tc) {
    tcase_add_test(tc, bolza_octagon);
    tcase_add_test(tc, commutator_bolza);
    tcase_add_test(tc, random_decagon);
    tcase_add_test(tc, random_rational_octagon);
    tcase_add_test(tc, points_outside_the_polygon);
    tcase_add_test(tc, dummy_points_on_polygons);
    tcase_add_test(tc, removals);
  });
}
