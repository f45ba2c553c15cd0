// AllStars, the rows behind hdt_vertex_stars and hdt_voronoi_cells, below
// the C API: its 64-bit path (taken by itself only from F >= 2^29, 24 GB of
// faces) forced on small triangulations, each row against vertex_star's
// walk and the 32-bit path byte for byte; and a broken star found by
// build(), before anything is written.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <stdexcept>
#include <vector>

#include "dual/adjacency.hpp"
#include "dual/all_stars.hpp"
#include "dual/constructions.hpp"
#include "mesh/triangulation.hpp"

#include <check.h>

#include "dummies/dummy_points.hpp"
#include "run_suite.hpp"

using namespace hdt::mesh;
using namespace hdt::dual;

namespace {

// n random points of the disk of Euclidean radius r (beyond F_g for r
// near 1: vertices whose homes are not the identity), then every third
// one removed (gaps in the ids).
void fill(Triangulation &t, int n, double r, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-r, r);
  std::vector<uint32_t> ids;
  for (int k = 0; k < n;) {
    const double x = u(rng), y = u(rng);
    if (x * x + y * y >= r * r) continue;
    ids.push_back(t.insert(x, y).vertex), ++k;
  }
  for (std::size_t k = 0; k < ids.size(); k += 3) t.remove(ids[k]);
  t.validate();
}

struct Out {
  std::vector<std::size_t> offsets;
  std::vector<uint32_t> faces;
  std::vector<uint8_t> corners;
  std::vector<int32_t> translations;
  std::vector<double> xy;
};

Out rows_of(const Triangulation &t, bool wide) {
  AllStars rows;
  rows.build(t, true, wide);
  const std::size_t n = rows.entries();
  ck_assert_uint_eq(n, 3 * t.faces().size());
  Out o{std::vector<std::size_t>(t.vertices().size() + 1), std::vector<uint32_t>(n), std::vector<uint8_t>(n),
        std::vector<int32_t>(n), std::vector<double>(2 * n)};
  rows.write(t, o.offsets.data(), o.faces.data(), o.corners.data(), o.translations.data());
  std::vector<Point> centre(t.faces().size());
  face_centres(t, centre.data(), nullptr);
  std::vector<std::size_t> again(o.offsets.size());
  rows.write_cells(t, again.data(), o.xy.data(), centre.data());
  ck_assert(again == o.offsets);
  return o;
}

// Every row against the walk, and the cells' corners against the centres
// mapped by the walk's translations.
void check_against_walks(const Triangulation &t, const Out &o) {
  std::vector<Point> centre(t.faces().size());
  face_centres(t, centre.data(), nullptr);
  std::vector<StarEntry> star;
  std::size_t at = 0;
  for (uint32_t v = 0; v < t.vertices().size(); ++v) {
    ck_assert_uint_eq(o.offsets[v], at);
    if (!t.vertices()[v].alive()) continue;
    vertex_star(t, v, &star);
    for (const StarEntry &s : star) {
      ck_assert_uint_eq(o.faces[at], s.face);
      ck_assert_int_eq(o.corners[at], s.corner);
      ck_assert_int_eq(o.translations[at], s.translation);
      const Point p = translate(t, s.translation, centre[s.face]);
      ck_assert(std::memcmp(&o.xy[2 * at], &p.re, sizeof p.re) == 0);
      ck_assert(std::memcmp(&o.xy[2 * at + 1], &p.im, sizeof p.im) == 0);
      ++at;
    }
  }
  ck_assert_uint_eq(o.offsets.back(), at);
  ck_assert_uint_eq(at, 3 * t.faces().size());
}

void check_both_paths(const Triangulation &t) {
  const Out narrow = rows_of(t, false), wide = rows_of(t, true);
  check_against_walks(t, wide);
  check_against_walks(t, narrow);
  ck_assert(wide.offsets == narrow.offsets && wide.faces == narrow.faces && wide.corners == narrow.corners &&
            wide.translations == narrow.translations);
  ck_assert(std::memcmp(wide.xy.data(), narrow.xy.data(), wide.xy.size() * sizeof(double)) == 0);
}

