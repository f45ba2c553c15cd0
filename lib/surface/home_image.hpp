// A point given far from F_g, with its image in F_g known closely.
//
// A vertex is stored as the caller's point z and its home h (h(z) lies in
// F_g): exact, but for z near the unit circle h is a long word whose
// matrix has entries about 1 / (1 - |z|^2), and every floating-point
// evaluation of h(z) cancels as many digits; the predicates then fell
// through to the field K_g, whose matrices of long words cost seconds.
// Such a point keeps its exact description, and the floating stages read
// instead the image h(z), computed once within 2^-128 (certified_image),
// like a site's approximation: a copy t(z) of it is then s(h(z)) for the
// short s = t h^-1. The exact stage still works on z and t.
#pragma once

#include <array>
#include <optional>

#include "group/moebius.hpp"
#include "group/presentation.hpp"
#include "group/translation_table.hpp"
#include "surface/site.hpp"

namespace hdt::surface {

struct HomeImage {
  double x, y;  // z, as stored
  group::TranslationId home, home_inverse;
  group::Complex<SiteReal> approximation;  // h(z) within 2^-128 in each coordinate
  group::Complex<double> rounded;          // the approximation rounded
  // Its hyperboloid vector rounded to double, and a bound on each entry's
  // error (absolute): the double stage's input.
  std::array<double, 3> vector;
  double vector_error;
};

// Whether the floating stages lose most of their digits on z under a
// non-trivial home: z this near the circle (the home word's entries, and
// the cancellation, grow as 1 / (1 - |z|^2)).
inline bool far_from_domain(double x, double y, group::TranslationId home) {
  return home != 0 && 1 - (x * x + y * y) < 0x1p-16;
}

// The image of z = x + iy under home, or nothing when it cannot be
// certified (the predicates then work on z as before).
std::optional<HomeImage> make_home_image(const group::Presentation &p, group::TranslationTable &table, double x,
                                         double y, group::TranslationId home);

}  // namespace hdt::surface
