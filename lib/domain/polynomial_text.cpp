#include "domain/polynomial_text.hpp"

#include <cctype>
#include <stdexcept>

#include "domain/rational_text.hpp"

namespace hdt::domain {

namespace {

bool identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

class PolynomialReader {
 public:
  PolynomialReader(const std::string &text, const std::string &gen) : s_(text), gen_(gen) {}

  std::vector<mpq_class> read() {
    if (s_.empty()) fail("it is empty");
    bool negative = sign();
    for (;;) {
      add_term(negative);
      if (i_ == s_.size()) break;
      if (s_[i_] != '+' && s_[i_] != '-') fail("expected + or - at character " + std::to_string(i_ + 1));
      negative = sign();
    }
    while (!c_.empty() && c_.back() == 0) c_.pop_back();
    return c_;
  }

 private:
  [[noreturn]] void fail(const std::string &why) const {
    throw std::invalid_argument("`" + s_ + "` is not a polynomial in " + gen_ + ": " + why);
  }
  bool sign() {
    if (i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-')) return s_[i_++] == '-';
    return false;
  }
  std::string digits() {
    const std::size_t from = i_;
    while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) ++i_;
    return s_.substr(from, i_ - from);
  }
  void add_term(bool negative) {
    mpq_class c = 1;
    long power = 0;
    if (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) {
      std::string number = digits();
      if (i_ < s_.size() && s_[i_] == '/') ++i_, number += "/" + digits();
      if (!parse_rational(number, c)) fail("`" + number + "` is not a rational");
      if (i_ < s_.size() && s_[i_] == '*') ++i_, power = monomial();
    } else {
      power = monomial();
    }
    if (static_cast<long>(c_.size()) <= power) c_.resize(static_cast<std::size_t>(power) + 1, 0);
    c_[static_cast<std::size_t>(power)] += negative ? mpq_class(-c) : c;
  }
  long monomial() {
    if (s_.compare(i_, gen_.size(), gen_) != 0 || (i_ + gen_.size() < s_.size() && identifier_char(s_[i_ + gen_.size()])))
      fail("expected " + gen_ + " at character " + std::to_string(i_ + 1));
    i_ += gen_.size();
    if (i_ == s_.size() || s_[i_] != '^') return 1;
    ++i_;
    const std::string e = digits();
    if (e.empty()) fail("expected a power after ^");
    if (e.size() > 5 || std::stol(e) > kExponentMax) fail("a power above " + std::to_string(kExponentMax));
    return std::stol(e);
  }

  const std::string &s_, &gen_;
  std::size_t i_ = 0;
  std::vector<mpq_class> c_;
};

}  // namespace

std::vector<mpq_class> parse_polynomial(const std::string &text, const std::string &gen) {
  return PolynomialReader(text, gen).read();
}

std::string polynomial_text(const std::vector<mpq_class> &c, const std::string &gen) {
  std::string out;
  for (std::size_t k = c.size(); k-- > 0;) {
    if (c[k] == 0) continue;
    const mpq_class a = abs(c[k]);
    if (c[k] < 0) out += '-';
    else if (!out.empty()) out += '+';
    if (k == 0 || a != 1) out += a.get_str() + (k > 0 ? "*" : "");
    if (k > 0) out += gen + (k > 1 ? "^" + std::to_string(k) : "");
  }
  return out.empty() ? "0" : out;
}

}  // namespace hdt::domain
