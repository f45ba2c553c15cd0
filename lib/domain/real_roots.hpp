// Counting the real roots of a polynomial with rational coefficients in an
// interval, exactly: what makes a `field` line's ball an isolating interval
// of one root before e-antic is asked to build the field.
#pragma once

#include <gmpxx.h>

#include <vector>

namespace hdt::domain {

// The number of real roots in the closed interval [a, b] (a < b) of the
// squarefree polynomial c_0 + c_1 x + ... + c_d x^d, d >= 1 (an irreducible
// polynomial is squarefree). The interior is counted by Sturm's theorem
// (FLINT) on q(t) = (1 + t)^d p((a + b t) / (1 + t)), whose positive roots
// are the roots of p in (a, b); the ends by evaluating p there.
long real_roots_in(const std::vector<mpq_class> &c, const mpq_class &a, const mpq_class &b);

}  // namespace hdt::domain
