// lib/domain's tiling of the disk by copies of a fundamental polygon: group
// elements in canonical form, the neighbour set N, the certified systole and
// the representative of a point in the polygon. Each expectation is computed
// here independently of the code under test: counts from the vertex cycles
// by the tiling argument, systoles from closed formulas or a brute force over
// short words in double, representatives checked exactly against P.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <complex>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "domain/ball_isometry.hpp"
#include "domain/error_double.hpp"
#include "domain/base_point.hpp"
#include "domain/element.hpp"
#include "domain/floating_walk.hpp"
#include "domain/hyperboloid_ball.hpp"
#include "domain/fundamental_polygon.hpp"
#include "domain/neighbours.hpp"
#include "domain/polygon_text.hpp"
#include "domain/random_octagon.hpp"
#include "domain/representative.hpp"
#include "domain/systole.hpp"
#include "domain/word.hpp"
#include "exact/unsupported.hpp"

extern "C" {
#include <check.h>
}

#include "run_suite.hpp"
#include "test_polygons.hpp"

using namespace hdt::domain;
using hdt::domain::test::bolza;
using hdt::domain::test::q;

namespace {

FundamentalPolygon genus_3_12_gon() { return FundamentalPolygon(test::genus_3_12_gon()); }


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


struct Matrix {
  std::complex<double> a, b, c, d;
};

// Pairing k in double, scaled to determinant 1 (for the brute force).
Matrix pairing_double(const FundamentalPolygon &P, int k) {
  const Moebius &g = P.pairing(k);
  auto d = [](const Complex &z) { return std::complex<double>(static_cast<double>(z.re), static_cast<double>(z.im)); };
  const std::complex<double> a = d(g.a), b = d(g.b), c = d(g.c), e = d(g.d), s = std::sqrt(a * e - b * c);
  return {a / s, b / s, c / s, e / s};
}

Matrix operator*(const Matrix &f, const Matrix &g) {
  return {f.a * g.a + f.b * g.c, f.a * g.b + f.b * g.d, f.c * g.a + f.d * g.c, f.c * g.b + f.d * g.d};
}

// The least translation length 2 arccosh(|tr| / 2) over the freely reduced
// words of length 1 to max_length (none of them the identity: the shortest
// relation has a vertex cycle's length, more than 4 here), in double,
// through nothing of lib/domain but the pairings' entries.
double brute_force_systole(const FundamentalPolygon &P, int max_length, std::vector<int> &argmin) {
  const int n = P.side_count();
  std::vector<Matrix> g;
  for (int k = 0; k < n; ++k) g.push_back(pairing_double(P, k));
  double best = INFINITY;
  std::vector<int> word;
  std::function<void(const Matrix &)> extend = [&](const Matrix &m) {
    if (!word.empty()) {
      const double l = 2 * std::acosh(std::max(1.0, std::abs(m.a + m.d) / 2));
      if (l < best) best = l, argmin = word;
    }
    if (int(word.size()) == max_length) return;
    for (int k = 0; k < n; ++k) {
      if (!word.empty() && P.paired(word.back()) == k) continue;
      word.push_back(k);
      extend(m * g[std::size_t(k)]);
      word.pop_back();
    }
  };
  extend(Matrix{1, 0, 0, 1});
  return best;
}

void check_length_interval(const Systole &s, double expected, const char *what) {
  std::printf("%s: systole in [%.17g, %.17g], %zu tiles walked, word of length %zu\n", what, s.length.lo,
              s.length.hi, s.tiles_walked, s.shortest.letters.size());
  ck_assert_msg(s.length.lo <= expected && expected <= s.length.hi, "%s: %.17g not in [%.17g, %.17g]", what,
                expected, s.length.lo, s.length.hi);
  ck_assert_msg(s.length.hi - s.length.lo < 1e-12, "%s: interval too wide", what);
}

// The certified systole against the brute force: never above it (it is a
// minimum over all elements, the brute force over some), and equal when the
// certified minimiser is a word the brute force tried.
void check_against_brute_force(const FundamentalPolygon &P, const char *what) {
  const Systole s = systole(P);
  std::vector<int> argmin;
  const double brute = brute_force_systole(P, 4, argmin);
  std::printf("%s: systole in [%.17g, %.17g] (word length %zu, %zu tiles), brute force %.17g (length %zu)\n", what,
              s.length.lo, s.length.hi, s.shortest.letters.size(), s.tiles_walked, brute, argmin.size());
  ck_assert_msg(s.length.lo <= brute + 1e-9, "%s: certified %.17g above brute force %.17g", what, s.length.lo, brute);
  if (s.shortest.letters.size() <= 4)
    ck_assert_msg(std::abs(s.length.lo - brute) < 1e-9, "%s: %.17g != %.17g", what, s.length.lo, brute);
  ck_assert(!s.shortest.element.is_identity());
  ck_assert(word_element(P, s.shortest.letters) == s.shortest.element);
  ck_assert(cosh2_half_translation(s.shortest.element) == s.cosh2_half);
  ck_assert(s.length.hi - s.length.lo < 1e-12);
}

// Which side of the geodesic through v_k and v_{k+1} z lies on, in the
// Poincare model (independent of the Klein computation under test): T_{v_k}
// sends that geodesic to a diameter through T(v_{k+1}), and z is on P's side
// (the left) when Im(T(z) conj T(v_{k+1})) > 0.
int side_sign(const FundamentalPolygon &P, int k, const Complex &z) {
  const Moebius T = to_origin(P.vertex(k));
  return (T.apply(z) * conj(T.apply(P.vertex(k + 1)))).im.sgn();
}

int smallest_of_cycle(const FundamentalPolygon &P, int v) {
  for (const auto &cycle : P.cycles())
    for (const int u : cycle)
      if (u == v) return *std::min_element(cycle.begin(), cycle.end());
  return -1;
}

// z in the half-open fundamental set: inside or on the closed polygon, on no
// side of larger index than its partner, and a vertex only when its cycle's
// smallest.
bool in_fundamental_set(const FundamentalPolygon &P, const Complex &z) {
  for (int k = 0; k < P.side_count(); ++k) {
    const int sign = side_sign(P, k, z);
    if (sign < 0) return false;
    if (sign > 0) continue;
    if (P.vertex(k) == z) return smallest_of_cycle(P, k) == k;
    if (P.vertex(k + 1) == z) return smallest_of_cycle(P, (k + 1) % P.side_count()) == (k + 1) % P.side_count();
    if (k > P.paired(k)) return false;
  }
  return true;
}

// A point of the open disk from doubles, exactly, in P's field.
Complex exact_point(const FundamentalPolygon &P, std::complex<double> z) { return P.exact_point(z.real(), z.imag()); }

void check_representative(const FundamentalPolygon &P, const Reduction &reduce, const Complex &z, const char *what) {
  const Representative r = reduce(z);
  ck_assert_msg(in_fundamental_set(P, r.point), "%s: the representative is not in the fundamental set", what);
  ck_assert_msg(r.word.element.apply(z) == r.point, "%s: t(z) is not the representative", what);
  ck_assert_msg(word_element(P, r.word.letters) == r.word.element, "%s: the word is not t", what);
}

// Points uniform in angle, radius up to 0.999 (a walk of hyperbolic length
// up to 2 artanh(0.999) = 7.6).
void check_random_points(const FundamentalPolygon &P, int count, std::uint64_t seed, const char *what) {
  const Reduction reduce(P);
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int s = 0; s < count; ++s) {
    const double r = 0.999 * std::sqrt(unit(random)), angle = 2 * M_PI * unit(random);
    check_representative(P, reduce, exact_point(P, std::polar(r, angle)), what);
  }
  check_representative(P, reduce, exact_point(P, std::polar(0.999, 1.0)), what);
}

