// The structural-zero stage: orientation and in-circle determinants that
// are exactly zero because of the rows' structure (points on an axis of F_g
// under translations along it); see stage_structural.cpp.
#pragma once

#include <cstdint>
#include <vector>

#include "predicates/filtered_point.hpp"
#include "predicates/sign.hpp"
#include "predicates/stage_exact.hpp"
#include "predicates/translated_point.hpp"
#include "surface/surface.hpp"

namespace hdt::predicates {

class StructuralStage {
 public:
  // exact: for the zeros of the exact matrices.
  StructuralStage(surface::Surface &surface, ExactStage &exact) : surface_(surface), exact_(exact) {}

  // zero when one of coordinates 1, 2 is exactly zero in the exact rows of
  // all n points (a sufficient condition for det[rows] and det[rows | w] to
  // vanish), else undecided. filtered[k] is points[k]'s certified double
  // point.
  Sign determinant(const TranslatedPoint *const *points, const FilteredPoint *const *filtered, int n);

 private:
  unsigned row_zeros(const TranslatedPoint &p);  // bit i: coordinate i (1, 2) of p's exact row is 0
  unsigned matrix_zeros(TranslationId id);       // bit 3i + j: entry (i, j) of the exact matrix is 0

  surface::Surface &surface_;
  ExactStage &exact_;
  std::vector<uint16_t> matrix_zeros_;  // by translation id, lazily (bit 15: computed)
  std::vector<uint16_t> site_zeros_;    // by site: bit 1 X = 0, bit 2 Y = 0 (bit 15: computed)
};

}  // namespace hdt::predicates
