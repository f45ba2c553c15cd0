#include "group/word_matrix.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <boost/multiprecision/gmp.hpp>

#include "exact/precision_ladder.hpp"
#include "exact/unit_disk.hpp"
#include "exact/unsupported.hpp"
#include "group/dehn.hpp"
#include "group/generators.hpp"
#include "group/rotated_products.hpp"

namespace hdt::group {

double word_precision_bits(const Presentation &p, std::size_t m) {
  const double A = half_trace<double>(p.genus());
  return (std::log2(6.0 * A * A) + 1.0) * double(m) + 2.0 * std::log2(double(m) + 2.0);
}

double word_certified_bits(const Presentation &p, std::size_t m) { return 64.0 + word_precision_bits(p, m); }

namespace {

// The rungs of accurate_moebius, accurate_lorentz and accurate_image: the
// smallest with enough bits, else the top (products beyond it are refused
// earlier by the words' length limits).
using AccurateLadder = exact::Ladder<40, 160, 640, 2560>;

template <class T>
double to_double(const T &x) {
  return x.template convert_to<double>();
}

}  // namespace

Moebius<double> accurate_moebius(const Presentation &p, const Letter *w, std::size_t length) {
  return AccurateLadder::with_bits(word_certified_bits(p, length), [&](auto zero) {
    using T = decltype(zero);
    const Moebius<T> m = shared_generators<T>(p).moebius(w, length);
    return Moebius<double>{{to_double(m.a.re), to_double(m.a.im)}, {to_double(m.b.re), to_double(m.b.im)}};
  });
}

Lorentz<double> accurate_lorentz(const Presentation &p, const Letter *w, std::size_t length) {
  return AccurateLadder::with_bits(word_certified_bits(p, length), [&](auto zero) {
    using T = decltype(zero);
    const Lorentz<T> m = shared_generators<T>(p).lorentz(w, length);
    Lorentz<double> r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r.m[i][j] = to_double(m.m[i][j]);
    return r;
  });
}

Complex<double> accurate_image(const Presentation &p, const Word &w, Complex<double> z) {
  // Mapping a point near the circle inwards cancels about log2(1/(1 - |z|))
  // bits in the denominator: add them, with a margin.
  const double gap = 1.0 - std::hypot(z.re, z.im);
  const double extra = 64.0 + (gap > 0 ? 2.0 * std::log2(1.0 / gap) : 2200.0);
  return AccurateLadder::with_bits(word_certified_bits(p, w.size()) + extra, [&](auto zero) {
    using T = decltype(zero);
    const Complex<T> image = shared_generators<T>(p).moebius(w).apply(Complex<T>{T(z.re), T(z.im)});
    return Complex<double>{to_double(image.re), to_double(image.im)};
  });
}

double moebius_precision_bits(const Presentation &p, std::size_t m, double target) {
  // The product [[a, b], [b~, a~]] at p bits (eps = 2^-p). Generators
  // g = [[A, B], [B~, A]], |B| < A = cot(pi/4g): A within 4.5 eps (pi, the
  // quotient, tan, 1/tan), |B| within 7.6 eps (A^2 - 1 cancels at most a
  // factor 1.21 for A >= cot(pi/8)), cos and sin of angles up to 2 pi within
  // 20 eps absolute: each real part of g within 29 eps A. The exact partial
  // products P_k have |a_k|, |b_k| <= (2A)^k; a step's error is
  // 2A (1 + 30 eps) E_{k-1} (propagated) + 46 eps A (2A)^{k-1} (g's error)
  // + 8.5 eps A (2A)^{k-1} (two complex products and a sum), so
  // E_m <= 32 m eps (2A)^m on |a|, |b| for m letters. from_moebius's entries
  // are quadratic in a, b: within 4 (|a| + |b|) E + 8 eps (|a|^2 + |b|^2)
  // <= (4 sqrt2 E + 8 eps) L_00 (L_00 = |a|^2 + |b|^2 >= 1). With
  // p >= target + 8 + log2(m + 1) + m log2(2A):
  // eps (182 m (2A)^m + 8) <= 2^-target L_00 (and E <= 2^-target).
  const double A = half_trace<double>(p.genus());
  return target + 8 + std::log2(double(m) + 1) + double(m) * std::log2(2 * A * (1 + 1e-9));
}

// ---------------------------------------------------------------------------
// Elements, for the C API

namespace {

// A lower bound on log2(1 - x^2 - y^2) for a point of the open unit disk.
double log2_disk_gap(double x, double y) {
  // Away from the circle the double value is within 2^-30 of its size.
  const double gap = 1.0 - (x * x + y * y);
  if (gap > 0x1p-20) return std::log2(gap) - 0x1p-20;
  using boost::multiprecision::mpq_rational;
  const mpq_rational qx(x), qy(y);
  const mpq_rational exact = 1 - qx * qx - qy * qy;
  // The numerator is at least 2^msb, the denominator below 2^(msb + 1).
  return double(boost::multiprecision::msb(numerator(exact))) -
         double(boost::multiprecision::msb(denominator(exact))) - 1.0;
}

std::string too_long(std::size_t m) {
  return "the Dehn-reduced word has " + std::to_string(m) + " letters and is too long for the built-in precision";
}

const char kOverflow[] = "the matrix entries exceed the double range";

// a and b within 2^-72 of |a| + |b| <= 2 |a| (and |b| >= sinh of the inradius
// of F_g > 2 for an element other than the identity): each Lorentz entry,
// quadratic in them, within 2^-66 L_00 as in accurate_matrices.
constexpr double kElementTarget = 72;

// The rungs of the element products: AccurateLadder's, and 800 digits,
// enough for the a posteriori bound of any product that fits in double
// (below).
using ElementLadder = exact::Ladder<40, 160, 640, 800, 2560>;


// |a| + |b| rounded up, in long double: its exponent range (2^16384) holds
// every product these bounds can certify.
template <class T>
long double norm_of(const Moebius<T> &m) {
  const auto ld = [](const T &x) { return x.template convert_to<long double>(); };
  // The conversions and the hypot are within a few 2^-64.
  return (std::hypot(ld(m.a.re), ld(m.a.im)) + std::hypot(ld(m.b.re), ld(m.b.im))) * (1 + 0x1p-56L);
}

// The error bound of a product P^_k = P^_(k-1) g^_k computed letter by letter
// with unit roundoff at most eps = 2^-bits; operator norms, |P| = |a| + |b|.
//
// Each step has |P^_k - P^_(k-1) g_k| <= l_k = 128 eps L |P^_(k-1)| (L >= |g_k|;
// g^_k within 46 eps A of g_k, see moebius_precision_bits, the product within
// 8.6 eps |P^| |g^|; 128 leaves room for this bookkeeping's own rounding).
// The error e_k of P^_k is the sum over j <= k of those local errors times
// g_(j+1) ... g_k, bounded two ways, the smaller kept:
//   a priori: e_k <= L e_(k-1) + l_k, which grows like L^k;
//   through the path: g_(j+1) ... g_k = P_j^-1 P_k, so the factor is at most
//   |P_j| |P_k| (|X^-1| = |X| in SU(1,1)), with |P_j| <= |P^_j| + e_j and
//   |P_k| <= L (|P^_(k-1)| + e_(k-1)).
// The second costs about 2 log2 max |P_j| bits, the first m log2 L: for a
// long reduced word whose product is moderate (chains of half relators at
// large genus grow a tenth of a bit a letter) the second is far smaller.
class ProductBound {
 public:
  ProductBound(const Presentation &p, double bits) {
    const long double A = half_trace<double>(p.genus());
    L_ = (A + std::sqrt(A * A - 1)) * (1 + 0x1p-30L);
    local_ = 128 * std::ldexp(1.0L, -int(bits)) * L_;
  }

