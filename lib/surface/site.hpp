// A site: a point of the disk with exact algebraic coordinates (F_g's
// vertices and side midpoints, the dummy points), and the double data the
// predicates read from it, computed once when it is registered.
#pragma once

#include <array>
#include <memory>

#include "exact/field.hpp"
#include "exact/multiprecision.hpp"
#include "group/moebius.hpp"

namespace hdt::surface {

// z = (X + iY) / Z with X, Y, Z in K_g and Z > 0 (the points of Q0, rotated
// images of rational points).
struct ExactSite {
  exact::FieldElement X, Y, Z;
};

// The reals in which a site's coordinates may be known within 2^-128.
using SiteReal = exact::mp_real<40>;

// A registered site.
struct Site {
  // Shared, never changed: a handle created from a cached dummy set adopts
  // its sites by copying the pointer, not the coefficients (at large genus
  // copying them was most of a cached hdt_create's work).
  std::shared_ptr<const ExactSite> exact;
  double x, y;  // the coordinates rounded to double (correctly when registered so)
  // Its hyperboloid vector N = (Z^2 + X^2 + Y^2, 2XZ, 2YZ) / (Z^2 - X^2 - Y^2),
  // each entry within 4u relative of exact (u = 2^-53): the double stage's
  // input for a site.
  std::array<double, 3> vector;
  bool has_approximation;                // whether `approximation` is set:
  group::Complex<SiteReal> approximation;  // the coordinates within 2^-128
};

// X, Y and Z in 133 bits with bounds on their errors (Field::evaluate_133).
struct SiteEvaluation {
  exact::mp_real<40> x, y, z, ex, ey, ez;
};
SiteEvaluation evaluate_site(const exact::Field &field, const ExactSite &site);

// The hyperboloid vector from the evaluations, each entry within
// u (1 + 2^-7) of exact, when their bounds certify that; success also
// certifies Z^2 - X^2 - Y^2 > 0 (the site is inside the disk). False, with
// nothing written, for a site very near the circle or outside it.
bool certified_site_vector(const SiteEvaluation &e, std::array<double, 3> *vector);

// The hyperboloid vector from exact products (dense at large genus), each
// entry within 4u of exact. Throws std::domain_error unless the site is
// inside the open unit disk.
std::array<double, 3> exact_site_vector(const exact::Field &field, const ExactSite &site);

}  // namespace hdt::surface
