#include "domain/field_text.hpp"

#include <flint/fmpz_poly.h>
#include <flint/fmpz_poly_factor.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <string>

namespace hdt::domain {

namespace {

std::string without_spaces(std::string s) {
  s.erase(std::remove_if(s.begin(), s.end(), [](unsigned char c) { return std::isspace(c); }), s.end());
  return s;
}

bool is_identifier(const std::string &s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  return std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; });
}

// The characters of a polynomial token: e-antic's parser gets nothing else.
bool is_polynomial_text(const std::string &s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](unsigned char c) {
    return std::isalnum(c) || c == '_' || c == '^' || c == '*' || c == '/' || c == '+' || c == '-';
  });
}

// The largest exponent written after a `^` (0 when none; more than
// kExponentMax when any is): the cost of e-antic's parsing, factoring and
// root isolation grows with it, so it is bounded before they run.
long largest_exponent(const std::string &s) {
  long largest = 0;
  for (std::size_t i = s.find('^'); i != std::string::npos; i = s.find('^', i + 1)) {
    std::size_t j = i + 1;
    long e = 0;
    while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j])) && e <= kExponentMax)
      e = 10 * e + (s[j++] - '0');
    largest = std::max(largest, e);
  }
  return largest;
}

// The defining polynomial of K is irreducible over Q: by Gauss's lemma, when
// its primitive integer multiple has one irreducible factor over Z, of
// multiplicity one, and positive degree.
bool irreducible(const eantic::renf_class &K) {
  fmpz_poly_t p;
  fmpz_poly_init(p);
  fmpq_poly_get_numerator(p, K.renf_t()->nf->pol);
  fmpz_poly_factor_t f;
  fmpz_poly_factor_init(f);
  fmpz_poly_factor(f, p);
  const bool one = fmpz_poly_degree(p) >= 1 && f->num == 1 && f->exp[0] == 1;
  fmpz_poly_factor_clear(f);
  fmpz_poly_clear(p);
  return one;
}

}  // namespace

FieldPtr make_field(const std::string &minpoly, const std::string &gen, const std::string &ball) {
  if (!is_identifier(gen)) throw std::invalid_argument("the generator's name `" + gen + "` is not an identifier");
  if (!is_polynomial_text(minpoly))
    throw std::invalid_argument("`" + minpoly + "` is not a polynomial in " + gen + " (no spaces; * and ^)");
  if (largest_exponent(minpoly) > kFieldDegreeMax)
    throw std::invalid_argument("`" + minpoly + "` has a power above " + std::to_string(kFieldDegreeMax) +
                                ", the largest field degree this build reads");
  const std::size_t pm = ball.find("+/-");
  if (pm == std::string::npos || pm == 0 || pm + 3 == ball.size())
    throw std::invalid_argument("the embedding `" + ball + "` is not a ball MID+/-RAD");
  FieldPtr K;
  try {
    K = eantic::renf_class::make(minpoly, gen, ball.substr(0, pm) + " +/- " + ball.substr(pm + 3));
  } catch (const std::exception &e) {
    throw std::invalid_argument("no field from `" + minpoly + "` with a root in " + ball + " (e-antic: " + e.what() +
                                ")");
  }
  if (!irreducible(*K)) throw std::invalid_argument("the polynomial `" + minpoly + "` is not irreducible over Q");
  return K;
}

std::string minpoly_token(const eantic::renf_class &K) { return without_spaces(std::get<0>(K.construction())); }

std::string ball_token(const eantic::renf_class &K) {
  std::string b = without_spaces(std::get<2>(K.construction()));  // [MID+/-RAD]
  if (!b.empty() && b.front() == '[') b.erase(0, 1);
  if (!b.empty() && b.back() == ']') b.pop_back();
  return b;
}

std::string element_token(const Number &x) {
  if (x.is_rational()) return static_cast<mpq_class>(x).get_str();
  return without_spaces(x.to_string(EANTIC_STR_ALG));
}

Number make_element(const eantic::renf_class &K, const std::string &token) {
  if (!is_polynomial_text(token))
    throw std::invalid_argument("`" + token + "` is not a polynomial in " + K.gen_name());
  if (largest_exponent(token) > kExponentMax)
    throw std::invalid_argument("`" + token + "` has a power above " + std::to_string(kExponentMax));
  try {
    return Number(K, token);
  } catch (const std::exception &) {
    throw std::invalid_argument("`" + token + "` is not a polynomial in " + K.gen_name() +
                                " with rational coefficients");
  }
}

}  // namespace hdt::domain
