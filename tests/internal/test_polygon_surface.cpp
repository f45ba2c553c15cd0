// lib/domain's PolygonSurface (polygon_surface.hpp): the home of a point as
// an element id must be the element of the exact reduction (representative.hpp,
// the walk with every decision exact), interned to the same id; the double
// image must be the exact representative rounded; the systole threshold must
// be a lower bound of cosh^2(sys / 4), checked against the published Bolza
// value and, exactly, against the systole's own cosh^2.
#include <cmath>
#include <complex>
#include <stdexcept>

#include "domain/field_lock.hpp"
#include "domain/polygon_surface.hpp"
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

// Random points up to radius r_max (uniform in the radius, so many near the
// circle), their homes against the exact walk.
void check_homes(FundamentalPolygon P, const char *name, int n, double r_max) {
  const FieldLock lock(P.field() != nullptr);
  const Reduction exact(P);
  PolygonSurface S(std::move(P));
  uint64_t state = 17;
  std::size_t moved = 0;
  for (int i = 0; i < n; ++i) {
    const double r = r_max * uniform01(&state), a = 2 * M_PI * uniform01(&state);
    const double x = r * std::cos(a), y = r * std::sin(a);
    const ElementId h = S.home(x, y);
    const Representative e = exact(S.polygon().exact_point(x, y));
    ck_assert_msg(S.table().element(h) == e.word.element, "%s: point %d (%.17g, %.17g): home is not the exact walk's",
                  name, i, x, y);
    ck_assert_msg(S.table().intern(e.word.element) == h, "%s: point %d: the same element under two ids", name, i);
    const std::complex<double> w = S.image(h, x, y);
    const double ex = static_cast<double>(e.point.re), ey = static_cast<double>(e.point.im);
    ck_assert_msg(std::abs(w - std::complex<double>(ex, ey)) < 1e-12, "%s: point %d: image %.17g %.17g, exact %.17g %.17g",
                  name, i, w.real(), w.imag(), ex, ey);
    moved += h != kIdentityId;
  }
  ck_assert_msg(moved > std::size_t(n) / 10, "%s: only %zu of %d points left P: the test tests little", name, moved, n);
}

}  // namespace

START_TEST(homes_on_the_bolza_octagon) { check_homes(bolza(), "bolza", 300, 0.995); }
END_TEST

START_TEST(homes_on_random_rational_octagons) {
  for (uint64_t seed = 1; seed <= 3; ++seed) check_homes(random_octagon(seed), "octagon", 200, 0.99);
}
END_TEST

START_TEST(homes_on_a_decagon_with_two_cycles) {
  check_homes(random_symmetric_polygon(5, 4), "decagon", 200, 0.99);
}
END_TEST

START_TEST(homes_on_the_commutator_12_gon) {
  check_homes(FundamentalPolygon(genus_3_commutator_12_gon()), "12-gon", 300, 0.999);
}
END_TEST

START_TEST(pairings_are_ids_and_inverse_in_pairs) {
  const FieldLock lock(true);
  PolygonSurface S(bolza());
  for (int k = 0; k < 8; ++k) {
    ck_assert_uint_ne(S.pairing(k), kIdentityId);
    ck_assert_uint_eq(S.table().compose(S.pairing(k), S.pairing(S.polygon().paired(k))), kIdentityId);
    ck_assert_uint_eq(S.table().inverse(S.pairing(k)), S.pairing(S.polygon().paired(k)));
  }
  // The centre and points near it are their own representatives.
  ck_assert_uint_eq(S.home(0, 0), kIdentityId);
  ck_assert_uint_eq(S.home(0.3, -0.2), kIdentityId);
}
END_TEST

START_TEST(points_off_the_open_disk_are_refused) {
  PolygonSurface S(random_octagon(1));
  const double points[][2] = {{1, 0}, {0, -1}, {0.8, 0.6000000000000001}, {NAN, 0}, {0, INFINITY}, {2, 2}};
  for (const auto &p : points) {
    bool refused = false;
    try {
      S.home(p[0], p[1]);
    } catch (const std::domain_error &) {
      refused = true;
    }
    ck_assert_msg(refused, "(%.17g, %.17g) was not refused", p[0], p[1]);
  }
  // Just inside the circle, exactly: 1 - 2^-53 < 1.
  const double x = std::nextafter(1.0, 0.0);
  ck_assert(S.home(x, 0) < S.table().size());
}
END_TEST

// Bolza: sys = 2 arccosh(1 + sqrt 2) (Aurich-Steiner, Jenni), so
// cosh^2(sys / 4) = (1 + cosh(sys / 2)) / 2 = 1 + sqrt(2) / 2.
START_TEST(threshold_below_the_bolza_value) {
  const FieldLock lock(true);
  PolygonSurface S(bolza());
  const double k = static_cast<double>(S.quarter_systole_cosh2_below());
  const double published = 1 + std::sqrt(2.0) / 2;
  ck_assert_msg(k <= published && k > published - 1e-14, "threshold %.17g, cosh^2(sys/4) = %.17g", k, published);
}
END_TEST

// Exactly: (2k - 1)^2 <= cosh^2(sys / 2), k >= 1, and within 1e-12 of the
// systole's length interval's value.
START_TEST(threshold_below_cosh2_of_the_systole) {
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    PolygonSurface S(random_octagon(seed));
    const Number &k = S.quarter_systole_cosh2_below();
    const Number s = 2 * k - 1;
    ck_assert(k >= 1);
    ck_assert(s * s <= S.systole().cosh2_half);
    const double c = std::cosh(S.systole().length.hi / 4);
    ck_assert_msg(std::abs(static_cast<double>(k) - c * c) < 1e-12, "seed %d: %.17g vs %.17g", int(seed),
                  static_cast<double>(k), c * c);
  }
}
END_TEST

int main() {
  return run_suite("polygon_surface", 300, [](TCase *tc) {
    tcase_add_test(tc, homes_on_the_bolza_octagon);
    tcase_add_test(tc, homes_on_random_rational_octagons);
    tcase_add_test(tc, homes_on_a_decagon_with_two_cycles);
    tcase_add_test(tc, homes_on_the_commutator_12_gon);
    tcase_add_test(tc, pairings_are_ids_and_inverse_in_pairs);
    tcase_add_test(tc, points_off_the_open_disk_are_refused);
    tcase_add_test(tc, threshold_below_the_bolza_value);
    tcase_add_test(tc, threshold_below_cosh2_of_the_systole);
  });
}
