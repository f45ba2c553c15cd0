// Home images (surface/home_image.hpp): the certified image of a point far
// from F_g under its home word, against the word's matrix multiplied at the
// top multiprecision rung (2560 digits: another route to the same point),
// and the double vector against that reference within its stated error.
#include <cmath>

#include "exact/multiprecision.hpp"
#include "group/certified_image.hpp"
#include "group/generators.hpp"
#include "predicates/kernel.hpp"
#include "predicates/representative.hpp"
#include "surface/home_image.hpp"
#include "surface/surface.hpp"

extern "C" {
#include <check.h>
}

#include "random.hpp"
#include "run_suite.hpp"

using namespace hdt;
using Reference = exact::mp_real<2560>;

namespace {

// Points with 1 - |z| in [gap, 2 gap] at random angles, their homes found by
// the exact representative walk, each checked.
void check_genus(int g, double gap, int count) {
  surface::Surface S(g);
  predicates::Kernel K(S);
  uint64_t rng = 77 + uint64_t(g);
  int far = 0;
  for (int i = 0; i < count; ++i) {
    const double r = 1 - gap * (1 + uniform01(&rng)), a = 2 * M_PI * uniform01(&rng);
    const double x = r * std::cos(a), y = r * std::sin(a);
    const group::TranslationId home = predicates::representative(K, x, y).translation;
    if (home == 0) continue;
    const group::Word &w = S.table().word(home);
    const group::Complex<Reference> ref = group::shared_generators<Reference>(S.presentation()).moebius(w).apply(
        group::Complex<Reference>{Reference(x), Reference(y)});
    const std::optional<surface::HomeImage> h = surface::make_home_image(S.presentation(), S.table(), x, y, home);
    ck_assert_msg(h.has_value(), "g=%d: no certified image of (%a, %a) (%zu letters)", g, x, y, w.size());
    const Reference ex = abs(Reference(h->approximation.re) - ref.re), ey = abs(Reference(h->approximation.im) - ref.im);
    ck_assert_msg(ex <= ldexp(Reference(1), -128) && ey <= ldexp(Reference(1), -128),
                  "g=%d: the image of (%a, %a) is off by 2^%.1f, 2^%.1f", g, x, y,
                  static_cast<double>(log2(ex + ldexp(Reference(1), -2000))),
                  static_cast<double>(log2(ey + ldexp(Reference(1), -2000))));
    const Reference s = ref.re * ref.re + ref.im * ref.im, den = 1 - s;
    const Reference n[3] = {(1 + s) / den, 2 * ref.re / den, 2 * ref.im / den};
    for (int k = 0; k < 3; ++k)
      ck_assert_msg(abs(Reference(h->vector[k]) - n[k]) <= Reference(h->vector_error),
                    "g=%d: vector entry %d of (%a, %a) outside its error bound", g, k, x, y);
    ++far;
  }
  ck_assert_msg(far * 2 >= count, "g=%d: only %d of %d points had a home", g, far, count);
}

}  // namespace

START_TEST(images_near_the_circle_within_2e_128) {
  check_genus(2, 1e-15, 30);
  check_genus(3, 0x1p-52, 20);
  check_genus(8, 1e-9, 20);
  check_genus(32, 1e-15, 10);
}
END_TEST

START_TEST(images_at_genus_256) { check_genus(256, 1e-15, 4); }
END_TEST

START_TEST(a_point_next_to_the_circle_is_far_and_one_inside_is_not) {
  ck_assert(surface::far_from_domain(1 - 1e-15, 0, 5));
  ck_assert(!surface::far_from_domain(1 - 1e-15, 0, 0));  // home in F_g: no image needed
  ck_assert(!surface::far_from_domain(0.9, 0, 5));
}
END_TEST

int main() {
  return run_suite("home_images", 300, [](TCase *tc) {
    tcase_add_test(tc, images_near_the_circle_within_2e_128);
    tcase_add_test(tc, images_at_genus_256);
    tcase_add_test(tc, a_point_next_to_the_circle_is_far_and_one_inside_is_not);
  });
}
