// lib/domain's polygon kernel (polygon_kernel.hpp) and element table. Every
// predicate's sign on random points and random words in the pairings must be
// that of an independent evaluation: Arb at 2000 bits on the images
// (z + b) / (c z + d) of the canonical matrices (not the kernel's SU(1,1)
// balls nor its rows), with the Euclidean formulas of the disk and of the
// Klein model (not the kernel's hyperboloid determinants). Exact
// degeneracies (the Bolza octagon's cocircular images of 0, a polygon with a
// vertex at 0) must come out exactly 0 from the exact stage, which the
// counters must show was reached.
#include <arb.h>
#include <flint/fmpq.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "domain/element_table.hpp"
#include "domain/polygon_kernel.hpp"
#include "domain/random_octagon.hpp"

extern "C" {
#include <check.h>
}

#include "random.hpp"
#include "run_suite.hpp"
#include "test_polygons.hpp"

using namespace hdt::domain;
using namespace hdt::domain::test;

namespace {

constexpr slong kHi = 2000;
constexpr int kUnknown = 2;  // a 2000-bit ball holding 0

// A 2000-bit Arb ball, with the few operations the checks need.
struct Hi {
  arb_t v;
  Hi() { arb_init(v); }
  explicit Hi(double d) : Hi() { arb_set_d(v, d); }
  Hi(const Hi &o) : Hi() { arb_set(v, o.v); }
  Hi &operator=(const Hi &o) {
    arb_set(v, o.v);
    return *this;
  }
  ~Hi() { arb_clear(v); }
  double mid() const { return arf_get_d(arb_midref(v), ARF_RND_NEAR); }
};

template <class F>
Hi op(F f) {
  Hi r;
  f(r.v);
  return r;
}
Hi operator+(const Hi &a, const Hi &b) { return op([&](arb_ptr r) { arb_add(r, a.v, b.v, kHi); }); }
Hi operator-(const Hi &a, const Hi &b) { return op([&](arb_ptr r) { arb_sub(r, a.v, b.v, kHi); }); }
Hi operator*(const Hi &a, const Hi &b) { return op([&](arb_ptr r) { arb_mul(r, a.v, b.v, kHi); }); }
Hi operator/(const Hi &a, const Hi &b) { return op([&](arb_ptr r) { arb_div(r, a.v, b.v, kHi); }); }
Hi hsqrt(const Hi &a) { return op([&](arb_ptr r) { arb_sqrt(r, a.v, kHi); }); }
Hi hatanh(const Hi &a) { return op([&](arb_ptr r) { arb_atanh(r, a.v, kHi); }); }

int sign(const Hi &x) { return arb_is_positive(x.v) ? 1 : arb_is_negative(x.v) ? -1 : kUnknown; }

Hi hi_of(const Number &x) {
  Hi r;
  if (x.is_rational()) {
    fmpq_t f;
    fmpq_init(f);
    fmpq_set_mpq(f, static_cast<mpq_class>(x).get_mpq_t());
    arb_set_fmpq(r.v, f, kHi);
    fmpq_clear(f);
  } else {
    renf_elem_get_arb(r.v, x.renf_elem_t(), x.parent().renf_t(), kHi);
  }
  return r;
}

struct HiC {
  Hi re, im;
};
HiC operator+(const HiC &a, const HiC &b) { return {a.re + b.re, a.im + b.im}; }
HiC operator-(const HiC &a, const HiC &b) { return {a.re - b.re, a.im - b.im}; }
HiC operator*(const HiC &a, const HiC &b) { return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re}; }
Hi norm(const HiC &a) { return a.re * a.re + a.im * a.im; }
HiC operator/(const HiC &a, const HiC &b) {
  const Hi n = norm(b);
  return {(a.re * b.re + a.im * b.im) / n, (a.im * b.re - a.re * b.im) / n};
}
HiC hi_of(const Complex &z) { return {hi_of(z.re), hi_of(z.im)}; }

