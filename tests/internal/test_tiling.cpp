// lib/domain's tiling of the disk by copies of a fundamental polygon: group
// elements in canonical form, the neighbour set N, the certified systole and
// the representative of a point in the polygon. Each expectation is computed
// here independently of the code under test: counts from the vertex cycles
// by the tiling argument, systoles from closed formulas or a brute force over
// short words in double, representatives checked exactly against P.
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "domain/element.hpp"
#include "domain/fundamental_polygon.hpp"
#include "domain/neighbours.hpp"
#include "domain/polygon_text.hpp"
#include "domain/random_octagon.hpp"
#include "domain/word.hpp"

extern "C" {
#include <check.h>
}

#include "run_suite.hpp"

using namespace hdt::domain;

namespace {

// The Bolza octagon and the regular genus-3 12-gon of test_domain.cpp.
std::string bolza_text(const char *pairing) {
  const std::string x = "1/2*a", y = "1/2*a^3-a", mx = "-1/2*a", my = "-1/2*a^3+a";
  return std::string("field a^4-2*a^2-1 a 1.5538+/-0.01\n8\n") + pairing + "\n" + x + " " + y + "\n" + y + " " + x +
         "\n" + my + " " + x + "\n" + mx + " " + y + "\n" + mx + " " + my + "\n" + my + " " + mx + "\n" + y + " " +
         mx + "\n" + x + " " + my + "\n";
}

FundamentalPolygon bolza(const char *pairing = "4 5 6 7 0 1 2 3") {
  return FundamentalPolygon(parse_polygon_text(bolza_text(pairing)));
}

FundamentalPolygon genus_3_12_gon() {
  PolygonText t;
  t.field = make_field("b^4-3", "b", "1.316+/-0.01");
  const Number x = make_element(*t.field, "1/4*b^3+1/4*b"), y = make_element(*t.field, "1/4*b^3-1/4*b"),
               h = make_element(*t.field, "1/2*b");
  t.vertices = {{x, y}, {h, h}, {y, x}, {-y, x}, {-h, h}, {-x, y}};
  for (int k = 0; k < 6; ++k) t.vertices.push_back(-t.vertices[std::size_t(k)]);
  for (int k = 0; k < 12; ++k) t.paired.push_back((k + 6) % 12);
  return FundamentalPolygon(t);
}

Number q(long p, long d) {
  mpq_class r(p, d);
  r.canonicalize();
  return Number(r);
}

// A Complex in P's field from a rational pair.
Complex point(const FundamentalPolygon &P, long xp, long yp, long den) {
  const auto &parent = P.vertex(0).re.parent();
  return {Number(parent, static_cast<mpq_class>(q(xp, den))), Number(parent, static_cast<mpq_class>(q(yp, den)))};
}


bool is_vertex(const FundamentalPolygon &P, const Complex &z) {
  for (int k = 0; k < P.side_count(); ++k)
    if (P.vertex(k) == z) return true;
  return false;
}

// The tiling argument for |N| (neighbours.hpp): around a vertex of a cycle C
// lie |C| tiles, P and |C| - 1 others; a tile sharing only a vertex with P is
// seen at that vertex alone, a tile across a side at both ends of the side.
// So |N| = 1 + sum over cycles of |C| (|C| - 1) - n.
std::size_t expected_neighbour_count(const FundamentalPolygon &P) {
  std::size_t count = 1;
  for (const auto &cycle : P.cycles()) count += cycle.size() * (cycle.size() - 1);
  return count - std::size_t(P.side_count());
}

}  // namespace

START_TEST(equal_maps_have_equal_elements) {
  const FundamentalPolygon P = random_octagon(3);
  const Element g0(P.pairing(0)), g4(P.pairing(4));
  ck_assert(g0 * g4 == identity_element(P.vertex(0).re));  // g_4 = g_0^{-1}
  ck_assert(inverse(g0) == g4);
  // A multiple of the matrix by a non-real scalar is the same element.
  const Complex s(q(3, 7), q(-2, 5));
  const Moebius &m = P.pairing(1);
  ck_assert(Element(Moebius{s * m.a, s * m.b, s * m.c, s * m.d}) == Element(m));
  ck_assert(Element(m).hash() == Element(Moebius{s * m.a, s * m.b, s * m.c, s * m.d}).hash());
  ck_assert(Element(m) != g0);
  const Complex z = point(P, 1, 2, 10);
  ck_assert((g0 * Element(m)).apply(z) == g0.apply(m.apply(z)));
}
END_TEST

