// The kernel's second filter stage: the same determinants as the double
// filter, in 133-bit MPFR arithmetic with a certified error bound. Near the
// corners of F_g a translation of N has entries up to cosh(2R) (3.4e5 at
// genus 16) and its image of a point cancels most of them, so double
// precision can lose 20 bits there; 133 bits leave ample room, at a few
// microseconds instead of the exact path's milliseconds.
#include <algorithm>
#include <cmath>

#include "group/word_matrix.hpp"
#include "predicates/kernel.hpp"

namespace hdt::predicates {

namespace {

using Mid = MidReal;

constexpr double kMidUnit = 0x1p-132;  // 133-bit rounding, with a bit to spare

double magnitude(const Mid &x) { return std::abs(static_cast<double>(x)) * (1 + 1e-15); }

struct MidDifference {
  Mid d[3];
  double error, size;  // error per entry; max |entry| + error
};

MidDifference difference(const MidPoint &a, const MidPoint &b) {
  MidDifference r;
  double m = 0;
  for (int i = 0; i < 3; ++i) {
    r.d[i] = a.n[i] - b.n[i];
    m = std::max(m, magnitude(r.d[i]));
  }
  r.error = (a.error + b.error + kMidUnit * m) * 1.01;
  r.size = m + r.error;
  return r;
}

// Sign of det[a; b; c] when certain, else 0.
int det3_sign(const Mid *a, double ea, double ma, const Mid *b, double eb, double mb, const Mid *c, double ec,
              double mc) {
  const Mid value = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                    a[2] * (b[0] * c[1] - b[1] * c[0]);
  const double bound = (6 * (ea * mb * mc + ma * eb * mc + ma * mb * ec) + 36 * kMidUnit * ma * mb * mc) * 1.02;
  const double v = static_cast<double>(value);
  return v > bound ? 1 : v < -bound ? -1 : 0;
}

}  // namespace

const group::Lorentz<Mid> &Kernel::mid_matrix(TranslationId id) {
  if (std::size_t(id) >= mid_matrices_.size()) mid_matrices_.resize(table_.size());
  auto &slot = mid_matrices_.at(id);
  if (!slot)
    slot = std::make_unique<group::Lorentz<Mid>>(group::accurate_lorentz_as<Mid>(presentation(), table_.word(id)));
  return *slot;
}

bool Kernel::mid_point(const TranslatedPoint &p, MidPoint *out) {
  double coordinate_error = 0;
  Mid x(p.x), y(p.y);
  if (p.site >= 0) {
    const SiteData &site = sites_[p.site];
    if (!site.has_mid) return false;
    x = site.mid.re, y = site.mid.im;
    coordinate_error = 0x1p-128;
  }
  const Mid s = x * x + y * y;
  const Mid hat[3] = {Mid(1) + s, x + x, y + y};
  const Mid w = Mid(1) - s;
  const double wd = static_cast<double>(w);
  if (!(wd > 0)) return false;
  const group::Lorentz<Mid> &L = mid_matrix(p.translation);
  double worst = 0, row = 0;
  for (int i = 0; i < 3; ++i) {
    const Mid v = L.m[i][0] * hat[0] + L.m[i][1] * hat[1] + L.m[i][2] * hat[2];
    out->n[i] = v / w;
    worst = std::max(worst, magnitude(L.m[i][0] * hat[0]) + magnitude(L.m[i][1] * hat[1]) + magnitude(L.m[i][2] * hat[2]));
    row = std::max(row, magnitude(L.m[i][0]) + magnitude(L.m[i][1]) + magnitude(L.m[i][2]));
  }
  // L and the hat vector within 2u' each, the sums 3u', the quotient u', and
  // w within 2u'(1 + s) / w relative; a site's coordinates move hat / w by at
  // most 6 / w^2 per unit in each.
  out->error = (worst / wd * (8 * kMidUnit + 4 * kMidUnit / wd) + row * 12 * coordinate_error / (wd * wd)) * 1.01;
  return true;
}

int Kernel::orientation_mid(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r) {
  MidPoint a, b, c;
  if (!mid_point(p, &a) || !mid_point(q, &b) || !mid_point(r, &c)) return 2;
  const MidDifference db = difference(b, a), dc = difference(c, a);
  double ma = 0;
  for (const Mid &v : a.n) ma = std::max(ma, magnitude(v));
  const int s = det3_sign(a.n, a.error, ma + a.error, db.d, db.error, db.size, dc.d, dc.error, dc.size);
  return s != 0 ? s : 2;
}

int Kernel::in_circle_mid(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r,
                          const TranslatedPoint &s) {
  MidPoint a, b, c, e;
  if (!mid_point(p, &a) || !mid_point(q, &b) || !mid_point(r, &c) || !mid_point(s, &e)) return 2;
  const MidDifference db = difference(b, a), dc = difference(c, a), de = difference(e, a);
  // det[N 1] = -det[N_q - N_p; N_r - N_p; N_s - N_p].
  const int sg = det3_sign(db.d, db.error, db.size, dc.d, dc.error, dc.size, de.d, de.error, de.size);
  return sg != 0 ? -sg : 2;
}

int Kernel::large_circumdisk_mid(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r) {
  // The double filter's computation (kernel.cpp) with u' for u.
  MidPoint a, b, e;
  if (!mid_point(p, &a) || !mid_point(q, &b) || !mid_point(r, &e)) return 2;
  const MidDifference d2 = difference(b, a), d3 = difference(e, a);
  const Mid c[3] = {d2.d[1] * d3.d[2] - d2.d[2] * d3.d[1], d2.d[2] * d3.d[0] - d2.d[0] * d3.d[2],
                    d2.d[0] * d3.d[1] - d2.d[1] * d3.d[0]};
  const double ec = 2 * (d2.error * d3.size + d2.size * d3.error) + 4 * kMidUnit * d2.size * d3.size;
  double cmax = 0, amax = 0;
  for (int i = 0; i < 3; ++i) cmax = std::max(cmax, magnitude(c[i])), amax = std::max(amax, magnitude(a.n[i]));
  cmax += ec, amax += a.error;
  const Mid c3 = -(c[0] * a.n[0] + c[1] * a.n[1] + c[2] * a.n[2]);
  const double e3 = 3 * (ec * amax + cmax * a.error) + 4 * kMidUnit * 3 * cmax * amax;
  const double c3max = magnitude(c3) + e3;
  const Mid mm = c[0] * c[0] - c[1] * c[1] - c[2] * c[2];
  const double emm = 3 * (2 * cmax * ec) + 6 * kMidUnit * 3 * cmax * cmax;
  using std::cos;
  const Mid k = Mid(1) + cos(exact::pi<Mid>() / Mid(2 * presentation().genus()));  // within 4u'
  const Mid Q = c3 * c3 - k * mm;
  const double eQ = 2 * c3max * e3 + 2 * emm + 8 * kMidUnit * 2 * 3 * cmax * cmax + 4 * kMidUnit * c3max * c3max;
  const double mmd = static_cast<double>(mm), Qd = static_cast<double>(Q);
  if (mmd < -emm * 1.02) return 1;
  if (mmd > emm * 1.02 && std::abs(Qd) > eQ * 1.02) return Qd > 0 ? 1 : -1;
  return 2;
}

std::array<double, 3> Kernel::hyperboloid(const TranslatedPoint &p, bool *accurate) {
  const FilteredPoint f = filtered(p);
  MidPoint m;
  const bool good = f.error < 1e-9 * f.n[0];
  if (!good && mid_point(p, &m) && m.error < 1e-12 * static_cast<double>(m.n[0])) {
    if (accurate) *accurate = true;
    return {static_cast<double>(m.n[0]), static_cast<double>(m.n[1]), static_cast<double>(m.n[2])};
  }
  if (accurate) *accurate = good;
  return {f.n[0], f.n[1], f.n[2]};
}

}  // namespace hdt::predicates
