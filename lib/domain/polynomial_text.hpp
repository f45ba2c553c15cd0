// Polynomials in one named generator with rational coefficients, as the
// polygon format writes them (`1/2*a^3-a`, `a^4-2*a^2-1`): read and written
// by libhdt itself, so that e-antic is handed only polynomials already
// known to be well formed (its own parser leaks memory on malformed text).
//
//   polynomial := [+|-] term { (+|-) term }
//   term       := coefficient [ * monomial ] | monomial
//   coefficient:= digits [ / digits ]
//   monomial   := GEN [ ^ digits ]
#pragma once

#include <gmpxx.h>

#include <string>
#include <vector>

namespace hdt::domain {

// Powers above this are refused before anything is built (x^k would be
// built before its reduction modulo the minimal polynomial).
constexpr long kExponentMax = 1024;

// The coefficients c_0 .. c_d (c_d != 0, or empty for the zero polynomial).
// Throws std::invalid_argument naming what is wrong.
std::vector<mpq_class> parse_polynomial(const std::string &text, const std::string &gen);
// The text that parse_polynomial reads back as the same coefficients.
std::string polynomial_text(const std::vector<mpq_class> &c, const std::string &gen);

}  // namespace hdt::domain
