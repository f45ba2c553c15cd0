// The kernel's refined filter stages: the same determinants as the double
// filter, in more precise arithmetic with a certified error bound. Near the
// corners of F_g a translation of N has entries up to cosh(2R) (3.4e5 at
// genus 16) and its image of a point cancels most of them, so double
// precision can lose 20 bits there.
//
// Stage 2a runs in double-double (double_double.hpp: about 106 bits, a few
// hundred instructions per point); stage 2b, when 2a cannot decide, in
// 133-bit MPFR (some 27,000 instructions per point); the exact path after
// both, at milliseconds.
//
// Both stages share one analysis (the templates below). It assumes only the
// standard model for each arithmetic operation of the stage's reals T:
// |op~(a, b) - a op b| <= U |a op b|, with U = `unit`:
//   MPFR at 133 bits rounds correctly: u = 2^-133, and U = kMidUnit = 2^-132
//     keeps a bit to spare;
//   double-double operations are within 13u^2 < 2^-102 (u = 2^-53; see
//     double_double.hpp): U = kFastUnit = 2^-100 keeps two bits to spare.
// Inputs rounded into T are within U as well (matrices, sites' coordinates,
// the constant of large_circumdisk; see where they are rounded). Bounds are
// first-order in U; the factors 1.01 and 1.02 cover the higher-order terms
// and the rounding of the bounds' own double evaluation. Double-double has
// the exponent range of double: a stage gives up unless every magnitude that
// enters a product lies in [2^-200, 2^200], so that no operation underflows
// or overflows beyond a few 2^-1074 absolutely, far below every bound. (They
// always do: every error bound is at least 2^-97, see refined_point.)
#include <mpfr.h>

#include <algorithm>
#include <cmath>

#include "exact/precision_ladder.hpp"
#include "surface/systole.hpp"
#include "group/generators.hpp"
#include "group/word_matrix.hpp"
#include "predicates/kernel.hpp"

