// Exact Lorentz matrices of group elements, over the field K_g.
//
// The Lorentz matrix of g_k is M_k / sin(pi/4g)^2 where M_k has entries in
// K_g (c = cos(pi/4g), sigma = sqrt(cos(pi/2g)), theta = k pi/2g):
//   [[c^2 + sigma^2,        2 c sigma cos(theta), 2 c sigma sin(theta)    ],
//    [2 c sigma cos(theta), c^2 + sigma^2 cos 2t, sigma^2 sin 2t          ],
//    [2 c sigma sin(theta), sigma^2 sin 2t,       c^2 - sigma^2 cos 2t    ]].
// A word of m letters has the Lorentz matrix M_w / sin(pi/4g)^{2m}: the
// positive scale changes no sign, so predicates work with M_w and carry the
// scale only where rows of different words are compared (Kernel::scale).
#pragma once

#include <array>

#include "exact/field.hpp"
#include "group/presentation.hpp"

namespace hdt::group {

struct ExactLorentz {
  std::array<std::array<exact::FieldElement, 3>, 3> m;
  int letters = 0;  // the matrix is m / sin(pi/4g)^(2 letters)
};

ExactLorentz exact_identity(const exact::Field &field);
ExactLorentz exact_generator(const exact::Field &field, Letter k);
ExactLorentz exact_product(const exact::Field &field, const ExactLorentz &a, const ExactLorentz &b);
ExactLorentz exact_lorentz(const exact::Field &field, const Word &w);

}  // namespace hdt::group