  // After a step, with the new product's norm_of.
  void step(long double next_norm) {
    const long double l = local_ * norm_;
    error_ = std::min(L_ * error_ + l, l + L_ * (norm_ + error_) * through_path_);
    norm_ = next_norm;
    through_path_ += l * (norm_ + error_);  // sum of l_j (|P^_j| + e_j)
  }

  bool finite() const { return std::isfinite(norm_) && std::isfinite(through_path_); }
  // Upper bounds of |P| and of |P^ - P| / |P| (infinite when unknown).
  long double norm() const { return norm_ + error_; }
  long double relative_error() const {
    const long double least = norm_ * (1 - 0x1p-50L) - error_;  // |P| >= |P^| - e
    return finite() && least > 0 ? error_ / least : std::numeric_limits<long double>::infinity();
  }

 private:
  long double L_, local_;
  long double norm_ = 1, error_ = 0, through_path_ = 0;
};

// The product of the reduced word on the rung of T, if it is within
// 2^-target of |P|.
template <class T>
bool certified_product(const Presentation &p, const Word &r, double bits, double target, Moebius<T> *out) {
  const GeneratorSet<T> &gens = shared_generators<T>(p);
  ProductBound bound(p, bits);
  Moebius<T> P = Moebius<T>::identity();
  for (const Letter k : r) {
    P = P * gens.moebius(k);
    bound.step(norm_of(P));
    if (!bound.finite()) return false;
  }
  if (!(bound.relative_error() <= std::ldexp(1.0L, -int(std::ceil(target))))) return false;
  *out = P;
  return true;
}

// The reduced word's Moebius product within 2^-target of its norm, handed to
// f in the number type of the lowest rung that certifies it (first the one
// of the smaller of the two bounds above, guessed: the a priori one, and
// twice the bound's log2 |P| with a margin for the path).
template <class F>
auto with_certified_product(const Presentation &p, const Word &r, double target, double log2_norm, F &&f) {
  using Result = decltype(f(Moebius<exact::mp_real<ElementLadder::kDigits10[0]>>{}));
  const double guess = std::min(moebius_precision_bits(p, r.size(), target),
                                target + 2.0 * log2_norm + std::log2(double(r.size()) + 1.0) + 48.0);
  const std::size_t first = std::min(ElementLadder::rung_for(guess), ElementLadder::kSize - 1);
  const std::optional<Result> result = ElementLadder::climb(first, [&](auto zero) -> std::optional<Result> {
    using T = decltype(zero);
    Moebius<T> P;
    if (!certified_product(p, r, double(exact::RungOf<T>::bits), target, &P)) return std::nullopt;
    return f(P);
  });
  if (result) return *result;
  throw exact::Unsupported(too_long(r.size()));
}

// ---- The group in double, for norm_log2_lower_bound ----

constexpr double kUnit = 0x1p-53;  // unit roundoff of double

struct Real2x2 {
  double m00, m01, m10, m11;
};

// A factor of the pass: m with norm >= |m|, least <= 1 / |m| (|m x| >= least
// |x| in SL(2,R)) and eta |c| >= the error of m c computed in double.
struct Block {
  Real2x2 m;
  double norm, least, eta;
};

// phi(a, b) = [[Re a + Im b, Im a + Re b], [Re b - Im a, Re a - Im b]] is a
// homomorphism SU(1,1) -> SL(2,R) (conjugation by a multiple of a unitary
// matrix), so it keeps the operator norm |a| + |b|; real products are
// cheaper than complex ones.
template <class T>
Real2x2 rounded_phi(const Moebius<T> &g) {
  return {to_double(T(g.a.re + g.b.im)), to_double(T(g.a.im + g.b.re)), to_double(T(g.b.re - g.a.im)),
          to_double(T(g.a.re - g.b.im))};
}

Block make_block(const Real2x2 &m, long double norm, double eta_over_norm) {
  const double upper = double(norm * (1 + 0x1p-40L));
  return {m, upper, (1.0 / upper) * (1.0 - 0x1p-40), eta_over_norm * upper};
}

// The generators, the rotations R_y (y pi / 2g about O, so g_y = R_y g_0
// R_y^-1) and the relator runs from g_0, run(d, l) = g_0 g_d ... g_((l-1) d)
// for the steps d = 2g + 1 and 2g - 1: the run y, y + d, ... is
// R_y run(d, l) R_y^-1. The pass takes a run as one factor: around a vertex
// of the tiling a run first shrinks the tracked vector, then stretches it by
// up to the run's norm (2^23 at genus 1024), and letter by letter that
// widens the cone past use. Built at 531 bits, rounded once; once per genus.
struct DoubleGroup {
  std::vector<Block> letters;
  std::vector<double> cos, sin;  // phi(R_y) = [[cos, sin], [-sin, cos]], angle y pi / 4g
  std::vector<Block> runs[2];    // by length l = 2..2g (0 and 1 unused)
};

const DoubleGroup &double_group(const Presentation &p) {
  static std::mutex mutex;
  static std::map<int, std::unique_ptr<const DoubleGroup>> cache;
  std::lock_guard<std::mutex> lock(mutex);
  auto &slot = cache[p.genus()];
  if (slot) return *slot;
  using T = exact::mp_real<160>;
  const double bits = exact::bits_of_digits10(160);
  const GeneratorSet<T> &gens = shared_generators<T>(p);
  auto G = std::make_unique<DoubleGroup>();
  const int n = p.letter_count(), h = p.half_relator();
  for (Letter k = 0; k < n; ++k) {
    ProductBound one(p, bits);
    one.step(norm_of(gens.moebius(k)));
    // Rounding to double (0.72 u |m|) and the product m c (2.83 u |m| |c|).
    G->letters.push_back(make_block(rounded_phi(gens.moebius(k)), one.norm(), 8 * kUnit));
    const T angle = exact::pi<T>() * T(k) / T(n);
    G->cos.push_back(to_double(T(cos(angle))));
    G->sin.push_back(to_double(T(sin(angle))));
  }
  for (int kind = 0; kind < 2; ++kind) {
    const int d = kind == 0 ? p.relator_step() : p.inverse_relator_step();
    ProductBound bound(p, bits);
    Moebius<T> run = Moebius<T>::identity();
    G->runs[kind].resize(std::size_t(h) + 1);
    for (int l = 1; l <= h; ++l) {
      run = run * gens.moebius(Letter((int64_t(l - 1) * d) % n));
      bound.step(norm_of(run));
      // Its own error, the rounding to double, the rotations (u each) and two
      // products in double before m c: 16 u with room.
      if (l >= 2)
        G->runs[kind][std::size_t(l)] =
            make_block(rounded_phi(run), bound.norm(), double(bound.relative_error()) + 16 * kUnit);
    }
  }
  slot = std::move(G);
  return *slot;
}

// R_y m R_y^-1 with R_y = [[c, s], [-s, c]].
Real2x2 rotated(const Real2x2 &m, double c, double s) {
  const Real2x2 t{c * m.m00 + s * m.m10, c * m.m01 + s * m.m11, c * m.m10 - s * m.m00, c * m.m11 - s * m.m01};
  return {t.m00 * c + t.m01 * s, t.m01 * c - t.m00 * s, t.m10 * c + t.m11 * s, t.m11 * c - t.m10 * s};
}

// Three test vectors carried through the pass, each with its cone.
class TestVectors {
 public:
  TestVectors() {
    for (int t = 0; t < kTests; ++t) nc_[t] = std::sqrt(c0_[t] * c0_[t] + c1_[t] * c1_[t]);
  }

