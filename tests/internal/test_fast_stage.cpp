// Internal tests of the kernel's double-double filter stage (stage 2a).
//
// 1. The double-double operations meet the error bounds that the stage's
//    analysis assumes (predicates/double_double.hpp), against MPFR at 400
//    bits, on random inputs with random low parts, wide exponent spreads and
//    heavy cancellation.
// 2. Configurations the double filter cannot decide at genus 16 and 32
//    (clusters of translated points at the corner v_0 of F_g, where the
//    translations' entries reach 1e5 and more): the kernel's answers, which
//    now pass through stage 2a, equal those of an independent 2126-bit
//    evaluation, and stage 2a decides nearly all of them.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "exact/multiprecision.hpp"
#include "group/generators.hpp"
#include "group/lorentz.hpp"
#include "group/presentation.hpp"
#include "predicates/double_double.hpp"
#include "predicates/kernel.hpp"
#include "predicates/stage_exact.hpp"
#include "surface/exact_polygon.hpp"
#include "surface/polygon.hpp"

// Last: check.h defines a macro named fail that breaks <iostream>.
#include <check.h>

#include "run_suite.hpp"

using namespace hdt;
using predicates::DoubleDouble;
using predicates::Kernel;
using predicates::Stage;
using predicates::TranslatedPoint;

