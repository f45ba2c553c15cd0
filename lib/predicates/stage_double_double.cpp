#include "predicates/stage_double_double.hpp"

#include <mpfr.h>

#include "group/word_matrix.hpp"

namespace hdt::predicates {

using namespace refined;

namespace {

// x (an MPFR number of p >= 133 bits) rounded to double-double. hi = RN(x)
// is a multiple of the last place of hi's binade, hence of x's: x - hi has
// at most p - 52 significant bits, so the MPFR subtraction is exact.
// lo = RN(x - hi) is within u |x - hi| <= u^2 |x|, and |lo| <= ulp(hi)/2;
// Fast2Sum normalises (hi + lo unchanged).
template <class U>
DoubleDouble round_mp(const U &x) {
  const double hi = mpfr_get_d(x.backend().data(), MPFR_RNDN);
  const U rest = x - U(hi);
  const double lo = mpfr_get_d(rest.backend().data(), MPFR_RNDN);
  return DoubleDouble::fast_two_sum(hi, lo);
}

}  // namespace

DoubleDouble round_to_double_double(const MpfrReal &x) { return round_mp(x); }

const group::Lorentz<DoubleDouble> &DoubleDoubleStage::matrix(TranslationId id) {
  group::TranslationTable &table = surface_.table();
  if (std::size_t(id) >= matrices_.size()) matrices_.resize(table.size());
  auto &slot = matrices_.at(id);
  if (slot) return *slot;
  // The analysis needs sum_j |L~_ij - L_ij| |hat_j| <= U sum_j |L_ij| |hat_j|
  // (up to the 1.01 margin). Since |hat_1|, |hat_2| <= hat_0 and
  // sum_j |L_ij| |hat_j| >= L_00 hat_0 for row 0, entries within
  // 2^-106 |L_ij| + 2^-121 L_00 suffice (2^-106 + 3 * 2^-121 < U).
  //
  // The word's matrix as the MPFR stage has it (group::accurate_lorentz_as:
  // within 2^-133 |L_ij| + 2^-137 L_00 of the exact one), rounded to double-double
  // (2^-106 of it, so 2^-106 |L_ij| + 2^-135 L_00 more): within 2^-106 |L_ij|
  // + 2^-132 L_00. It is computed again rather than taken from the MPFR stage,
  // which keeps only the matrices it needs itself.
  const group::Lorentz<MpfrReal> M = group::accurate_lorentz_as<MpfrReal>(surface_.presentation(), table.word(id));
  auto L = std::make_unique<group::Lorentz<DoubleDouble>>();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) L->m[i][j] = round_mp(M.m[i][j]);
  slot = std::move(L);
  return *slot;
}

const group::Complex<DoubleDouble> &DoubleDoubleStage::site_coordinates(int32_t site) {
  while (site_coordinates_.size() <= std::size_t(site)) {
    const surface::Site &d = surface_.site(int32_t(site_coordinates_.size()));
    site_coordinates_.push_back(d.has_approximation ? group::Complex<DoubleDouble>{round_mp(d.approximation.re),
                                                                               round_mp(d.approximation.im)}
                                                    : group::Complex<DoubleDouble>{DoubleDouble(0), DoubleDouble(0)});
  }
  return site_coordinates_[std::size_t(site)];
}

bool DoubleDoubleStage::point(const TranslatedPoint &p, DoubleDoublePoint *out) {
  const Entry &e = cache_.get(p, [this](const TranslatedPoint &q) { return compute_point(q); });
  *out = e.point;
  return e.ok;
}

DoubleDoubleStage::Entry DoubleDoubleStage::compute_point(const TranslatedPoint &p) {
  Entry e{};
  if (p.site >= 0) {
    // The MPFR coordinates (within 2^-128 of the exact ones) rounded
    // (2^-106 |.| < 2^-106 more, |x|, |y| < 1).
    if (!surface_.site(p.site).has_approximation) return e;
    const group::Complex<DoubleDouble> &z = site_coordinates(p.site);
    e.ok = refined_point(z.re, z.im, 0x1p-128 + 0x1p-106, &matrix(p.translation), kUnit, &e.point);
    return e;
  }
  if (p.translation == 0) {
    e.ok = refined_point<DoubleDouble>(DoubleDouble(p.x), DoubleDouble(p.y), 0, nullptr, kUnit, &e.point);
    return e;
  }
  if (const surface::HomeImage *image = surface_.home_image(p.x, p.y)) {
    // As a site's: h(z) within 2^-128, rounded (2^-106), under s = t h^-1.
    group::TranslationTable &table = surface_.table();
    const DoubleDouble zx = round_mp(image->approximation.re), zy = round_mp(image->approximation.im);
    e.ok = refined_point(zx, zy, 0x1p-128 + 0x1p-106, &matrix(table.compose(p.translation, image->home_inverse)),
                         kUnit, &e.point);
    return e;
  }
  // The table's Moebius matrix split into two doubles per part: no
  // multiprecision product for this id (a Lorentz matrix in double-double
  // costs one at 265 bits). Its product is certified within 2^-72 (|a| + |b|)
  // (N's elements at genus 32 to 128: mostly 2^-76 to 2^-92), 2^28 U at
  // worst, and that is enough: inserting 10^5 points at genus 128 left 22
  // calls to the 133-bit stage, 23 with the Lorentz matrices (112,744 calls
  // reached this stage). The split adds 2^-106 of each part.
  group::TranslationTable &table = surface_.table();
  const group::Moebius<double> &hi = table.moebius(p.translation), &lo = table.moebius_low(p.translation);
  auto part = [](double h, double l) { return DoubleDouble::fast_two_sum(h, l); };
  const group::Moebius<DoubleDouble> M{{part(hi.a.re, lo.a.re), part(hi.a.im, lo.a.im)},
                                   {part(hi.b.re, lo.b.re), part(hi.b.im, lo.b.im)}};
  e.ok = refined_point_moebius(DoubleDouble(p.x), DoubleDouble(p.y), M, table.moebius_error(p.translation) + 0x1p-105,
                               kUnit, &e.point);
  return e;
}

const DoubleDouble &DoubleDoubleStage::circumdisk_constant() {
  if (circumdisk_constant_.hi == 0) circumdisk_constant_ = round_mp(mpfr_.circumdisk_constant());
  return circumdisk_constant_;
}

}  // namespace hdt::predicates