  void apply(const Block &B) {
    const Real2x2 &M = B.m;
    for (int t = 0; t < kTests; ++t) {
      const double r0 = M.m00 * c0_[t] + M.m01 * c1_[t], r1 = M.m10 * c0_[t] + M.m11 * c1_[t];
      // Two-term sums of squares and a square root: norms within 3 u.
      const double nr = std::sqrt(r0 * r0 + r1 * r1);
      // The factors 1 - 32u and 1 - 4u absorb the roundings of these lines
      // (the norm's own margin that of norm * theta).
      const double q = std::max(nr / nc_[t] * (1.0 - 32.0 * kUnit) - B.eta, B.least);           // <= |M c^|
      const double growth = std::max((q - B.norm * theta_[t]) * (1.0 - 4.0 * kUnit), B.least);  // <= |M x^|
      // The rounding turns M c by at most pi/2 eta / q; room for underflow
      // in a vector kept at |c| >= 2^-200. Any two vectors are within pi of
      // each other: 3.5 says "no cone".
      const double drift = 1.6 * B.eta / q + 0x1p-800;
      theta_[t] = std::min((theta_[t] / (growth * growth) + drift) * (1.0 + 8.0 * kUnit), 3.5);
      // Rounded down: two roundings of at most u each.
      mantissa_[t] = mantissa_[t] * growth * (1.0 - 4.0 * kUnit);
      c0_[t] = r0, c1_[t] = r1, nc_[t] = nr;
      // Powers of two rescale exactly.
      if (nr > 0x1p200 || nr < 0x1p-200) {
        int e;
        std::frexp(nr, &e);
        c0_[t] = std::ldexp(r0, -e), c1_[t] = std::ldexp(r1, -e), nc_[t] = std::ldexp(nr, -e);
      }
      if (mantissa_[t] > 0x1p500 || mantissa_[t] < 0x1p-500) {
        int e;
        mantissa_[t] = std::frexp(mantissa_[t], &e);
        exponent_[t] += e;
      }
    }
  }