// The independent evaluations, on the disk points w.
HiC image(const Element &g, double x, double y) {
  const Moebius &m = g.matrix();
  const HiC z{Hi(x), Hi(y)};
  return (hi_of(m.a) * z + hi_of(m.b)) / (hi_of(m.c) * z + hi_of(m.d));
}
HiC klein(const HiC &w) {
  const Hi s = Hi(2.0) / (Hi(1.0) + norm(w));
  return {s * w.re, s * w.im};
}
Hi cross(const HiC &a, const HiC &b, const HiC &c) {
  return (b.re - a.re) * (c.im - a.im) - (b.im - a.im) * (c.re - a.re);
}
int hi_orientation(const HiC &a, const HiC &b, const HiC &c) { return sign(cross(klein(a), klein(b), klein(c))); }
// Shewchuk's in-circle determinant of the disk points: + when d is inside
// the circle of a, b, c, counterclockwise.
int hi_in_circle(const HiC &a, const HiC &b, const HiC &c, const HiC &d) {
  const HiC u = a - d, v = b - d, w = c - d;
  const Hi nu = norm(u), nv = norm(v), nw = norm(w);
  return sign(u.re * (v.im * nw - nv * w.im) - u.im * (v.re * nw - nv * w.re) + nu * (v.re * w.im - v.im * w.re));
}
Hi cosh_d(const HiC &a, const HiC &b) {
  return Hi(1.0) + Hi(2.0) * norm(a - b) / ((Hi(1.0) - norm(a)) * (Hi(1.0) - norm(b)));
}
int hi_compare_distance(const HiC &p, const HiC &a, const HiC &b) { return sign(cosh_d(p, a) - cosh_d(p, b)); }
int hi_beyond_side(const FundamentalPolygon &P, int k, const HiC &w) {
  const int s = hi_orientation(hi_of(P.vertex(k)), hi_of(P.vertex(k + 1)), w);
  return s == kUnknown ? s : -s;
}
// The Euclidean circle through a, b, c: a hyperbolic circle when inside the
// disk, its radius from the two points on the diameter through its centre.
int hi_large_circumdisk(const HiC &a, const HiC &b, const HiC &c, const Number &k) {
  const Hi D = Hi(2.0) * (a.re * (b.im - c.im) + b.re * (c.im - a.im) + c.re * (a.im - b.im));
  const Hi na = norm(a), nb = norm(b), nc = norm(c);
  const HiC U{(na * (b.im - c.im) + nb * (c.im - a.im) + nc * (a.im - b.im)) / D,
              (na * (c.re - b.re) + nb * (a.re - c.re) + nc * (b.re - a.re)) / D};
  const Hi R = hsqrt(norm(a - U)), u = hsqrt(norm(U));
  const int circle = sign(Hi(1.0) - (u + R));
  if (circle != 1) return circle == kUnknown ? kUnknown : 1;
  const Hi rho = hatanh(u + R) - hatanh(u - R);
  Hi ch;
  arb_cosh(ch.v, rho.v, kHi);
  const int s = sign(ch * ch - hi_of(k));
  return s == kUnknown ? s : (s >= 0 ? 1 : -1);
}

// The perturbed in-circle sign of four cocircular points from the
// definition: the coefficient of eps_v in det[N_i, 1 + eps_{v_i}], largest v
// first, with the hyperboloid vectors N in 2000 bits; 0 when every
// coefficient is 0 to 2000 bits.
int hi_perturbed_tie(const std::array<HiC, 4> &w, const std::array<uint32_t, 4> &vertex) {
  std::array<std::array<Hi, 3>, 4> N;
  for (int i = 0; i < 4; ++i) {
    const Hi r2 = norm(w[i]), s = Hi(1.0) / (Hi(1.0) - r2);
    N[i] = {(Hi(1.0) + r2) * s, Hi(2.0) * w[i].re * s, Hi(2.0) * w[i].im * s};
  }
  auto det3 = [](const std::array<Hi, 3> &a, const std::array<Hi, 3> &b, const std::array<Hi, 3> &c) {
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  };
  std::array<uint32_t, 4> order = vertex;
  std::sort(order.begin(), order.end(), std::greater<uint32_t>());
  for (const uint32_t v : order) {
    Hi coefficient(0.0);
    for (int r = 0; r < 4; ++r) {
      if (vertex[r] != v) continue;
      std::vector<const std::array<Hi, 3> *> o;
      for (int i = 0; i < 4; ++i)
        if (i != r) o.push_back(&N[std::size_t(i)]);
      const Hi term = det3(*o[0], *o[1], *o[2]);
      coefficient = r % 2 == 1 ? coefficient + term : coefficient - term;
    }
    if (const int s = sign(coefficient); s != kUnknown) return s;
  }
  return 0;
}

