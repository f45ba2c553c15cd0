// The MPFR stage: every predicate in 133-bit MPFR reals with a certified
// bound (the analysis of stage_refined.hpp, U = 2^-132). It decides what
// double-double cannot near the polygon's corners; sites without an
// approximation (surface.hpp) are left to the exact stage.
#pragma once

#include <memory>
#include <vector>

#include "exact/multiprecision.hpp"
#include "group/lorentz.hpp"
#include "predicates/sign.hpp"
#include "predicates/stage_refined.hpp"
#include "predicates/stage_refined_predicates.hpp"
#include "predicates/translated_point.hpp"
#include "surface/surface.hpp"

namespace hdt::predicates {

using MpfrReal = exact::mp_real<40>;
using MpfrPoint = RefinedPoint<MpfrReal>;

class MpfrStage : public RefinedPredicates<MpfrStage, MpfrReal> {
 public:
  static constexpr double kUnit = 0x1p-132;  // correct rounding, u = 2^-133: a bit to spare

  explicit MpfrStage(surface::Surface &surface) : surface_(surface) {}

  // p's hyperboloid vector; false when the stage does not apply (a site
  // without an approximation, or a point too near the circle).
  bool point(const TranslatedPoint &p, MpfrPoint *out);
  // The translation's matrix within 2^-133 |L_ij| + 2^-137 L_00 of the exact
  // one (group::accurate_lorentz_as), lazily. The analysis needs
  // sum_j |L~_ij - L_ij| |hat_j| <= U sum_j |L_ij| |hat_j|, and
  // |hat_1|, |hat_2| <= hat_0 <= sum_j |L_0j| |hat_j| / L_00 (row 0):
  // 2^-133 + 3 * 2^-137 < U.
  const group::Lorentz<MpfrReal> &matrix(TranslationId id);
  // 1 + cos(pi/2g) within 4U relative.
  const MpfrReal &circumdisk_constant();

 private:
  surface::Surface &surface_;
  std::vector<std::unique_ptr<group::Lorentz<MpfrReal>>> matrices_;  // by translation id, lazily
  std::unique_ptr<MpfrReal> circumdisk_constant_;
};

}  // namespace hdt::predicates
