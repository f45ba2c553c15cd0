#include "domain/polygon_surface.hpp"

#include <gmpxx.h>
#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "domain/ball.hpp"
#include "domain/base_point.hpp"
#include "domain/real_bounds.hpp"
#include "domain/word.hpp"

namespace hdt::domain {

namespace {

// Whether x + iy lies in the open unit disk, exactly: x^2 + y^2 in double
// is within 3 ulps of the exact sum, so only a point within that of the
// circle pays the rational test.
bool in_open_disk(double x, double y) {
  if (!std::isfinite(x) || !std::isfinite(y)) return false;
  const double r2 = x * x + y * y;
  if (r2 < 1 - 0x1p-50) return true;
  if (r2 > 1 + 0x1p-50) return false;
  const mpq_class qx(x), qy(y);
  return qx * qx + qy * qy < 1;
}

// sqrt(q) rounded down to a double, as an exact rational.
mpq_class sqrt_below(const mpq_class &q) {
  mpfr_t m;
  mpfr_init2(m, 53);
  mpfr_set_q(m, q.get_mpq_t(), MPFR_RNDD);
  mpfr_sqrt(m, m, MPFR_RNDD);
  mpq_class r(mpfr_get_d(m, MPFR_RNDD));
  mpfr_clear(m);
  r.canonicalize();
  return r;
}

}  // namespace

PolygonSurface::PolygonSurface(FundamentalPolygon polygon)
    : polygon_(std::move(polygon)),
      table_(polygon_.vertex(0).re),
      kernel_(polygon_, table_),
      reduction_(polygon_),
      base_(base_point(polygon_)) {
  for (const Element &g : pairing_elements(polygon_)) pairings_.push_back(table_.intern(g));
}

ElementId PolygonSurface::home(double x, double y) {
  if (!in_open_disk(x, y)) throw std::domain_error("domain::PolygonSurface: a point outside the open unit disk");
  ElementId h = kIdentityId;
  for (const int k : reduction_.pairings_applied(x, y)) h = table_.compose(pairing(k), h);
  return h;
}

std::array<std::complex<double>, 2> PolygonSurface::rounded(ElementId h) const {
  while (rounded_.size() <= h) {
    const BallIsometry &U = table_.ball(ElementId(rounded_.size()));
    rounded_.push_back({std::complex<double>(real(U.a).mid(), imag(U.a).mid()),
                        std::complex<double>(real(U.b).mid(), imag(U.b).mid())});
  }
  return rounded_[h];
}

namespace {

// A ball's midpoint as hi + lo, and its radius into *radius (the larger).
void split_part(const RealBall &x, double *hi, double *lo, double *radius) {
  arf_t rest, top;
  arf_init(rest);
  arf_init(top);
  *hi = arf_get_d(arb_midref(x.get()), ARF_RND_NEAR);
  arf_set_d(top, *hi);
  arf_sub(rest, arb_midref(x.get()), top, ARF_PREC_EXACT, ARF_RND_DOWN);
  *lo = arf_get_d(rest, ARF_RND_NEAR);
  arf_clear(top);
  arf_clear(rest);
  *radius = std::max(*radius, mag_get_d(arb_radref(x.get())));
}

// The number x rounded to out's precision.
void round_to(const Number &x, mpfr_ptr out) {
  if (x.is_rational()) {
    mpfr_set_q(out, static_cast<mpq_class>(x).get_mpq_t(), MPFR_RNDN);
    return;
  }
  arb_t b;
  arb_init(b);
  renf_elem_get_arb(b, x.renf_elem_t(), x.parent().renf_t(), slong(mpfr_get_prec(out)) + 32);
  arf_get_mpfr(out, arb_midref(b), MPFR_RNDN);
  arb_clear(b);
}

}  // namespace

PolygonSurface::SplitMatrix PolygonSurface::split(ElementId h) const {
  const BallIsometry &U = table_.ball(h);
  SplitMatrix m{};
  double radius = 0, ar, ai, br, bi, lr, li, mr, mi;
  split_part(real(U.a), &ar, &lr, &radius);
  split_part(imag(U.a), &ai, &li, &radius);
  split_part(real(U.b), &br, &mr, &radius);
  split_part(imag(U.b), &bi, &mi, &radius);
  m.a_hi = {ar, ai}, m.a_lo = {lr, li}, m.b_hi = {br, bi}, m.b_lo = {mr, mi};
  // |a| >= 1: the radius over 1 bounds it relatively, rounded up by 2x.
  m.error = 2 * radius;
  return m;
}

void PolygonSurface::precise_image(ElementId h, double x, double y, mpfr_ptr re, mpfr_ptr im) const {
  const Number &like = polygon_.vertex(0).re;
  const Complex z(Number(like.parent(), mpq_class(x)), Number(like.parent(), mpq_class(y)));
  const Complex w = h == kIdentityId ? z : table_.element(h).apply(z);
  round_to(w.re, re);
  round_to(w.im, im);
}

std::complex<double> PolygonSurface::image(ElementId h, double x, double y) const {
  const auto [a, b] = rounded(h);
  const std::complex<double> z(x, y);
  return (a * z + b) / (std::conj(b) * z + std::conj(a));
}

std::vector<int> PolygonSurface::word(ElementId h) const {
  const Representative t = reduction_(table_.element(h).apply(base_));
  std::vector<int> letters;
  for (auto k = t.word.letters.rbegin(); k != t.word.letters.rend(); ++k)
    letters.push_back(polygon_.paired(*k));  // g_k^-1 = g_paired(k)
  // The exact product, not ids: composing ids would intern the prefixes.
  if (word_element(polygon_, letters) != table_.element(h))
    throw std::logic_error("domain::PolygonSurface: a word that does not multiply to its element");
  return letters;
}

const Homology &PolygonSurface::homology() const {
  if (!homology_) homology_.emplace(polygon_);
  return *homology_;
}

const Systole &PolygonSurface::systole() {
  if (!systole_) systole_ = domain::systole(polygon_);
  return *systole_;
}

// cosh^2(sys / 4) = (1 + cosh(sys / 2)) / 2 and cosh(sys / 2) = sqrt(C) for
// the systole's exact C = cosh^2(sys / 2): with s <= sqrt(C) (s >= 0 and
// s^2 <= C, checked exactly), k = (1 + s) / 2 is the bound.
const Number &PolygonSurface::quarter_systole_cosh2_below() {
  if (threshold_) return *threshold_;
  const Number &C = systole().cosh2_half;
  mpq_class s = sqrt_below(rational_below(C));
  if (s < 0 || Number(C.parent(), mpq_class(s * s)) > C)
    throw std::logic_error("domain::PolygonSurface: a square root bound that does not hold");
  if (s < 1) s = 1;  // cosh >= 1: keeps k >= 1, still a lower bound
  threshold_ = Number(C.parent(), mpq_class((1 + s) / 2));
  return *threshold_;
}

}  // namespace hdt::domain
