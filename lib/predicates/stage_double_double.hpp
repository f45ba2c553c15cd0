// The double-double stage: every predicate in double-double reals (about
// 106 bits in plain double operations, double_double.hpp) with a certified
// bound (the analysis of stage_refined.hpp, U = 2^-100). It runs for most
// faces near the corners of F_g at large genus, where the hyperboloid is
// nearly flat in the coordinates and the double stage cannot decide
// in-circle tests, and for points in one frame near a tie.
#pragma once

#include <memory>
#include <vector>

#include "group/lorentz.hpp"
#include "predicates/double_double.hpp"
#include "predicates/sign.hpp"
#include "predicates/stage_mpfr.hpp"
#include "predicates/stage_refined.hpp"
#include "predicates/stage_refined_predicates.hpp"
#include "predicates/translated_point.hpp"
#include "surface/surface.hpp"

namespace hdt::predicates {

using DoubleDoublePoint = RefinedPoint<DoubleDouble>;

// x rounded to double-double (hi = RN(x), lo = RN(x - hi)): within
// u^2 |x| = 2^-106 |x|.
DoubleDouble round_to_double_double(const MpfrReal &x);

class DoubleDoubleStage : public RefinedPredicates<DoubleDoubleStage, DoubleDouble> {
 public:
  static constexpr double kUnit = 0x1p-100;  // every operation within 13u^2 < 2^-102: two bits to spare

  // mpfr: for the matrices of long words and the sites' coordinates.
  DoubleDoubleStage(surface::Surface &surface, MpfrStage &mpfr) : surface_(surface), mpfr_(mpfr) {}

  // p's hyperboloid vector (cached); false when the stage does not apply.
  bool point(const TranslatedPoint &p, DoubleDoublePoint *out);
  // The stored point (x, y) got a home image: its cached points go.
  void forget(double x, double y) { cache_.forget(x, y); }

  // Each entry within 2^-106 |L_ij| + 2^-121 L_00 <= U L_00, by translation id, lazily:
  // for sites and the sides' generators (stored points use the table's split
  // Moebius matrix, compute_point).
  const group::Lorentz<DoubleDouble> &matrix(TranslationId id);
  // 1 + cos(pi/2g): the MPFR stage's (within 4 * 2^-133) rounded (2^-106), within U.
  const DoubleDouble &circumdisk_constant();

 private:
  struct Entry {
    bool ok;  // point's answer
    DoubleDoublePoint point;
  };
  Entry compute_point(const TranslatedPoint &p);
  // A site's coordinates: the MPFR ones (within 2^-128) rounded.
  const group::Complex<DoubleDouble> &site_coordinates(int32_t site);

  surface::Surface &surface_;
  MpfrStage &mpfr_;
  PointCache<Entry> cache_;
  std::vector<std::unique_ptr<group::Lorentz<DoubleDouble>>> matrices_;
  std::vector<group::Complex<DoubleDouble>> site_coordinates_;  // by site id, up to the last one asked for
  DoubleDouble circumdisk_constant_{0};  // 1 + cos(pi/2g) within U; 0: not yet
};

}  // namespace hdt::predicates
