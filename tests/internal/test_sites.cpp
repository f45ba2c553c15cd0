// Exact algebraic sites: the points of Q0 (vertices, side midpoints) and
// rotated images of rational points, their exact degeneracies and their
// canonical representatives.
#include <cmath>
#include <vector>

#include "exact/multiprecision.hpp"
#include "predicates/kernel.hpp"
#include "predicates/stage_double.hpp"
#include "predicates/stage_exact.hpp"
#include "surface/exact_polygon.hpp"
#include "surface/polygon.hpp"
#include "predicates/representative.hpp"
#include "surface/systole.hpp"

// Last: check.h defines a macro named fail that breaks <iostream>.
#include <check.h>

#include "run_suite.hpp"

using namespace hdt;
using predicates::Kernel;
using predicates::TranslatedPoint;

namespace {

struct Q0 {
  std::vector<TranslatedPoint> vertices, midpoints;
};

Q0 polygon_sites(Kernel &kernel) {
  Q0 q;
  const int n = kernel.surface().presentation().letter_count();
  for (int k = 0; k < n; ++k) {
    q.vertices.push_back(kernel.site_point(kernel.surface().add_site(surface::exact_vertex(kernel.surface().field(), k)), 0));
    q.midpoints.push_back(
        kernel.site_point(kernel.surface().add_site(surface::exact_side_midpoint(kernel.surface().field(), k)), 0));
  }
  return q;
}

// |a - b| in units of 2^-53 |b|, b = (x, y) a point: one coordinate may be
// (near) zero, so the point's modulus sets the scale.
double error_in_units(double a, double b, double modulus) { return std::abs(a - b) / (std::ldexp(1.0, -53) * modulus); }

}  // namespace

START_TEST(site_coordinates_match_multiprecision_formulas) {
  using T = exact::mp_real<60>;
  for (int g = 2; g <= 8; ++g) {
    surface::Surface M(g);
    Kernel kernel{M};
    const Q0 q = polygon_sites(kernel);
    for (int k = 0; k < 4 * g; ++k) {
      const auto v = surface::polygon_vertex<T>(g, k), m = surface::polygon_side_midpoint<T>(g, k);
      const double rv = std::hypot(q.vertices[k].x, q.vertices[k].y), rm = std::hypot(q.midpoints[k].x, q.midpoints[k].y);
      ck_assert_double_le(error_in_units(q.vertices[k].x, v.re.convert_to<double>(), rv), 4);
      ck_assert_double_le(error_in_units(q.vertices[k].y, v.im.convert_to<double>(), rv), 4);
      ck_assert_double_le(error_in_units(q.midpoints[k].x, m.re.convert_to<double>(), rm), 4);
      ck_assert_double_le(error_in_units(q.midpoints[k].y, m.im.convert_to<double>(), rm), 4);
    }
  }
}
END_TEST

// The rotation sequence gives each midpoint exactly as its own two products
// do: every one at small genus (Phi_8g = x^4g + 1 or not: 2, 3, 5, 6, 8), a
// few at 127 (Phi_1016 has 127 nonzero coefficients of 505) and 128.
START_TEST(side_midpoints_from_rotations_are_the_products) {
  for (int g : {2, 3, 5, 6, 8, 127, 128}) {
    const exact::Field &F = exact::field_of_genus(g);
    const std::vector<surface::ExactSite> all = surface::exact_side_midpoints(F, 4 * g);
    ck_assert_uint_eq(all.size(), 4 * std::size_t(g));
    auto equal = [&](const exact::FieldElement &a, const exact::FieldElement &b) { return F.is_zero(F.sub(a, b)); };
    for (int k = 0; k < 4 * g; ++k) {
      if (g > 8 && k != 0 && k != 1 && k != g - 1 && k != g && k != 2 * g + 1 && k != 4 * g - 1) continue;
      const surface::ExactSite one = surface::exact_side_midpoint(F, k);
      ck_assert_msg(equal(all[k].X, one.X) && equal(all[k].Y, one.Y) && equal(all[k].Z, one.Z), "g=%d k=%d", g, k);
    }
  }
  ck_assert_uint_eq(surface::exact_side_midpoints(exact::field_of_genus(4), 3).size(), 3);
}
END_TEST