// Bolza: the pairing of side 0 translates along the axis through the
// midpoints of sides 4 and 0 by twice the inradius rho, cosh rho =
// cot(pi/8) = 1 + sqrt2; and d(0, g 0) = 2 rho, cosh = 2 cosh^2 rho - 1.
START_TEST(translation_and_displacement_of_a_bolza_pairing) {
  const FundamentalPolygon P = bolza();
  const Element g(P.pairing(0));
  const Number c2 = cosh2_half_translation(g);
  const double expected = std::pow(1 + std::sqrt(2.0), 2);
  ck_assert_msg(std::abs(static_cast<double>(c2) - expected) < 1e-12, "%.17g", static_cast<double>(c2));
  const Complex zero = point(P, 0, 0, 1);
  ck_assert(cosh_displacement(g, zero) == 2 * c2 - 1);
  ck_assert(cosh2_half_translation(identity_element(zero.re)) == 1);
}
END_TEST

START_TEST(bolza_has_49_neighbours) {
  const FundamentalPolygon P = bolza();
  ck_assert_uint_eq(expected_neighbour_count(P), 49);  // 1 + 8 * 7 - 8, M_2's count
  ck_assert_uint_eq(neighbours(P).size(), 49);
  ck_assert_uint_eq(neighbours(bolza("2 3 0 1 6 7 4 5")).size(), 49);
}
END_TEST

START_TEST(genus_3_12_gon_has_121_neighbours) {
  const FundamentalPolygon P = genus_3_12_gon();
  ck_assert_uint_eq(expected_neighbour_count(P), 121);  // 1 + 12 * 11 - 12
  ck_assert_uint_eq(neighbours(P).size(), 121);
}
END_TEST

// Every h in N maps a vertex of P onto a vertex of P (h(P) and P share a
// vertex), the elements are distinct, N is closed under inverse, and each
// word gives its element.
void check_neighbour_set(const FundamentalPolygon &P, const char *what) {
  const std::vector<Word> N = neighbours(P);
  ck_assert_msg(N.size() == expected_neighbour_count(P), "%s: |N| = %zu, expected %zu", what, N.size(),
                expected_neighbour_count(P));
  ck_assert(N.front().element.is_identity());
  for (std::size_t s = 0; s < N.size(); ++s) {
    bool maps_a_vertex = false, has_inverse = false;
    for (int k = 0; k < P.side_count(); ++k) maps_a_vertex |= is_vertex(P, N[s].element.apply(P.vertex(k)));
    const Element inv = inverse(N[s].element);
    for (std::size_t t = 0; t < N.size(); ++t) {
      if (t != s) ck_assert_msg(N[t].element != N[s].element, "%s: elements %zu and %zu equal", what, s, t);
      has_inverse |= N[t].element == inv;
    }
    ck_assert_msg(maps_a_vertex && has_inverse, "%s: element %zu", what, s);
    ck_assert(word_element(P, N[s].letters) == N[s].element);
  }
}

START_TEST(random_octagon_neighbours_share_a_vertex) {
  for (unsigned seed = 1; seed <= 3; ++seed) check_neighbour_set(random_octagon(seed), "octagon");
}
END_TEST

// Two cycles of 5: 1 + 2 * 5 * 4 - 10 = 31.
START_TEST(decagon_has_31_neighbours) {
  const FundamentalPolygon P = random_symmetric_polygon(5, 1);
  ck_assert_uint_eq(expected_neighbour_count(P), 31);
  check_neighbour_set(P, "decagon");
}
END_TEST

int main() {
  return run_suite("tiling", 300, [](TCase *tc) {
    tcase_add_test(tc, equal_maps_have_equal_elements);
    tcase_add_test(tc, translation_and_displacement_of_a_bolza_pairing);
    tcase_add_test(tc, bolza_has_49_neighbours);
    tcase_add_test(tc, genus_3_12_gon_has_121_neighbours);
    tcase_add_test(tc, random_octagon_neighbours_share_a_vertex);
    tcase_add_test(tc, decagon_has_31_neighbours);
  });
}
