#include "predicates/stage_mpfr.hpp"

#include "group/word_matrix.hpp"
#include "surface/systole.hpp"

namespace hdt::predicates {

using namespace refined;

const group::Lorentz<MpfrReal> &MpfrStage::matrix(TranslationId id) {
  group::TranslationTable &table = surface_.table();
  if (std::size_t(id) >= matrices_.size()) matrices_.resize(table.size());
  auto &slot = matrices_.at(id);
  if (!slot)
    slot = std::make_unique<group::Lorentz<MpfrReal>>(
        group::accurate_lorentz_as<MpfrReal>(surface_.presentation(), table.word(id)));
  return *slot;
}

bool MpfrStage::point(const TranslatedPoint &p, MpfrPoint *out) {
  if (p.site >= 0) {
    const surface::Site &site = surface_.site(p.site);
    if (!site.has_approximation) return false;
    return refined_point(site.approximation.re, site.approximation.im, 0x1p-128, &matrix(p.translation), kUnit,
                         out);
  }
  if (p.translation == 0)
    return refined_point(MpfrReal(p.x), MpfrReal(p.y), 0, static_cast<const group::Lorentz<MpfrReal> *>(nullptr), kUnit, out);
  if (const surface::HomeImage *image = surface_.home_image(p.x, p.y)) {
    // As a site's: h(z) within 2^-128 under s = t h^-1.
    group::TranslationTable &table = surface_.table();
    return refined_point(image->approximation.re, image->approximation.im, 0x1p-128,
                         &matrix(table.compose(p.translation, image->home_inverse)), kUnit, out);
  }
  const group::Lorentz<MpfrReal> *L = &matrix(p.translation);
  return refined_point(MpfrReal(p.x), MpfrReal(p.y), 0, L, kUnit, out);
}

const MpfrReal &MpfrStage::circumdisk_constant() {
  if (!circumdisk_constant_) {
    // pi and pi/2g within U each, cos within U plus its argument's error
    // (|sin| <= 1, the argument <= pi/4), the sum U: within 4U of k >= 1.
    using std::cos;
    circumdisk_constant_ = std::make_unique<MpfrReal>(surface::quarter_systole_cosh2<MpfrReal>(surface_.genus()));
  }
  return *circumdisk_constant_;
}

}  // namespace hdt::predicates