namespace hdt::predicates {

namespace {

// x (an MPFR number of p >= 133 bits) rounded to double-double. hi = RN(x)
// is a multiple of the last place of hi's binade, hence of x's: x - hi has
// at most p - 52 significant bits, so the MPFR subtraction is exact.
// lo = RN(x - hi) is within u |x - hi| <= u^2 |x|, and |lo| <= ulp(hi)/2;
// Fast2Sum normalises (hi + lo unchanged).
template <class U>
FastReal round_mp(const U &x) {
  const double hi = mpfr_get_d(x.backend().data(), MPFR_RNDN);
  const U rest = x - U(hi);
  const double lo = mpfr_get_d(rest.backend().data(), MPFR_RNDN);
  return DoubleDouble::fast_two_sum(hi, lo);
}

}  // namespace

FastReal round_to_fast(const MidReal &x) { return round_mp(x); }

namespace {

using Mid = MidReal;
using Fast = FastReal;

constexpr double kMidUnit = 0x1p-132;   // 133-bit MPFR: correct rounding, u = 2^-133
constexpr double kFastUnit = 0x1p-100;  // double-double: every operation within 13u^2 < 2^-102
constexpr double kTiny = 0x1p-200, kHuge = 0x1p200;

// An upper bound on |x|: |double(x)| = |RN(x)| <= |x| (1 + 2^-53) for MPFR;
// for double-double double(x) = hi and |hi + lo| <= |hi| (1 + 2^-53).
template <class T>
double magnitude(const T &x) {
  return std::abs(static_cast<double>(x)) * (1 + 1e-15);
}

bool in_range(double m) { return m >= kTiny && m <= kHuge; }

template <class T>
struct Difference {
  T d[3];
  double error, size;  // error per entry; max |entry| + error
};

template <class T>
Difference<T> difference(const RefinedPoint<T> &a, const RefinedPoint<T> &b, double unit) {
  // Input errors add; the subtraction rounds by U of the result.
  Difference<T> r;
  double m = 0;
  for (int i = 0; i < 3; ++i) {
    r.d[i] = a.n[i] - b.n[i];
    m = std::max(m, magnitude(r.d[i]));
  }
  r.error = (a.error + b.error + unit * m) * 1.01;
  r.size = m + r.error;
  return r;
}

// Sign of det[a; b; c] when certain, else 0. ea, ma: row a's entry error and
// magnitude bound (max |entry| + error), likewise for b, c.
template <class T>
int det3_sign(const T *a, double ea, double ma, const T *b, double eb, double mb, const T *c, double ec, double mc,
              double unit) {
  if (!in_range(ma) || !in_range(mb) || !in_range(mc)) return 0;
  const T value =
      a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  // Input errors: each of the 6 terms of the expansion moves by at most
  // ea mb mc + ma eb mc + ma mb ec. Rounding: each term passes through 5
  // operations (2 products, a difference, a product, the outer sums: at most
  // 2 of them), each U of at most 2 ma mb mc per cofactor, 6 terms: 36 U.
  const double bound = (6 * (ea * mb * mc + ma * eb * mc + ma * mb * ec) + 36 * unit * ma * mb * mc) * 1.02;
  const double v = static_cast<double>(value);
  return v > bound ? 1 : v < -bound ? -1 : 0;
}

// N = L p^ / w for the disk point (x, y) (within coordinate_error in each
// coordinate), L the translation's matrix (each entry within U relative;
// null for the identity).
template <class T>
bool refined_point(const T &x, const T &y, double coordinate_error, const group::Lorentz<T> *L, double unit,
                   RefinedPoint<T> *out) {
  const T s = x * x + y * y;
  const T hat[3] = {T(1) + s, x + x, y + y};
  const T w = T(1) - s;
  const double wd = static_cast<double>(w);
  if (!(wd > 0x1p-100)) return false;
  double h[3];
  for (int j = 0; j < 3; ++j) h[j] = magnitude(hat[j]);
  double worst = 0, row = 1;
  if (!L) {
    for (int i = 0; i < 3; ++i) out->n[i] = hat[i] / w;
    worst = h[0];  // >= |hat_1|, |hat_2|
  } else {
    row = 0;
    for (int i = 0; i < 3; ++i) {
      const T v = L->m[i][0] * hat[0] + L->m[i][1] * hat[1] + L->m[i][2] * hat[2];
      out->n[i] = v / w;
      const double l[3] = {magnitude(L->m[i][0]), magnitude(L->m[i][1]), magnitude(L->m[i][2])};
      worst = std::max(worst, l[0] * h[0] + l[1] * h[1] + l[2] * h[2]);
      row = std::max(row, l[0] + l[1] + l[2]);
    }
  }
  // Relative to worst (>= sum |L_ij hat_j|, and >= 1 since L_00, hat_0 >= 1):
  // L within U and hat within 2U (hat_0 = 1 + s: s = x^2 + y^2 within 2U s,
  // then U (1 + s), and (1 + 3s) <= 2(1 + s); 2x, 2y exact): 3U; products U,
  // the two sums 2U: 7U; the quotient U: 8U. w = 1 - s within 2U s + U w, at
  // most 2U (1 + s) / w relative, which moves N by at most worst/w * 4U/w.
  // A site's coordinates, off by coordinate_error each, move hat / w by at
  // most (2/w + 4/w^2) <= 6/w^2 per unit in each, and L multiplies by at most
  // its row sum. (The error is at least 8U >= 2^-129: never below 2^-200.)
  out->error = (worst / wd * (8 * unit + 4 * unit / wd) + row * 12 * coordinate_error / (wd * wd)) * 1.01;
  return true;
}

template <class T>
int orientation_sign(const RefinedPoint<T> &a, const RefinedPoint<T> &b, const RefinedPoint<T> &c, double unit) {
  const Difference<T> db = difference(b, a, unit), dc = difference(c, a, unit);
  // det[N_p; N_q; N_r] = det[N_p; N_q - N_p; N_r - N_p].
  double ma = 0;
  for (const T &v : a.n) ma = std::max(ma, magnitude(v));
  const int s = det3_sign(a.n, a.error, ma + a.error, db.d, db.error, db.size, dc.d, dc.error, dc.size, unit);
  return s != 0 ? s : 2;
}

template <class T>
int in_circle_sign(const RefinedPoint<T> &a, const RefinedPoint<T> &b, const RefinedPoint<T> &c,
                   const RefinedPoint<T> &e, double unit) {
  const Difference<T> db = difference(b, a, unit), dc = difference(c, a, unit), de = difference(e, a, unit);
  // det[N 1] = -det[N_q - N_p; N_r - N_p; N_s - N_p].
  const int sg = det3_sign(db.d, db.error, db.size, dc.d, dc.error, dc.size, de.d, de.error, de.size, unit);
  return sg != 0 ? -sg : 2;
}

// The double filter's computation (kernel.cpp) with U for u; k = 1 + cos(pi/2g)
// within 4U relative.
template <class T>
int large_circumdisk_sign(const RefinedPoint<T> &a, const RefinedPoint<T> &b, const RefinedPoint<T> &e, const T &k,
                          double unit) {
  const Difference<T> d2 = difference(b, a, unit), d3 = difference(e, a, unit);
  double amax = 0;
  for (int i = 0; i < 3; ++i) amax = std::max(amax, magnitude(a.n[i]));
  amax += a.error;
  if (!in_range(d2.size) || !in_range(d3.size) || !in_range(amax)) return 2;
  const T c[3] = {d2.d[1] * d3.d[2] - d2.d[2] * d3.d[1], d2.d[2] * d3.d[0] - d2.d[0] * d3.d[2],
                  d2.d[0] * d3.d[1] - d2.d[1] * d3.d[0]};
  const double ec = 2 * (d2.error * d3.size + d2.size * d3.error) + 4 * unit * d2.size * d3.size;
  double cmax = 0;
  for (int i = 0; i < 3; ++i) cmax = std::max(cmax, magnitude(c[i]));
  cmax += ec;
  if (!in_range(cmax)) return 2;
  const T c3 = -(c[0] * a.n[0] + c[1] * a.n[1] + c[2] * a.n[2]);
  const double e3 = 3 * (ec * amax + cmax * a.error) + 4 * unit * 3 * cmax * amax;
  const double c3max = magnitude(c3) + e3;
  const T mm = c[0] * c[0] - c[1] * c[1] - c[2] * c[2];
  const double emm = 3 * (2 * cmax * ec) + 6 * unit * 3 * cmax * cmax;
  const T Q = c3 * c3 - k * mm;
  const double eQ = 2 * c3max * e3 + 2 * emm + 8 * unit * 2 * 3 * cmax * cmax + 4 * unit * c3max * c3max;
  const double mmd = static_cast<double>(mm), Qd = static_cast<double>(Q);
  if (mmd < -emm * 1.02) return 1;
  if (mmd > emm * 1.02 && std::abs(Qd) > eQ * 1.02) return Qd > 0 ? 1 : -1;
  return 2;
}

}  // namespace

// Stage 2b: 133-bit MPFR.

const group::Lorentz<Mid> &Kernel::mid_matrix(TranslationId id) {
  if (std::size_t(id) >= mid_matrices_.size()) mid_matrices_.resize(table_.size());
  auto &slot = mid_matrices_.at(id);
  if (!slot)
    slot = std::make_unique<group::Lorentz<Mid>>(group::accurate_lorentz_as<Mid>(surface_.presentation(), table_.word(id)));
  return *slot;
}

bool Kernel::mid_point(const TranslatedPoint &p, MidPoint *out) {
  if (p.site >= 0) {
    const SiteStages &site = site_stages(p.site);
    if (!site.has_mid) return false;
    return refined_point(site.mid.re, site.mid.im, 0x1p-128, &mid_matrix(p.translation), kMidUnit, out);
  }
  // The matrix is the exact one rounded once to 133 bits (within u = 2^-133).
  const group::Lorentz<Mid> *L = p.translation == 0 ? nullptr : &mid_matrix(p.translation);
  return refined_point(Mid(p.x), Mid(p.y), 0, L, kMidUnit, out);
}

int Kernel::orientation_mid(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r) {
  MidPoint a, b, c;
  if (!mid_point(p, &a) || !mid_point(q, &b) || !mid_point(r, &c)) return 2;
  return orientation_sign(a, b, c, kMidUnit);
}

int Kernel::in_circle_mid(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r,
                          const TranslatedPoint &s) {
  MidPoint a, b, c, e;
  if (!mid_point(p, &a) || !mid_point(q, &b) || !mid_point(r, &c) || !mid_point(s, &e)) return 2;
  return in_circle_sign(a, b, c, e, kMidUnit);
}

int Kernel::large_circumdisk_mid(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r) {
  MidPoint a, b, e;
  if (!mid_point(p, &a) || !mid_point(q, &b) || !mid_point(r, &e)) return 2;
  using std::cos;
  // pi and pi/2g within U each, cos within U plus its argument's error
  // (|sin| <= 1, the argument <= pi/4), the sum U: within 4U of k >= 1.
  const Mid k = surface::quarter_systole_cosh2<Mid>(surface_.genus());
  return large_circumdisk_sign(a, b, e, k, kMidUnit);
}

// Stage 2a: double-double.

const group::Lorentz<Fast> &Kernel::fast_matrix(TranslationId id) {
  if (std::size_t(id) >= fast_matrices_.size()) fast_matrices_.resize(table_.size());
  auto &slot = fast_matrices_.at(id);
  if (slot) return *slot;
  // The analysis needs sum_j |L~_ij - L_ij| |hat_j| <= U sum_j |L_ij| |hat_j|
  // (up to the 1.01 margin). Since |hat_1|, |hat_2| <= hat_0 and
  // sum_j |L_ij| |hat_j| >= L_00 hat_0 for row 0, entries within
  // 2^-106 |L_ij| + 2^-121 L_00 suffice (2^-106 + 3 * 2^-121 < U).
  //
  // The word's Moebius matrix at group::moebius_precision_bits(127) (every
  // entry of L = from_moebius(a, b) within 2^-127 L_00, well within
  // 2^-121 L_00), then rounded to double-double (2^-106 relative). (The
  // Lorentz product of accurate_lorentz_as loses about twice as many bits
  // per letter: this puts most words of N on a lower rung.)
  const group::Word &word = table_.word(id);
  const double bits = group::moebius_precision_bits(surface_.presentation(), word.size(), 127);
  if (bits > exact::ladder_top_bits()) {
    // The mid matrix (within 2^-133 |L_ij| + 2^-197 of the exact one, see
    // word_matrix.hpp) rounded to double-double (2^-106 relative).
    const group::Lorentz<Mid> &M = mid_matrix(id);
    auto L = std::make_unique<group::Lorentz<Fast>>();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) L->m[i][j] = round_mp(M.m[i][j]);
    slot = std::move(L);
    return *slot;
  }
  slot = exact::with_precision(bits, [&](auto zero) {
    using U = decltype(zero);
    const group::Lorentz<U> M =
        group::Lorentz<U>::from_moebius(group::shared_generators<U>(surface_.presentation()).moebius(word));
    auto L = std::make_unique<group::Lorentz<Fast>>();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) L->m[i][j] = round_mp(M.m[i][j]);
    return L;
  });
  return *slot;
}