// A polygon, its table with the pairings and random words in them, and the kernel.
struct Setup {
  FundamentalPolygon P;
  ElementTable table;
  PolygonKernel kernel;
  std::vector<ElementId> gens, pool;

  explicit Setup(FundamentalPolygon polygon, uint64_t seed = 1)
      : P(std::move(polygon)), table(P.vertex(0).re), kernel(P, table) {
    for (int k = 0; k < P.side_count(); ++k) gens.push_back(table.intern(Element(P.pairing(k))));
    pool.push_back(kIdentityId);
    uint64_t s = seed;
    for (int w = 0; w < 24; ++w) {
      ElementId g = kIdentityId;
      const int length = 1 + int(splitmix(&s) % 4);
      for (int l = 0; l < length; ++l) g = table.compose(g, gens[splitmix(&s) % gens.size()]);
      pool.push_back(g);
    }
  }
  HiC hi(const PolygonPoint &p) const { return image(table.element(p.t), p.x, p.y); }
};

PolygonPoint random_point(Setup &S, uint64_t *s) {
  const double r = 0.95 * std::sqrt(uniform01(s)), a = 2 * M_PI * uniform01(s);
  return {r * std::cos(a), r * std::sin(a), S.pool[splitmix(s) % S.pool.size()]};
}

// A point near q's image, through another element g: z the double nearest to
// (t g)^{-1}(image of q moved by delta times its distance to the circle).
PolygonPoint near_point(Setup &S, const PolygonPoint &q, double delta, uint64_t *s) {
  const ElementId g = S.pool[splitmix(s) % S.pool.size()], t = S.table.compose(q.t, g);
  const HiC w = S.hi(q);
  const double room = delta * (1 - std::sqrt(norm(w).mid())) / 2;
  const double dx = room * (2 * uniform01(s) - 1), dy = room * (2 * uniform01(s) - 1);
  const HiC moved{w.re + Hi(dx), w.im + Hi(dy)};
  const Element back = inverse(S.table.element(t));
  const HiC z = (hi_of(back.matrix().a) * moved + hi_of(back.matrix().b)) /
                (hi_of(back.matrix().c) * moved + hi_of(back.matrix().d));
  return {z.re.mid(), z.im.mid(), t};
}

// Four points: independent (mode 0), or near each other at a random scale
// through the same element (1) or through other elements (2, and 3 a
// thousand times nearer).
std::array<PolygonPoint, 4> random_points(Setup &S, uint64_t *s, int mode = -1) {
  std::array<PolygonPoint, 4> p;
  p[0] = random_point(S, s);
  if (mode < 0) mode = int(splitmix(s) % 4);
  const double delta = std::pow(10.0, -4 * uniform01(s));
  for (int i = 1; i < 4; ++i) {
    if (mode == 0) p[i] = random_point(S, s);
    if (mode == 1) {
      const double r = std::hypot(p[0].x, p[0].y), room = 0.99 - r;
      p[i] = {p[0].x + room * delta * (2 * uniform01(s) - 1) / 2, p[0].y + room * delta * (2 * uniform01(s) - 1) / 2,
              p[0].t};
    }
    if (mode == 2) p[i] = near_point(S, p[0], delta, s);
    if (mode == 3) p[i] = near_point(S, p[0], delta * 1e-3, s);
  }
  return p;
}

// Tallies of one predicate: agreements by sign, and 2000-bit balls that
// could not decide (none is expected on random points).
struct Tally {
  long plus = 0, minus = 0, zero = 0, unknown = 0;
  void add(int kernel, int expected, const char *what) {
    if (expected == kUnknown) {
      ++unknown;
      return;
    }
    ck_assert_msg(kernel == expected, "%s: kernel %d, 2000 bits %d", what, kernel, expected);
    (expected > 0 ? plus : expected < 0 ? minus : zero)++;
  }
};