namespace {

using Big = exact::mp_real<120>;  // about 400 bits
using Rng = std::mt19937_64;

constexpr double kU2 = 0x1p-106;  // u^2
constexpr double kOff = 0x1p-108;  // how far the sites off the polygon's vertices are

Big big(const DoubleDouble &x) { return Big(x.hi) + Big(x.lo); }

bool normalised(const DoubleDouble &x) { return x.hi + x.lo == x.hi && std::abs(x.lo) <= 0x1p-53 * std::abs(x.hi); }

// A random normalised double-double of magnitude about 2^e.
DoubleDouble random_dd(Rng &rng, int e) {
  std::uniform_real_distribution<double> unit(0.5, 1.0);
  std::uniform_int_distribution<int> sign(0, 1);
  const double hi = std::ldexp(unit(rng), e) * (sign(rng) ? 1 : -1);
  const double lo = std::ldexp(unit(rng), e - 53 - int(rng() % 4)) * (sign(rng) ? 1 : -1);
  return DoubleDouble::fast_two_sum(hi, lo);
}

double relative_error(const DoubleDouble &computed, const Big &exact) {
  if (exact == 0) return big(computed) == 0 ? 0 : INFINITY;
  return static_cast<double>(abs((big(computed) - exact) / exact));
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

START_TEST(double_double_error_bounds) {
  Rng rng(7001);
  double worst_add = 0, worst_mul = 0, worst_div = 0;
  for (int i = 0; i < 200000; ++i) {
    const int ex = int(rng() % 80) - 40, ey = int(rng() % 80) - 40;
    const DoubleDouble x = random_dd(rng, ex);
    DoubleDouble y = random_dd(rng, ey);
    if (i % 4 == 0) {
      // Heavy cancellation in x + y: y = -x + a few last places of x.
      const DoubleDouble d = random_dd(rng, ex - 40 - int(rng() % 60));
      y = -(x + d);
    }
    const DoubleDouble s = x + y, p = x * y, q = x / y, t = x - y;
    ck_assert(normalised(s) && normalised(p) && normalised(q) && normalised(t));
    worst_add = std::max({worst_add, relative_error(s, big(x) + big(y)), relative_error(t, big(x) - big(y))});
    worst_mul = std::max(worst_mul, relative_error(p, big(x) * big(y)));
    worst_div = std::max(worst_div, relative_error(q, big(x) / big(y)));
  }
  // Products and quotients by plain doubles too (lo = 0).
  for (int i = 0; i < 50000; ++i) {
    const DoubleDouble x = random_dd(rng, int(rng() % 40) - 20), y(random_dd(rng, int(rng() % 40) - 20).hi);
    worst_mul = std::max(worst_mul, relative_error(x * y, big(x) * big(y)));
    worst_div = std::max(worst_div, relative_error(y / x, big(y) / big(x)));
  }
  std::printf("double-double: worst relative errors add %.3f u^2, mul %.3f u^2, div %.3f u^2\n", worst_add / kU2,
              worst_mul / kU2, worst_div / kU2);
  ck_assert_msg(worst_add <= 3.01 * kU2, "add: %g u^2", worst_add / kU2);
  ck_assert_msg(worst_mul <= 8.01 * kU2, "mul: %g u^2", worst_mul / kU2);
  ck_assert_msg(worst_div <= 12.2 * kU2, "div: %g u^2", worst_div / kU2);
}
END_TEST

namespace {

// The reference: hyperboloid vectors from generator products in MPFR at
// 2126 bits (a word of genus 32 loses at most 64 * 14.3 bits), and the
// determinants from them; each sign is asserted to be far above the
// reference's own error (absolute, about 2^-1100 of the points' size).
using Ref = exact::mp_real<640>;
struct RefPoint {
  Ref n[3];
};

RefPoint reference_point(Kernel &kernel, const TranslatedPoint &p) {
  const group::Word &word = kernel.surface().table().word(p.translation);
  const group::Lorentz<Ref> L = group::shared_generators<Ref>(kernel.surface().presentation()).lorentz(word);
  const Ref x(p.x), y(p.y), s = x * x + y * y, w = Ref(1) - s;
  const Ref hat[3] = {Ref(1) + s, x + x, y + y};
  RefPoint r;
  for (int i = 0; i < 3; ++i) r.n[i] = (L.m[i][0] * hat[0] + L.m[i][1] * hat[1] + L.m[i][2] * hat[2]) / w;
  return r;
}

Ref det3(const Ref *a, const Ref *b, const Ref *c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

// The sign of v, asserted decisive: |v| > 2^-900 scale.
int decisive_sign(const Ref &v, const Ref &scale) {
  ck_assert_msg(abs(v) > scale * Ref(0x1p-900), "the reference cannot decide");
  return v > 0 ? 1 : -1;
}

Ref size_of(std::initializer_list<const RefPoint *> points) {
  Ref m(1);
  for (const RefPoint *p : points)
    for (const Ref &x : p->n) m = std::max(m, Ref(abs(x)));
  return m;
}

int reference_orientation(const RefPoint &a, const RefPoint &b, const RefPoint &c) {
  const Ref m = size_of({&a, &b, &c});
  return decisive_sign(det3(a.n, b.n, c.n), m * m * m);
}

int reference_in_circle(const RefPoint &a, const RefPoint &b, const RefPoint &c, const RefPoint &e) {
  Ref d[3][3];
  const RefPoint *q[3] = {&b, &c, &e};
  for (int r = 0; r < 3; ++r)
    for (int i = 0; i < 3; ++i) d[r][i] = q[r]->n[i] - a.n[i];
  const Ref m = size_of({&a, &b, &c, &e});
  return -decisive_sign(det3(d[0], d[1], d[2]), m * m * m);
}

int reference_large_circumdisk(const RefPoint &a, const RefPoint &b, const RefPoint &e, int genus) {
  Ref d2[3], d3[3];
  for (int i = 0; i < 3; ++i) d2[i] = b.n[i] - a.n[i], d3[i] = e.n[i] - a.n[i];
  const Ref c[3] = {d2[1] * d3[2] - d2[2] * d3[1], d2[2] * d3[0] - d2[0] * d3[2], d2[0] * d3[1] - d2[1] * d3[0]};
  const Ref c3 = -(c[0] * a.n[0] + c[1] * a.n[1] + c[2] * a.n[2]);
  const Ref mm = c[0] * c[0] - c[1] * c[1] - c[2] * c[2];
  const Ref m = size_of({&a, &b, &e}), m4 = m * m * m * m;
  if (decisive_sign(mm, m4) < 0) return 1;
  const Ref k = Ref(1) + cos(exact::pi<Ref>() / Ref(2 * genus));
  return decisive_sign(c3 * c3 - k * mm, m4 * m * m);
}

// The copies of F_g around v_0: (j, h) with h(v_j) = v_0 for a neighbour h
// (in double the Minkowski product may be off by 1e-2 at genus 32; other
// vertices of the tiling are much farther). One per vertex v_j.
struct Copy {
  int j;
  group::TranslationId h;
};
std::vector<Copy> copies_around_v0(surface::Surface &M) {
  const int g = M.genus(), n = 4 * g;
  const group::HyperboloidPoint<double> v0 = group::to_hyperboloid(surface::polygon_vertex<double>(g, 0));
  std::vector<Copy> copies;
  for (group::TranslationId h = 0; std::size_t(h) < M.table().neighbour_count(); ++h)
    for (int j = 0; j < n; ++j) {
      const auto image = M.table().lorentz(h).apply(group::to_hyperboloid(surface::polygon_vertex<double>(g, j)));
      if (group::minkowski(image, v0) < 1.5) copies.push_back({j, h});
    }
  ck_assert_int_eq(int(copies.size()), n);
  return copies;
}

}  // namespace

START_TEST(corner_clusters_agree_with_reference) {
  const int g = _i == 0 ? 16 : 32;
  const auto t0 = std::chrono::steady_clock::now();
  surface::Surface M(g);
  Kernel kernel{M};
  const std::vector<Copy> copies = copies_around_v0(M);
  Rng rng(7100 + g);
  // A point of copy c: v_j moved towards 0 by a relative gap in [1e-9, 1e-5]
  // and a small sideways step, then mapped by h close to v_0.
  auto corner_point = [&](const Copy &c) {
    const auto v = surface::polygon_vertex<double>(g, c.j);
    const double gap = std::pow(10.0, std::uniform_real_distribution<double>(-9, -5)(rng));
    const double side = std::uniform_real_distribution<double>(-0.2, 0.2)(rng) * gap;
    return TranslatedPoint{v.re * (1 - gap) - v.im * side, v.im * (1 - gap) + v.re * side, c.h};
  };
  int calls = 0;
  kernel.reset_statistics();
  const int configurations = 150;
  for (int i = 0; i < configurations; ++i) {
    std::array<TranslatedPoint, 4> t;
    for (auto &p : t) p = corner_point(copies[rng() % copies.size()]);
    std::array<RefPoint, 4> r;
    for (int k = 0; k < 4; ++k) r[k] = reference_point(kernel, t[k]);
    const int o = reference_orientation(r[0], r[1], r[2]);
    ck_assert_int_eq(kernel.orientation(t[0], t[1], t[2]), o);
    // in_circle wants a counterclockwise triangle.
    if (o < 0) std::swap(t[1], t[2]), std::swap(r[1], r[2]);
    ck_assert_int_eq(kernel.in_circle(t[0], t[1], t[2], t[3]), reference_in_circle(r[0], r[1], r[2], r[3]));
    ck_assert_int_eq(kernel.large_circumdisk(t[0], t[1], t[2]), reference_large_circumdisk(r[0], r[1], r[2], g));
    calls += 3;
  }
  const auto s = kernel.statistics();
  std::printf("corner clusters g=%d: %d calls: filter %lu, double-double %lu, 133-bit %lu, exact %lu (%.1f s)\n", g,
              calls, s.filtered(), s[Stage::double_double], s[Stage::mpfr], s[Stage::exact], seconds_since(t0));
  // The double stage fails on a third of these and more: every
  // large_circumdisk (the hyperboloid's determinants lose too much here, and
  // it has no disk form), a few in-circle tests and orientations; the
  // double-double stage takes nearly all of those.
  ck_assert_uint_gt(s.past_filters(), calls / 3);
  ck_assert_uint_gt(s[Stage::double_double], s.past_filters() * 9 / 10);
}
END_TEST

// beyond_side, compare_distance and same_point through their refined stages
// (double-double, MPFR) near exact ties, under the long translations of the
// copies of F_g around v_0: h(v_j) = v_0. The sites v_j (with their 133-bit
// approximations) under h are v_0 exactly: on the lines of the two sides
// through v_0 (beyond_side 0), at equal distance from every copy's centre
// h(O) (compare_distance 0), and the same point as v_0. Stored points near
// v_j under h are near those ties. Every call that the double stage leaves
// undecided is compared with the exact stage: a refined stage whose bound is
// too small decides a tie as +1 or -1 and fails here.
START_TEST(refined_stages_agree_with_exact_near_ties) {
  const int g = _i == 0 ? 4 : 16;
  const auto t0 = std::chrono::steady_clock::now();
  surface::Surface M(g);
  Kernel kernel{M};
  // The kernel's last stage on its own, on the same surface, as the reference.
  predicates::ExactStage exact_stage(M);
  const int n = 4 * g;
  const std::vector<Copy> copies = copies_around_v0(M);
  std::vector<int32_t> vertex_site(n), off_site(n);
  for (int j = 0; j < n; ++j) {
    const group::Complex<predicates::MpfrReal> v = surface::polygon_vertex<predicates::MpfrReal>(g, j);
    const group::Complex<double> rounded = surface::vertex(M.presentation(), j);
    const surface::ExactSite exact = surface::exact_vertex(M.field(), j);
    vertex_site[j] = M.add_site(exact, &v, &rounded);
    // v_j + 2^-108, exactly: too near the ties for double-double (its site
    // coordinates are within 2^-106), decided by the 133-bit stage (2^-128).
    const group::Complex<predicates::MpfrReal> w{v.re + kOff, v.im};
    const group::Complex<double> w_rounded{static_cast<double>(w.re), static_cast<double>(w.im)};
    const surface::ExactSite moved{M.field().add(exact.X, M.field().from_double(kOff)), exact.Y, exact.Z};
    off_site[j] = M.add_site(moved, &w, &w_rounded);
  }
  Rng rng(7200 + g);
  auto near_point = [&](const Copy &c) {
    const auto v = surface::polygon_vertex<double>(g, c.j);
    const double gap = std::pow(10.0, std::uniform_real_distribution<double>(-15, -9)(rng));
    const double side = std::uniform_real_distribution<double>(-1, 1)(rng) * gap;
    return TranslatedPoint{v.re * (1 - gap) - v.im * side, v.im * (1 - gap) + v.re * side, c.h};
  };
  const TranslatedPoint v0_site = kernel.site_point(vertex_site[0], 0);
  int compared = 0, ties = 0;
  std::map<std::string, int> by_mpfr;  // calls decided by the 133-bit stage, by predicate
  kernel.reset_statistics();
  // A result that the double stage did not decide (the filtered count did
  // not move), compared with exact().
  auto check = [&](const char *what, int result, const predicates::FilterStatistics &before, auto exact) {
    const predicates::FilterStatistics after = kernel.statistics();
    if (after.filtered() != before.filtered()) return;
    by_mpfr[what] += after[Stage::mpfr] != before[Stage::mpfr];
    const int e = exact();
    ++compared;
    ties += e == 0;
    ck_assert_msg(result == e, "g=%d %s: %d, exact %d", g, what, result, e);
  };
  for (const Copy &c : copies) {
    const TranslatedPoint on = kernel.site_point(vertex_site[c.j], c.h);
    const TranslatedPoint off = kernel.site_point(off_site[c.j], c.h);
    for (const TranslatedPoint &p : {on, off, near_point(c), near_point(c)}) {
      for (int k = 0; k < n; ++k) {
        const predicates::FilterStatistics before = kernel.statistics();
        const int s = kernel.beyond_side(p, k);
        check("beyond_side", s, before, [&] { return to_int(exact_stage.beyond_side(p, k)); });
      }
      for (int t = 0; t < 3; ++t) {
        const TranslatedPoint a{0, 0, copies[rng() % copies.size()].h}, b{0, 0, copies[rng() % copies.size()].h};
        const predicates::FilterStatistics before = kernel.statistics();
        const int s = kernel.compare_distance(p, a, b);
        check("compare_distance", s, before, [&] { return to_int(exact_stage.compare_distance(p, a, b)); });
      }
      const predicates::FilterStatistics before = kernel.statistics();
      const bool same = kernel.same_point(p, v0_site);
      ck_assert_int_eq(same, exact_stage.distinct(p, v0_site) == predicates::Sign::zero);
      const predicates::FilterStatistics after = kernel.statistics();
      if (after.filtered() == before.filtered()) ++compared, ties += same;
      by_mpfr["same_point"] += after[Stage::mpfr] != before[Stage::mpfr];
    }
    ck_assert(kernel.same_point(on, v0_site));
    ck_assert(!kernel.same_point(off, v0_site));
  }
  const auto s = kernel.statistics();
  std::printf("ties g=%d: %d calls past the double stage (%d ties): double-double %lu, 133-bit %lu, exact %lu "
              "(%.1f s)\n", g, compared, ties, s[Stage::double_double], s[Stage::mpfr], s[Stage::exact],
              seconds_since(t0));
  // Every site on v_0 is on two side lines: the ties reach the exact stage,
  // and the refined stages decide the near ones (the sites 2^-108 off v_j
  // the 133-bit stage: each of the three predicates at genus 4; at genus 16
  // the translations' entries, up to 2^18, leave some to the exact stage).
  ck_assert_int_ge(ties, 2 * n);
  ck_assert_uint_ge(s[Stage::exact], (unsigned long)ties);
  ck_assert_uint_gt(s[Stage::double_double], (unsigned long)n);
  for (const char *what : {"beyond_side", "compare_distance", "same_point"}) {
    std::printf("  %s: %d decided by the 133-bit stage\n", what, by_mpfr[what]);
    if (g == 4) ck_assert_msg(by_mpfr[what] > 0, "g=%d: the 133-bit stage never decided %s", g, what);
  }
  ck_assert_uint_gt(s[Stage::mpfr], 0);
}
END_TEST

// The double stage's points (filtered_point with a translation's Moebius
// matrix), and the double-double stage's from the table's split matrix,
// are within their stated error of the 2126-bit reference, for
// translations of N and products of two, on points anywhere in the disk
// (down to 1e-14 from the circle) and near the corners and side midpoints
// of F_g, where the cancellation is worst. The bound there is also sharp
// enough to matter: relative to N0 at most 1e-10 near the corners at genus
// 64 (1.6e-11 measured; the bound of the Lorentz product L p^ / w that the
// stage used before reached 7e-8 on these points).
START_TEST(double_points_within_their_error_bounds) {
  const int g = _i == 0 ? 2 : _i == 1 ? 16 : 64;
  surface::Surface M(g);
  Kernel kernel{M};
  group::TranslationTable &T = M.table();
  Rng rng(9300 + g);
  std::uniform_real_distribution<double> unit(0, 1);
  const int n = 4 * g;
  double worst = 0, worst_corner_bound = 0, worst_dd = 0;
  int points = 0;
  for (int k = 0; k < 400; ++k) {
    const auto N = group::TranslationId(T.neighbour_count());
    group::TranslationId h = group::TranslationId(rng() % std::size_t(N));
    if (k % 4 == 3) h = T.compose(h, group::TranslationId(rng() % std::size_t(N)));
    const auto v = surface::polygon_vertex<double>(g, int(rng() % unsigned(n)));
    const auto m = surface::polygon_side_midpoint<double>(g, int(rng() % unsigned(n)));
    const double angle = 2 * M_PI * unit(rng), radius = 1 - std::pow(10.0, -14 * unit(rng));
    const double gap = std::pow(10.0, -9 + 7 * unit(rng));
    const std::array<std::array<double, 2>, 3> zs = {{{radius * std::cos(angle), radius * std::sin(angle)},
                                                      {v.re * (1 - gap), v.im * (1 - gap)},
                                                      {m.re * (1 - gap), m.im * (1 - gap)}}};
    for (int c = 0; c < 3; ++c) {
      const TranslatedPoint p{zs[c][0], zs[c][1], h};
      const predicates::FilteredPoint f = predicates::filtered_point(p.x, p.y, T.moebius(h));
      const RefPoint r = reference_point(kernel, p);
      for (int i = 0; i < 3; ++i) {
        const double off = static_cast<double>(abs(Ref(f.n[i]) - r.n[i]));
        ck_assert_msg(off <= f.error, "g=%d id %d point (%.17g, %.17g): N%d off by %g, bound %g", g, h, p.x, p.y, i,
                      off, f.error);
        worst = std::max(worst, off / f.error);
      }
      if (c == 1) worst_corner_bound = std::max(worst_corner_bound, f.error / f.n[0]);
      // The double-double stage's point from the table's split matrix.
      const group::Moebius<double> &hi = T.moebius(h), &lo = T.moebius_low(h);
      auto part = [](double a, double b) { return DoubleDouble::fast_two_sum(a, b); };
      const group::Moebius<DoubleDouble> dd{{part(hi.a.re, lo.a.re), part(hi.a.im, lo.a.im)},
                                            {part(hi.b.re, lo.b.re), part(hi.b.im, lo.b.im)}};
      predicates::RefinedPoint<DoubleDouble> e;
      ck_assert(predicates::refined::refined_point_moebius(DoubleDouble(p.x), DoubleDouble(p.y), dd,
                                                           T.moebius_error(h) + 0x1p-105,
                                                           predicates::DoubleDoubleStage::kUnit, &e));
      for (int i = 0; i < 3; ++i) {
        const double off = static_cast<double>(abs(Ref(e.n[i].hi) + Ref(e.n[i].lo) - r.n[i]));
        ck_assert_msg(off <= e.error, "g=%d id %d: double-double N%d off by %g, bound %g", g, h, i, off, e.error);
        worst_dd = std::max(worst_dd, off / e.error);
      }
      ++points;
    }
  }
  std::printf("double points g=%d: %d points, largest error / bound %.3g (double-double %.3g), largest relative "
              "bound near corners %.3g\n", g, points, worst, worst_dd, worst_corner_bound);
  if (g == 64) ck_assert_double_le(worst_corner_bound, 1e-10);
}
END_TEST

// Kernel::hyperboloid's last resort, the 133-bit point, answers where the
// double point (8u + 2^-102 / w relative, w = 1 - |z|^2 computed with
// error-free products) misses 1e-9 and the double-double one
// (4 * 2^-100 / w) misses 1e-12: for an untranslated point, w between about
// 2^-90 (where the MPFR point's 4 * 2^-132 / w misses 1e-12 too) and 2^-72.
// z = (1 - 2^-53, 2^-26 - 2^-55) has w = 2^-80 - 2^-106 - 2^-110. Checked
// against the vector in 400 bits (the squares of doubles are exact there).
START_TEST(hyperboloid_falls_back_to_the_mpfr_point) {
  surface::Surface M(2);
  Kernel kernel{M};
  const double x = 1 - 0x1p-53, y = 0x1p-26 - 0x1p-55;
  const TranslatedPoint p{x, y, 0};
  const Big bx(x), by(y), r2 = bx * bx + by * by, w = Big(1) - r2;
  ck_assert(w == ldexp(Big(1), -80) - ldexp(Big(1), -106) - ldexp(Big(1), -110));
  // Where each stage stands on p (the kernel's stages, built alike).
  const predicates::FilteredPoint f = predicates::filtered_point(x, y);
  ck_assert(!(f.error < 1e-9 * f.n[0]));
  predicates::MpfrStage mpfr(M);
  predicates::DoubleDoubleStage double_double(M, mpfr);
  predicates::DoubleDoublePoint d;
  ck_assert(double_double.point(p, &d));
  ck_assert(!(d.error < 1e-12 * static_cast<double>(d.n[0])));
  predicates::MpfrPoint m;
  ck_assert(mpfr.point(p, &m));
  ck_assert(m.error < 1e-12 * static_cast<double>(m.n[0]));
  bool accurate = false;
  const std::array<double, 3> n = kernel.hyperboloid(p, &accurate);
  ck_assert(accurate);
  const Big ref[3] = {(Big(1) + r2) / w, Big(2) * bx / w, Big(2) * by / w};
  for (int i = 0; i < 3; ++i) {
    // Within the MPFR point's certified bound and the rounding to double,
    // far inside the 1e-12 of N0 that `accurate` promises.
    const Big off = abs(Big(n[i]) - ref[i]);
    ck_assert_msg(off <= Big(m.error) + ldexp(abs(ref[i]), -53), "N%d: %.17g, reference %.17g, bound %g", i, n[i],
                  static_cast<double>(ref[i]), m.error);
    ck_assert(off < Big(1e-12) * ref[0]);
  }
}
END_TEST

int main(void) {
  return run_suite("fast_stage", 600, [](TCase *tc) {
    tcase_add_test(tc, double_double_error_bounds);
    tcase_add_loop_test(tc, double_points_within_their_error_bounds, 0, 3);
    tcase_add_loop_test(tc, corner_clusters_agree_with_reference, 0, 2);
    tcase_add_loop_test(tc, refined_stages_agree_with_exact_near_ties, 0, 2);
    tcase_add_test(tc, hyperboloid_falls_back_to_the_mpfr_point);
  });
}
