// include/hdt.hpp, the header-only C++17 layer, against the C API it wraps:
// every result equals the C call's, failures become hdt::Error with the
// status and the library's message and change nothing, the handle is owned
// once (moves leave nothing to free twice; valgrind and ASan run this suite),
// and copy() is an independent equal triangulation.
#include <hdt.hpp>

#include <check.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace {

std::vector<hdt::Point> some_points(std::size_t n) {
  std::vector<hdt::Point> p;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = 0.55 * std::sqrt((double(i) + 0.5) / double(n)), a = 2.399963229728653 * double(i);
    p.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return p;
}

// The status an hdt::Error carries, or HDT_OK when the call did not throw.
template <class Call>
hdt_status status_of(Call &&call) {
  try {
    call();
  } catch (const hdt::Error &e) {
    ck_assert_ptr_nonnull(std::strstr(e.what(), hdt_status_string(e.status())));
    return e.status();
  }
  return HDT_OK;
}

}  // namespace

START_TEST(results_are_the_c_api_results) {
  hdt::Triangulation t(3);
  const std::vector<hdt::Point> points = some_points(200);
  const std::vector<uint32_t> ids = t.insert_many(points);
  t.validate();
  // the same calls in C on a second handle
  hdt_triangulation *c = nullptr;
  ck_assert_int_eq(hdt_create(&c, 3), HDT_OK);
  std::vector<uint32_t> c_ids(points.size());
  ck_assert_int_eq(hdt_insert_many(c, &points[0].x, points.size(), c_ids.data()), HDT_OK);
  ck_assert(ids == c_ids);
  ck_assert_uint_eq(t.vertex_count(), hdt_vertex_count(c));
  ck_assert_uint_eq(t.face_count(), 2 * (t.vertex_count() + 2 * 3 - 2));  // Euler on M_3
  const std::vector<hdt::Face> faces = t.faces();
  std::vector<uint32_t> fv(3 * faces.size());
  std::vector<int32_t> ft(3 * faces.size());
  std::size_t count = 0;
  ck_assert_int_eq(hdt_faces(c, fv.data(), ft.data(), faces.size(), &count), HDT_OK);
  ck_assert_uint_eq(count, faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      ck_assert_uint_eq(faces[f].vertices[k], fv[3 * f + k]);
      ck_assert_int_eq(faces[f].translations[k], ft[3 * f + k]);
    }
  // vertices, points, words and matrices agree with each other
  const std::vector<hdt::Vertex> vertices = t.vertices();
  ck_assert_uint_eq(vertices.size(), t.vertex_count());
  std::size_t dummies = 0;
  for (const hdt::Vertex &v : vertices) {
    const hdt::Point p = t.vertex_point(v.id);
    ck_assert(p.x == v.point.x && p.y == v.point.y);
    ck_assert(v.dummy == t.is_dummy(v.id));
    dummies += v.dummy;
  }
  ck_assert_uint_eq(dummies, t.dummy_count());
  for (const hdt::Face &f : faces)
    for (const int32_t id : f.translations) {
      const hdt::Matrix a = t.translation_matrix(id), b = hdt::word_matrix(3, t.translation_word(id));
      for (int k = 0; k < 4; ++k) ck_assert(std::fabs(a[k] - b[k]) <= 1e-12 * (1 + std::fabs(a[k])));
    }
  const std::vector<std::array<hdt::Point, 3>> corners = t.face_points();
  ck_assert_uint_eq(corners.size(), faces.size());
  const std::vector<hdt::Edge> edges = t.edges();
  ck_assert_uint_eq(edges.size(), 3 * faces.size() / 2);
  for (const hdt::Edge &e : edges) ck_assert(e.length > 0);
  const hdt::Location at = t.locate(0.1, 0.05);
  ck_assert_uint_lt(at.face, faces.size());
  const uint32_t near = t.nearest_vertex(points[7].x, points[7].y);
  ck_assert_uint_eq(near, ids[7]);
  ck_assert_uint_eq(t.edge_count(), edges.size());
  hdt_destroy(c);
}
END_TEST

START_TEST(failures_throw_the_status_and_change_nothing) {
  ck_assert_int_eq(status_of([] { hdt::Triangulation t(1); }), HDT_EINVAL);
  hdt::Triangulation t(2);
  const std::vector<unsigned char> before = t.save();
  ck_assert_int_eq(status_of([&] { t.insert(1.0, 0.0); }), HDT_EDOMAIN);
  ck_assert_int_eq(status_of([&] { t.insert(NAN, 0.0); }), HDT_EDOMAIN);
  ck_assert_int_eq(status_of([&] { t.insert_many({{0.1, 0.1}, {0.0, 2.0}}); }), HDT_EDOMAIN);
  ck_assert_int_eq(status_of([&] { t.refine(-1, 2); }), HDT_EINVAL);
  ck_assert_int_eq(status_of([&] { t.epsilon_net(1e-4); }), HDT_ENOMEM);  // refused up front
  ck_assert_int_eq(status_of([&] { t.translation_word(-5); }), HDT_EINVAL);
  ck_assert(t.save() == before);
  const uint32_t v = t.insert(0.2, 0.1);
  ck_assert_int_eq(status_of([&] { t.insert(0.2, 0.1); }), HDT_EEXISTS);
  ck_assert_int_eq(status_of([&] { hdt::Triangulation::load({1, 2, 3}); }), HDT_EINVAL);
  try {
    t.insert(0.0, 1.5);
    ck_abort_msg("no exception");
  } catch (const hdt::Error &e) {
    ck_assert_ptr_nonnull(std::strstr(e.what(), "hdt_insert"));
  }
  ck_assert(t.vertex_point(v).x == 0.2);
}
END_TEST