void check_random(Setup &S, int rounds, uint64_t seed, const char *name) {
  uint64_t s = seed;
  Tally orient, circle, perturbed, distance, beyond, large, same;
  const std::vector<Number> thresholds{q(3, 2), q(4, 1), q(50, 1), cosh2_half_translation(S.table.element(S.gens[0]))};
  for (int round = 0; round < rounds; ++round) {
    const std::array<PolygonPoint, 4> p = random_points(S, &s);
    std::array<HiC, 4> w;
    for (int i = 0; i < 4; ++i) w[i] = S.hi(p[i]);
    PolygonKernel &K = S.kernel;
    orient.add(K.orientation(p[0], p[1], p[2]), hi_orientation(w[0], w[1], w[2]), "orientation");
    const int ic = hi_in_circle(w[0], w[1], w[2], w[3]);
    circle.add(K.in_circle(p[0], p[1], p[2], p[3]), ic, "in_circle");
    perturbed.add(K.in_circle_perturbed(p, {3, 1, 0, 2}), ic, "in_circle_perturbed");
    distance.add(K.compare_distance(p[0], p[1], p[2]), hi_compare_distance(w[0], w[1], w[2]), "compare_distance");
    same.add(K.same_point(p[0], p[1]) ? 0 : 1, sign(norm(w[0] - w[1])), "same_point");
    for (int k = 0; k < S.P.side_count(); ++k)
      beyond.add(K.beyond_side(p[3], k), hi_beyond_side(S.P, k, w[3]), "beyond_side");
    const Number &k = thresholds[std::size_t(round) % thresholds.size()];
    large.add(K.large_circumdisk(p[0], p[1], p[2], k), hi_large_circumdisk(w[0], w[1], w[2], k), "large_circumdisk");
  }
  const std::pair<const char *, Tally *> all[] = {{"orientation", &orient},  {"in_circle", &circle},
                                                  {"perturbed", &perturbed}, {"compare_distance", &distance},
                                                  {"beyond_side", &beyond},  {"large_circumdisk", &large}};
  for (const auto &[what, t] : all) {
    ck_assert_msg(t->unknown == 0, "%s %s: %ld undecided at 2000 bits", name, what, t->unknown);
    ck_assert_msg(t->plus > rounds / 20 && t->minus > rounds / 20, "%s %s: signs + %ld, - %ld of %d", name, what,
                  t->plus, t->minus, rounds);
  }
  ck_assert_int_eq(same.unknown + same.zero, 0);
}

unsigned long exact_count(const PolygonKernel &K, PolygonPredicate p) {
  return K.statistics().decided_by(p, PolygonStage::exact);
}

void print_statistics(const char *name, const PolygonKernel &K) {
  static const char *names[] = {"orientation",      "in_circle",   "in_circle_perturbed", "compare_distance",
                                "same_point",       "beyond_side", "large_circumdisk"};
  for (std::size_t p = 0; p < kPolygonPredicateCount; ++p) {
    const auto &d = K.statistics().decided[p];
    std::printf("%s %-20s structural %lu double %lu ball %lu exact %lu\n", name, names[p], d[0], d[1], d[2], d[3]);
  }
}

// Random points, three ways: all stages, from the ball stage on, the exact
// stage alone; each stage's signs are checked.
void random_suite(FundamentalPolygon P, const char *name, int rounds) {
  Setup S(std::move(P));
  PolygonKernel &K = S.kernel;
  check_random(S, rounds, 7, name);
  print_statistics(name, K);
  ck_assert_uint_gt(K.statistics().decided_by(PolygonPredicate::in_circle, PolygonStage::double_filter), rounds / 3);
  K.reset_statistics();
  K.set_first_stage(PolygonStage::ball);
  check_random(S, rounds / 2, 8, name);
  ck_assert_uint_eq(K.statistics().decided_by(PolygonPredicate::in_circle, PolygonStage::double_filter), 0);
  ck_assert_uint_gt(K.statistics().decided_by(PolygonPredicate::in_circle, PolygonStage::ball), rounds / 4);
  K.reset_statistics();
  K.set_first_stage(PolygonStage::exact);
  check_random(S, rounds / 4, 9, name);
  ck_assert(exact_count(K, PolygonPredicate::in_circle) == unsigned(rounds / 4));
}

}  // namespace

