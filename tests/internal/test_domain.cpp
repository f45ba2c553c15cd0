// lib/domain: fundamental polygons read, written and checked exactly. The
// random octagons and decagons must pass every check of FundamentalPolygon
// (the test of both), the Bolza octagon given in a number field must pass
// with both of its classical pairings, each broken polygon must be refused
// with the reason, and the text must read back exactly.
#include <cmath>
#include <complex>
#include <cstring>
#include <string>

#include "domain/fundamental_polygon.hpp"
#include "domain/polygon_text.hpp"
#include "domain/random_octagon.hpp"
#include "domain/turning.hpp"

extern "C" {
#include <check.h>
}

#include "run_suite.hpp"
#include "test_polygons.hpp"

using namespace hdt::domain;
using namespace hdt::domain::test;

namespace {

// Angles pi/3, sum 4 pi: cosh R = cot(pi/12) cot(pi/6) gives r^2 = sqrt3 - 1;
// with c = sqrt(2 sqrt3 - 2) (c^4 + 4c^2 - 8 = 0, sqrt3 = c^2/2 + 1) x = c^3/8 +
// c/2, y = c^3/8, h = c/2. Sides equal, pairings composing to the identity
// around the one cycle (a rotation by 4 pi), and still no surface.
PolygonText four_pi_12_gon() {
  return regular_12_gon("c^4+4*c^2-8", "c", "1.21+/-0.01", "1/8*c^3+1/2*c", "1/8*c^3", "1/2*c");
}

// The area from the vertices in double, through nothing of lib/domain but
// vertex_double: (n - 2) pi minus the angles, each arg(T_v(prev) / T_v(next)).
double double_area(const FundamentalPolygon &P) {
  const int n = P.side_count();
  double sum = 0;
  for (int k = 0; k < n; ++k) {
    const std::complex<double> v = P.vertex_double(k), prev = P.vertex_double(k - 1), next = P.vertex_double(k + 1);
    auto T = [v](std::complex<double> w) { return (w - v) / (1.0 - std::conj(v) * w); };
    sum += std::arg(T(prev) / T(next));
  }
  return (n - 2) * M_PI - sum;
}

void check_gauss_bonnet(const FundamentalPolygon &P, const char *what) {
  const double area = double_area(P), expected = 4 * M_PI * (P.genus() - 1);
  ck_assert_msg(std::abs(area - expected) < 1e-9, "%s: area %.17g, 4 pi (g - 1) = %.17g", what, area, expected);
}

// The message of the InvalidPolygon that building P throws, or "".
std::string refusal(const PolygonText &t) {
  try {
    FundamentalPolygon P(t);
  } catch (const InvalidPolygon &e) {
    return e.what();
  }
  return "";
}

void expect_refusal(const PolygonText &t, const char *phrase) {
  const std::string m = refusal(t);
  ck_assert_msg(m.find(phrase) != std::string::npos, "expected a refusal with \"%s\", got \"%s\"", phrase, m.c_str());
}

std::string parse_error(const std::string &text) {
  try {
    parse_polygon_text(text);
  } catch (const ParseError &e) {
    return e.what();
  }
  return "";
}

void expect_same(const PolygonText &a, const PolygonText &b) {
  ck_assert(a.paired == b.paired);
  ck_assert_uint_eq(a.vertices.size(), b.vertices.size());
  for (std::size_t k = 0; k < a.vertices.size(); ++k) ck_assert(a.vertices[k] == b.vertices[k]);
  ck_assert((a.field == nullptr) == (b.field == nullptr));
  if (a.field) ck_assert(*a.field == *b.field);
}

}  // namespace

START_TEST(random_octagons_pass_with_one_cycle_of_eight) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const FundamentalPolygon P = random_octagon(seed);
    ck_assert_int_eq(P.genus(), 2);
    ck_assert_uint_eq(P.cycles().size(), 1);
    ck_assert_uint_eq(P.cycles()[0].size(), 8);
    ck_assert(P.field() == nullptr);
    check_gauss_bonnet(P, ("octagon " + std::to_string(seed)).c_str());
  }
}
END_TEST

START_TEST(random_octagons_differ_by_seed) {
  ck_assert(random_octagon(1).vertex(1) != random_octagon(2).vertex(1));
  ck_assert(random_octagon(3).vertex(2) == random_octagon(3).vertex(2));
}
END_TEST

START_TEST(random_decagons_pass_with_two_cycles_of_five) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const FundamentalPolygon P = random_symmetric_polygon(5, seed);
    ck_assert_int_eq(P.genus(), 2);
    ck_assert_uint_eq(P.cycles().size(), 2);
    ck_assert_uint_eq(P.cycles()[0].size(), 5);
    ck_assert_uint_eq(P.cycles()[1].size(), 5);
    check_gauss_bonnet(P, ("decagon " + std::to_string(seed)).c_str());
  }
}
END_TEST