  double log2_bound() const {
    double best = 0;  // |P| >= 1 in SL(2,R)
    for (int t = 0; t < kTests; ++t) best = std::max(best, double(exponent_[t]) + std::log2(mantissa_[t]) - 1e-9);
    return best;
  }

 private:
  static constexpr int kTests = 3;
  // 0, 60 and 120 degrees.
  double c0_[kTests] = {1.0, 1.0, -1.0}, c1_[kTests] = {0.0, std::sqrt(3.0), std::sqrt(3.0)};
  double nc_[kTests], theta_[kTests] = {0, 0, 0}, mantissa_[kTests] = {1, 1, 1};
  long exponent_[kTests] = {0, 0, 0};
};

}  // namespace

// How the bound is certified. P = M_1 ... M_m in SL(2,R) (phi above; the M_i
// letters or runs) acts on a test vector v from the right: x_i = M_i x_(i+1),
// x_(m+1) = v. The pass keeps a double vector c and an angle theta with
// angle(x_i, c) <= theta, and multiplies lower bounds of |M_i x| / |x| over
// that cone: |M x^| >= |M c^| - |M| theta (unit vectors), |M c| is the
// computed product's norm less its rounding (eta |c|), and the cone's image
// has angle at most theta / min |M x^|^2 (the derivative of the action of
// SL(2,R) on directions) plus the rounding's angle. The floor 1/|M| is always
// valid. So the product bounds |P v| / |v| <= |P| with no error left out.
// While P grows, |M x^| > 1 and the cone stays about as narrow as the
// rounding, so the bound stays within m 2^-40 of log2 |P v| / |v|; of three
// test vectors 60 degrees apart one has |P v| >= cos(30 deg) |P| |v|. A test
// vector that some suffix of the word maps nearly to its contracting
// direction only gets a weaker bound.
double norm_log2_lower_bound(const Presentation &p, const Letter *w, std::size_t length) {
  if (length == 0) return 0;
  const DoubleGroup &G = double_group(p);
  const int n = p.letter_count(), h = p.half_relator();
  const auto step = [n](Letter a, Letter b) { return b >= a ? b - a : b - a + n; };
  TestVectors tests;
  for (std::size_t i = length; i > 0;) {
    // The factor ending at letter i - 1: the relator run there (at most 2g
    // letters), or the letter alone.
    std::size_t l = 1;
    int kind = -1;
    if (i >= 2) {
      const int s = step(w[i - 2], w[i - 1]);
      kind = s == h + 1 ? 0 : s == h - 1 ? 1 : -1;
      if (kind >= 0)
        for (l = 2; l < std::size_t(h) && l < i && step(w[i - l - 1], w[i - l]) == s;) ++l;
    }
    const std::size_t y = std::size_t(w[i - l]);
    i -= l;
    if (kind < 0) {
      tests.apply(G.letters[y]);
    } else {
      Block B = G.runs[kind][l];
      B.m = rotated(B.m, G.cos[y], G.sin[y]);
      tests.apply(B);
    }
  }
  return tests.log2_bound();
}

Moebius<double> element_moebius(const Presentation &p, const Letter *w, std::size_t length) {
  const Word r = dehn_reduce(p, w, length);
  if (r.empty()) return Moebius<double>::identity();
  // |a| >= (|a| + |b|) / 2, and Re a or Im a is at least |a| / sqrt 2: above
  // 2^1024, which rounds to infinity, once the bound exceeds 1025.5.
  const double log2_norm = norm_log2_lower_bound(p, r.data(), r.size());
  if (log2_norm > 1025.5) throw std::domain_error(kOverflow);
  const Moebius<double> m = with_certified_product(p, r, kElementTarget, log2_norm, [](const auto &f) {
    return Moebius<double>{{to_double(f.a.re), to_double(f.a.im)}, {to_double(f.b.re), to_double(f.b.im)}};
  });
  if (!(std::isfinite(m.a.re) && std::isfinite(m.a.im) && std::isfinite(m.b.re) && std::isfinite(m.b.im)))
    throw std::domain_error(kOverflow);
  return m;
}

Lorentz<double> element_lorentz(const Presentation &p, const Letter *w, std::size_t length) {
  const Word r = dehn_reduce(p, w, length);
  if (r.empty()) return Lorentz<double>::identity();
  // L_00 = |a|^2 + |b|^2 >= (|a| + |b|)^2 / 2: above 2^1024 once the bound
  // exceeds 512.5.
  const double log2_norm = norm_log2_lower_bound(p, r.data(), r.size());
  if (log2_norm > 512.5) throw std::domain_error(kOverflow);
  const Lorentz<double> L = with_certified_product(p, r, kElementTarget, log2_norm, [](const auto &f) {
    using T = std::decay_t<decltype(f.a.re)>;
    const Lorentz<T> exact = Lorentz<T>::from_moebius(f);
    Lorentz<double> rounded;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) rounded.m[i][j] = to_double(exact.m[i][j]);
    return rounded;
  });
  for (const auto &row : L.m)
    for (const double entry : row)
      if (!std::isfinite(entry)) throw std::domain_error(kOverflow);
  return L;
}

