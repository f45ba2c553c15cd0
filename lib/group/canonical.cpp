#include "group/canonical.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <utility>
#include <vector>

#include "exact/precision_ladder.hpp"
#include "exact/unsupported.hpp"
#include "group/dehn.hpp"
#include "group/generators.hpp"
#include "group/word_matrix.hpp"

// How the letters are found. P = h(O) is computed once from the Dehn-reduced
// word; each letter k found moves it by g_k^{-1} (P <- L_{k+2g} P), so a word
// of m letters costs about 2m matrix-vector products instead of m^2 / 2.
// Every separation test is first tried in double precision with an error
// bound; only the few that bound leaves open (P close to a side line, seen
// from far away) are evaluated in multiprecision. Once P is close to O the
// remaining letters are usually found in double precision altogether.
//
// Precision of the incremental peeling: P is known up to a relative error u
// in each coordinate, which places a point at distance d from O only within
// about u e^{2d} of its true position along the ray from O (its coordinates
// are of size e^d and nearly cancel in t^2 - u^2 - v^2). Peeling back to O
// uncovers that error, so it costs as many bits as computing P did: peeling
// j letters off a product of m letters is certified at the precision of a
// product of m + j letters (the bound of word_precision_bits, see
// segment_capacity). Long words either take a higher rung or peel in
// segments, each starting again from a Dehn-reduced word of the rest.