// The point of side k at "fraction" lam: T^{-1}(lam T(v_{k+1})), T = T_{v_k},
// on the geodesic from v_k to v_{k+1}, exactly.
Complex point_on_side(const FundamentalPolygon &P, int k, const Number &lam) {
  const Moebius T = to_origin(P.vertex(k));
  return inverse(T).apply(lam * T.apply(P.vertex(k + 1)));
}

// The walk's Lorentz matrices (ball_isometry.hpp) against the Moebius action
// they stand for: L hyperboloid(z) = hyperboloid(h(z)) for products of up to
// four pairings and random z, on balls at 128 bits.
void check_lorentz(const FundamentalPolygon &P, const char *name) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-0.65, 0.65);
  std::vector<BallIsometry> g;
  for (int k = 0; k < P.side_count(); ++k) g.push_back(ball_isometry(P.pairing(k)));
  for (int trial = 0; trial < 200; ++trial) {
    BallIsometry h = ball_identity();
    for (int n = int(rng() % 5); n > 0; --n) h = h * g[rng() % g.size()];
    const ComplexBall z = complex_ball(u(rng), u(rng));
    const HyperboloidBall moved = hyperboloid(h.apply(z)), X = hyperboloid(z);
    const std::array<RealBall, 9> L = h.lorentz();
    const RealBall *want[3] = {&moved.x0, &moved.x1, &moved.x2};
    for (int i = 0; i < 3; ++i) {
      const RealBall got = L[3 * i] * X.x0 + L[3 * i + 1] * X.x1 + L[3 * i + 2] * X.x2;
      const RealBall gap = abs(got - *want[i]);
      ck_assert_msg(gap.upper() < 1e-25 * (1 + abs(*want[i]).upper()), "%s: trial %d row %d: %g vs %g", name, trial, i,
                    got.mid(), want[i]->mid());
    }
  }
}

