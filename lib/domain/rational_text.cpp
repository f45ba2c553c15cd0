#include "domain/rational_text.hpp"

#include <cctype>
#include <cstdlib>

namespace hdt::domain {

namespace {

bool all_digits(const std::string &s, std::size_t from, std::size_t to) {
  if (from >= to) return false;
  for (std::size_t i = from; i < to; ++i)
    if (!std::isdigit(static_cast<unsigned char>(s[i]))) return false;
  return true;
}

mpz_class ten_to(unsigned long k) {
  mpz_class p;
  mpz_ui_pow_ui(p.get_mpz_t(), 10, k);
  return p;
}

}  // namespace

bool is_integer_text(const std::string &s) {
  const std::size_t start = (!s.empty() && (s[0] == '+' || s[0] == '-')) ? 1 : 0;
  return all_digits(s, start, s.size());
}

bool parse_rational(const std::string &s, mpq_class &q) {
  const std::size_t start = (!s.empty() && (s[0] == '+' || s[0] == '-')) ? 1 : 0;
  const bool negative = start == 1 && s[0] == '-';
  const std::size_t slash = s.find('/'), dot = s.find('.');
  if (slash != std::string::npos && dot == std::string::npos) {
    if (!all_digits(s, start, slash) || !all_digits(s, slash + 1, s.size())) return false;
    const mpz_class num(s.substr(start, slash - start), 10), den(s.substr(slash + 1), 10);
    if (den == 0) return false;
    q = mpq_class(num, den);
  } else if (dot != std::string::npos && slash == std::string::npos) {
    if (!all_digits(s, start, dot) || !all_digits(s, dot + 1, s.size())) return false;
    q = mpq_class(mpz_class(s.substr(start, dot - start) + s.substr(dot + 1), 10), ten_to(s.size() - dot - 1));
  } else if (slash == std::string::npos && dot == std::string::npos) {
    if (!all_digits(s, start, s.size())) return false;
    q = mpq_class(mpz_class(s.substr(start), 10));
  } else {
    return false;
  }
  q.canonicalize();
  if (negative) q = -q;
  return true;
}

bool parse_scientific(const std::string &s, mpq_class &q) {
  const std::size_t e = s.find_first_of("eE");
  if (e == std::string::npos) return parse_rational(s, q);
  if (s.find('/') != std::string::npos || !parse_rational(s.substr(0, e), q)) return false;
  const std::size_t start = e + 1 < s.size() && (s[e + 1] == '+' || s[e + 1] == '-') ? e + 2 : e + 1;
  if (!all_digits(s, start, s.size()) || s.size() - start > 5) return false;
  const long k = std::strtol(s.c_str() + start, nullptr, 10);
  if (k > 10000) return false;
  const mpq_class scale(ten_to(static_cast<unsigned long>(k)));
  q = s[e + 1] == '-' ? mpq_class(q / scale) : mpq_class(q * scale);
  q.canonicalize();
  return true;
}

}  // namespace hdt::domain
