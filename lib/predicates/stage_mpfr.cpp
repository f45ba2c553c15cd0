#include "predicates/stage_mpfr.hpp"

#include "group/word_matrix.hpp"
#include "surface/systole.hpp"

namespace hdt::predicates {

using namespace refined;

const group::Lorentz<MidReal> &MpfrStage::matrix(TranslationId id) {
  group::TranslationTable &table = surface_.table();
  if (std::size_t(id) >= matrices_.size()) matrices_.resize(table.size());
  auto &slot = matrices_.at(id);
  if (!slot)
    slot = std::make_unique<group::Lorentz<MidReal>>(
        group::accurate_lorentz_as<MidReal>(surface_.presentation(), table.word(id)));
  return *slot;
}

bool MpfrStage::point(const TranslatedPoint &p, MidPoint *out) {
  if (p.site >= 0) {
    const surface::Site &site = surface_.site(p.site);
    if (!site.has_approximation) return false;
    return refined_point(site.approximation.re, site.approximation.im, 0x1p-128, &matrix(p.translation), kUnit,
                         out);
  }
  const group::Lorentz<MidReal> *L = p.translation == 0 ? nullptr : &matrix(p.translation);
  return refined_point(MidReal(p.x), MidReal(p.y), 0, L, kUnit, out);
}

const MidReal &MpfrStage::circumdisk_constant() {
  if (!circumdisk_constant_) {
    // pi and pi/2g within U each, cos within U plus its argument's error
    // (|sin| <= 1, the argument <= pi/4), the sum U: within 4U of k >= 1.
    using std::cos;
    circumdisk_constant_ = std::make_unique<MidReal>(surface::quarter_systole_cosh2<MidReal>(surface_.genus()));
  }
  return *circumdisk_constant_;
}

Sign MpfrStage::orientation(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r) {
  MidPoint a, b, c;
  if (!point(p, &a) || !point(q, &b) || !point(r, &c)) return Sign::undecided;
  return orientation_sign(a, b, c, kUnit);
}

Sign MpfrStage::in_circle(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r,
                          const TranslatedPoint &s) {
  MidPoint a, b, c, e;
  if (!point(p, &a) || !point(q, &b) || !point(r, &c) || !point(s, &e)) return Sign::undecided;
  return in_circle_sign(a, b, c, e, kUnit);
}

Sign MpfrStage::beyond_side(const TranslatedPoint &p, int side) {
  MidPoint a;
  if (!point(p, &a)) return Sign::undecided;
  // g_k's matrix: entries within 2^-133 |L_ij| + 2^-197 <= U L00 (L00 >= 1);
  // 1 - L00 rounds once more: every n_i within 2U L00.
  const group::Lorentz<MidReal> &L = matrix(surface::Surface::letter(group::Letter(side)));
  const MidReal n[3] = {MidReal(1) - L.m[0][0], L.m[1][0], L.m[2][0]};
  const double L00 = magnitude(L.m[0][0]) * (1 + 2 * kUnit);
  return beyond_side_sign(a, n, L00, 2 * kUnit * L00, kUnit);
}

Sign MpfrStage::compare_distance(const TranslatedPoint &p, const TranslatedPoint &a, const TranslatedPoint &b) {
  MidPoint x, y, z;
  if (!point(p, &x) || !point(a, &y) || !point(b, &z)) return Sign::undecided;
  return compare_distance_sign(x, y, z, kUnit);
}

Sign MpfrStage::distinct(const TranslatedPoint &p, const TranslatedPoint &q) {
  MidPoint a, b;
  if (!point(p, &a) || !point(q, &b)) return Sign::undecided;
  return distinct_sign(a, b, kUnit);
}

Sign MpfrStage::large_circumdisk(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r) {
  MidPoint a, b, e;
  if (!point(p, &a) || !point(q, &b) || !point(r, &e)) return Sign::undecided;
  return large_circumdisk_sign(a, b, e, circumdisk_constant(), kUnit);
}

}  // namespace hdt::predicates