Complex<double> element_image(const Presentation &p, const Letter *w, std::size_t length, Complex<double> z) {
  const Word r = dehn_reduce(p, w, length);
  if (r.empty()) return z;
  // 1 - |h(z)| <= 2 e^-d(O, h(z)), d(O, h(z)) >= d(O, h(O)) - d(O, z),
  // d(O, h(O)) = 2 arccosh |a| >= 2 ln |a| >= 2 ln 2^(G - 1) and
  // d(O, z) <= ln(4 / (1 - |z|^2)): 1 - |h(z)| <= 2^(5 - 2G) / (1 - |z|^2).
  const double log2_norm = norm_log2_lower_bound(p, r.data(), r.size());
  const double log2_gap = log2_disk_gap(z.re, z.im);
  if (5.0 - 2.0 * log2_norm - log2_gap < -kImageMargin)
    throw std::domain_error("the image lies within 2^-" + std::to_string(kImageMargin) + " of the unit circle");
  // h(z) = (a z + b) / (conj b z + conj a) and |conj b z + conj a| >=
  // |a| (1 - |z|) >= (|a| + |b|) (1 - |z|^2) / 4: an error of 2^-t (|a| + |b|)
  // in a, b and in the arithmetic moves h(z) by at most about 2^(5 - t) / (1 - |z|^2).
  const double target = kElementTarget + 8.0 - log2_gap;
  const Complex<double> image = with_certified_product(p, r, target, log2_norm, [&](const auto &f) {
    using T = std::decay_t<decltype(f.a.re)>;
    const Complex<T> h = f.apply(Complex<T>{T(z.re), T(z.im)});
    return Complex<double>{to_double(h.re), to_double(h.im)};
  });
  if (!exact::inside_unit_disk(image.re, image.im)) throw std::domain_error("the image rounds to the unit circle");
  return image;
}


