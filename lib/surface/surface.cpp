#include "surface/surface.hpp"

#include <cmath>
#include <stdexcept>

#include "group/cyclic.hpp"
#include "group/generators.hpp"
#include "group/word_matrix.hpp"

namespace hdt::surface {

using exact::Cyclotomic;
using exact::FieldElement;

Surface::Surface(int genus)
    : presentation_(genus),
      field_(exact::field_of_genus(genus)),
      table_(presentation_),
      half_trace_(group::half_trace<double>(genus)),
      quarter_systole_cosh_rounded_(std::sqrt(1 + std::cos(M_PI / (2.0 * genus)))) {
  const int n = presentation_.letter_count();
  for (group::Letter k = 0; k < n; ++k) {
    if (table_.word(letter(k)) != group::Word{k})
      throw std::logic_error("Surface: translation id " + std::to_string(letter(k)) + " is not the letter " +
                             std::to_string(k));
    const auto L = group::accurate_lorentz(presentation_, group::Word{k});
    side_normals_.push_back({1.0 - L.m[0][0], L.m[1][0], L.m[2][0]});  // O - g_k(O), as <N, .> coefficients
  }
  exact_generators_.resize(std::size_t(n));
  const exact::CyclotomicField &K = field_.cyclotomic();
  const Cyclotomic s = K.sin_2pi(1);
  sin2_ = K.mul(s, s);
  quarter_systole_cosh2_ = field_.from_cyclotomic(K.add(K.integer(1), K.cos_2pi(2)));
  // Side k's line is the bisector of O and g_k(O), at distance r (the
  // inradius) from O across the direction theta_k of g_k(O); its ends lie at
  // theta_k +- beta on the circle, cos beta = tanh r, and the line and all
  // beyond it lie in the sector |arg z - theta_k| < beta. Each side is listed
  // in the sectors (2 per side, of 2 pi / 8g) meeting that sector widened by
  // 1e-6 radians, far more than the roundings of atan2 and of theta_k.
  const int sectors = 2 * n;
  sides_by_sector_.assign(std::size_t(sectors), {});
  for (int k = 0; k < n; ++k) {
    const double L00 = 1 - side_normals_[k][0];  // cosh 2r
    const double beta = std::acos(std::sqrt((L00 - 1) / (L00 + 1))) + 1e-6;
    const double theta = std::atan2(side_normals_[k][2], side_normals_[k][1]);
    const double width = 2 * M_PI / sectors;
    const long first = long(std::floor((theta - beta + M_PI) / width));
    const long last = long(std::floor((theta + beta + M_PI) / width));
    for (long j = first; j <= last; ++j) sides_by_sector_[std::size_t(group::cyclic(j, long(sectors)))].push_back(k);
  }
}

const group::ExactLorentz &Surface::exact_generator(int k) const {
  std::unique_ptr<group::ExactLorentz> &slot = exact_generators_.at(std::size_t(k));
  if (!slot) slot = std::make_unique<group::ExactLorentz>(group::exact_generator(field_, k));
  return *slot;
}

const std::vector<int> &Surface::sides_near(double angle) const {
  const int sectors = int(sides_by_sector_.size());
  const long j = long(std::floor((angle + M_PI) / (2 * M_PI / sectors)));
  return sides_by_sector_[std::size_t(group::cyclic(j, long(sectors)))];
}

int32_t Surface::add_site(const ExactSite &site, const group::Complex<SiteReal> *approximation,
                          const group::Complex<double> *rounded) {
  const SiteEvaluation e = evaluate_site(field_, site);
  if (!(e.z > e.ez) && field_.sign(site.Z) != exact::Sign::positive)
    throw std::domain_error("add_site: Z must be positive");
  Site data{std::make_shared<const ExactSite>(site), 0, 0, {}, false, {}};
  // The evaluations certify the vector, and with it that the site is inside
  // the disk, except very near the circle: only there are the exact
  // products (dense at large genus) formed.
  if (!certified_site_vector(e, &data.vector)) data.vector = exact_site_vector(field_, site);
  // X, Y and Z rounded (the values Field::approximate rounds), then divided:
  // within 3u |.| of exact, and a correctly rounded value (within u |.|) is
  // no further from these than 4u |.|.
  const double z = e.z.convert_to<double>();
  data.x = e.x.convert_to<double>() / z, data.y = e.y.convert_to<double>() / z;
  if (rounded) {
    const double bound = 4 * 0x1p-53 * std::max(std::abs(data.x), std::abs(data.y)) + 0x1p-100;
    if (!(std::abs(rounded->re - data.x) <= bound && std::abs(rounded->im - data.y) <= bound))
      throw std::logic_error("add_site: the given rounding is not this point's");
    data.x = rounded->re, data.y = rounded->im;
  }
  if (approximation) data.has_approximation = true, data.approximation = *approximation;
  sites_.push_back(data);
  return int32_t(sites_.size() - 1);
}

}  // namespace hdt::surface