namespace hdt::group {

namespace {

// ---------------------------------------------------------------------------
// Precision

// The bits needed to decide every separation test on a word of m letters
// are word_certified_bits(m): the amplified rounding error
// (word_precision_bits) must stay far below the margin 2(A^2 - 1) >= 2.

// The rungs for peeling: one between each two of the accurate products'
// rungs (word_matrix.cpp). The bits a word needs grow steadily with its
// length, and the cost of a multiplication about quadratically with the
// bits, so a fine ladder wastes less. Past its top (canonical_ladder_length)
// come its run-time rungs.
using PeelLadder = exact::Ladder<40, 80, 160, 320, 640, 1280, 2560>;
constexpr std::size_t kRungs = PeelLadder::kSize;

// Relative cost of a matrix-vector product on each rung (MPFR on x86-64,
// measured once): the plan of rungs below needs only their ratios.
constexpr double kRungCost[kRungs] = {1, 1.4, 1.9, 3, 7.3, 22, 58};

// The longest product, in letters, that `bits` of precision certify: n
// with word_certified_bits(n) <= bits. Peeling j letters off a word of m letters
// needs m + j <= n. Why: each peeling step multiplies the error carried so
// far by at most |g^{-1}| <= 6A^2 (the bound word_precision_bits uses for a
// product factor) and adds its own rounding, no larger than a product
// factor's since |P| only decreases as letters come off (P moves towards O).
// After j steps the error is that of a product of m + j letters: at most
// 2^-64 in each coordinate on the rung, far below the margin.
std::size_t capacity_at_bits(const Presentation &p, double bits) {
  const double per_letter = word_precision_bits(p, 1) - 2.0 * std::log2(3.0);
  // word_certified_bits(n) = 64 + per_letter n + 2 log2(n + 2): start above
  // the answer (the logarithm left out) and step down.
  double n = std::floor((bits - 64.0) / per_letter);
  while (n > 0 && word_certified_bits(p, std::size_t(n)) > bits) n -= 1;
  return n > 0 ? std::size_t(n) : 0;
}

std::size_t segment_capacity(const Presentation &p, std::size_t rung) {
  return capacity_at_bits(p, double(PeelLadder::bits(rung)));
}

struct Segment {
  std::size_t rung = 0;
  std::size_t steps = 0;  // letters the segment may peel; 0: no rung can
};

// The rung for peeling a word of m letters, chosen for the cheapest whole
// schedule: a segment on rung r that peels j letters off n costs (n + j)
// products at kRungCost[r] and leaves a word of about n - j letters for the
// next one. A low rung that peels in a few segments often beats the next rung
// up, whose multiplications cost several times more.
Segment plan_segment(const Presentation &p, std::size_t m) {
  std::size_t capacity[kRungs];
  for (std::size_t r = 0; r < kRungs; ++r) capacity[r] = segment_capacity(p, r);
  std::vector<double> cost(m + 1, std::numeric_limits<double>::infinity());
  std::vector<Segment> first(m + 1);
  cost[0] = 0;
  for (std::size_t n = 1; n <= m; ++n)
    for (std::size_t r = 0; r < kRungs; ++r) {
      if (capacity[r] <= n) continue;
      const std::size_t j = std::min(n, capacity[r] - n);
      const double c = double(n + j) * kRungCost[r] + cost[n - j];
      if (c < cost[n]) cost[n] = c, first[n] = Segment{r, capacity[r] - n};
    }
  return first[m];
}

// ---------------------------------------------------------------------------
// Double precision with an error bound

// The generators' Lorentz matrices rounded from multiprecision (within one
// ulp per entry), once per genus.
const std::vector<Lorentz<double>> &rounded_generators(const Presentation &p) {
  static std::mutex mutex;
  static std::map<int, std::unique_ptr<std::vector<Lorentz<double>>>> cache;
  std::lock_guard<std::mutex> lock(mutex);
  auto &slot = cache[p.genus()];
  if (!slot) {
    auto v = std::make_unique<std::vector<Lorentz<double>>>();
    for (Letter k = 0; k < p.letter_count(); ++k) v->push_back(accurate_lorentz(p, Word{k}));
    slot = std::move(v);
  }
  return *slot;
}

struct DoubleGenerators {
  const std::vector<Lorentz<double>> &lorentz;
  double margin;  // A^2 - 1, half the proven gap, rounded down
  // tanh(l/2) for the generators' translation length l, rounded down: a
  // point P with |(u, v)| < inradius_slope t is nearer O than every side line.
  double inradius_slope;
};

DoubleGenerators double_generators(const Presentation &p) {
  const std::vector<Lorentz<double>> &L = rounded_generators(p);
  // L[0][0][0] = cosh of the translation length = 2A^2 - 1 with A = cot(pi/4g).
  // tanh(l/2) = sqrt((C - 1) / (C + 1)) for C = cosh l, within one ulp in
  // L: a few roundings, far below the slack.
  const double C = L[0].m[0][0];
  return {L, ((C + 1) / 2 - 1) * (1 - 0x1p-40), std::sqrt((C - 1) / (C + 1)) * (1 - 0x1p-40)};
}

constexpr double kUnit = 0x1p-53;  // unit roundoff of double
constexpr double kTiny = 0x1p-1020;  // covers underflow of scaled coordinates

// A hyperboloid point 2^scale (P +- E): E bounds the absolute error of each
// coordinate of P.
struct DoublePoint {
  double P[3] = {1, 0, 0};
  double E[3] = {0, 0, 0};
  int scale = 0;
};

// L x with its error bound (x unscaled).
DoublePoint apply(const Lorentz<double> &L, const DoublePoint &x) {
  const auto &m = L.m;
  DoublePoint y;
  for (int r = 0; r < 3; ++r) {
    y.P[r] = m[r][0] * x.P[0] + m[r][1] * x.P[1] + m[r][2] * x.P[2];
    const double S = std::abs(m[r][0] * x.P[0]) + std::abs(m[r][1] * x.P[1]) + std::abs(m[r][2] * x.P[2]);
    const double carried = std::abs(m[r][0]) * x.E[0] + std::abs(m[r][1]) * x.E[1] + std::abs(m[r][2]) * x.E[2];
    // One ulp in each entry of m, three roundings in the sum, slack.
    y.E[r] = (carried + 6 * kUnit * S) * (1 + 8 * kUnit);
  }
  return y;
}

// h(O) for the element h of the word, in double precision.
DoublePoint double_image(const DoubleGenerators &d, const Word &w) {
  DoublePoint x;
  for (std::size_t i = w.size(); i-- > 0;) x = apply(d.lorentz[w[i]], x);
  return x;
}

// The sign of the separation test <P, O - g_k(O)> when the error bound
// certifies it with at least the margin, 0 otherwise (also for overflow).
int certified_side(const DoubleGenerators &d, Letter k, const DoublePoint &x) {
  const auto &m = d.lorentz[k].m;  // g_k(O) is the first column
  const double n[3] = {1 - m[0][0], m[1][0], m[2][0]};
  const double side = x.P[0] * n[0] + x.P[1] * n[1] + x.P[2] * n[2];
  const double size = std::abs(x.P[0] * n[0]) + std::abs(x.P[1] * n[1]) + std::abs(x.P[2] * n[2]);
  // x's error, one ulp in each entry of n and the rounding of 1 - m00, the
  // products and the sums.
  const double error =
      (x.E[0] * std::abs(n[0]) + x.E[1] * std::abs(n[1]) + x.E[2] * std::abs(n[2]) + 8 * kUnit * size + kTiny) * 1.01;
  if (std::abs(side) - error >= std::ldexp(d.margin, -x.scale)) return side > 0 ? 1 : -1;
  return 0;
}

constexpr Letter kNoLetter = -1;   // no side line separates: the point is O
constexpr Letter kUndecided = -2;  // a test was left open

// The least letter k whose side line separates O from the point x. A test
// the double bound leaves open goes to decide(k), which returns its sign or
// 0 to leave it open.
//
// Why not a scan of all 4g sides (a third of the canonical words' cost at
// genus 120): with C = cosh and S = sinh of a generator's translation length
// and P = (t, r cos phi, r sin phi), side k's test is
// S r cos(k pi/2g - phi) - t (C - 1), positive on an arc of directions
// around phi narrower than pi. So the separating letters are a cyclic run,
// and unless it holds 0 (tested first) its least letter is where the run
// begins: found by bisection below a letter of the run, the side facing P.
// Each test is still certified; the direction, when P's error bound
// certifies it, only chooses which letters are tested. When it does not, or
// a test is left open, the scan decides as before.
template <class Decide>
Letter least_separating_letter(const DoubleGenerators &d, const DoublePoint &x, Decide &&decide) {
  const Letter count = Letter(d.lorentz.size());
  auto test = [&](Letter k) {
    const int sign = certified_side(d, k, x);
    return sign != 0 ? sign : decide(k);
  };
  const int first = test(0);
  if (first == 0) return kUndecided;
  if (first > 0) return 0;
  // The run is centred on phi: if it holds a letter, it holds the one nearest
  // phi. P's error bound gives phi to within 2 (E_u + E_v) / r; when that is
  // below a quarter of the letters' spacing, the nearest letter is `facing`
  // or one of its neighbours, and if none of them separates, none does.
  const double r = std::hypot(x.P[1], x.P[2]), spread = x.E[1] + x.E[2];
  // Near O (the last step of every word) the direction is noise, but P is
  // inside the inscribed circle of F_g.
  if (std::hypot(std::abs(x.P[1]) + x.E[1], std::abs(x.P[2]) + x.E[2]) * (1 + 0x1p-40) <
      d.inradius_slope * (x.P[0] - x.E[0]))
    return kNoLetter;
  const bool direction_known = 8 * spread * count < r;
  if (direction_known) {
    const double turns = std::atan2(x.P[2], x.P[1]) / (2 * M_PI);  // in [-1/2, 1/2]
    const Letter facing = Letter(std::lround(turns * count + count)) % count;
    Letter inside = kNoLetter;
    bool open = false;
    for (Letter k : {facing, Letter((facing + 1) % count), Letter((facing + count - 1) % count)}) {
      const int sign = k == 0 ? first : test(k);
      open = sign == 0;
      if (sign != -1) {
        inside = sign > 0 ? k : kNoLetter;
        break;
      }
    }
    if (!open && inside == kNoLetter) return kNoLetter;
    // The run holds `inside` but not 0, and at most count/2 letters, so it
    // begins in (outside, inside] for the outside below: bisect, keeping
    // `outside` out of the run and `inside` in it.
    Letter outside = std::max<Letter>(0, inside - count / 2);
    while (!open && inside - outside > 1) {
      const Letter k = outside + (inside - outside) / 2;
      const int sign = test(k);
      open = sign == 0;
      (sign > 0 ? inside : outside) = k;
    }
    if (!open) return inside;
  }
  for (Letter k = 1; k < count; ++k) {
    const int sign = test(k);
    if (sign == 0) return kUndecided;
    if (sign > 0) return k;
  }
  return kNoLetter;
}

// Each letter lowers the geodesic length of the rest by one.
void append_letter(Word &out, Letter k, std::size_t bound) {
  if (out.size() >= bound) throw std::logic_error("canonical_word: peeling did not shorten the word");
  out.push_back(k);
}

// Peels letters off the point x in double precision while its error bound
// certifies every test, appending them to out. True when x reached O; false
// when a test stayed open (the letters found so far are kept).
bool peel_in_double(const Presentation &p, const DoubleGenerators &d, DoublePoint x, Word &out, std::size_t bound) {
  for (;;) {
    const Letter k = least_separating_letter(d, x, [](Letter) { return 0; });
    if (k == kNoLetter) return true;
    if (k == kUndecided) return false;
    append_letter(out, k, bound);
    x = apply(d.lorentz[p.inverse(k)], x);
  }
}

// ---------------------------------------------------------------------------
// Multiprecision

// P scaled by the binary exponent of P.t (its largest coordinate) and
// rounded to double, so that far points neither overflow nor lose the
// filter. The error bound also holds `error`, a bound on each coordinate's
// distance to the true point (by default 2^-64, the invariant of a segment,
// see segment_capacity).
DoublePoint rounded_point(mpfr_srcptr t, mpfr_srcptr u, mpfr_srcptr v, double error = 0x1p-64) {
  DoublePoint x;
  x.scale = int(mpfr_get_exp(t));
  const mpfr_srcptr coordinates[3] = {t, u, v};
  const double carried = std::ldexp(error, -x.scale);
  for (int i = 0; i < 3; ++i) {
    long exponent = 0;
    const double mantissa = mpfr_get_d_2exp(&exponent, coordinates[i], MPFR_RNDN);
    x.P[i] = std::ldexp(mantissa, int(exponent - x.scale));
    x.E[i] = kUnit * std::abs(x.P[i]) + carried + kTiny;
  }
  return x;
}

template <class T>
DoublePoint rounded_point(const HyperboloidPoint<T> &P, double error = 0x1p-64) {
  return rounded_point(P.t.backend().data(), P.u.backend().data(), P.v.backend().data(), error);
}

// The same point without the scale, for peeling on in double precision.
DoublePoint unscaled(const DoublePoint &x) {
  DoublePoint y;
  for (int i = 0; i < 3; ++i) y.P[i] = std::ldexp(x.P[i], x.scale), y.E[i] = std::ldexp(x.E[i], x.scale);
  return y;
}

// Below cosh d(O, P) = 2^24 double precision may finish the job: P's
// rounding grows about like |P|^2 u on the way back to O.
constexpr int kDoubleScale = 24;

// The separation test for side k in multiprecision, checked against the
// margin that the precision guarantees.
template <class T>
int side_sign(const GeneratorSet<T> &gens, const HyperboloidPoint<T> &P, Letter k, const T &margin, const Word &w) {
  const auto &m = gens.lorentz(k).m;  // g_k(O) is the first column
  const T side = P.t * (T(1) - m[0][0]) + P.u * m[1][0] + P.v * m[2][0];
  using std::abs;
  if (abs(side) < margin)
    throw std::logic_error("canonical_word: separation test below its certified margin for " + word_to_string(w));
  return side > 0 ? 1 : -1;
}

// One segment at the precision of T: computes P = h(O) for the element h of
// the Dehn-reduced word w and peels letters off it, appending them to out.
// True when P reached O; false once `budget` letters are peeled and the
// precision is spent.
template <class T>
bool peel_segment(const Presentation &p, const DoubleGenerators &d, const Word &w, std::size_t budget, Word &out,
                  std::size_t bound) {
  const GeneratorSet<T> &gens = shared_generators<T>(p);
  const T A = gens.moebius(0).a.re;
  const T margin = A * A - T(1);  // half the proven bound 2(A^2 - 1)
  HyperboloidPoint<T> P = gens.apply(w, HyperboloidPoint<T>{});
  for (std::size_t j = 0;; ++j) {
    const DoublePoint x = rounded_point(P);
    if (x.scale <= kDoubleScale) {
      // Try to finish in double precision; if it cannot, forget its letters
      // (P stays where it is) and take one more step here.
      const std::size_t before = out.size();
      if (peel_in_double(p, d, unscaled(x), out, bound)) return true;
      out.resize(before);
    }
    if (j == budget) return false;
    const Letter k = least_separating_letter(d, x, [&](Letter k) { return side_sign(gens, P, k, margin, w); });
    if (k == kNoLetter) return true;  // unreachable in practice: the double path finishes at O
    append_letter(out, k, bound);
    P = gens.lorentz(p.inverse(k)).apply(P);
  }
}

// ---------------------------------------------------------------------------
// Multiprecision with an error bound from the points' distances
//
// peel_segment's precision is chosen before the first product, from the
// word's length alone: each letter may multiply the error by the norm of a
// generator. For the words a triangulation meets that is far too much: the
// tiles around a corner of F_g have words of up to 2g letters whose points
// all stay near O, and at genus 120 they took the 2560-digit rung. Here the
// bound follows the points instead. A Lorentz matrix R has operator norm
// e^{d(O, R O)}, and if R maps the true point P_a to P_i, then
// d(O, R O) <= d(O, P_i) + d(O, P_a), so ||R|| <= 2 t_i 2 t_a (e^d <= 2 cosh d).
// An error e_j made at step j reaches step i through such an R, so the
// error of step i is at most 2 t_i K_i with K_i = sum_{j<i} 2 t_{j+1} |e_j|:
// it grows with the points' sizes, not with the number of letters. True t's
// are bounded from computed ones (see step()).

// A point P = (word)(O) in the multiprecision type T with a bound `error`
// on the Euclidean norm of its distance to the true point.
template <class T>
class TrackedPoint {
 public:
  // size: an upper bound on every generator's entries (C = cosh l, up).
  explicit TrackedPoint(double size) : size_(size) {}
  // From P0 with a bound e0 on its error: e0 reaches step i through a
  // matrix of norm at most 2 t_i 2 t_0, as an error made at a step does.
  TrackedPoint(double size, const HyperboloidPoint<T> &P0, double e0) : P_(P0), size_(size) {
    tau_ = (std::abs(to_double(P0.t)) + e0) * (1 + 0x1p-40);
    K_ = 2 * tau_ * e0 * (1 + 0x1p-40);
    error_ = e0;
  }