// ---- Matrices of translations, for the translation table and the refined stages ----

namespace {

// The rungs of these products: the ladder's and one between its first two
// (a word of N needs a few dozen bits above its target, see below, and the
// ladder's second rung has 531).
using WordLadder = exact::Ladder<40, 80, 160, 640, 2560>;


// A product of a word starting with letter 0 and ProductBound's bound on its
// relative error (infinite when unknown).
template <class T>
struct BoundedProduct {
  Moebius<T> m;
  long double relative_error;
};

template <class T>
BoundedProduct<T> bounded_product(const GeneratorSet<T> &gens, const Word &u, double bits) {
  ProductBound bound(gens.presentation(), bits);
  Moebius<T> P = Moebius<T>::identity();
  for (const Letter k : u) {
    P = P * gens.moebius(k);
    bound.step(norm_of(P));
  }
  return {P, bound.relative_error()};
}

// The step of a word with constant steps between its letters (at least
// two), else 0.
int constant_step(const Presentation &p, const Word &u) {
  const int n = p.letter_count();
  if (u.size() < 2) return 0;
  const int step = (u[1] - u[0] + n) % n;
  for (std::size_t i = 2; i < u.size(); ++i)
    if ((u[i] - u[i - 1] + n) % n != step) return 0;
  return step;
}

// Products of the runs 0, d, 2d, ... (every element of N is a rotated
// run: neighbours.hpp) by length, each with its bound, extended on demand:
// one pass of 2g letters per step serves all the runs of that step, where a
// product per run cost 2g^2 letters per step, which dominated a first
// hdt_create at large genus. Per genus, rung and step, for the life of the
// process like the generator sets.
template <class T>
struct RunPrefixes {
  explicit RunPrefixes(const Presentation &p, double bits) : bound(p, bits) {}
  std::vector<BoundedProduct<T>> by_length{{Moebius<T>::identity(), 0}};
  ProductBound bound;
};

template <class T>
BoundedProduct<T> run_product(const GeneratorSet<T> &gens, int step, std::size_t length, double bits) {
  static std::mutex mutex;
  static std::map<std::pair<int, int>, std::unique_ptr<RunPrefixes<T>>> cache;
  const Presentation &p = gens.presentation();
  std::lock_guard<std::mutex> lock(mutex);
  auto &slot = cache[{p.genus(), step}];
  if (!slot) slot = std::make_unique<RunPrefixes<T>>(p, bits);
  RunPrefixes<T> &r = *slot;
  while (r.by_length.size() <= length) {
    const std::size_t l = r.by_length.size();  // by_length[l]: the letters 0, step, ..., (l - 1) step
    const Letter k = Letter((int64_t(l - 1) * step) % p.letter_count());
    const Moebius<T> P = r.by_length.back().m * gens.moebius(k);
    r.bound.step(norm_of(P));
    r.by_length.push_back({P, r.bound.relative_error()});
  }
  return r.by_length[length];
}

// Runs longer than this go through the per-word cache (N's runs have at
// most 2g letters; longer ones are rare and need not stay).
std::size_t run_prefix_max(const Presentation &p) { return std::size_t(p.half_relator()); }

// The word's Moebius product with a and b within 2^-target (|a| + |b|),
// handed to f in the number type of the lowest rung whose bound certifies
// it. The bound is ProductBound's, computed along the product: for the words
// met here (canonical words, whose partial products stay below the final
// norm or, for the relator runs of N, below cosh R = A^2) it costs about
// 2 log2 max |P_j| bits, a few dozen, where the a priori bound of
// moebius_precision_bits costs m log2(2A) (2,138 bits for a run of 2g
// letters at genus 128, which put those words on the 8,503-bit rung).
// The product is that of the word shifted to start with letter 0, cached
// per genus and rung (rotated_products.hpp), turned by the rotation
// e^{i k pi/2g}: its real and imaginary parts are B_k / B_0, the error of |B|
// cancels and each part is within 23 eps of the exact one (cos within 20
// eps, three roundings), so |r~ - r| < 33 eps, and b r~ adds its rounding
// (3 eps): the turn adds at most 64 eps (|a| + |b|) to the error, counted
// below with room.
template <class F>
auto with_bounded_product(const Presentation &p, const Word &w, double target, F &&f) {
  using Result = decltype(f(Moebius<exact::mp_real<WordLadder::kDigits10[0]>>{}, 0.0));
  const long double wanted = std::ldexp(1.0L, -int(std::ceil(target)));
  // Fewer than 16 bits above the target cannot pay for the bookkeeping.
  const std::optional<Result> result =
      WordLadder::climb(WordLadder::rung_for(target + 16), [&](auto zero) -> std::optional<Result> {
        using T = decltype(zero);
        const double bits = double(exact::RungOf<T>::bits);
        const GeneratorSet<T> &gens = shared_generators<T>(p);
        int k;
        const Word u = rotation_detail::normalised(p, w.data(), w.size(), &k);
        const int step = constant_step(p, u);
        const BoundedProduct<T> c = step != 0 && u.size() <= run_prefix_max(p)
                                        ? run_product(gens, step, u.size(), bits)
                                        : rotation_detail::cached<BoundedProduct<T>>(
                                              p.genus(), u, [&] { return bounded_product(gens, u, bits); });
        const long double eps = std::ldexp(1.0L, -int(bits));
        const long double error = c.relative_error + 128 * eps * (1 + c.relative_error);
        if (!(error <= wanted)) return std::nullopt;
        Moebius<T> m = c.m;
        if (k != 0) m.b = m.b * gens.rotation(k);
        return f(m, double(error) * (1 + 0x1p-50));
      });
  if (result) return *result;
  throw exact::Unsupported(too_long(w.size()));
}

}  // namespace