START_TEST(bolza_octagon_in_a_number_field) {
  const FundamentalPolygon P(parse_polygon_text(bolza_text("4 5 6 7 0 1 2 3")));
  ck_assert(P.field() != nullptr);
  ck_assert_int_eq(P.genus(), 2);
  ck_assert_uint_eq(P.cycles().size(), 1);
  ck_assert_uint_eq(P.cycles()[0].size(), 8);
  const double r = std::pow(2.0, -0.25);
  for (int k = 0; k < 8; ++k) {
    const std::complex<double> expected = std::polar(r, (2 * k + 1) * M_PI / 8);
    ck_assert_msg(std::abs(P.vertex_double(k) - expected) < 1e-15, "Bolza vertex %d", k);
  }
  check_gauss_bonnet(P, "Bolza");
  // The pairing of side 0 sends side 4 onto it: v_5 to v_0, v_4 to v_1.
  ck_assert(P.pairing(0).apply(P.vertex(5)) == P.vertex(0));
  ck_assert(P.pairing(0).apply(P.vertex(4)) == P.vertex(1));
}
END_TEST

START_TEST(bolza_octagon_with_the_commutator_pairing) {
  // a b a^-1 b^-1: sides 0 <-> 2, 1 <-> 3, 4 <-> 6, 5 <-> 7.
  const FundamentalPolygon P(parse_polygon_text(bolza_text("2 3 0 1 6 7 4 5")));
  ck_assert_int_eq(P.genus(), 2);
  ck_assert_uint_eq(P.cycles().size(), 1);
  check_gauss_bonnet(P, "Bolza, commutators");
}
END_TEST

START_TEST(regular_12_gon_of_genus_3) {
  const FundamentalPolygon P(genus_3_12_gon());
  ck_assert_int_eq(P.genus(), 3);
  ck_assert_uint_eq(P.cycles().size(), 1);
  ck_assert_uint_eq(P.cycles()[0].size(), 12);
  const double r = std::sqrt(std::sqrt(3.0) / 2);
  for (int k = 0; k < 12; ++k)
    ck_assert_msg(std::abs(P.vertex_double(k) - std::polar(r, (2 * k + 1) * M_PI / 12)) < 1e-15, "vertex %d", k);
  check_gauss_bonnet(P, "genus 3");
}
END_TEST

START_TEST(regular_12_gon_with_the_commutator_pairing) {
  const FundamentalPolygon P(genus_3_commutator_12_gon());
  ck_assert_int_eq(P.genus(), 3);
  ck_assert_uint_eq(P.cycles().size(), 1);
  ck_assert_uint_eq(P.cycles()[0].size(), 12);
  check_gauss_bonnet(P, "genus 3, commutators");
}
END_TEST

// The 4 pi 12-gon's pairings (built here as FundamentalPolygon builds them)
// compose to the identity around its cycle: only the turn count refuses it.
START_TEST(a_4_pi_cycle_composes_to_the_identity) {
  const PolygonText t = four_pi_12_gon();
  auto v = [&t](int k) { return t.vertices[std::size_t(((k % 12) + 12) % 12)]; };
  Moebius around = identity(v(0).re);
  for (int u = 0, step = 0; step < 12; ++step, u = (u + 7) % 12) {
    const int j = t.paired[std::size_t(u)];  // the pairing of side j sends v_u to v_{j+1}
    const int i = t.paired[std::size_t(j)];
    around = segment_map(v(i + 1), v(i), v(j), v(j + 1)) * around;
  }
  ck_assert(around.is_identity());
}
END_TEST

START_TEST(refusals_name_the_reason) {
  const PolygonText good = random_octagon(7).text();
  PolygonText t = good;
  t.vertices.pop_back();
  t.paired = {1, 0, 3, 2, 6, 5, 4};
  expect_refusal(t, "an even number");
  t = good;
  t.paired[0] = 5;
  expect_refusal(t, "not a perfect matching: side 0");
  t = good;
  t.paired[3] = 3;
  expect_refusal(t, "paired with itself");
  t = good;
  t.vertices[0] = Complex(Number(1), Number(0));
  expect_refusal(t, "vertex 0 is not in the open unit disk");
  t = good;
  t.vertices[2] = q(1, 10) * t.vertices[2];
  expect_refusal(t, "not strictly convex");
  t = good;
  t.vertices[1].re += q(1, 10000);
  expect_refusal(t, "different hyperbolic lengths");
  // A small centrally symmetric octagon: convex, opposite sides equal by
  // symmetry, but almost Euclidean: its angles sum to nearly 6 pi.
  t.field = nullptr;
  t.paired = {4, 5, 6, 7, 0, 1, 2, 3};
  t.vertices.clear();
  const long xy[4][2] = {{2, 1}, {1, 2}, {-1, 2}, {-2, 1}};
  for (int s : {1, -1})
    for (const auto &p : xy) t.vertices.emplace_back(q(s * p[0], 10), q(s * p[1], 10));
  expect_refusal(t, "sum to between 5 pi and 6 pi: the angle sum must be 2 pi");
  expect_refusal(four_pi_12_gon(), "vertex cycle (0 7 2 9 4 11 6 1 8 3 10 5) sum to 4 pi: the angle sum must be 2 pi");
}
END_TEST