// A site's hyperboloid vector (from 133-bit evaluations with certified
// bounds when they suffice, else from exact products) is
// within 4u of each entry of the vector computed in 200 bits from the
// polygon's formulas: the vertices and side midpoints at genus 2, 16 and
// 127, and a site 2^-70 from the circle (where the evaluations cannot tell).
START_TEST(site_vectors_within_four_units) {
  using T = exact::mp_real<60>;
  const double u = std::ldexp(1.0, -53);
  for (int g : {2, 16, 127}) {
    surface::Surface M(g);
    const exact::Field &F = M.field();
    std::vector<std::array<T, 2>> z;
    const std::vector<surface::ExactSite> m = surface::exact_side_midpoints(F, 4 * g);
    for (int k = 0; k < 4 * g; k += (g > 16 ? 7 : 1)) {
      M.add_site(surface::exact_vertex(F, k));
      const auto v = surface::polygon_vertex<T>(g, k);
      z.push_back({v.re, v.im});
      M.add_site(m[std::size_t(k)]);
      const auto w = surface::polygon_side_midpoint<T>(g, k);
      z.push_back({w.re, w.im});
    }
    const exact::FieldElement one = F.from_double(1), tiny = F.from_double(std::ldexp(1.0, -70));
    M.add_site({F.sub(one, tiny), F.zero(), one});
    z.push_back({T(1) - ldexp(T(1), -70), T(0)});
    for (std::size_t s = 0; s < z.size(); ++s) {
      const std::array<double, 3> &n = M.site(int32_t(s)).vector;
      const T r2 = z[s][0] * z[s][0] + z[s][1] * z[s][1], w = 1 - r2;
      const T ref[3] = {(1 + r2) / w, 2 * z[s][0] / w, 2 * z[s][1] / w};
      for (int i = 0; i < 3; ++i)
        ck_assert_msg(abs(T(n[i]) - ref[i]) <= T(4 * u) * abs(ref[i]) + T(1e-50), "g=%d site %zu entry %d: %.17g, %.17g",
                      g, s, i, n[i], ref[i].convert_to<double>());
    }
  }
}
END_TEST

START_TEST(polygon_points_are_exactly_cocircular_and_on_sides) {
  for (int g = 2; g <= 5; ++g) {
    surface::Surface M(g);
    Kernel kernel{M};
    const Q0 q = polygon_sites(kernel);
    const int n = 4 * g;
    const TranslatedPoint origin{0, 0, 0};
    for (int k = 0; k < n; ++k) {
      const int a = k, b = (k + 1) % n, c = (k + 2) % n, d = (k + 3) % n;
      // Four midpoints (and four vertices) on the circle about 0.
      ck_assert_int_eq(kernel.in_circle(q.midpoints[a], q.midpoints[b], q.midpoints[c], q.midpoints[d]), 0);
      ck_assert_int_eq(kernel.in_circle(q.vertices[a], q.vertices[b], q.vertices[c], q.vertices[d]), 0);
      ck_assert_int_eq(kernel.in_circle(q.midpoints[a], q.midpoints[b], q.midpoints[c], origin), 1);
      ck_assert_int_eq(kernel.orientation(q.midpoints[a], q.midpoints[b], q.midpoints[c]), 1);
      // m_k on side s_k; v_k on s_k and s_{k+1}; strictly inside the others.
      for (int s = 0; s < n; ++s) {
        ck_assert_int_eq(kernel.beyond_side(q.midpoints[k], s), s == k ? 0 : -1);
        ck_assert_int_eq(kernel.beyond_side(q.vertices[k], s), (s == k || s == b) ? 0 : -1);
      }
      // A translated copy of the circle stays exactly a circle.
      const group::TranslationId t = group::TranslationId(1 + k % (kernel.surface().table().neighbour_count() - 1));
      auto moved = [&](const TranslatedPoint &p) { return TranslatedPoint{p.x, p.y, t, p.site}; };
      ck_assert_int_eq(
          kernel.in_circle(moved(q.midpoints[a]), moved(q.midpoints[b]), moved(q.midpoints[c]), moved(q.midpoints[d])),
          0);
    }
  }
}
END_TEST

