// The structural-zero stage (stage_structural.hpp): determinants that vanish because every row has
// an exact zero in one coordinate, found without field arithmetic per query.
//
// The axes of F_g through side midpoints that are coordinate axes (y = 0
// through m_0 and m_2g; x = 0 through m_g) are geodesics that the
// translations along them (g_0, g_g and their inverses, and words that
// compose to them) map to themselves. A point given with y = 0 exactly, under
// such a translation, has an exact hyperboloid row (M_h p^) with third
// coordinate exactly 0; so do the Q0 sites on the axis. Three such points
// are on one geodesic (orientation 0) and four on one "circle" (in-circle
// 0): true degeneracies that no floating-point stage can decide, and that
// the field K_g decides at tens of microseconds each. Users sample such axes,
// and the walk and the conflict search meet these zeros at every step along
// the axis across a side.
//
// Row coordinate i (1 or 2) is sum_j M_ij hat_j with hat = (Z^2 + X^2 + Y^2,
// 2XZ, 2YZ) (see ExactStage::row): it is exactly zero when every term is,
// i.e. for each j the matrix entry M_ij or hat_j is exactly zero. hat_0 > 0
// always; hat_1 = 0 exactly when X = 0, hat_2 when Y = 0. Zeros of the exact
// matrix are decided exactly (Field::is_zero) once per translation, of a
// site's X and Y once per site. A common zero column makes det[rows] and
// det[rows | w] exactly 0; this is only a sufficient condition, the later
// stages decide every other case.
//
// The certified double points decide first which coordinates can be zero
// (an exact zero has |computed| <= error): for points in general position
// no coordinate passes, and the stage costs a few comparisons and never
// builds an exact matrix.
#include "predicates/stage_structural.hpp"

namespace hdt::predicates {

namespace {
constexpr unsigned kKnown = 1u << 15;  // a mask's flag: computed
}

unsigned StructuralStage::matrix_zeros(TranslationId id) {
  if (id == 0) return 0b011'101'110;  // the identity: the off-diagonal entries (rows 2, 1, 0)
  if (std::size_t(id) >= matrix_zeros_.size()) matrix_zeros_.resize(surface_.table().size(), 0);
  uint16_t &mask = matrix_zeros_.at(id);
  if (!(mask & kKnown)) {
    const group::ExactLorentz &M = exact_.matrix(id);
    const exact::Field &field = exact_.field();
    unsigned zeros = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (field.is_zero(M.m[i][j])) zeros |= 1u << (3 * i + j);
    mask = uint16_t(zeros | kKnown);
  }
  return mask & ~kKnown;
}

unsigned StructuralStage::row_zeros(const TranslatedPoint &p) {
  // Bit j of hat_zeros: hat_j = 0 exactly.
  unsigned hat_zeros;
  if (p.site >= 0) {
    if (site_zeros_.size() < surface_.site_count()) site_zeros_.resize(surface_.site_count(), 0);
    uint16_t &mask = site_zeros_[std::size_t(p.site)];
    if (!(mask & kKnown)) {
      const surface::ExactSite &s = *surface_.site(p.site).exact;
      const exact::Field &field = exact_.field();
      mask = uint16_t((field.is_zero(s.X) ? 2u : 0u) | (field.is_zero(s.Y) ? 4u : 0u) | kKnown);
    }
    hat_zeros = mask & ~kKnown;
  } else {
    hat_zeros = (p.x == 0 ? 2u : 0u) | (p.y == 0 ? 4u : 0u);
  }
  const unsigned m = matrix_zeros(p.translation);
  unsigned zeros = 0;
  for (int i = 1; i < 3; ++i) {
    const unsigned row = (m >> (3 * i)) & 7u;  // bit j: M_ij = 0
    if ((row | hat_zeros) == 7u) zeros |= 1u << i;
  }
  return zeros;
}

Sign StructuralStage::determinant(const TranslatedPoint *const *points, const FilteredPoint *const *filtered,
                                   int n) {
  unsigned candidates = 0b110;  // coordinates 1 and 2 (coordinate 0 is positive)
  for (int k = 0; k < n && candidates; ++k)
    for (int i = 1; i < 3; ++i)
      if (std::abs(filtered[k]->n[i]) > filtered[k]->error) candidates &= ~(1u << i);
  for (int k = 0; k < n && candidates; ++k) candidates &= row_zeros(*points[k]);
  return candidates != 0 ? Sign::zero : Sign::undecided;
}

}  // namespace hdt::predicates
