// A real embedded number field as text: the `field` line of the polygon
// format (docs/polygons.md), and its elements as polynomials in the
// generator.
//
//   field MINPOLY GEN BALL
//   field a^4-2*a^2-1 a 1.5538+/-0.01
//
// Three whitespace-free tokens: the minimal polynomial in the generator GEN
// with rational coefficients (e-antic's syntax: `*` for products, `^` for
// powers), GEN an identifier, and BALL = MID+/-RAD a real interval that
// holds exactly one real root of MINPOLY, the generator's embedding.
#pragma once

#include <e-antic/renf_class.hpp>

#include <string>

#include "domain/complex.hpp"

namespace hdt::domain {

using FieldPtr = boost::intrusive_ptr<const eantic::renf_class>;

// The largest field degree read, so that every text is read in bounded
// time (factoring and isolating a root of degree 256 takes about 0.1 s, of
// degree 2048 seconds). Written powers are bounded too (polynomial_text.hpp).
constexpr long kFieldDegreeMax = 256;

// The field of the three tokens. Throws std::invalid_argument naming what is
// wrong: a malformed token, a polynomial e-antic cannot read, one that is
// reducible over Q (K would not be a field: exact zero tests would lie), or a
// ball that does not isolate one real root.
FieldPtr make_field(const std::string &minpoly, const std::string &gen, const std::string &ball);

// The three tokens that make_field reads back as the same field.
std::string minpoly_token(const eantic::renf_class &K);
std::string ball_token(const eantic::renf_class &K);

// An element as one token: `p/q` or `p` when rational, else the polynomial in
// the generator (no spaces), which make_element reads back exactly.
std::string element_token(const Number &x);
// A polynomial token in K's generator. Throws std::invalid_argument.
Number make_element(const eantic::renf_class &K, const std::string &token);

}  // namespace hdt::domain