START_TEST(element_table_interns_and_caches) {
  Setup S(bolza());
  ElementTable &T = S.table;
  for (std::size_t k = 0; k < S.gens.size(); ++k) {
    ck_assert(T.intern(Element(S.P.pairing(int(k)))) == S.gens[k]);
    ck_assert(T.compose(S.gens[k], T.inverse(S.gens[k])) == kIdentityId);
    ck_assert(T.inverse(T.inverse(S.gens[k])) == S.gens[k]);
  }
  // The opposite pairings of the Bolza octagon are inverse to each other.
  ck_assert(T.inverse(S.gens[0]) == S.gens[4]);
  // A multiple of a pairing's matrix is the same element.
  Moebius m = S.P.pairing(3);
  const Complex two = Complex(Number(m.a.re.parent(), 2), Number(m.a.re.parent(), 1));
  m = {two * m.a, two * m.b, two * m.c, two * m.d};
  ck_assert(T.intern(Element(m)) == S.gens[3]);
  const ElementId ab = T.compose(S.gens[1], S.gens[2]);
  ck_assert(T.compose(S.gens[1], S.gens[2]) == ab);
  ck_assert(T.element(ab) == T.element(S.gens[1]) * T.element(S.gens[2]));
  // Around the vertex cycle (angle 2 pi) the pairings compose to the identity.
  const std::vector<int> &cycle = S.P.cycles()[0];
  ElementId around = kIdentityId;
  for (int u = cycle[0], step = 0; step < int(cycle.size()); ++step, u = S.P.paired(u) + 1)
    around = T.compose(S.gens[std::size_t(S.P.paired(u))], around);
  ck_assert(around == kIdentityId);
}
END_TEST

// The sign conventions on plain disk points: orientation is the Klein
// model's (the point between the chord and the geodesic from 0.9 to 0.9i is
// clockwise, though counterclockwise for the Poincare points), in_circle +1
// inside.
START_TEST(sign_conventions) {
  Setup S(random_octagon(1));
  PolygonKernel &K = S.kernel;
  const PolygonPoint p{0.9, 0, kIdentityId}, q{0, 0.9, kIdentityId}, r{0.35, 0.35, kIdentityId};
  ck_assert_int_eq(K.orientation(p, q, r), -1);
  ck_assert_int_eq(K.orientation(p, q, {0.25, 0.25, kIdentityId}), 1);
  const PolygonPoint a{0.5, 0, kIdentityId}, b{-0.25, 0.4, kIdentityId}, c{-0.25, -0.4, kIdentityId};
  ck_assert_int_eq(K.orientation(a, b, c), 1);
  ck_assert_int_eq(K.in_circle(a, b, c, {0, 0, kIdentityId}), 1);
  ck_assert_int_eq(K.in_circle(a, b, c, {0.9, 0, kIdentityId}), -1);
  ck_assert_int_eq(K.in_circle(b, a, c, {0, 0, kIdentityId}), -1);
  ck_assert_int_eq(K.compare_distance({0, 0, kIdentityId}, {0.1, 0, kIdentityId}, {0, -0.2, kIdentityId}), -1);
  // The origin is inside every octagon: on the polygon's side of each line.
  for (int k = 0; k < 8; ++k) ck_assert_int_eq(K.beyond_side({0, 0, kIdentityId}, k), -1);
}
END_TEST

START_TEST(random_points_on_the_bolza_octagon) { random_suite(bolza(), "bolza", 400); }
END_TEST

START_TEST(random_points_on_a_rational_octagon) { random_suite(random_octagon(3), "octagon", 400); }
END_TEST

START_TEST(random_points_on_a_regular_12_gon) { random_suite(FundamentalPolygon(genus_3_12_gon()), "12-gon", 300); }
END_TEST

