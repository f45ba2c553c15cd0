// Exact test that a point with double coordinates lies in the open unit disk.
#pragma once

namespace hdt::exact {

// x^2 + y^2 < 1 decided exactly: a floating-point evaluation with an error
// bound, and rational arithmetic (GMP) only when the bound cannot decide.
// Coordinates must be finite.
bool inside_unit_disk(double x, double y);

}  // namespace hdt::exact
