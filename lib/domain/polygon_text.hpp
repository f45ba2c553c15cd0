// A fundamental polygon as text: CGAL's format (Hyperbolic_fundamental_domain_2's
// to_stream / from_stream) with an optional number-field line. docs/polygons.md
// has the whole description; in short, whitespace-separated tokens:
//
//   [field MINPOLY GEN MID+/-RAD]      optional (domain/field_text.hpp)
//   n                                  the number of vertices = sides
//   p_0 ... p_{n-1}                    side k (vertex k to k+1) is paired with side p_k
//   x_0 y_0 ... x_{n-1} y_{n-1}        the vertices, exactly
//
// A coordinate is a rational as GMP writes an mpq (`p/q` or `p`, optional
// sign), or a plain decimal `[-]digits.digits` (read exactly: 0.125 is 1/8;
// no exponent), or, after a field line, a polynomial in GEN with rational
// coefficients (`1/2*a^3-a`). Only syntax is checked here; whether the data
// is a fundamental polygon is FundamentalPolygon's question.
#pragma once

#include <iosfwd>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "domain/complex.hpp"
#include "domain/field_text.hpp"

namespace hdt::domain {

// Malformed text. The message names the token (its 1-based index, line and
// column) and what was expected there.
struct ParseError : std::runtime_error {
  explicit ParseError(const std::string &what) : std::runtime_error(what) {}
};

struct PolygonText {
  FieldPtr field;           // null: the coordinates are rationals
  std::vector<int> paired;  // paired[k]: the side glued to side k
  std::vector<Complex> vertices;
};

PolygonText read_polygon_text(std::istream &in);

// Whether the text begins with a field line (its numbers then need the
// FieldLock while they are read and checked: field_lock.hpp).
bool names_field(std::string_view text);
PolygonText parse_polygon_text(const std::string &text);

// The same format back: read(write(p)) has the same field, pairing and
// exactly the same coordinates.
void write_polygon_text(std::ostream &out, const PolygonText &p);
std::string polygon_text(const PolygonText &p);

}  // namespace hdt::domain