START_TEST(ownership_moves_and_copies) {
  hdt::Triangulation a(2);
  a.insert_many(some_points(50));
  hdt_triangulation *handle = a.handle();
  hdt::Triangulation b(std::move(a));
  ck_assert_ptr_eq(b.handle(), handle);
  ck_assert_ptr_null(a.handle());
  hdt::Triangulation c(3);
  c = std::move(b);  // c's own handle freed, b's taken
  ck_assert_ptr_eq(c.handle(), handle);
  hdt::Triangulation d = c.copy();
  ck_assert(d.save() == c.save());
  d.insert(0.01, -0.02);
  ck_assert_uint_eq(d.vertex_count(), c.vertex_count() + 1);
  const hdt::Refined r = d.epsilon_net(0.3);
  ck_assert_uint_eq(r.unmet, 0);
  const hdt::Quality q = d.quality();
  ck_assert(q.max_radius <= 0.3 * (1 + 1e-9));
  d.remove_dummies();
  d.validate();
  ck_assert_ptr_nonnull(std::strstr(d.svg(400, "a title").c_str(), "a title"));
}
END_TEST

START_TEST(surface_and_group) {
  ck_assert(std::fabs(hdt::systole(2) - 3.0571418389619963) < 1e-15);
  const hdt::Point m = hdt::polygon_side_midpoint(2, 0);
  ck_assert(m.x > 0);
  const hdt::Point v = hdt::polygon_vertex(2, 0);
  ck_assert(std::hypot(v.x, v.y) > std::hypot(m.x, m.y));
  ck_assert(hdt::reduce_word(2, {0, 5, 2, 7, 4, 1, 6, 3}).empty());  // the relation of genus 2
  const hdt::Representative r = hdt::point_representative(2, 0.9, 0.1);
  ck_assert(!r.word.empty());
  ck_assert(hdt::point_representative(2, 0.1, 0.1).word.empty());
  ck_assert_int_eq(status_of([] { hdt::point_representative(2, 1.0, 0.0); }), HDT_EDOMAIN);
}
END_TEST

// The polygon surface's wrapper gives the C API's values; a refused polygon
// throws its status; its text round-trips; ownership moves.
START_TEST(polygon_surfaces) {
  hdt::PolygonSurface s = hdt::PolygonSurface::random_symmetric(10, 4);
  ck_assert_int_eq(s.genus(), 2);
  ck_assert_int_eq(s.side_count(), 10);
  double x, y, m[4];
  int paired;
  ck_assert_int_eq(hdt_surface_vertex(s.handle(), 3, &x, &y), HDT_OK);
  ck_assert(s.vertex(3).x == x && s.vertex(3).y == y);
  ck_assert_int_eq(hdt_surface_pairing(s.handle(), 3, &paired, m), HDT_OK);
  const hdt::Pairing p = s.pairing(3);
  ck_assert(p.paired_side == paired && p.matrix[0] == m[0] && p.matrix[3] == m[3]);
  const std::vector<int> cycles = s.vertex_cycles();
  ck_assert_int_eq(int(cycles.size()), 10);
  ck_assert_int_eq(cycles[0], 0);
  ck_assert(*std::max_element(cycles.begin(), cycles.end()) == 1);
  const std::string text = s.polygon_text();
  hdt::PolygonSurface t = hdt::PolygonSurface::from_polygon(text);
  ck_assert(t.polygon_text() == text);
  s = std::move(t);
  ck_assert(s.polygon_text() == text && t.handle() == nullptr);
  ck_assert_int_eq(status_of([] { hdt::PolygonSurface::from_polygon("8\n4 5 6 7 0 1 2 x\n"); }), HDT_EINVAL);
  ck_assert_int_eq(status_of([] { hdt::PolygonSurface::random_symmetric(6, 1); }), HDT_EINVAL);
  double lo, hi, rx, ry;
  std::size_t count, length;
  // The wrapper gives the C call's certified interval (the walk's values
  // are tested in test_surfaces and against a brute force in test_tiling).
  // Seed 2's walk is the shortest of the random octagons (59 tiles).
  const hdt::PolygonSurface octagon = hdt::PolygonSurface::random_symmetric(8, 2);
  ck_assert_int_eq(hdt_surface_systole(octagon.handle(), &lo, &hi), HDT_OK);
  ck_assert(lo <= hi && hi - lo < 1e-12);
  ck_assert(octagon.systole()[0] == lo && octagon.systole()[1] == hi);
  ck_assert_int_eq(hdt_surface_neighbour_count(s.handle(), &count), HDT_OK);
  ck_assert(s.neighbour_count() == count);
  int32_t word[64];
  ck_assert_int_eq(hdt_surface_representative(s.handle(), 0.9, 0.2, &rx, &ry, word, 64, &length), HDT_OK);
  const hdt::Representative r = s.representative(0.9, 0.2);
  ck_assert(r.point.x == rx && r.point.y == ry && r.word == hdt::Word(word, word + length));
  ck_assert(s.svg(500).rfind("<svg ", 0) == 0);
}
END_TEST

int main() {
  Suite *s = suite_create("hpp");
  TCase *tc = tcase_create("hpp");
  tcase_set_timeout(tc, 120);
  tcase_add_test(tc, results_are_the_c_api_results);
  tcase_add_test(tc, failures_throw_the_status_and_change_nothing);
  tcase_add_test(tc, ownership_moves_and_copies);
  tcase_add_test(tc, surface_and_group);
  tcase_add_test(tc, polygon_surfaces);
  suite_add_tcase(s, tc);
  SRunner *runner = srunner_create(s);
  srunner_run_all(runner, CK_NORMAL);
  const int failed = srunner_ntests_failed(runner);
  srunner_free(runner);
  return failed == 0 ? 0 : 1;
}