START_TEST(paired_points_have_one_representative) {
  for (int g = 2; g <= 8; ++g) {
    surface::Surface M(g);
    Kernel kernel{M};
    const Q0 q = polygon_sites(kernel);
    const int n = 4 * g, half = 2 * g;
    const predicates::Representative rv0 = predicates::representative(kernel, q.vertices[0]);
    ck_assert_int_eq(rv0.where, predicates::Representative::vertex);
    ck_assert_int_eq(rv0.translation, 0);
    for (int k = 0; k < n; ++k) {
      // Every vertex goes to v_0 itself.
      const predicates::Representative rv = predicates::representative(kernel, q.vertices[k]);
      ck_assert_int_eq(rv.where, predicates::Representative::vertex);
      ck_assert(kernel.same_point({q.vertices[k].x, q.vertices[k].y, rv.translation, q.vertices[k].site}, q.vertices[0]));
      // m_k and m_{k+2g} share the representative m_{k mod 2g}.
      const predicates::Representative rm = predicates::representative(kernel, q.midpoints[k]);
      ck_assert_int_eq(rm.where, predicates::Representative::side);
      ck_assert_int_eq(rm.side_index, k % half);
      ck_assert(kernel.same_point({q.midpoints[k].x, q.midpoints[k].y, rm.translation, q.midpoints[k].site},
                                  q.midpoints[k % half]));
      ck_assert(!kernel.same_point(q.midpoints[k], q.midpoints[(k + 1) % n]));
    }
  }
}
END_TEST

START_TEST(rotated_rational_points_are_cocircular) {
  // z = (5/16, 1/8) rotated by j pi/2g: 8g exact points on one circle about 0.
  for (int g : {2, 3, 4}) {
    surface::Surface M(g);
    Kernel kernel{M};
    const exact::Field &F = kernel.surface().field();
    const exact::CyclotomicField &K = F.cyclotomic();
    std::vector<TranslatedPoint> ring;
    for (int j = 0; j < 8 * g; ++j) {
      const exact::Cyclotomic c = K.cos_2pi(j), s = K.sin_2pi(j);  // angle j pi/4g
      const exact::Cyclotomic x = K.from_double(0.3125), y = K.from_double(0.125);
      const predicates::ExactSite site{F.from_cyclotomic(K.sub(K.mul(x, c), K.mul(y, s))),
                                       F.from_cyclotomic(K.add(K.mul(x, s), K.mul(y, c))),
                                       F.from_cyclotomic(K.integer(1))};
      ring.push_back(kernel.site_point(kernel.surface().add_site(site), 0));
    }
    const int n = int(ring.size());
    for (int j = 0; j < n; ++j)
      ck_assert_int_eq(kernel.in_circle(ring[j], ring[(j + 1) % n], ring[(j + 3) % n], ring[(j + 6) % n]), 0);
    // The rational point itself is on the ring too (j = 0 is exact).
    ck_assert(kernel.same_point(ring[0], TranslatedPoint{0.3125, 0.125, 0}));
    // One ulp outward is outside, one ulp inward inside.
    const TranslatedPoint out{std::nextafter(0.3125, 1.0), 0.125, 0}, in{std::nextafter(0.3125, 0.0), 0.125, 0};
    ck_assert_int_eq(kernel.in_circle(ring[1], ring[3], ring[5], out), -1);
    ck_assert_int_eq(kernel.in_circle(ring[1], ring[3], ring[5], in), 1);
  }
}
END_TEST

START_TEST(sites_reject_points_outside_the_disk) {
  surface::Surface M(2);
  Kernel kernel{M};
  const exact::Field &F = kernel.surface().field();
  const exact::CyclotomicField &K = F.cyclotomic();
  // sigma e^{i pi/8} / (1/2): outside.
  predicates::ExactSite outside = surface::exact_vertex(F, 0);
  outside.Z = F.from_cyclotomic(K.from_double(0.5));
  ck_assert_int_eq(int(kernel.statistics().calls()), 0);
  bool thrown = false;
  try {
    kernel.surface().add_site(outside);
  } catch (const std::domain_error &) {
    thrown = true;
  }
  ck_assert(thrown);
  // sigma e^{i pi/8} / sigma: on the circle, where no evaluation can tell and
  // the exact test refuses the tie.
  predicates::ExactSite on = surface::exact_vertex(F, 0);
  on.Z = F.sigma();
  thrown = false;
  try {
    kernel.surface().add_site(on);
  } catch (const std::domain_error &) {
    thrown = true;
  }
  ck_assert(thrown);
}
END_TEST