  // P <- L P for the multiprecision matrix L of a generator. False when the
  // bound no longer certifies anything (the caller falls back).
  bool step(const Lorentz<T> &L) {
    const double norm = euclidean_norm();
    P_ = L.apply(P_);
    // The new error: L's entries within 2^10 units of T of the true ones
    // (a generous bound on the few roundings of GeneratorSet), and the
    // product's three roundings per row: in 2-norm at most 3 (2^10 + 3) u C |P|.
    const double made = 3 * (0x1p10 + 3) * unit_ * size_ * norm * (1 + 0x1p-40);
    // t_new <= 2 C t_old a priori (one letter moves P by the translation
    // length); then twice: error <= 2 tau (K + 2 tau made), tau = t~ + error.
    const double t = std::abs(to_double(P_.t)) * (1 + 0x1p-40);
    double tau = 2 * size_ * tau_;
    for (int pass = 0; pass < 2; ++pass) error_ = 2 * tau * (K_ + 2 * tau * made) * (1 + 0x1p-40), tau = t + error_;
    tau_ = tau;
    K_ = (K_ + 2 * tau_ * made) * (1 + 0x1p-40);
    return std::isfinite(tau_) && error_ < 0x1p-20 * t;
  }

  // P rounded to a DoublePoint whose bound also holds the tracked error.
  DoublePoint rounded() const { return rounded_point(P_, error_ * (1 + 0x1p-40)); }
  const HyperboloidPoint<T> &point() const { return P_; }
  double error() const { return error_; }