// The walk's dot products on ErrorDouble (error_double.hpp): the bound holds
// the exact value of every sum of products within its inputs' bounds (the
// corners of the boxes, computed exactly on 2000-bit balls), cancelling sums
// included; a sign is claimed only where the exact numbers have it.
void check_error_bounded_dots() {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 2000; ++trial) {
    ErrorDouble a[3], b[3];
    const double scale = std::ldexp(1.0, int(rng() % 80) - 40);
    for (int i = 0; i < 3; ++i) {
      a[i] = {u(rng) * scale, trial % 3 ? std::fabs(u(rng)) * scale * 0x1p-45 : 0};
      b[i] = {u(rng), trial % 2 ? std::fabs(u(rng)) * 0x1p-50 : 0};
    }
    if (trial % 4 == 0) a[2].v = -(a[0].v * b[0].v + a[1].v * b[1].v) / b[2].v;  // cancelling
    const ErrorDouble d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    for (int corner = 0; corner < 64; ++corner) {
      arb_t exact, term, x, y;
      arb_init(exact), arb_init(term), arb_init(x), arb_init(y);
      for (int i = 0; i < 3; ++i) {
        arb_set_d(x, a[i].v), arb_set_d(term, (corner >> i) & 1 ? a[i].e : -a[i].e), arb_add(x, x, term, 2000);
        arb_set_d(y, b[i].v), arb_set_d(term, (corner >> (3 + i)) & 1 ? b[i].e : -b[i].e), arb_add(y, y, term, 2000);
        arb_mul(term, x, y, 2000);
        arb_add(exact, exact, term, 2000);
      }
      const int sign = arb_is_zero(exact) ? 0 : arf_sgn(arb_midref(exact));
      arb_set_d(term, d.v);
      arb_sub(exact, exact, term, 2000);
      arb_abs(exact, exact);
      ck_assert_msg(arb_is_exact(exact), "trial %d: the corner's value is not exact", trial);
      const double off = arf_get_d(arb_midref(exact), ARF_RND_UP);
      ck_assert_msg(off <= d.e, "trial %d corner %d: off %g, bound %g", trial, corner, off, d.e);
      ck_assert(certain_sign(d) == 0 || certain_sign(d) == sign);
      arb_clear(exact), arb_clear(term), arb_clear(x), arb_clear(y);
    }
  }
}