bool Kernel::fast_point(const TranslatedPoint &p, FastPoint *out) {
  auto &c = fast_cache_[cache_slot(p)];
  if (!identical(c.key, p)) {
    FastEntry computed;  // then stored: a throw leaves the entry as it was
    computed.ok = compute_fast_point(p, &computed.point);
    c.point = computed;
    c.key = p;
  }
  *out = c.point.point;
  return c.point.ok;
}

bool Kernel::compute_fast_point(const TranslatedPoint &p, FastPoint *out) {
  if (p.site >= 0) {
    // site.fast: the mid coordinates (within 2^-128 of the exact ones) rounded
    // (2^-106 |.| < 2^-106 more, |x|, |y| < 1).
    const SiteStages &site = site_stages(p.site);
    if (!site.has_mid) return false;
    return refined_point(site.fast.re, site.fast.im, 0x1p-128 + 0x1p-106, &fast_matrix(p.translation), kFastUnit, out);
  }
  const group::Lorentz<Fast> *L = p.translation == 0 ? nullptr : &fast_matrix(p.translation);
  return refined_point(Fast(p.x), Fast(p.y), 0, L, kFastUnit, out);
}

int Kernel::orientation_fast(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r) {
  FastPoint a, b, c;
  if (!fast_point(p, &a) || !fast_point(q, &b) || !fast_point(r, &c)) return 2;
  return orientation_sign(a, b, c, kFastUnit);
}