// Field::evaluate_133's bound holds the value computed independently in 200
// bits (the polygon's formulas in MPFR) and is tiny: the side midpoints'
// coordinates X = Re(m) sigma, Y = Im(m) sigma, and sigma itself. The
// site vectors' certificate rests on it.
START_TEST(evaluation_bounds_hold_the_multiprecision_values) {
  using T = exact::mp_real<60>;
  for (int g : {2, 3, 5, 127}) {
    const exact::Field &F = exact::field_of_genus(g);
    const T sigma = sqrt(cos(exact::pi<T>() / T(2 * g)));
    const std::vector<surface::ExactSite> m = surface::exact_side_midpoints(F, 4 * g);
    for (int k = 0; k < 4 * g; k += (g > 5 ? 17 : 1)) {
      const auto ref = surface::polygon_side_midpoint<T>(g, k);
      const T values[3] = {ref.re * sigma, ref.im * sigma, sigma};
      const exact::FieldElement *elements[3] = {&m[k].X, &m[k].Y, &m[k].Z};
      for (int c = 0; c < 3; ++c) {
        exact::mp_real<40> value, bound;
        F.evaluate_133(*elements[c], &value, &bound);
        // An exact zero (a midpoint on an axis) evaluates to 0 with bound 0;
        // the reference is zero up to its own rounding there.
        const bool zero = value == 0 && bound == 0 && abs(values[c]) < T(1e-50);
        ck_assert_msg(zero || abs(T(value) - values[c]) <= T(bound), "g=%d k=%d coordinate %d outside its bound", g, k,
                      c);
        ck_assert_msg(bound <= ldexp(exact::mp_real<40>(1), -100) * (abs(value) > 1 ? abs(value) : exact::mp_real<40>(1)),
                      "g=%d k=%d coordinate %d: bound %g too wide", g, k, c, bound.convert_to<double>());
      }
    }
  }
}
END_TEST

START_TEST(large_circumdisk_matches_the_systole_threshold) {
  // (r, 0), (0, r), (-r, 0) lie on the circle about 0 of hyperbolic radius
  // 2 artanh(r): its diameter reaches sys/2 exactly when r = tanh(sys/8).
  for (int g = 2; g <= 6; ++g) {
    surface::Surface M(g);
    Kernel kernel{M};
    predicates::ExactStage exact(M);  // the kernel's last stage, on its own
    const double critical = std::tanh(surface::systole<double>(g) / 8);
    for (double offset : {-1e-3, -1e-9, 1e-9, 1e-3}) {
      const double r = std::ldexp(std::round(std::ldexp(critical + offset, 40)), -40);  // dyadic
      const int expected = r > critical ? 1 : -1;
      for (group::TranslationId t : {0, 1, 5, 17}) {
        const TranslatedPoint a{r, 0, t}, b{0, r, t}, c{-r, 0, t};
        ck_assert_int_eq(kernel.large_circumdisk(a, b, c), expected);
        ck_assert_int_eq(to_int(exact.large_circumdisk(a, b, c)), expected);
        ck_assert_int_eq(kernel.large_circumdisk(b, c, a), expected);
      }
    }
    // Three points far apart are on no circle at all (a hypercycle): large.
    ck_assert_int_eq(kernel.large_circumdisk({0.9, 0, 0}, {-0.9, 0.001, 0}, {0, 0.0001, 0}), 1);
    // Random triples: the filter agrees with the exact evaluation.
    uint64_t seed = 99;
    auto uniform = [&seed]() {
      seed = seed * 6364136223846793005ull + 1442695040888963407ull;
      return double(seed >> 11) * 0x1p-53 * 1.2 - 0.6;
    };
    for (int i = 0; i < 300; ++i) {
      const TranslatedPoint a{uniform(), uniform(), 0}, b{uniform(), uniform(), group::TranslationId(i % 9)},
          c{uniform() * 0.5, uniform() * 0.5, 0};
      ck_assert_int_eq(kernel.large_circumdisk(a, b, c), to_int(exact.large_circumdisk(a, b, c)));
    }
  }
}
END_TEST

int main(void) {
  return run_suite("sites", 300, [](TCase *tc) {
    tcase_add_test(tc, site_coordinates_match_multiprecision_formulas);
    tcase_add_test(tc, side_midpoints_from_rotations_are_the_products);
    tcase_add_test(tc, site_vectors_within_four_units);
    tcase_add_test(tc, polygon_points_are_exactly_cocircular_and_on_sides);
    tcase_add_test(tc, paired_points_have_one_representative);
    tcase_add_test(tc, rotated_rational_points_are_cocircular);
    tcase_add_test(tc, sites_reject_points_outside_the_disk);
    tcase_add_test(tc, evaluation_bounds_hold_the_multiprecision_values);
    tcase_add_test(tc, large_circumdisk_matches_the_systole_threshold);
  });
}
