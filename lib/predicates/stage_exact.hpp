// The exact stage: every predicate evaluated in the field K_g
// (exact/field.hpp) on the unnormalised rows (M_h p^, s^2m w), a positive
// multiple of (N, 1) row by row (see group/exact_lorentz.hpp). Always
// decides, at tens of microseconds to milliseconds per call.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "exact/field.hpp"
#include "group/exact_lorentz.hpp"
#include "predicates/sign.hpp"
#include "predicates/translated_point.hpp"
#include "surface/surface.hpp"

namespace hdt::predicates {

class ExactStage {
 public:
  // The exact row (M_h p^, s^2m w) of a point.
  struct Row {
    std::array<exact::FieldElement, 4> v;
  };

  explicit ExactStage(surface::Surface &surface);

  Row row(const TranslatedPoint &p);
  // The translation's exact matrix, lazily.
  const group::ExactLorentz &matrix(TranslationId id);
  const exact::Field &field() const { return field_; }

  Sign orientation(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r);
  Sign in_circle(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r,
                 const TranslatedPoint &s) {
    return in_circle(rows(p, q, r, s));
  }
  Sign in_circle(const std::array<Row, 4> &rows) const { return field_sign(det4(rows)); }
  std::array<Row, 4> rows(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r,
                          const TranslatedPoint &s) {
    return {row(p), row(q), row(r), row(s)};
  }
  Sign beyond_side(const TranslatedPoint &p, int side);
  Sign compare_distance(const TranslatedPoint &p, const TranslatedPoint &a, const TranslatedPoint &b);
  // zero when p and q are the same point, positive otherwise.
  Sign distinct(const TranslatedPoint &p, const TranslatedPoint &q);
  Sign large_circumdisk(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r);
  // The coefficient of eps_v in the perturbed in-circle determinant (see
  // kernel.hpp): the sign of the sum over v's rows r of (-1)^(r+1) v_r3
  // cofactor(r, 3).
  Sign perturbation_coefficient(const std::array<Row, 4> &rows, const std::array<uint32_t, 4> &vertex,
                                uint32_t v) const;

 private:
  Sign field_sign(const exact::FieldElement &x) const { return field_.sign(x); }
  exact::FieldElement det3(const std::array<const std::array<exact::FieldElement, 4> *, 3> &rows) const;
  exact::FieldElement det4(const std::array<Row, 4> &rows) const;
  // sin(pi/4g)^(2 letters): the positive factor of an exact matrix's rows.
  const exact::Cyclotomic &scale(int letters);

  surface::Surface &surface_;
  const exact::Field &field_;  // surface_'s
  std::vector<std::unique_ptr<group::ExactLorentz>> matrices_;  // by translation id, lazily
  std::vector<exact::Cyclotomic> scale_powers_;
};

}  // namespace hdt::predicates