 private:
  static double to_double(const T &x) { return x.template convert_to<double>(); }
  double euclidean_norm() const {
    const double t = to_double(P_.t), u = to_double(P_.u), v = to_double(P_.v);
    return std::sqrt(t * t + u * u + v * v) * (1 + 0x1p-40);
  }

  HyperboloidPoint<T> P_{};
  double size_;
  const double unit_ = std::ldexp(1.0, -int(mpfr_get_prec(T(0).backend().data())));
  double tau_ = 1;    // upper bound on the true point's t
  double K_ = 0;      // the sum K_i above
  double error_ = 0;  // bound on |P~ - P| in 2-norm
};

// The whole word at the precision of T with the tracked bound: computes
// h(O) and peels every letter off it, appending them to out. False, with out
// as it was, when a test or the bound is left open (the caller then takes
// the precision schedule of peel_segment).
template <class T>
bool peel_tracked(const Presentation &p, const DoubleGenerators &d, const Word &w, Word &out, std::size_t bound) {
  const GeneratorSet<T> &gens = shared_generators<T>(p);
  const std::size_t start = out.size();
  auto fail = [&] {
    out.resize(start);
    return false;
  };
  TrackedPoint<T> P(d.lorentz[0].m[0][0] * (1 + 0x1p-40));
  for (std::size_t i = w.size(); i-- > 0;)
    if (!P.step(gens.lorentz(w[i]))) return fail();
  for (;;) {
    const DoublePoint x = P.rounded();
    if (x.scale <= kDoubleScale) {
      const std::size_t before = out.size();
      if (peel_in_double(p, d, unscaled(x), out, bound)) return true;
      out.resize(before);
    }
    const Letter k = least_separating_letter(d, x, [](Letter) { return 0; });
    if (k == kUndecided) return fail();
    if (k == kNoLetter) return true;
    if (out.size() >= bound) return fail();
    out.push_back(k);
    if (!P.step(gens.lorentz(p.inverse(k)))) return fail();
  }
}

// ---------------------------------------------------------------------------
// Beyond the ladder: MPFR at a precision chosen at run time
//
// A Dehn-reduced word longer than the top rung's capacity (412 letters at
// genus 256: the words of points within 10^-15 of the circle reach 490) is
// peeled in one segment on the least of PeelLadder's run-time rungs that
// the same bound as the rungs certifies, word_certified_bits(2m) for a word
// of m letters: every letter off it (the canonical word is no longer than
// m) at the error of a product of 2m letters, 2^-64 in each coordinate. The
// values are raw mpfr_t of that precision (never a default precision); the
// generators are built once per genus and rung.

// n MPFR values of one precision, initialised and cleared together.
class MpValues {
 public:
  MpValues(std::size_t n, mpfr_prec_t prec) : v_(n) {
    for (__mpfr_struct &x : v_) mpfr_init2(&x, prec);
  }
  ~MpValues() {
    for (__mpfr_struct &x : v_) mpfr_clear(&x);
  }
  MpValues(const MpValues &) = delete;
  MpValues &operator=(const MpValues &) = delete;
  mpfr_ptr operator[](std::size_t i) { return &v_[i]; }
  mpfr_srcptr operator[](std::size_t i) const { return &v_[i]; }

