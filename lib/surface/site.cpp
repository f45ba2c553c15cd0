#include "surface/site.hpp"

#include <stdexcept>

namespace hdt::surface {

SiteEvaluation evaluate_site(const exact::Field &field, const ExactSite &site) {
  SiteEvaluation e;
  field.evaluate_133(site.X, &e.x, &e.ex);
  field.evaluate_133(site.Y, &e.y, &e.ey);
  field.evaluate_133(site.Z, &e.z, &e.ez);
  return e;
}

bool certified_site_vector(const SiteEvaluation &e, std::array<double, 3> *vector) {
  using R = exact::mp_real<40>;
  // |x| + ex bounds |X|, and a product of two values with errors ea, eb
  // errs by at most |a| eb + |b| ea + ea eb, before rounding; the 133-bit
  // roundings of the few operations below add at most a few 2^-133 of the
  // terms' sizes (their sum S below), which `rounding`, 2^-126 S, covers.
  const R ax = abs(e.x), ay = abs(e.y), az = abs(e.z);
  const R exx = 2 * ax * e.ex + e.ex * e.ex, eyy = 2 * ay * e.ey + e.ey * e.ey, ezz = 2 * az * e.ez + e.ez * e.ez;
  const R xx = e.x * e.x, yy = e.y * e.y, zz = e.z * e.z;
  const R S = xx + yy + zz + exx + eyy + ezz;
  const R rounding = S * ldexp(R(1), -126);
  const R w = zz - xx - yy, n0 = zz + xx + yy, n1 = 2 * e.x * e.z, n2 = 2 * e.y * e.z;
  const R ew = exx + eyy + ezz + rounding, e0 = ew;
  // (A coordinate known to be exactly 0 gives a product exactly 0: a
  // midpoint on an axis keeps this path.)
  const R e1 = 2 * (ax * e.ez + az * e.ex + e.ex * e.ez) + (n1 == 0 ? R(0) : rounding);
  const R e2 = 2 * (ay * e.ez + az * e.ey + e.ey * e.ez) + (n2 == 0 ? R(0) : rounding);
  // N_i = num_i / w: relative error at most rel(num_i) + rel(w) (1 + ...),
  // certified below 2^-60 when each part is below 2^-62; rounded to double,
  // within u (1 + 2^-7).
  const R limit = ldexp(R(1), -62);
  if (!(w > 0) || !(ew < limit * w)) return false;
  const R parts[3][2] = {{n0, e0}, {n1, e1}, {n2, e2}};
  for (int i = 0; i < 3; ++i)
    if (!(parts[i][1] <= limit * abs(parts[i][0])) && !(parts[i][0] == 0 && parts[i][1] == 0)) return false;
  for (int i = 0; i < 3; ++i) (*vector)[i] = R(parts[i][0] / w).convert_to<double>();
  return true;
}

std::array<double, 3> exact_site_vector(const exact::Field &field, const ExactSite &site) {
  // Each part exact before its rounding (u) and the division (u more).
  const exact::FieldElement zz = field.mul(site.Z, site.Z);
  const exact::FieldElement r2 = field.add(field.mul(site.X, site.X), field.mul(site.Y, site.Y));
  const exact::FieldElement w = field.sub(zz, r2);
  if (field.sign(w) != exact::Sign::positive)
    throw std::domain_error("add_site: the point is not inside the open unit disk");
  const exact::FieldElement two_z = field.add(site.Z, site.Z);
  const double den = field.approximate(w);
  return {field.approximate(field.add(zz, r2)) / den, field.approximate(field.mul(site.X, two_z)) / den,
          field.approximate(field.mul(site.Y, two_z)) / den};
}

}  // namespace hdt::surface
