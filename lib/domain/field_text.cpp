#include "domain/field_text.hpp"

#include <flint/fmpq_poly.h>
#include <flint/fmpz_poly.h>
#include <flint/fmpz_poly_factor.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <string>
#include <vector>

#include "domain/field_lock.hpp"
#include "domain/polynomial_text.hpp"
#include "domain/rational_text.hpp"
#include "domain/real_roots.hpp"

namespace hdt::domain {

namespace {

bool is_identifier(const std::string &s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  return std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; });
}

// The polynomial's primitive integer multiple, in FLINT.
void set_integer_multiple(fmpz_poly_t z, const std::vector<mpq_class> &c) {
  fmpq_poly_t q;
  fmpq_poly_init(q);
  for (std::size_t k = 0; k < c.size(); ++k) fmpq_poly_set_coeff_mpq(q, slong(k), c[k].get_mpq_t());
  fmpq_poly_get_numerator(z, q);
  fmpz_poly_primitive_part(z, z);
  fmpq_poly_clear(q);
}

// Irreducible over Q: by Gauss's lemma, when its primitive integer multiple
// has one irreducible factor over Z, of multiplicity one.
bool irreducible(const std::vector<mpq_class> &c) {
  fmpz_poly_t p;
  fmpz_poly_init(p);
  set_integer_multiple(p, c);
  fmpz_poly_factor_t f;
  fmpz_poly_factor_init(f);
  fmpz_poly_factor(f, p);
  const bool one = f->num == 1 && f->exp[0] == 1;
  fmpz_poly_factor_clear(f);
  fmpz_poly_clear(p);
  return one;
}

std::vector<mpq_class> minpoly_of(const eantic::renf_class &K) {
  const fmpq_poly_struct *pol = K.renf_t()->nf->pol;
  std::vector<mpq_class> c(std::size_t(fmpq_poly_length(pol)));
  for (std::size_t k = 0; k < c.size(); ++k) fmpq_poly_get_coeff_mpq(c[k].get_mpq_t(), pol, slong(k));
  return c;
}

std::vector<mpq_class> checked_minpoly(const std::string &minpoly, const std::string &gen) {
  const std::vector<mpq_class> c = parse_polynomial(minpoly, gen);
  if (c.size() < 2) throw std::invalid_argument("`" + minpoly + "` is constant: no field");
  if (long(c.size()) - 1 > kFieldDegreeMax)
    throw std::invalid_argument("`" + minpoly + "` has degree " + std::to_string(c.size() - 1) +
                                ", above the largest field degree this build reads, " +
                                std::to_string(kFieldDegreeMax));
  if (!irreducible(c)) throw std::invalid_argument("the polynomial `" + minpoly + "` is not irreducible over Q");
  return c;
}

// MID+/-RAD with RAD > 0, holding exactly one real root of c, and so does
// the same ball widened by 2^-30 of its radius: arb's reading of the ball
// (rounded outwards, far less than that) then holds it alone too.
void check_ball(const std::vector<mpq_class> &c, const std::string &ball, std::string *mid, std::string *rad) {
  const std::size_t pm = ball.find("+/-");
  mpq_class m, r;
  if (pm == std::string::npos || !parse_scientific(ball.substr(0, pm), m) ||
      !parse_scientific(ball.substr(pm + 3), r) || r <= 0)
    throw std::invalid_argument("the embedding `" + ball + "` is not a ball MID+/-RAD (decimals, RAD > 0)");
  const mpq_class wide = r + r / mpq_class(1L << 30);
  const long roots = real_roots_in(c, m - r, m + r), wide_roots = real_roots_in(c, m - wide, m + wide);
  if (roots != 1 || wide_roots != 1)
    throw std::invalid_argument("the ball " + ball + " holds " + std::to_string(roots) +
                                " real roots of the polynomial (or another just outside it), not one");
  *mid = ball.substr(0, pm), *rad = ball.substr(pm + 3);
}

// e-antic keeps one field per definition (its fields are unique) and frees it
// with its last element; a thread freeing it while another is handed the
// same field by make() is a race inside e-antic 1.3 (ThreadSanitizer sees
// it: test_threads). So every field made here is kept until the process
// ends, and made under the field lock (field_lock.hpp): its count never
// falls to zero while threads use it. The fields are few (one per distinct
// field line read).
FieldPtr kept_field(const std::string &minpoly, const std::string &gen, const std::string &ball) {
  static std::vector<FieldPtr> kept;
  const FieldLock lock(true);
  FieldPtr K = eantic::renf_class::make(minpoly, gen, ball);
  if (std::find(kept.begin(), kept.end(), K) == kept.end()) kept.push_back(K);
  return K;
}

}  // namespace

// Everything e-antic is given has been checked first: its own parsing and
// root isolation leak memory when they fail.
FieldPtr make_field(const std::string &minpoly, const std::string &gen, const std::string &ball) {
  if (!is_identifier(gen)) throw std::invalid_argument("the generator's name `" + gen + "` is not an identifier");
  const std::vector<mpq_class> c = checked_minpoly(minpoly, gen);
  std::string mid, rad;
  check_ball(c, ball, &mid, &rad);
  return kept_field(polynomial_text(c, gen), gen, mid + " +/- " + rad);
}

std::string minpoly_token(const eantic::renf_class &K) { return polynomial_text(minpoly_of(K), K.gen_name()); }

std::string ball_token(const eantic::renf_class &K) {
  std::string b = std::get<2>(K.construction());  // [MID +/- RAD]
  b.erase(std::remove_if(b.begin(), b.end(), [](unsigned char ch) { return std::isspace(ch) || ch == '[' || ch == ']'; }),
          b.end());
  return b;
}

std::string element_token(const Number &x) {
  if (x.is_rational()) return static_cast<mpq_class>(x).get_str();
  const std::vector<mpz_class> num = x.num_vector();
  const mpz_class den = x.den();
  std::vector<mpq_class> c;
  for (const mpz_class &n : num) c.push_back(mpq_class(n, den)), c.back().canonicalize();
  return polynomial_text(c, x.parent().gen_name());
}

Number make_element(const eantic::renf_class &K, const std::string &token) {
  const std::vector<mpq_class> c = parse_polynomial(token, K.gen_name());
  Number x(K, 0);
  for (std::size_t k = c.size(); k-- > 0;) x = x * K.gen() + Number(K, c[k]);
  return x;
}

}  // namespace hdt::domain
