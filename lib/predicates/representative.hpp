// The canonical representative of a point of the disk in the half-open
// fundamental domain.
//
// The half-open domain holds the interior of F_g, the open sides
// s_0 .. s_{2g-1} (their paired sides s_2g .. s_{4g-1} are left out) and the
// one vertex v_0 (all 4g vertices are one point of M_g; v_0 lies on s_0 and
// s_1). Every point z of the open disk has exactly one image h(z), h in
// Gamma_g, in this set; representative() finds h with exact predicates:
//   1. while z is strictly beyond the line of some side s_k, apply g_k^{-1}
//      (the distance to the origin strictly decreases: this is a Dirichlet
//      domain, so the loop ends);
//   2. on a left-out side s_{k+2g} alone, apply g_k (onto s_k);
//   3. at a vertex v_k, walk the vertex cycle to v_0: g_{k-2g} maps v_k to
//      v_{k-2g-1}.
#pragma once

#include "predicates/kernel.hpp"

namespace hdt::predicates {

struct Representative {
  group::TranslationId translation;  // h: h(x + iy) lies in the half-open domain
  enum Where { interior, side, vertex } where;
  int side_index;  // the side (0..2g-1) when where == side, 0 otherwise
};

// The representative of the point p stands for (its translation is the
// starting element: the result's translation includes it).
Representative representative(Kernel &kernel, const TranslatedPoint &p);
// For a double point; throws std::domain_error when (x, y) is not a finite
// point of the open disk.
Representative representative(Kernel &kernel, double x, double y);

// For callers without a triangulation (hdt_point_representative): the
// canonical word of the translation h and, when with_image, h(x + iy)
// rounded from a multiprecision image (else (x, y)). A surface and kernel per thread, of the genus last
// asked for, are kept: building them costs far more than a representative,
// and callers usually ask many times for one genus.
struct RepresentativeImage {
  group::Word word;
  group::Complex<double> image;
};
RepresentativeImage representative_image(int genus, double x, double y, bool with_image);

}  // namespace hdt::predicates
