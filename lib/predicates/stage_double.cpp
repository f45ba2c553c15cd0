#include "predicates/stage_double.hpp"

#include "group/lorentz.hpp"
#include "predicates/stage_refined.hpp"
#include "surface/systole.hpp"

namespace hdt::predicates {

const std::array<double, 3> &DoubleStage::site_vector(int32_t site) {
  const exact::Field &field = surface_.field();
  while (site_vectors_.size() <= std::size_t(site)) {
    const surface::ExactSite &e = surface_.site(int32_t(site_vectors_.size())).exact;
    // N = (Z^2 + X^2 + Y^2, 2XZ, 2YZ) / w, w = Z^2 - X^2 - Y^2, each part
    // exact before rounding.
    const exact::FieldElement zz = field.mul(e.Z, e.Z);
    const exact::FieldElement r2 = field.add(field.mul(e.X, e.X), field.mul(e.Y, e.Y));
    const exact::FieldElement two_z = field.add(e.Z, e.Z);
    const double den = field.approximate(field.sub(zz, r2));
    site_vectors_.push_back({field.approximate(field.add(zz, r2)) / den, field.approximate(field.mul(e.X, two_z)) / den,
                             field.approximate(field.mul(e.Y, two_z)) / den});
  }
  return site_vectors_[std::size_t(site)];
}

FilteredPoint DoubleStage::compute_point(const TranslatedPoint &p) {
  if (p.site < 0 && p.translation == 0) return filtered_point(p.x, p.y);
  if (p.site < 0) return filtered_point(p.x, p.y, surface_.table().moebius(p.translation));
  const group::Lorentz<double> &L = surface_.table().lorentz(p.translation);
  // A site's hyperboloid vector is stored rounded (4u per entry): apply L
  // (u per entry) with three more roundings.
  const std::array<double, 3> &n = site_vector(p.site);
  FilteredPoint r;
  double worst = 0;
  for (int i = 0; i < 3; ++i) {
    r.n[i] = L.m[i][0] * n[0] + L.m[i][1] * n[1] + L.m[i][2] * n[2];
    worst = std::max(worst, std::abs(L.m[i][0] * n[0]) + std::abs(L.m[i][1] * n[1]) + std::abs(L.m[i][2] * n[2]));
  }
  r.error = 10 * kUnit * worst * 1.01;
  return r;
}

Sign DoubleStage::large_circumdisk(const FilteredPoint &a, const FilteredPoint &b, const FilteredPoint &c) const {
  auto as_refined = [](const FilteredPoint &f) { return RefinedPoint<double>{{f.n[0], f.n[1], f.n[2]}, f.error}; };
  // k within 4u of the exact value.
  const double k = surface::quarter_systole_cosh2<double>(surface_.genus());
  return refined::large_circumdisk_sign(as_refined(a), as_refined(b), as_refined(c), k, kUnit);
}

}  // namespace hdt::predicates
