#include "domain/element.hpp"

#include <functional>
#include <stdexcept>

#include "domain/distance.hpp"

namespace hdt::domain {

namespace {

Moebius divided_by_top_left(const Moebius &m) {
  if (m.a.is_zero()) throw std::domain_error("domain::Element: a top-left entry 0 is no disk isometry");
  return {complex_one(m.a.re), m.b / m.a, m.c / m.a, m.d / m.a};
}

void mix(std::size_t &h, const Number &x) {
  h ^= std::hash<double>()(static_cast<double>(x)) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
}

std::size_t entries_hash(const Moebius &m) {
  std::size_t h = 0;
  for (const Complex *z : {&m.b, &m.c, &m.d}) {
    mix(h, z->re);
    mix(h, z->im);
  }
  return h;
}

}  // namespace

Element::Element(const Moebius &m) : matrix_(divided_by_top_left(m)), hash_(entries_hash(matrix_)) {}

// The top-left entries are both 1, so the other three decide.
bool Element::operator==(const Element &o) const {
  return hash_ == o.hash_ && matrix_.b == o.matrix_.b && matrix_.c == o.matrix_.c && matrix_.d == o.matrix_.d;
}

Element operator*(const Element &f, const Element &g) { return Element(f.matrix() * g.matrix()); }

Element inverse(const Element &g) { return Element(inverse(g.matrix())); }

Element identity_element(const Number &like) { return Element(identity(like)); }

// With a = 1: tr = 1 + d, det = d - b c.
Number cosh2_half_translation(const Element &g) {
  const Moebius &m = g.matrix();
  const Complex trace = m.a + m.d, det = m.a * m.d - m.b * m.c;
  const Complex q = trace * trace / (Number(m.a.re.parent(), 4) * det);
  if (!q.im.is_zero()) throw std::logic_error("domain::Element: tr^2 / det not real: no disk isometry");
  return q.re;
}

Number cosh_displacement(const Element &g, const Complex &p) { return cosh_distance(p, g.apply(p)); }

}  // namespace hdt::domain
