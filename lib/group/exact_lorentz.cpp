#include "group/exact_lorentz.hpp"

namespace hdt::group {

using exact::Cyclotomic;
using exact::FieldElement;

ExactLorentz exact_identity(const exact::Field &field) {
  ExactLorentz r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = i == j ? field.from_cyclotomic(field.cyclotomic().integer(1)) : field.zero();
  return r;
}

ExactLorentz exact_generator(const exact::Field &field, Letter k) {
  const exact::CyclotomicField &K = field.cyclotomic();
  // Angles as multiples of 2 pi / 8g: pi/4g is 1, theta = k pi/2g is 2k.
  const Cyclotomic c = K.cos_2pi(1), s2 = K.cos_2pi(2);
  const Cyclotomic cos_t = K.cos_2pi(2L * k), sin_t = K.sin_2pi(2L * k);
  const Cyclotomic cos_2t = K.cos_2pi(4L * k), sin_2t = K.sin_2pi(4L * k);
  const Cyclotomic c2 = K.mul(c, c), two_c = K.mul_2exp(c, 1);
  const Cyclotomic s2_cos_2t = K.mul(s2, cos_2t), s2_sin_2t = K.mul(s2, sin_2t);
  ExactLorentz r;
  r.letters = 1;
  r.m[0][0] = field.from_cyclotomic(K.add(c2, s2));
  r.m[0][1] = r.m[1][0] = FieldElement{{}, K.mul(two_c, cos_t)};
  r.m[0][2] = r.m[2][0] = FieldElement{{}, K.mul(two_c, sin_t)};
  r.m[1][1] = field.from_cyclotomic(K.add(c2, s2_cos_2t));
  r.m[1][2] = r.m[2][1] = field.from_cyclotomic(s2_sin_2t);
  r.m[2][2] = field.from_cyclotomic(K.sub(c2, s2_cos_2t));
  return r;
}

ExactLorentz exact_product(const exact::Field &field, const ExactLorentz &a, const ExactLorentz &b) {
  ExactLorentz r;
  r.letters = a.letters + b.letters;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      FieldElement sum = field.mul(a.m[i][0], b.m[0][j]);
      sum = field.add(sum, field.mul(a.m[i][1], b.m[1][j]));
      r.m[i][j] = field.add(sum, field.mul(a.m[i][2], b.m[2][j]));
    }
  return r;
}

ExactLorentz exact_lorentz(const exact::Field &field, const Word &w) {
  ExactLorentz r = exact_identity(field);
  for (Letter k : w) r = exact_product(field, r, exact_generator(field, k));
  return r;
}

}  // namespace hdt::group