// The images g_k(0) of the centre under the 8 pairings of the Bolza octagon
// lie on one circle about 0 (the pairings are conjugate by the rotation by
// pi/4): exact zeros, which only the exact stage can tell.
START_TEST(bolza_images_of_the_centre_are_cocircular) {
  Setup S(bolza());
  PolygonKernel &K = S.kernel;
  const Complex zero = S.P.exact_point(0, 0);
  const Number c0 = cosh_displacement(S.table.element(S.gens[0]), zero);
  std::vector<PolygonPoint> ring;
  for (const ElementId g : S.gens) {
    ck_assert(cosh_displacement(S.table.element(g), zero) == c0);
    ring.push_back({0, 0, g});
  }
  auto angle = [&](const PolygonPoint &p) {
    const HiC w = S.hi(p);
    return std::atan2(w.im.mid(), w.re.mid());
  };
  std::sort(ring.begin(), ring.end(), [&](auto &a, auto &b) { return angle(a) < angle(b); });
  const PolygonPoint O{0, 0, kIdentityId};
  // Vertex ids, not in the ring's order.
  auto vid = [&](int i) { return uint32_t((5 * i + 3) % 8); };
  int quadruples = 0;
  for (int a = 0; a < 8; ++a)
    for (int b = a + 1; b < 8; ++b)
      for (int c = b + 1; c < 8; ++c)
        for (int d = c + 1; d < 8; ++d) {
          const PolygonPoint &A = ring[a], &B = ring[b], &C = ring[c], &D = ring[d];
          ck_assert_int_eq(K.orientation(A, B, C), 1);
          ck_assert_int_eq(K.in_circle(A, B, C, D), 0);
          ck_assert_int_eq(K.in_circle(D, A, B, C), 0);
          const std::array<uint32_t, 4> v{vid(a), vid(b), vid(c), vid(d)};
          const int s = K.in_circle_perturbed({A, B, C, D}, v);
          ck_assert_int_ne(s, 0);
          // Even permutations keep the perturbed sign, odd ones flip it.
          ck_assert_int_eq(K.in_circle_perturbed({B, C, A, D}, {v[1], v[2], v[0], v[3]}), s);
          ck_assert_int_eq(K.in_circle_perturbed({C, A, B, D}, {v[2], v[0], v[1], v[3]}), s);
          ck_assert_int_eq(K.in_circle_perturbed({B, A, C, D}, {v[1], v[0], v[2], v[3]}), -s);
          ck_assert_int_eq(K.in_circle_perturbed({A, B, D, C}, {v[0], v[1], v[3], v[2]}), -s);
          // The largest id decides: (-1)^(r+1) times the orientation of the other three.
          const int r = int(std::max_element(v.begin(), v.end()) - v.begin());
          std::vector<HiC> others;
          const std::array<const PolygonPoint *, 4> pts{&A, &B, &C, &D};
          for (int i = 0; i < 4; ++i)
            if (i != r) others.push_back(S.hi(*pts[std::size_t(i)]));
          ck_assert_int_eq(s, (r % 2 == 1 ? 1 : -1) * hi_orientation(others[0], others[1], others[2]));
          // The newest point (largest id) on the circle of a ccw triangle is inside it.
          ck_assert_int_eq(K.in_circle_perturbed({A, B, C, D}, {0, 1, 2, 9}), 1);
          // Repeated vertices (copies of one vertex): the definition's sign, or no decision.
          const std::array<HiC, 4> w{S.hi(A), S.hi(B), S.hi(C), S.hi(D)};
          for (const std::array<uint32_t, 4> &u : {std::array<uint32_t, 4>{7, 7, 1, 2}, {3, 1, 3, 3}, {2, 6, 6, 2},
                                                   {4, 4, 4, 4}}) {
            const int expected = hi_perturbed_tie(w, u);
            if (expected == 0) {
              bool refused = false;
              try {
                K.in_circle_perturbed({A, B, C, D}, u);
              } catch (const std::logic_error &) {
                refused = true;
              }
              ck_assert(refused);
            } else {
              ck_assert_int_eq(K.in_circle_perturbed({A, B, C, D}, u), expected);
            }
          }
          ++quadruples;
        }
  ck_assert_int_eq(quadruples, 70);
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) ck_assert_int_eq(K.compare_distance(O, ring[i], ring[j]), 0);
  // Opposite images are antipodal: on one diameter with 0.
  for (int i = 0; i < 4; ++i) {
    ck_assert_int_eq(K.orientation(ring[i], O, ring[i + 4]), 0);
    ck_assert_int_eq(K.orientation(O, ring[i], ring[i + 4]), 0);
  }
  // The circle's radius is d(0, g_k 0): equal to it is large, just above it is not.
  const Number k = c0 * c0, tiny = q(1, 1000000000) * q(1, 1000000000) * q(1, 1000000000) * q(1, 10000000000);
  ck_assert_int_eq(K.large_circumdisk(ring[0], ring[2], ring[5], k), 1);
  ck_assert_int_eq(K.large_circumdisk(ring[0], ring[2], ring[5], k + tiny), -1);
  ck_assert_int_eq(K.large_circumdisk(ring[1], ring[3], ring[4], k - tiny), 1);
  print_statistics("cocircular", K);
  for (const PolygonPredicate p : {PolygonPredicate::in_circle, PolygonPredicate::in_circle_perturbed,
                                   PolygonPredicate::compare_distance, PolygonPredicate::large_circumdisk})
    ck_assert_msg(exact_count(K, p) > 0, "predicate %d never reached the exact stage", int(p));
  ck_assert_uint_eq(K.statistics().decided_by(PolygonPredicate::in_circle, PolygonStage::ball), 0);
  ck_assert_uint_ge(exact_count(K, PolygonPredicate::orientation), 8);
}
END_TEST