 private:
  std::vector<__mpfr_struct> v_;
};

// The generators of one genus at a run-time precision, kept as what their
// Lorentz matrices are made of (GeneratorSet's 4g matrices of 9 entries
// would take 110 MB at genus 1024 and 24,000 bits). With B_k = |B| e^{i th},
// th = k pi/2g, Lorentz::from_moebius gives
//   [[N, X cos th, X sin th], [X cos th, A^2 + Z cos 2th, Z sin 2th],
//    [X sin th, Z sin 2th, A^2 - Z cos 2th]],
// N = 2A^2 - 1, X = 2A|B|, Z = |B|^2 = A^2 - 1: stored are X c_a and Z c_a
// for c_a = cos(a pi/2g), a = 0..g, from which every angle k pi/2g folds
// with a sign, as in GeneratorSet. Each stored value is computed 32 bits
// above the precision (c_a as quarter_turn_cosines does) and rounded once:
// within one ulp, as the rungs' entries are. A product rounds each row
// three times, each rounding at most a unit of the row's absolute sum, as a
// product on a rung does, so word_certified_bits bounds its error the same
// way.
class RuntimeGenerators {
 public:
  RuntimeGenerators(const Presentation &p, mpfr_prec_t prec)
      : g_(p.genus()), prec_(prec), c_(kConstants, prec), X_(std::size_t(g_) + 1, prec), Z_(std::size_t(g_) + 1, prec) {
    const mpfr_prec_t high = prec + 32;
    MpValues w(8, high);
    mpfr_ptr A = w[0], A2 = w[1], Bm = w[2], X = w[3], angle = w[4], cz = w[5], sz = w[6], next = w[7];
    mpfr_const_pi(angle, MPFR_RNDN);
    mpfr_div_ui(angle, angle, 4 * static_cast<unsigned long>(g_), MPFR_RNDN);
    mpfr_cot(A, angle, MPFR_RNDN);
    mpfr_sqr(A2, A, MPFR_RNDN);
    mpfr_sub_ui(Bm, A2, 1, MPFR_RNDN);  // |B|^2 = Z
    mpfr_set(c_[kZ], Bm, MPFR_RNDN);
    mpfr_set(c_[kA2], A2, MPFR_RNDN);
    mpfr_mul_2ui(next, A2, 1, MPFR_RNDN);
    mpfr_sub_ui(next, next, 1, MPFR_RNDN);  // N = 2A^2 - 1
    mpfr_set(c_[kN], next, MPFR_RNDN);
    mpfr_ui_sub(next, 1, next, MPFR_RNDN);  // 1 - N, for the separation tests
    mpfr_set(c_[kOneMinusN], next, MPFR_RNDN);
    mpfr_set(c_[kMargin], Bm, MPFR_RNDD);  // A^2 - 1: half the proven bound 2(A^2 - 1)
    mpfr_sqrt(X, Bm, MPFR_RNDN);
    mpfr_mul(X, X, A, MPFR_RNDN);
    mpfr_mul_2ui(X, X, 1, MPFR_RNDN);  // X = 2A|B|
    // cos(a pi/2g) as powers of e^{i pi/2g} (see quarter_turn_cosines).
    mpfr_const_pi(angle, MPFR_RNDN);
    mpfr_div_ui(angle, angle, 2 * static_cast<unsigned long>(g_), MPFR_RNDN);
    mpfr_sin_cos(sz, cz, angle, MPFR_RNDN);
    MpValues z(2, high);
    mpfr_set_ui(z[0], 1, MPFR_RNDN);
    mpfr_set_ui(z[1], 0, MPFR_RNDN);
    for (int a = 0; a <= g_; ++a) {
      if (a == g_) {
        mpfr_set_zero(X_[std::size_t(a)], 1), mpfr_set_zero(Z_[std::size_t(a)], 1);
        break;
      }
      mpfr_mul(X_[std::size_t(a)], X, z[0], MPFR_RNDN);
      mpfr_mul(Z_[std::size_t(a)], Bm, z[0], MPFR_RNDN);
      mpfr_fmms(next, z[0], cz, z[1], sz, MPFR_RNDN);
      mpfr_fmma(z[1], z[0], sz, z[1], cz, MPFR_RNDN);
      mpfr_swap(z[0], next);
    }
  }