// The double overload of the reduction (floating_walk.hpp) gives what the
// exact one gives: random points out to 1 - |z| = 1e-4, points on the sides
// computed in double (from the Klein chord, so within a few ulps of the
// line, on either side of it), and points on the rays from the base point 0
// through P's vertices (segments through a vertex: the tie of two exit
// sides). The walk in double must decide most of them, or it is not tested.
void check_double_reduction(const FundamentalPolygon &P, unsigned seed, const char *name) {
  const Reduction reduce(P);
  const FloatingWalk floating(P, base_point(P));
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::complex<double>> points;
  for (int i = 0; i < 300; ++i) points.push_back(std::polar(1 - std::pow(10.0, -4 * u(rng)), 2 * M_PI * u(rng)));
  const auto to_klein = [](std::complex<double> v) { return 2.0 * v / (1 + std::norm(v)); };
  for (int k = 0; k < P.side_count(); ++k) {
    for (const double s : {0.5, 0.25, 1e-3}) {
      const std::complex<double> a = to_klein(P.vertex_double(k)), b = to_klein(P.vertex_double(k + 1));
      const std::complex<double> x = a + s * (b - a);
      points.push_back(x / (1 + std::sqrt(1 - std::norm(x))));
    }
    for (const double r : {1.0, 1.3, 1.6}) points.push_back(r * P.vertex_double(k));
  }
  int decided = 0, walked = 0;
  for (const std::complex<double> &z : points) {
    if (std::norm(z) >= 1) continue;
    const Representative fast = reduce(z.real(), z.imag()), exact = reduce(P.exact_point(z.real(), z.imag()));
    ck_assert_msg(fast.word.letters == exact.word.letters, "%s: (%.17g, %.17g)", name, z.real(), z.imag());
    ck_assert_msg(fast.point == exact.point && fast.word.element == exact.word.element, "%s", name);
    const auto applied = floating.pairings_applied(z.real(), z.imag());
    decided += bool(applied);
    walked += applied && !applied->empty();
  }
  ck_assert_msg(decided > 250 && walked > 200, "%s: the walk in double decided %d points, %d outside P", name, decided,
                walked);
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

// cosh(l/2) = 1 + sqrt2 = a^2 (a^4 - 2a^2 - 1 = 0), so cosh^2(l/2) = a^4 = 2a^2 + 1.
START_TEST(lorentz_matrices_move_points_as_the_pairings_do) {
  check_lorentz(bolza(), "Bolza");
  check_lorentz(random_octagon(2), "octagon 2");
  check_lorentz(genus_3_12_gon(), "genus 3");
}
END_TEST

START_TEST(error_bounded_dot_products_hold_the_exact_value) { check_error_bounded_dots(); }
END_TEST

START_TEST(bolza_systole) {
  const FundamentalPolygon P = bolza();
  const Systole s = systole(P);
  check_length_interval(s, 2 * std::acosh(1 + std::sqrt(2.0)), "Bolza");
  ck_assert(s.cosh2_half == 2 * pow(P.vertex(0).re * 2, 2) + 1);  // v_0 = a/2 + ...
  ck_assert_msg(std::abs(s.length.lo - 3.0571418389619963) < 1e-12, "%.17g", s.length.lo);
  check_against_brute_force(P, "Bolza");
}
END_TEST

// M_g's formula 2 arccosh(1 + 2 cos(pi/(2g))): cosh(l/2) = 1 + sqrt3 = 1 + b^2
// (b = 3^{1/4} = 2 h, h = Re v_1), cosh^2(l/2) = 4 + 2 b^2.
START_TEST(genus_3_systole) {
  const FundamentalPolygon P = genus_3_12_gon();
  const Systole s = systole(P);
  check_length_interval(s, 2 * std::acosh(1 + 2 * std::cos(M_PI / 6)), "genus 3");
  ck_assert(s.cosh2_half == 4 + 2 * pow(P.vertex(1).re * 2, 2));
  check_against_brute_force(P, "genus 3");
}
END_TEST

START_TEST(commutator_12_gon_systole_and_neighbours) {
  const FundamentalPolygon P(test::genus_3_commutator_12_gon());
  check_against_brute_force(P, "genus 3, commutator pairing");
  ck_assert_uint_eq(neighbours(P).size(), expected_neighbour_count(P));
  check_neighbour_set(P, "genus 3, commutators");
  check_random_points(P, 50, 9, "genus 3, commutators");
}
END_TEST

START_TEST(commutator_bolza_systole) {
  const FundamentalPolygon P = bolza("2 3 0 1 6 7 4 5");
  check_against_brute_force(P, "Bolza, commutator pairing");
  // The same surface as with the opposite pairing? Not assumed: the value is
  // reported (see the printed line), and checked against the brute force.
}
END_TEST

// Seeds 3 and 4 are thin (vertices at hyperbolic distance 5.8 from 0): a
// walk over a ball about the base point would need some 10^5 times more
// tiles; the cover's walk (systole.hpp) takes about as many as for a round
// octagon. A limit below the estimate is refused before the walk starts.
START_TEST(random_octagon_systoles) {
  // Seeds 1, 4, 5 and 6 pass too; two are enough for CI.
  check_against_brute_force(random_octagon(2), "octagon 2");
  check_against_brute_force(random_octagon(3), "thin octagon 3");
  std::string refusal;
  try {
    systole(random_octagon(3), 10);
  } catch (const hdt::exact::Unsupported &e) {
    refusal = e.what();
  }
  ck_assert_msg(refusal.find("would walk about") != std::string::npos, "%s", refusal.c_str());
}
END_TEST

START_TEST(decagon_systoles) {
  // Seed 2 passes too (4419 tiles).
  check_against_brute_force(random_symmetric_polygon(5, 1), "decagon 1");
}
END_TEST

START_TEST(random_points_reduce_into_the_fundamental_set) {
  check_random_points(bolza(), 150, 1, "Bolza");
  check_random_points(random_octagon(2), 150, 2, "octagon 2");
  check_random_points(random_symmetric_polygon(5, 1), 150, 3, "decagon 1");
  check_random_points(genus_3_12_gon(), 50, 4, "genus 3");
}
END_TEST

START_TEST(the_double_reduction_agrees_with_the_exact_one) {
  check_double_reduction(bolza(), 5, "Bolza");
  check_double_reduction(random_octagon(3), 6, "octagon 3");
  check_double_reduction(genus_3_12_gon(), 7, "genus 3");
}
END_TEST

// A vertex goes to its cycle's smallest vertex; a point inside side k to
// itself when k < paired(k), else onto the paired side.
void check_boundary(const FundamentalPolygon &P, const char *what) {
  const Reduction reduce(P);
  for (int k = 0; k < P.side_count(); ++k) {
    const Representative at_vertex = reduce(P.vertex(k));
    ck_assert_msg(at_vertex.point == P.vertex(smallest_of_cycle(P, k)), "%s: vertex %d", what, k);
    ck_assert(at_vertex.word.element.apply(P.vertex(k)) == at_vertex.point);
    const Complex z = point_on_side(P, k, P.vertex(0).re * 0 + q(1, 3));
    const Representative on_side = reduce(z);
    ck_assert_msg(on_side.word.element.apply(z) == on_side.point, "%s: side %d", what, k);
    ck_assert_msg(side_sign(P, std::min(k, P.paired(k)), on_side.point) == 0, "%s: side %d", what, k);
    ck_assert_msg(in_fundamental_set(P, on_side.point), "%s: side %d", what, k);
    if (k < P.paired(k)) ck_assert_msg(on_side.point == z && on_side.word.element.is_identity(), "%s: %d", what, k);
  }
}

START_TEST(boundary_points_go_to_the_included_copy) {
  check_boundary(bolza(), "Bolza");
  check_boundary(random_octagon(4), "octagon 4");
  check_boundary(random_symmetric_polygon(5, 2), "decagon 2");
  check_boundary(bolza("2 3 0 1 6 7 4 5"), "Bolza, commutators");
}
END_TEST

// h(z) for z in the fundamental set reduces to z itself with t = h^{-1}: for
// every h in N and for random words of length 5 to 8.
// z itself is first reduced (checked in the fundamental set), since a fixed
// rational point need not lie in a random polygon.
void check_images_reduce_back(const FundamentalPolygon &P, const Complex &z0, const char *what) {
  const Reduction reduce(P);
  const Complex z = reduce(z0).point;
  ck_assert(in_fundamental_set(P, z));
  std::vector<Word> elements = neighbours(P);
  std::mt19937_64 random(7);
  for (int s = 0; s < 30; ++s) {
    std::vector<int> letters(5 + random() % 4);
    for (int &k : letters) k = int(random() % unsigned(P.side_count()));
    elements.push_back({letters, word_element(P, letters)});
  }
  for (const Word &h : elements) {
    const Representative r = reduce(h.element.apply(z));
    ck_assert_msg(r.point == z, "%s: h(z) did not reduce to z", what);
    ck_assert_msg(r.word.element == inverse(h.element), "%s: t is not h^-1", what);
  }
}

START_TEST(images_reduce_back) {
  const FundamentalPolygon B = bolza(), O = random_octagon(5), D = random_symmetric_polygon(5, 1);
  check_images_reduce_back(B, point(B, 1, 2, 7), "Bolza");
  check_images_reduce_back(B, point_on_side(B, 1, B.vertex(0).re * 0 + q(2, 5)), "Bolza, side 1");
  check_images_reduce_back(B, B.vertex(0), "Bolza, vertex 0");
  check_images_reduce_back(O, point(O, -1, 3, 10), "octagon 5");
  check_images_reduce_back(D, point(D, 2, -1, 9), "decagon 1");
  check_images_reduce_back(D, D.vertex(1), "decagon 1, vertex 1");
}
END_TEST

int main() {
  return run_suite("tiling", 300, [](TCase *tc) {
    tcase_add_test(tc, equal_maps_have_equal_elements);
    tcase_add_test(tc, lorentz_matrices_move_points_as_the_pairings_do);
    tcase_add_test(tc, error_bounded_dot_products_hold_the_exact_value);
    tcase_add_test(tc, translation_and_displacement_of_a_bolza_pairing);
    tcase_add_test(tc, bolza_has_49_neighbours);
    tcase_add_test(tc, genus_3_12_gon_has_121_neighbours);
    tcase_add_test(tc, random_octagon_neighbours_share_a_vertex);
    tcase_add_test(tc, decagon_has_31_neighbours);
    tcase_add_test(tc, random_points_reduce_into_the_fundamental_set);
    tcase_add_test(tc, the_double_reduction_agrees_with_the_exact_one);
    tcase_add_test(tc, boundary_points_go_to_the_included_copy);
    tcase_add_test(tc, images_reduce_back);
    tcase_add_test(tc, bolza_systole);
    tcase_add_test(tc, genus_3_systole);
    tcase_add_test(tc, commutator_bolza_systole);
    tcase_add_test(tc, commutator_12_gon_systole_and_neighbours);
    tcase_add_test(tc, random_octagon_systoles);
    tcase_add_test(tc, decagon_systoles);
  });
}