int Kernel::in_circle_fast(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r,
                           const TranslatedPoint &s) {
  FastPoint a, b, c, e;
  if (!fast_point(p, &a) || !fast_point(q, &b) || !fast_point(r, &c) || !fast_point(s, &e)) return 2;
  return in_circle_sign(a, b, c, e, kFastUnit);
}

int Kernel::large_circumdisk_fast(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r) {
  FastPoint a, b, e;
  if (!fast_point(p, &a) || !fast_point(q, &b) || !fast_point(r, &e)) return 2;
  if (fast_circumdisk_k_.hi == 0) {
    // The mid stage's k (within 4 * 2^-133) rounded (2^-106): within U.
    using std::cos;
    fast_circumdisk_k_ = round_mp(surface::quarter_systole_cosh2<Mid>(surface_.genus()));
  }
  return large_circumdisk_sign(a, b, e, fast_circumdisk_k_, kFastUnit);
}

// The stages in order.

int Kernel::orientation_refined(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r) {
  if (const int s = orientation_fast(p, q, r); s != 2) return ++statistics_.fast, s;
  if (const int s = orientation_mid(p, q, r); s != 2) return ++statistics_.refined, s;
  return 2;
}

int Kernel::in_circle_refined(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r,
                              const TranslatedPoint &s) {
  if (const int sg = in_circle_fast(p, q, r, s); sg != 2) return ++statistics_.fast, sg;
  if (const int sg = in_circle_mid(p, q, r, s); sg != 2) return ++statistics_.refined, sg;
  return 2;
}

int Kernel::large_circumdisk_refined(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r) {
  if (const int s = large_circumdisk_fast(p, q, r); s != 2) return ++statistics_.fast, s;
  if (const int s = large_circumdisk_mid(p, q, r); s != 2) return ++statistics_.refined, s;
  return 2;
}

std::array<double, 3> Kernel::hyperboloid(const TranslatedPoint &p, bool *accurate) {
  const FilteredPoint f = filtered(p);
  const bool good = f.error < 1e-9 * f.n[0];
  if (!good) {
    FastPoint d;
    if (fast_point(p, &d) && d.error < 1e-12 * static_cast<double>(d.n[0])) {
      if (accurate) *accurate = true;
      return {static_cast<double>(d.n[0]), static_cast<double>(d.n[1]), static_cast<double>(d.n[2])};
    }
    MidPoint m;
    if (mid_point(p, &m) && m.error < 1e-12 * static_cast<double>(m.n[0])) {
      if (accurate) *accurate = true;
      return {static_cast<double>(m.n[0]), static_cast<double>(m.n[1]), static_cast<double>(m.n[2])};
    }
  }
  if (accurate) *accurate = good;
  return {f.n[0], f.n[1], f.n[2]};
}

}  // namespace hdt::predicates