// a, b within 2^-72 (|a| + |b|): each Lorentz entry, quadratic in them,
// within 2^-66 L_00 (as kElementTarget), its own rounding included.
void accurate_matrices(const Presentation &p, const Word &w, Moebius<double> *moebius, Lorentz<double> *lorentz,
                       Moebius<double> *moebius_low, double *moebius_error) {
  with_bounded_product(p, w, 72, [&](const auto &m, double error) {
    using T = std::decay_t<decltype(m.a.re)>;
    // hi = RN(x) is a multiple of the last place of hi's binade, hence of
    // x's: x - hi is exact in T, and lo = RN(x - hi) within u^2 |x|.
    auto split = [](const T &x, double *lo) {
      const double hi = to_double(x);
      *lo = to_double(T(x - hi));
      return hi;
    };
    *moebius = Moebius<double>{{split(m.a.re, &moebius_low->a.re), split(m.a.im, &moebius_low->a.im)},
                               {split(m.b.re, &moebius_low->b.re), split(m.b.im, &moebius_low->b.im)}};
    *moebius_error = error;
    if (!lorentz) return 0;
    const Lorentz<T> L = Lorentz<T>::from_moebius(m);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) lorentz->m[i][j] = to_double(L.m[i][j]);
    return 0;
  });
}

template <class T>
Lorentz<T> accurate_lorentz_as(const Presentation &p, const Word &w) {
  // Entries within 2^-(d + 4) L_00 before the rounding to T's d bits: a, b
  // within 2^-(d + 10) (|a| + |b|), as in accurate_matrices.
  const double target = double(std::numeric_limits<T>::digits) + 10;
  return with_bounded_product(p, w, target, [&](const auto &m, double) {
    using U = std::decay_t<decltype(m.a.re)>;
    const Lorentz<U> L = Lorentz<U>::from_moebius(m);
    Lorentz<T> r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r.m[i][j] = static_cast<T>(L.m[i][j]);
    return r;
  });
}

template Lorentz<exact::mp_real<40>> accurate_lorentz_as(const Presentation &, const Word &);

}  // namespace hdt::group
