// Exact rationals as text: `p/q` or `p` (as GMP writes an mpq), or a plain
// decimal `digits.digits`, each with an optional sign; read exactly.
#pragma once

#include <gmpxx.h>

#include <string>

namespace hdt::domain {

// [+-]digits.
bool is_integer_text(const std::string &s);
// The exact value of s, canonical (e-antic needs lowest terms), or false
// when s is not of the forms above or its denominator is zero.
bool parse_rational(const std::string &s, mpq_class &q);
// The same, also with a decimal exponent (`4.13e-21`, |exponent| <= 10000),
// as e-antic writes a ball's midpoint and radius.
bool parse_scientific(const std::string &s, mpq_class &q);

}  // namespace hdt::domain