START_TEST(turn_counting_tells_4_pi_from_2_pi) {
  const Complex one(Number(1), Number(0)), i(Number(0), Number(1));
  std::vector<Complex> d{one};
  for (int t = 0; t < 8; ++t) d.push_back(d.back() * i);  // eight right angles: 4 pi
  ck_assert_int_eq(half_turns(d), 4);
  ck_assert(is_positive_real(d.back()));
  d.resize(5);  // four: 2 pi
  ck_assert_int_eq(half_turns(d), 2);
  d.resize(4);
  ck_assert_int_eq(half_turns(d), 1);  // 3 pi/2
}
END_TEST

START_TEST(parse_errors_name_the_token) {
  std::string m = parse_error("8\n4 5 6 7 0 1 2 x\n");
  ck_assert_msg(m.find("token 9 (line 2, column 15) `x`: expected the side paired with side 7") == 0, "%s", m.c_str());
  m = parse_error("4\n2 3 0 1\n1/2 0 0 1/2 -1/2 0 0 a\n");
  ck_assert_msg(m.find("token 13") == 0 && m.find("y of vertex 3") != std::string::npos, "%s", m.c_str());
  m = parse_error("4\n2 3 0 1\n1/2 0 0 1/2 -1/2 0 0\n");
  ck_assert_msg(m.find("the text ends where y of vertex 3") != std::string::npos, "%s", m.c_str());
  m = parse_error("4\n2 3 0 1\n1/0 0 0 1/2 -1/2 0 0 -1/2\n");
  ck_assert_msg(m.find("token 6") == 0, "%s", m.c_str());
  m = parse_error("field a^2-4 a 2+/-0.1\n4\n");
  ck_assert_msg(m.find("not irreducible") != std::string::npos, "%s", m.c_str());
  m = parse_error("field a^2-2 a 1.4+/-0.1\n4\n2 3 0 1\nb 0 0 1/2 -1/2 0 0 -1/2\n");
  ck_assert_msg(m.find("token 10") == 0, "%s", m.c_str());
  m = parse_error("4 2 3 0 1 0 0 0 0 0 0 0 0 9");
  ck_assert_msg(m.find("expected the end of the text") != std::string::npos, "%s", m.c_str());
}
END_TEST

START_TEST(decimals_are_exact) {
  const PolygonText t = parse_polygon_text("4\n2 3 0 1\n0.125 -0.5 -3 +2 7/14 0.0 -00.10 1\n");
  ck_assert(t.vertices[0].re == q(1, 8));
  ck_assert(t.vertices[0].im == q(-1, 2));
  ck_assert(t.vertices[1].im == q(2, 1));
  ck_assert(t.vertices[2].re == q(1, 2));
  ck_assert(t.vertices[3].re == q(-1, 10));
}
END_TEST

START_TEST(text_round_trip_is_exact) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const PolygonText t = random_octagon(seed).text();
    expect_same(t, parse_polygon_text(polygon_text(t)));
  }
  const PolygonText b = FundamentalPolygon(parse_polygon_text(bolza_text("4 5 6 7 0 1 2 3"))).text();
  const std::string written = polygon_text(b);
  ck_assert_msg(written.rfind("field a^4-2*a^2-1 a ", 0) == 0, "%s", written.c_str());
  expect_same(b, parse_polygon_text(written));
  const PolygonText g3 = genus_3_12_gon();
  expect_same(g3, parse_polygon_text(polygon_text(g3)));
}
END_TEST

int main() {
  return run_suite("domain", 300, [](TCase *tc) {
    tcase_add_test(tc, random_octagons_pass_with_one_cycle_of_eight);
    tcase_add_test(tc, random_octagons_differ_by_seed);
    tcase_add_test(tc, random_decagons_pass_with_two_cycles_of_five);
    tcase_add_test(tc, bolza_octagon_in_a_number_field);
    tcase_add_test(tc, bolza_octagon_with_the_commutator_pairing);
    tcase_add_test(tc, regular_12_gon_of_genus_3);
    tcase_add_test(tc, regular_12_gon_with_the_commutator_pairing);
    tcase_add_test(tc, a_4_pi_cycle_composes_to_the_identity);
    tcase_add_test(tc, refusals_name_the_reason);
    tcase_add_test(tc, turn_counting_tells_4_pi_from_2_pi);
    tcase_add_test(tc, parse_errors_name_the_token);
    tcase_add_test(tc, decimals_are_exact);
    tcase_add_test(tc, text_round_trip_is_exact);
  });
}