// Four points on the real axis, a geodesic (the Bolza octagon's g_3 and g_7
// send 0 onto it): orientation is exactly 0, and no perturbation decides.
START_TEST(four_points_on_one_geodesic) {
  Setup S(bolza());
  PolygonKernel &K = S.kernel;
  std::vector<PolygonPoint> axis{{0, 0, kIdentityId}, {0.3, 0, kIdentityId}};
  for (const ElementId g : S.gens) {
    const HiC w = S.hi({0, 0, g});
    if (sign(w.im) == kUnknown) axis.push_back({0, 0, g});
  }
  ck_assert_uint_eq(axis.size(), 4);
  ck_assert_int_eq(K.orientation(axis[0], axis[2], axis[3]), 0);
  ck_assert_int_eq(K.orientation(axis[1], axis[2], axis[0]), 0);
  ck_assert_int_eq(K.orientation(axis[0], axis[2], {0.1, 1e-300, kIdentityId}), -K.orientation(axis[0], axis[3], {0.1, 1e-300, kIdentityId}));
  ck_assert_int_eq(K.in_circle(axis[0], axis[1], axis[2], axis[3]), 0);
  bool refused = false;
  try {
    K.in_circle_perturbed({axis[0], axis[1], axis[2], axis[3]}, {0, 1, 2, 3});
  } catch (const std::logic_error &) {
    refused = true;
  }
  ck_assert(refused);
  ck_assert_uint_ge(exact_count(K, PolygonPredicate::orientation), 2);
}
END_TEST

// The Bolza octagon moved by an isometry that sends v_0 to 0: the double
// point 0 is a vertex, on the lines of sides 7 and 0, and its images under
// the pairings are vertices on other side lines. Every sign must be the
// 2000-bit one, and every one that 2000 bits cannot tell must be exactly 0.
START_TEST(a_vertex_at_the_origin_is_on_two_side_lines) {
  const FundamentalPolygon B = bolza();
  const Complex v0 = B.vertex(0);
  std::vector<Complex> moved;
  std::vector<int> paired;
  for (int k = 0; k < 8; ++k) {
    const Complex &v = B.vertex(k);
    moved.push_back((v - v0) / (complex_one(v0.re) - conj(v0) * v));
    paired.push_back(B.paired(k));
  }
  Setup S(FundamentalPolygon(B.field(), paired, moved));
  PolygonKernel &K = S.kernel;
  const PolygonPoint O{0, 0, kIdentityId};
  ck_assert_int_eq(K.beyond_side(O, 0), 0);
  ck_assert_int_eq(K.beyond_side(O, 7), 0);
  for (int k = 1; k < 7; ++k) ck_assert_int_eq(K.beyond_side(O, k), -1);
  std::vector<ElementId> elements = S.gens;
  for (const ElementId a : S.gens)
    for (const ElementId b : S.gens) elements.push_back(S.table.compose(a, b));
  long zeros = 0;
  for (const ElementId g : elements) {
    const PolygonPoint p{0, 0, g};
    const HiC w = S.hi(p);
    for (int k = 0; k < 8; ++k) {
      const int expected = hi_beyond_side(S.P, k, w), got = K.beyond_side(p, k);
      ck_assert_int_eq(got, expected == kUnknown ? 0 : expected);
      zeros += got == 0;
    }
  }
  // Each pairing sends 0 to a vertex, on two side lines.
  ck_assert_int_ge(zeros, 16);
  ck_assert_uint_ge(exact_count(K, PolygonPredicate::beyond_side), 18);
  print_statistics("vertex at 0", K);
}
END_TEST

