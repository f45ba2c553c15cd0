#include "domain/polygon_text.hpp"

#include <cctype>
#include <climits>
#include <istream>
#include <iterator>
#include <sstream>

#include "domain/rational_text.hpp"

namespace hdt::domain {

namespace {

// The largest n read: a bound against a huge allocation from one token.
constexpr long kMaxSides = 1L << 20;

struct Token {
  std::string text;
  int line, column;
};

std::vector<Token> tokenise(const std::string &text) {
  std::vector<Token> out;
  int line = 1, column = 1;
  for (std::size_t i = 0; i < text.size();) {
    if (std::isspace(static_cast<unsigned char>(text[i]))) {
      if (text[i] == '\n') ++line, column = 0;
      ++i, ++column;
      continue;
    }
    Token t{{}, line, column};
    while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i]))) t.text += text[i++], ++column;
    out.push_back(std::move(t));
  }
  return out;
}

class Reader {
 public:
  explicit Reader(const std::string &text) : tokens_(tokenise(text)) {}

  PolygonText read() {
    PolygonText p;
    if (at("field")) p.field = field();
    const long n = integer("the number of vertices n", 1, kMaxSides);
    for (long k = 0; k < n; ++k)
      p.paired.push_back(int(integer("the side paired with side " + std::to_string(k), INT_MIN, INT_MAX)));
    for (long k = 0; k < n; ++k) {
      Number x = coordinate(p.field, "x", k);
      p.vertices.emplace_back(std::move(x), coordinate(p.field, "y", k));
    }
    if (next_ < tokens_.size()) fail("the end of the text (n = " + std::to_string(n) + " vertices were read)");
    return p;
  }

 private:
  std::vector<Token> tokens_;
  std::size_t next_ = 0;

  bool at(const std::string &word) const { return next_ < tokens_.size() && tokens_[next_].text == word; }

  [[noreturn]] void fail(const std::string &expected) const {
    if (next_ >= tokens_.size())
      throw ParseError("token " + std::to_string(next_ + 1) + ": the text ends where " + expected + " was expected");
    const Token &t = tokens_[next_];
    throw ParseError("token " + std::to_string(next_ + 1) + " (line " + std::to_string(t.line) + ", column " +
                     std::to_string(t.column) + ") `" + t.text + "`: expected " + expected);
  }

  const std::string &take(const std::string &expected) {
    if (next_ >= tokens_.size()) fail(expected);
    return tokens_[next_++].text;
  }

  long integer(const std::string &what, long low, long high) {
    const std::string &s = take(what);
    if (is_integer_text(s) && s.size() <= 18) {
      const long v = std::stol(s);
      if (v >= low && v <= high) return v;
    }
    --next_;
    fail(what + ", an integer in [" + std::to_string(low) + ", " + std::to_string(high) + "]");
  }

  FieldPtr field() {
    ++next_;  // `field`
    const std::size_t first = next_;
    const std::string minpoly = take("the minimal polynomial of the field line");
    const std::string gen = take("the generator's name of the field line");
    const std::string ball = take("the embedding MID+/-RAD of the field line");
    try {
      return make_field(minpoly, gen, ball);
    } catch (const std::invalid_argument &e) {
      next_ = first;
      fail(std::string("a field `field MINPOLY GEN MID+/-RAD`: ") + e.what());
    }
  }

  Number coordinate(const FieldPtr &K, const char *axis, long k) {
    const std::string what = std::string(axis) + " of vertex " + std::to_string(k);
    const std::string &s = take(what);
    mpq_class q;
    if (parse_rational(s, q)) return K ? Number(*K, q) : Number(q);
    if (!K) {
      --next_;
      fail(what + ", a rational p/q or p or a decimal [-]digits.digits");
    }
    try {
      return make_element(*K, s);
    } catch (const std::invalid_argument &e) {
      --next_;
      fail(what + ", a rational or " + e.what());
    }
  }
};

}  // namespace

bool names_field(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  return text.compare(i, 5, "field") == 0 &&
         (i + 5 == text.size() || std::isspace(static_cast<unsigned char>(text[i + 5])));
}

PolygonText parse_polygon_text(const std::string &text) { return Reader(text).read(); }

PolygonText read_polygon_text(std::istream &in) {
  return parse_polygon_text(std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()));
}

void write_polygon_text(std::ostream &out, const PolygonText &p) {
  if (p.field)
    out << "field " << minpoly_token(*p.field) << ' ' << p.field->gen_name() << ' ' << ball_token(*p.field) << '\n';
  out << p.vertices.size() << '\n';
  for (std::size_t k = 0; k < p.paired.size(); ++k) out << (k ? " " : "") << p.paired[k];
  out << '\n';
  for (const Complex &z : p.vertices) out << element_token(z.re) << ' ' << element_token(z.im) << '\n';
}

std::string polygon_text(const PolygonText &p) {
  std::ostringstream out;
  write_polygon_text(out, p);
  return out.str();
}

}  // namespace hdt::domain