  mpfr_prec_t precision() const { return prec_; }
  mpfr_srcptr margin() const { return c_[kMargin]; }

  // P <- L_k P; scratch holds at least 6 values of the precision.
  void apply(Letter k, mpfr_ptr t, mpfr_ptr u, mpfr_ptr v, MpValues &s) const {
    mpfr_ptr xc = s[0], xs = s[1], zc = s[2], zs = s[3], r1 = s[4], r2 = s[5], r3 = s[6], r4 = s[7];
    fold(X_, k, xc, xs);
    fold(Z_, (2 * k) % (4 * g_), zc, zs);
    mpfr_fmma(r1, c_[kN], t, xc, u, MPFR_RNDN);
    mpfr_mul(r2, xs, v, MPFR_RNDN);
    mpfr_add(r1, r1, r2, MPFR_RNDN);  // t'
    mpfr_fmma(r2, xc, t, c_[kA2], u, MPFR_RNDN);
    mpfr_fmma(r3, zc, u, zs, v, MPFR_RNDN);
    mpfr_add(r2, r2, r3, MPFR_RNDN);  // u'
    mpfr_fmma(r3, xs, t, zs, u, MPFR_RNDN);
    mpfr_fmms(r4, c_[kA2], v, zc, v, MPFR_RNDN);
    mpfr_add(v, r3, r4, MPFR_RNDN);  // v'
    mpfr_swap(t, r1);
    mpfr_swap(u, r2);
  }

  // The separation test <P, O - g_k(O)> = t (1 - N) + u X cos th + v X sin th.
  int side_sign(Letter k, mpfr_srcptr t, mpfr_srcptr u, mpfr_srcptr v, MpValues &s, const Word &w) const {
    mpfr_ptr xc = s[0], xs = s[1], r1 = s[4], r2 = s[5];
    fold(X_, k, xc, xs);
    mpfr_fmma(r1, t, c_[kOneMinusN], u, xc, MPFR_RNDN);
    mpfr_mul(r2, v, xs, MPFR_RNDN);
    mpfr_add(r1, r1, r2, MPFR_RNDN);
    if (mpfr_cmpabs(r1, c_[kMargin]) < 0)
      throw std::logic_error("canonical_word: separation test below its certified margin for " + word_to_string(w));
    return mpfr_sgn(r1) > 0 ? 1 : -1;
  }

 private:
  enum { kN, kA2, kZ, kOneMinusN, kMargin, kConstants };

  // (V cos, V sin) of k pi/2g from the stored V c_a: k pi/2g = q pi/2 + a pi/2g.
  void fold(const MpValues &V, int k, mpfr_ptr c, mpfr_ptr s) const {
    const int q = k / g_, a = k % g_;
    const mpfr_srcptr ca = V[std::size_t(a)], sa = V[std::size_t(g_ - a)];
    switch (q) {
      case 0: mpfr_set(c, ca, MPFR_RNDN), mpfr_set(s, sa, MPFR_RNDN); break;
      case 1: mpfr_neg(c, sa, MPFR_RNDN), mpfr_set(s, ca, MPFR_RNDN); break;
      case 2: mpfr_neg(c, ca, MPFR_RNDN), mpfr_neg(s, sa, MPFR_RNDN); break;
      default: mpfr_set(c, sa, MPFR_RNDN), mpfr_neg(s, ca, MPFR_RNDN); break;
    }
  }

