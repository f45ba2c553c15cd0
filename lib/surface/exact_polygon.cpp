#include "surface/exact_polygon.hpp"

namespace hdt::surface {

using exact::Cyclotomic;
using exact::FieldElement;

namespace {

int wrap(int k, int n) { return ((k % n) + n) % n; }

}  // namespace

ExactSite exact_vertex(const exact::Field &field, int k) {
  const exact::CyclotomicField &K = field.cyclotomic();
  const long angle = 2L * wrap(k, 4 * field.genus()) + 1;  // in units of 2 pi / 8g
  // sigma cos, sigma sin: the sigma part of a FieldElement.
  return {FieldElement{{}, K.cos_2pi(angle)}, FieldElement{{}, K.sin_2pi(angle)},
          field.from_cyclotomic(K.integer(1))};
}

ExactSite exact_side_midpoint(const exact::Field &field, int k) {
  const exact::CyclotomicField &K = field.cyclotomic();
  const long angle = 2L * wrap(k, 4 * field.genus());
  const Cyclotomic radius = K.sub(K.cos_2pi(1), K.sin_2pi(1));  // c - s
  return {field.from_cyclotomic(K.mul(radius, K.cos_2pi(angle))),
          field.from_cyclotomic(K.mul(radius, K.sin_2pi(angle))), field.sigma()};
}

}  // namespace hdt::surface
