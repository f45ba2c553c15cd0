// The predicates of a refined stage (double-double, MPFR), written once.
// A stage supplies its points and constants; this base evaluates each
// predicate with the shared analysis of stage_refined.hpp. Every predicate
// is undecided when one of its points is not available in the stage.
//
// Stage (CRTP) must provide, with Real its reals and Stage::kUnit the U of
// stage_refined.hpp:
//   bool point(const TranslatedPoint &, RefinedPoint<Real> *);
//   const group::Lorentz<Real> &matrix(TranslationId);  // entries within U L00 of the exact ones
//   const Real &circumdisk_constant();                    // 1 + cos(pi/2g) within U relative
#pragma once

#include "group/lorentz.hpp"
#include "predicates/sign.hpp"
#include "predicates/stage_refined.hpp"
#include "predicates/translated_point.hpp"
#include "surface/surface.hpp"

namespace hdt::predicates {

template <class Stage, class Real>
class RefinedPredicates {
 public:
  using Point = RefinedPoint<Real>;

  Sign orientation(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r) {
    Point a, b, c;
    if (!points({&p, &q, &r}, {&a, &b, &c})) return Sign::undecided;
    return refined::orientation_sign(a, b, c, Stage::kUnit);
  }

  Sign in_circle(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r,
                 const TranslatedPoint &s) {
    Point a, b, c, e;
    if (!points({&p, &q, &r, &s}, {&a, &b, &c, &e})) return Sign::undecided;
    return refined::in_circle_sign(a, b, c, e, Stage::kUnit);
  }

  Sign beyond_side(const TranslatedPoint &p, int side) {
    Point a;
    if (!points({&p}, {&a})) return Sign::undecided;
    // g_k's matrix entries within U L00 (the stage's contract); 1 - L00
    // rounds once more, within U |1 - L00| <= U L00: every n_i within 2U L00.
    const group::Lorentz<Real> &L = stage().matrix(surface::Surface::letter(group::Letter(side)));
    const Real n[3] = {Real(1) - L.m[0][0], L.m[1][0], L.m[2][0]};
    const double L00 = refined::magnitude(L.m[0][0]) * (1 + 2 * Stage::kUnit);
    return refined::beyond_side_sign(a, n, L00, 2 * Stage::kUnit * L00, Stage::kUnit);
  }

  Sign compare_distance(const TranslatedPoint &p, const TranslatedPoint &a, const TranslatedPoint &b) {
    Point x, y, z;
    if (!points({&p, &a, &b}, {&x, &y, &z})) return Sign::undecided;
    return refined::compare_distance_sign(x, y, z, Stage::kUnit);
  }

  Sign distinct(const TranslatedPoint &p, const TranslatedPoint &q) {
    Point a, b;
    if (!points({&p, &q}, {&a, &b})) return Sign::undecided;
    return refined::distinct_sign(a, b, Stage::kUnit);
  }

  Sign large_circumdisk(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r) {
    Point a, b, e;
    if (!points({&p, &q, &r}, {&a, &b, &e})) return Sign::undecided;
    return refined::large_circumdisk_sign(a, b, e, stage().circumdisk_constant(), Stage::kUnit);
  }

 private:
  Stage &stage() { return static_cast<Stage &>(*this); }

  // Each input's point in the stage, in order; false at the first missing one.
  template <std::size_t N>
  bool points(const TranslatedPoint *const (&in)[N], Point *const (&out)[N]) {
    for (std::size_t i = 0; i < N; ++i)
      if (!stage().point(*in[i], out[i])) return false;
    return true;
  }
};

}  // namespace hdt::predicates