  int g_;
  mpfr_prec_t prec_;
  MpValues c_, X_, Z_;
};

// Built once per genus and run-time rung and never freed, as
// shared_generators does (a few MB each at genus 1024, for the rare words
// that need them).
const RuntimeGenerators &runtime_generators(const Presentation &p, long bits) {
  static std::mutex mutex;
  static std::map<std::pair<int, long>, std::unique_ptr<const RuntimeGenerators>> cache;
  std::lock_guard<std::mutex> lock(mutex);
  auto &slot = cache[{p.genus(), bits}];
  if (!slot) slot = std::make_unique<const RuntimeGenerators>(p, mpfr_prec_t(bits));
  return *slot;
}

// peel_segment for a word beyond the ladder: the whole word on a run-time
// rung of `bits` that certifies 2m letters. True when P reached O.
bool peel_beyond_ladder(const Presentation &p, const DoubleGenerators &d, const Word &w, long bits, Word &out,
                        std::size_t bound) {
  const RuntimeGenerators &gens = runtime_generators(p, bits);
  const std::size_t budget = capacity_at_bits(p, double(gens.precision())) - w.size();
  MpValues P(3, gens.precision()), scratch(8, gens.precision());
  mpfr_ptr t = P[0], u = P[1], v = P[2];
  mpfr_set_ui(t, 1, MPFR_RNDN), mpfr_set_ui(u, 0, MPFR_RNDN), mpfr_set_ui(v, 0, MPFR_RNDN);
  for (std::size_t i = w.size(); i-- > 0;) gens.apply(w[i], t, u, v, scratch);
  for (std::size_t j = 0;; ++j) {
    const DoublePoint x = rounded_point(t, u, v);
    if (x.scale <= kDoubleScale) {
      const std::size_t before = out.size();
      if (peel_in_double(p, d, unscaled(x), out, bound)) return true;
      out.resize(before);
    }
    if (j == budget) return false;
    const Letter k =
        least_separating_letter(d, x, [&](Letter k) { return gens.side_sign(k, t, u, v, scratch, w); });
    if (k == kNoLetter) return true;
    append_letter(out, k, bound);
    gens.apply(p.inverse(k), t, u, v, scratch);
  }
}

// check_canonical's passes. Each is given the word from the right and
// answers whether every letter is the least separating letter of its
// suffix's point; kOpen when its precision leaves a test open.
CanonicalCheck check_in_double(const DoubleGenerators &d, const Letter *w, std::size_t length) {
  DoublePoint x;
  for (std::size_t i = length; i-- > 0;) {
    x = apply(d.lorentz[std::size_t(w[i])], x);
    const Letter k = least_separating_letter(d, x, [](Letter) { return 0; });
    if (k == kUndecided) return CanonicalCheck::kOpen;
    if (k != w[i]) return CanonicalCheck::kNotCanonical;
  }
  return CanonicalCheck::kCanonical;
}

template <class T>
CanonicalCheck check_tracked(const Presentation &p, const DoubleGenerators &d, const Letter *w, std::size_t length) {
  const GeneratorSet<T> &gens = shared_generators<T>(p);
  TrackedPoint<T> P(d.lorentz[0].m[0][0] * (1 + 0x1p-40));
  // A test the rounded point leaves open (P near a side line, seen from
  // far) is evaluated in T: side = <P~, n~> for n~ = O - g_k(O) from T's
  // matrix, off the true one by at most |P~ - P| |n|, the matrix entries'
  // 2^10 units (as step() allows) and the sum's few roundings, each a unit
  // of |P~| |n|; n from the double matrix, within an ulp, with slack.
  auto decide = [&](Letter k) {
    const auto &m = gens.lorentz(k).m;
    const HyperboloidPoint<T> &x = P.point();
    const T side = x.t * (T(1) - m[0][0]) + x.u * m[1][0] + x.v * m[2][0];
    const double n = std::abs(d.lorentz[std::size_t(k)].m[0][0] - 1) + std::abs(d.lorentz[std::size_t(k)].m[1][0]) +
                     std::abs(d.lorentz[std::size_t(k)].m[2][0]);
    const double size = std::abs(x.t.template convert_to<double>()) + std::abs(x.u.template convert_to<double>()) +
                        std::abs(x.v.template convert_to<double>());
    const double unit = std::ldexp(1.0, -int(mpfr_get_prec(side.backend().data())));
    const double error = (P.error() + (0x1p10 + 16) * unit * size) * n * (1 + 0x1p-20) + 0x1p-1000;
    using std::abs;
    if (abs(side) <= T(error)) return 0;
    return side > 0 ? 1 : -1;
  };
  for (std::size_t i = length; i-- > 0;) {
    if (!P.step(gens.lorentz(w[i]))) return CanonicalCheck::kOpen;
    const Letter k = least_separating_letter(d, P.rounded(), decide);
    if (k == kUndecided) return CanonicalCheck::kOpen;
    if (k != w[i]) return CanonicalCheck::kNotCanonical;
  }
  return CanonicalCheck::kCanonical;
}

}  // namespace

CanonicalCheck check_canonical(const Presentation &p, const Letter *w, std::size_t length) {
  const DoubleGenerators d = double_generators(p);
  CanonicalCheck c = check_in_double(d, w, length);
  if (c != CanonicalCheck::kOpen) return c;
  c = check_tracked<exact::mp_real<PeelLadder::kDigits10[0]>>(p, d, w, length);
  if (c != CanonicalCheck::kOpen) return c;
  return check_tracked<exact::mp_real<PeelLadder::kDigits10[2]>>(p, d, w, length);
}

namespace {

// walk_into_domain at the precision of T, with the generators d of p.
template <class T>
bool walk_at(const Presentation &p, const DoubleGenerators &d, double x, double y, Word &letters,
             std::size_t max_steps) {
  // The point's signs need no margin (a tile centre's distance from the
  // lines is what the canonical words' margin is for): any certified sign
  // will do. (Not 0: a test equal to its error bound is not certified.)
  const DoubleGenerators signs{d.lorentz, 0x1p-900, d.inradius_slope};
  const GeneratorSet<T> &gens = shared_generators<T>(p);
  // The hyperboloid point of x + iy. x^2 and y^2 are exact in T, r^2 within
  // u r^2 <= u of the true one (exact unless its terms are far apart), so
  // w = 1 - r^2 within u, a relative u / w; then three roundings a
  // coordinate. In 2-norm, with slack.
  const T X(x), Y(y), r2 = X * X + Y * Y, w = T(1) - r2;
  const HyperboloidPoint<T> P0{(T(1) + r2) / w, T(2) * X / w, T(2) * Y / w};
  const double unit = std::ldexp(1.0, -int(mpfr_get_prec(r2.backend().data())));
  const double size = std::abs(P0.t.template convert_to<double>()) + std::abs(P0.u.template convert_to<double>()) +
                      std::abs(P0.v.template convert_to<double>());
  const double e0 = 4 * size * (4 + 2 / w.template convert_to<double>()) * unit;
  TrackedPoint<T> P(d.lorentz[0].m[0][0] * (1 + 0x1p-40), P0, e0);
  for (;;) {
    const Letter k = least_separating_letter(signs, P.rounded(), [](Letter) { return 0; });
    if (k == kNoLetter) return true;
    if (k == kUndecided || letters.size() >= max_steps) return false;
    letters.push_back(k);
    if (!P.step(gens.lorentz(p.inverse(k)))) return false;
  }
}

}  // namespace

bool walk_into_domain(const Presentation &p, double x, double y, Word &letters, std::size_t max_steps) {
  // The tracked bound lets an error at the start, where the point's t0 is
  // about 2 / (1 - |z|^2), reach step i multiplied by up to 4 t_i t0, and
  // the start's relative error is up to u t0: the precision needs about
  // 3 log2 t0 bits, and the generators' size and 64 more for the tests.
  const DoubleGenerators d = double_generators(p);
  const double t0 = 2 / (1 - (x * x + y * y));
  const double need = 3 * std::log2(t0) + std::log2(d.lorentz[0].m[0][0]) + 64;
  return PeelLadder::at(need <= double(PeelLadder::bits(1)) ? 1 : 2, [&](auto zero) {
    return walk_at<decltype(zero)>(p, d, x, y, letters, max_steps);
  });
}

std::size_t canonical_ladder_length(const Presentation &p) {
  // word_certified_bits(m) = 64 + b m + 2 log2(m + 2) with
  // b = word_precision_bits(p, 1) - 2 log2(3); bound the logarithm by that
  // of the top and keep 2 letters of slack for the peeled words.
  const double top = double(PeelLadder::top_bits());
  const double per_letter = (word_precision_bits(p, 1) - 2.0 * std::log2(3.0));
  const double m = std::floor((top - 64.0 - 2.0 * std::log2(top + 2.0)) / per_letter) - 2.0;
  return m > 0 ? std::size_t(m) : 0;
}

Word canonical_word(const Presentation &p, const Letter *input, std::size_t length, std::size_t max_runtime_length) {
  p.check_word(input, length);
  Word w = dehn_reduce(p, input, length);
  // Peel the least possible first letter off h until nothing is left. Each
  // step lowers the geodesic length by one, so there are at most |w| steps.
  const std::size_t bound = w.size();
  const DoubleGenerators d = double_generators(p);
  Word out;
  while (!w.empty()) {
    const std::size_t start = out.size();
    // Double precision first (most words met by a triangulation are short),
    // multiprecision when it cannot find even the first letter.
    if (peel_in_double(p, d, double_image(d, w), out, bound)) break;
    if (out.size() == start) {
      // 40 digits with the tracked bound finish most words; the schedule
      // of rungs by length is the fallback. Before a rung above 160 digits
      // (or a run-time precision), 160 digits with the tracked bound: the
      // words of points near the circle are long but their points stay
      // within cosh 2^53 of O, a few hundred bits, where the length asks for
      // tens of thousands, whose products cost far more.
      using exact::mp_real;
      if (peel_tracked<mp_real<PeelLadder::kDigits10[0]>>(p, d, w, out, bound)) break;
      const Segment s = plan_segment(p, w.size());
      if ((s.steps == 0 || s.rung > 2) && peel_tracked<mp_real<PeelLadder::kDigits10[2]>>(p, d, w, out, bound)) break;
      // Longer than the top rung certifies: a run-time rung.
      if (s.steps == 0 && w.size() > max_runtime_length)
        throw exact::Unsupported("the Dehn-reduced word has " + std::to_string(w.size()) +
                                " letters and needs a run-time precision, computed up to " +
                                std::to_string(max_runtime_length) + " letters");
      const std::size_t rung = s.steps == 0 ? PeelLadder::rung_for(word_certified_bits(p, 2 * w.size())) : s.rung;
      if (PeelLadder::at(
              rung, [&](auto zero) { return peel_segment<decltype(zero)>(p, d, w, s.steps, out, bound); },
              [&](long bits) { return peel_beyond_ladder(p, d, w, bits, out, bound); }))
        break;
    }
    // The bound or the rung's bits are spent: go on from a Dehn-reduced word
    // of the rest, h with the letters found since `start` peeled off.
    Word rest = p.inverse(Word(out.begin() + std::ptrdiff_t(start), out.end()));
    rest.insert(rest.end(), w.begin(), w.end());
    w = dehn_reduce(p, rest);
  }
  return out;
}

}  // namespace hdt::group