// same_point: one element compares the doubles; an identity-equivalent word
// is the identity's id; near images through other elements are apart, by
// balls or, forced, by the exact stage.
START_TEST(same_point_of_words_and_near_images) {
  Setup S(random_octagon(2));
  PolygonKernel &K = S.kernel;
  const std::vector<int> &cycle = S.P.cycles()[0];
  ElementId around = kIdentityId;
  for (int u = cycle[0], step = 0; step < int(cycle.size()); ++step, u = S.P.paired(u) + 1)
    around = S.table.compose(S.gens[std::size_t(S.P.paired(u))], around);
  ck_assert(K.same_point({0.25, -0.5, around}, {0.25, -0.5, kIdentityId}));
  ck_assert(!K.same_point({0.25, -0.5, S.gens[1]}, {0.25, 0.5, S.gens[1]}));
  uint64_t s = 11;
  for (const PolygonStage first : {PolygonStage::double_filter, PolygonStage::ball, PolygonStage::exact}) {
    K.set_first_stage(first);
    for (int i = 0; i < 50; ++i) {
      const PolygonPoint p = random_point(S, &s), n = near_point(S, p, 0, &s);
      ck_assert_int_eq(K.same_point(p, n), p.t == n.t && p.x == n.x && p.y == n.y);
      ck_assert(K.same_point(p, p));
      const PolygonPoint far = random_point(S, &s);
      ck_assert_int_eq(K.same_point(p, far), p.t == far.t && p.x == far.x && p.y == far.y);
    }
  }
  ck_assert_uint_gt(exact_count(K, PolygonPredicate::same_point), 0);
  ck_assert_uint_gt(K.statistics().decided_by(PolygonPredicate::same_point, PolygonStage::ball), 0);
  ck_assert_uint_gt(K.statistics().decided_by(PolygonPredicate::same_point, PolygonStage::double_filter), 0);
}
END_TEST

// Not a check: microseconds per call on random points of the Bolza octagon,
// all stages, from the ball stage on, exact alone, printed for the record.
START_TEST(costs) {
  Setup S(bolza());
  uint64_t s = 5;
  std::vector<std::array<PolygonPoint, 4>> mixed, independent;
  for (int i = 0; i < 400; ++i) mixed.push_back(random_points(S, &s));
  for (int i = 0; i < 400; ++i) independent.push_back(random_points(S, &s, 0));
  const Number k = q(4, 1);
  const std::pair<const char *, std::function<void(const std::array<PolygonPoint, 4> &)>> predicates[] = {
      {"orientation", [&](const auto &p) { S.kernel.orientation(p[0], p[1], p[2]); }},
      {"in_circle", [&](const auto &p) { S.kernel.in_circle(p[0], p[1], p[2], p[3]); }},
      {"compare_distance", [&](const auto &p) { S.kernel.compare_distance(p[0], p[1], p[2]); }},
      {"beyond_side", [&](const auto &p) { S.kernel.beyond_side(p[0], 3); }},
      {"large_circumdisk", [&](const auto &p) { S.kernel.large_circumdisk(p[0], p[1], p[2], k); }},
      {"same_point", [&](const auto &p) { S.kernel.same_point(p[0], p[1]); }},
  };
  const std::pair<const char *, PolygonStage> firsts[] = {
      {"staged", PolygonStage::double_filter}, {"ball", PolygonStage::ball}, {"exact", PolygonStage::exact}};
  for (const auto &[stage, first] : firsts)
    for (const auto *inputs : {&mixed, &independent}) {
      S.kernel.set_first_stage(first);
      S.kernel.reset_statistics();
      for (const auto &[name, f] : predicates) {
        const auto start = std::chrono::steady_clock::now();
        for (const auto &p : *inputs) f(p);
        const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
        std::printf("cost %-6s %-11s %-18s %8.2f us\n", stage, inputs == &mixed ? "mixed" : "independent", name,
                    us / double(inputs->size()));
      }
      if (first == PolygonStage::double_filter) print_statistics(inputs == &mixed ? "mixed" : "independent", S.kernel);
    }
}
END_TEST

int main() {
  return run_suite("polygon_kernel", 300, [](TCase *tc) {
    tcase_add_test(tc, element_table_interns_and_caches);
    tcase_add_test(tc, sign_conventions);
    tcase_add_test(tc, random_points_on_the_bolza_octagon);
    tcase_add_test(tc, random_points_on_a_rational_octagon);
    tcase_add_test(tc, random_points_on_a_regular_12_gon);
    tcase_add_test(tc, bolza_images_of_the_centre_are_cocircular);
    tcase_add_test(tc, four_points_on_one_geodesic);
    tcase_add_test(tc, a_vertex_at_the_origin_is_on_two_side_lines);
    tcase_add_test(tc, same_point_of_words_and_near_images);
    tcase_add_test(tc, costs);
  });
}
