#include "surface/exact_polygon.hpp"

#include <stdexcept>

#include "group/cyclic.hpp"

namespace hdt::surface {

using exact::Cyclotomic;
using exact::FieldElement;


ExactSite exact_vertex(const exact::Field &field, int k) {
  const exact::CyclotomicField &K = field.cyclotomic();
  const long angle = 2L * group::cyclic(k, 4 * field.genus()) + 1;  // in units of 2 pi / 8g
  // sigma cos, sigma sin: the sigma part of a FieldElement.
  return {FieldElement{{}, K.cos_2pi(angle)}, FieldElement{{}, K.sin_2pi(angle)},
          field.from_cyclotomic(K.integer(1))};
}

ExactSite exact_side_midpoint(const exact::Field &field, int k) {
  const exact::CyclotomicField &K = field.cyclotomic();
  const long angle = 2L * group::cyclic(k, 4 * field.genus());
  const Cyclotomic radius = K.sub(K.cos_2pi(1), K.sin_2pi(1));  // c - s
  return {field.from_cyclotomic(K.mul(radius, K.cos_2pi(angle))),
          field.from_cyclotomic(K.mul(radius, K.sin_2pi(angle))), field.sigma()};
}

std::vector<ExactSite> exact_side_midpoints(const exact::Field &field, int count) {
  const exact::CyclotomicField &K = field.cyclotomic();
  const int g = field.genus(), sides = 4 * g;
  if (count < 0 || count > sides) throw std::invalid_argument("exact_side_midpoints: at most 4g midpoints");
  // With R = c - s (real), Z_j = R zeta^2j: m_j = Z_j / sigma, X_j = Re Z_j =
  // (Z_j + Z_{-j}) / 2 (R is real, so conj Z_j = Z_{-j}), and Y_j = Re(-i Z_j)
  // = X_{j-g} (-i = zeta^{-2g}). Each Z_j is the previous one times zeta^2.
  std::vector<Cyclotomic> X(std::size_t(sides), K.zero());
  Cyclotomic Z = K.sub(K.cos_2pi(1), K.sin_2pi(1));
  for (int j = 0; j < sides; ++j) {
    X[std::size_t(j)] = K.add(X[std::size_t(j)], Z);
    X[std::size_t(group::cyclic(-j, sides))] = K.add(X[std::size_t(group::cyclic(-j, sides))], Z);
    if (j + 1 < sides) Z = K.mul_zeta_power(Z, 2);
  }
  std::vector<ExactSite> out;
  out.reserve(std::size_t(count));
  for (int k = 0; k < count; ++k)
    out.push_back({field.from_cyclotomic(K.mul_2exp(X[std::size_t(k)], -1)),
                   field.from_cyclotomic(K.mul_2exp(X[std::size_t(group::cyclic(k - g, sides))], -1)), field.sigma()});
  return out;
}

}  // namespace hdt::surface