std::size_t longest_row(const Triangulation &t) {
  std::vector<std::size_t> degree(t.vertices().size());
  for (const Face &f : t.faces())
    for (uint32_t v : f.v) ++degree[v];
  std::size_t d = 0;
  for (std::size_t x : degree) d = std::max(d, x);
  return d;
}

// Whether some live vertex has exactly d faces.
bool has_degree(const Triangulation &t, std::size_t d) {
  std::vector<std::size_t> degree(t.vertices().size());
  for (const Face &f : t.faces())
    for (uint32_t v : f.v) ++degree[v];
  return std::find(degree.begin(), degree.end(), d) != degree.end();
}

START_TEST(wide_rows_genus_2) {
  // The dummy points alone, then the origin and 40 points on a circle
  // about it (a row of 16 entries and more takes another path), then
  // random points.
  Triangulation t = hdt::dummies::new_triangulation(2);
  check_both_paths(t);
  t.insert(0, 0);
  for (int k = 0; k < 40; ++k) t.insert(0.1 * std::cos(k * M_PI / 20), 0.1 * std::sin(k * M_PI / 20));
  ck_assert_uint_ge(longest_row(t), 40);
  check_both_paths(t);
  fill(t, 600, 0.6, 1);
  // Rows that fill the 8 slots a vertex has, and rows one longer (the
  // first entry in the overflow list), among the rows compared.
  ck_assert(has_degree(t, 8) && has_degree(t, 9));
  check_both_paths(t);
}
END_TEST

START_TEST(wide_rows_spread) {
  for (int genus : {2, 3}) {
    Triangulation t = hdt::dummies::new_triangulation(genus);
    fill(t, 500, 0.97, 7 + genus);
    t.remove_dummies();
    check_both_paths(t);
  }
}
END_TEST

// Whether AllStars::build finds the broken invariant (std::logic_error).
bool build_throws(const Triangulation &t, bool wide) {
  AllStars rows;
  try {
    rows.build(t, false, wide);
  } catch (const std::logic_error &) {
    return true;
  }
  return false;
}

// A face whose link to its next face about a vertex is wrong: build()
// throws, on either path (before, the error came from the writing, with
// the rows before it written).
START_TEST(broken_star_found_before_writing) {
  for (bool wide : {false, true}) {
    Triangulation t = hdt::dummies::new_triangulation(2);
    fill(t, 200, 0.6, 3);
    // Face 0's link about its corner 0 points to a face without that vertex.
    Face &f = const_cast<std::vector<Face> &>(t.faces())[0];
    const uint32_t v = f.v[0];
    uint32_t other = 0;
    while (other < t.faces().size() &&
           (t.faces()[other].v[0] == v || t.faces()[other].v[1] == v || t.faces()[other].v[2] == v))
      ++other;
    ck_assert_uint_lt(other, t.faces().size());
    f.n[1] = other;
    ck_assert(build_throws(t, wide));
  }
}
END_TEST

// A star whose second face leads back to the first: a walk of an even
// number of steps then ends where it began, half the entries unmet; build()
// throws on either path (the 64-bit one orders entry by entry).
START_TEST(star_closing_too_soon_found) {
  for (bool wide : {false, true}) {
    Triangulation t = hdt::dummies::new_triangulation(2);
    fill(t, 200, 0.6, 5);
    std::vector<StarEntry> star;
    uint32_t v = 0;
    for (; v < t.vertices().size(); ++v) {
      if (!t.vertices()[v].alive()) continue;
      vertex_star(t, v, &star);
      if (star.size() % 2 == 0 && star.size() >= 4) break;
    }
    ck_assert_uint_lt(v, t.vertices().size());
    Face &g = const_cast<std::vector<Face> &>(t.faces())[star[1].face];
    g.n[next(star[1].corner)] = star[0].face;
    ck_assert(build_throws(t, wide));
  }
}
END_TEST

}  // namespace

int main() {
  return run_suite("all_stars", 300, [](TCase *tc) {
    tcase_add_test(tc, wide_rows_genus_2);
    tcase_add_test(tc, wide_rows_spread);
    tcase_add_test(tc, broken_star_found_before_writing);
    tcase_add_test(tc, star_closing_too_soon_found);
  });
}
