// Internal tests of the exact predicates (Check, compiled as C++).
//
// The kernel's answers (filter then exact, and the exact path alone) are
// compared with an independent reference: the same determinants evaluated in
// MPFR at 610 decimal digits (about 2026 bits) from the Lorentz matrices of
// group::GeneratorSet, with a relative threshold far above that precision's
// rounding and far below any value a non-degenerate double input can give.
// Degenerate inputs are built so that they are degenerate exactly in doubles:
//   - circles centred at 0: the 8 images of z under z -> iz, -z, conj z are
//     exact in doubles;
//   - hypercycles: the points h^n(z) of one orbit of a cyclic subgroup lie on
//     one equidistant curve of the axis of h (a plane section of the
//     hyperboloid), so det[N 1] = 0 for any four of them;
//   - the centres h(0) of the 4g tiles around the vertex v_0: equidistant from
//     v_0, hence cocircular, although every one has a different translation;
//   - geodesics: diameters at angle 0, pi/4, pi/2, 3pi/4 hold exact points
//     t (1, 0), t (1, 1), ..., and the generator whose axis is that diameter
//     keeps it, so its powers give translated points on the same geodesic.
// A common translation c applied to any such set keeps it degenerate.
#include <algorithm>
#include <array>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "exact/multiprecision.hpp"
#include "exact/unit_disk.hpp"
#include "group/generators.hpp"
#include "group/lorentz.hpp"
#include "group/moebius.hpp"
#include "group/presentation.hpp"
#include "group/translation_table.hpp"
#include "group/word_matrix.hpp"
#include "predicates/kernel.hpp"
#include "predicates/stage_exact.hpp"
#include "surface/polygon.hpp"
#include "predicates/representative.hpp"

// Last: check.h defines a macro named fail that breaks <iostream>.
#include <check.h>

#include "run_suite.hpp"

using namespace hdt;
using group::Complex;
using group::Letter;
using group::Presentation;
using group::TranslationId;
using group::Word;
using predicates::Kernel;
using predicates::TranslatedPoint;

namespace {

using Real = exact::mp_real<610>;  // the reference's precision
using Mid = exact::mp_real<100>;   // images of points (representative tests)

using Rng = std::mt19937_64;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// ---------------------------------------------------------------------------
// The MPFR reference.

class Reference {
 public:
  using Vec = std::array<Real, 3>;

  explicit Reference(Kernel &kernel)
      : kernel_(kernel),
        gens_(group::shared_generators<Real>(kernel.surface().presentation())),
        exact_(kernel.surface()),
        tiny_("1e-450") {}

  // The kernel's last stage (predicates::ExactStage, as Kernel holds it) on
  // the same surface: checked against the reference on its own, since the
  // pipeline decides most inputs before it.
  predicates::ExactStage &exact() { return exact_; }

  const group::Lorentz<Real> &lorentz(TranslationId id) {
    if (std::size_t(id) >= matrices_.size()) matrices_.resize(std::size_t(id) + 1);
    auto &slot = matrices_[std::size_t(id)];
    if (!slot) slot = std::make_unique<group::Lorentz<Real>>(gens_.lorentz(kernel_.surface().table().word(id)));
    return *slot;
  }

  // N = L_h (1 + x^2 + y^2, 2x, 2y) / (1 - x^2 - y^2); x and y convert exactly.
  Vec vec(const TranslatedPoint &p) {
    const Real x(p.x), y(p.y);
    const Real r2 = x * x + y * y;
    const Real w = Real(1) - r2;
    const Real hat[3] = {Real(1) + r2, Real(2) * x, Real(2) * y};
    const auto &L = lorentz(p.translation);
    Vec n;
    for (int i = 0; i < 3; ++i) n[i] = (L.m[i][0] * hat[0] + L.m[i][1] * hat[1] + L.m[i][2] * hat[2]) / w;
    return n;
  }

  int orientation(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r) {
    const Vec a = vec(p), b = vec(q), c = vec(r);
    return decide(det3(a, b, c), size(a) * size(b) * size(c));
  }

  // sign det[N_p 1; N_q 1; N_r 1; N_s 1], expanded along the last column.
  int in_circle(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r,
                const TranslatedPoint &s) {
    const Vec v[4] = {vec(p), vec(q), vec(r), vec(s)};
    Real d = 0, scale = 0;
    for (int skip = 0; skip < 4; ++skip) {
      const Vec *o[3];
      for (int i = 0, j = 0; i < 4; ++i)
        if (i != skip) o[j++] = &v[i];
      const Real minor = det3(*o[0], *o[1], *o[2]);
      d = (skip % 2 == 1) ? d + minor : d - minor;  // cofactor sign (-1)^(skip + 3)
      scale += size(*o[0]) * size(*o[1]) * size(*o[2]);
    }
    return decide(d, scale);
  }

  // sign(<N, O> - <N, g_k O>), O = (1, 0, 0), <a, b> = a0 b0 - a1 b1 - a2 b2.
  int beyond_side(const TranslatedPoint &p, int k) {
    const Vec n = vec(p);
    const auto &G = gens_.lorentz(Letter(k));
    const Real gO[3] = {G.m[0][0], G.m[1][0], G.m[2][0]};
    const Real value = n[0] - (n[0] * gO[0] - n[1] * gO[1] - n[2] * gO[2]);
    const Real scale = abs(n[0]) * (Real(1) + abs(gO[0])) + abs(n[1] * gO[1]) + abs(n[2] * gO[2]);
    return decide(value, scale);
  }

  // The image of a disk point under the element id, in MPFR.
  Complex<double> image(TranslationId id, double x, double y) {
    const Vec n = vec({x, y, id});
    const Real s = Real(1) / (Real(1) + n[0]);
    return {static_cast<double>(n[1] * s), static_cast<double>(n[2] * s)};
  }

 private:
  static Real det3(const Vec &a, const Vec &b, const Vec &c) {
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
           a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  static Real size(const Vec &a) { return abs(a[0]) + abs(a[1]) + abs(a[2]) + Real(1); }
  int decide(const Real &value, const Real &scale) const {
    if (abs(value) <= scale * tiny_) return 0;
    return value > 0 ? 1 : -1;
  }

  Kernel &kernel_;
  const group::GeneratorSet<Real> &gens_;
  std::vector<std::unique_ptr<group::Lorentz<Real>>> matrices_;
  predicates::ExactStage exact_;
  Real tiny_;
};

// ---------------------------------------------------------------------------
// Comparisons; every message names the inputs exactly (%a) for a reproducer.

std::string show(Kernel &kernel, const TranslatedPoint &p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "{%a, %a, %d}", p.x, p.y, int(p.translation));
  return std::string(buf) + "=[" + group::word_to_string(kernel.surface().table().word(p.translation)) + "]";
}

template <std::size_t n>
std::string show(Kernel &kernel, const std::array<TranslatedPoint, n> &pts) {
  std::string s = "g=" + std::to_string(kernel.surface().presentation().genus()) + ":";
  for (const auto &p : pts) s += " " + show(kernel, p);
  return s;
}

// Each returns the reference sign after checking the kernel against it.
int check_orientation(Kernel &kernel, Reference &ref, const std::array<TranslatedPoint, 3> &t, const char *what,
                      bool exact_too = true) {
  const int e = ref.orientation(t[0], t[1], t[2]);
  const int f = kernel.orientation(t[0], t[1], t[2]);
  ck_assert_msg(f == e, "%s: orientation %d, reference %d, %s", what, f, e, show(kernel, t).c_str());
  if (exact_too) {
    const int x = to_int(ref.exact().orientation(t[0], t[1], t[2]));
    ck_assert_msg(x == e, "%s: exact stage's orientation %d, reference %d, %s", what, x, e, show(kernel, t).c_str());
  }
  return e;
}

int check_in_circle(Kernel &kernel, Reference &ref, const std::array<TranslatedPoint, 4> &t, const char *what,
                    bool exact_too = true) {
  const int e = ref.in_circle(t[0], t[1], t[2], t[3]);
  const int f = kernel.in_circle(t[0], t[1], t[2], t[3]);
  ck_assert_msg(f == e, "%s: in_circle %d, reference %d, %s", what, f, e, show(kernel, t).c_str());
  if (exact_too) {
    const int x = to_int(ref.exact().in_circle(t[0], t[1], t[2], t[3]));
    ck_assert_msg(x == e, "%s: exact stage's in_circle %d, reference %d, %s", what, x, e, show(kernel, t).c_str());
  }
  return e;
}

int check_beyond_side(Kernel &kernel, Reference &ref, const TranslatedPoint &p, int k, const char *what,
                      bool exact_too = true) {
  const int e = ref.beyond_side(p, k);
  const int f = kernel.beyond_side(p, k);
  ck_assert_msg(f == e, "%s: beyond_side(side %d) %d, reference %d, %s", what, k, f, e, show(kernel, p).c_str());
  if (exact_too) {
    const int x = to_int(ref.exact().beyond_side(p, k));
    ck_assert_msg(x == e, "%s: exact stage's beyond_side(side %d) %d, reference %d, %s", what, k, x, e,
                  show(kernel, p).c_str());
  }
  return e;
}

// ---------------------------------------------------------------------------
// Random and degenerate inputs.

TranslationId random_neighbour(Rng &rng, Kernel &kernel) {
  return TranslationId(std::uniform_int_distribution<int>(0, int(kernel.surface().table().neighbour_count()) - 1)(rng));
}

Complex<double> random_in_disk(Rng &rng, double radius) {
  std::uniform_real_distribution<double> u(-1, 1);
  for (;;) {
    const double x = u(rng), y = u(rng);
    if (x * x + y * y < 1) return {radius * x, radius * y};
  }
}

// Approximately in F_g (doubles; only used to choose inputs).
bool roughly_in_polygon(const group::GeneratorSet<double> &gens, double x, double y) {
  const auto n = group::to_hyperboloid(Complex<double>{x, y});
  for (Letter k = 0; k < gens.presentation().letter_count(); ++k) {
    const auto &G = gens.lorentz(k);
    if (n.t - (n.t * G.m[0][0] - n.u * G.m[1][0] - n.v * G.m[2][0]) > 0) return false;
  }
  return true;
}

Complex<double> random_in_polygon(Rng &rng, const group::GeneratorSet<double> &gens) {
  const double radius = std::sqrt(std::cos(M_PI / (2 * gens.presentation().genus())));  // the vertices'
  for (;;) {
    const auto z = random_in_disk(rng, radius);
    if (roughly_in_polygon(gens, z.re, z.im)) return z;
  }
}

TranslatedPoint random_point(Rng &rng, Kernel &kernel, const group::GeneratorSet<double> &gens) {
  const auto z = (rng() % 2) ? random_in_polygon(rng, gens) : random_in_disk(rng, 0.8);
  return {z.re, z.im, random_neighbour(rng, kernel)};
}

// A dyadic coordinate a / 1024 with |a| <= limit.
double dyadic(Rng &rng, int limit) { return std::uniform_int_distribution<int>(-limit, limit)(rng) / 1024.0; }

Word concat(const Word &a, const Word &b) {
  Word w = a;
  w.insert(w.end(), b.begin(), b.end());
  return w;
}

Word power(const Presentation &p, const Word &w, int n) {
  const Word base = n < 0 ? p.inverse(w) : w;
  Word r;
  for (int i = 0; i < std::abs(n); ++i) r = concat(r, base);
  return r;
}

// The id of c h^n.
TranslationId translate_power(Kernel &kernel, TranslationId c, const Word &h, int n) {
  return kernel.surface().table().intern(concat(kernel.surface().table().word(c), power(kernel.surface().presentation(), h, n)));
}

enum class Kind { circle, hypercycle, star, geodesic };

struct Quad {
  std::array<TranslatedPoint, 4> p;
  Kind kind;
  int coordinate_across = -1;  // geodesic: the coordinate that leaves the line (-1: either)
};

// Four of the eight images of z under the symmetries of the square, on the
// circle |z| centred at 0 (or its image under the common translation c).
Quad circle_quad(Rng &rng, Kernel &, TranslationId c) {
  double x, y;
  do {
    x = dyadic(rng, 900), y = dyadic(rng, 900);
  } while (x == 0 || y == 0 || std::abs(x) == std::abs(y) || x * x + y * y >= 0.81);
  std::array<Complex<double>, 8> images{{{x, y}, {-y, x}, {-x, -y}, {y, -x}, {x, -y}, {y, x}, {-x, y}, {-y, -x}}};
  std::shuffle(images.begin(), images.end(), rng);
  Quad q{{}, Kind::circle};
  for (int i = 0; i < 4; ++i) q.p[i] = {images[i].re, images[i].im, c};
  return q;
}

// c h^n(z) for four distinct n in -1..2: one hypercycle of the axis of c h c^-1.
Quad hypercycle_quad(Rng &rng, Kernel &kernel, TranslationId c) {
  double x, y;
  do {
    x = dyadic(rng, 900), y = dyadic(rng, 900);
  } while (x == 0 || y == 0 || x * x + y * y >= 0.81);
  TranslationId h;
  do h = random_neighbour(rng, kernel);
  while (h == 0);
  const Word hw = kernel.surface().table().word(h);
  std::array<int, 4> n{-1, 0, 1, 2};
  std::shuffle(n.begin(), n.end(), rng);
  Quad q{{}, Kind::hypercycle};
  for (int i = 0; i < 4; ++i) q.p[i] = {x, y, translate_power(kernel, c, hw, n[i])};
  return q;
}

// The ids h in N with h(F) containing v_0 (4g of them): their centres h(0)
// are cocircular about v_0.
std::vector<TranslationId> vertex_star(Kernel &kernel) {
  const Presentation &p = kernel.surface().presentation();
  const auto v0 = surface::polygon_vertex<double>(p.genus(), 0);
  std::vector<TranslationId> star;
  for (TranslationId id = 0; std::size_t(id) < kernel.surface().table().neighbour_count(); ++id) {
    const auto pre = kernel.surface().table().moebius(id).inverse().apply(v0);
    for (int j = 0; j < p.letter_count(); ++j) {
      const auto v = surface::polygon_vertex<double>(p.genus(), j);
      if (std::hypot(pre.re - v.re, pre.im - v.im) < 1e-9) {
        star.push_back(id);
        break;
      }
    }
  }
  ck_assert_uint_eq(star.size(), std::size_t(p.letter_count()));
  return star;
}

Quad star_quad(Rng &rng, Kernel &kernel, const std::vector<TranslationId> &star, TranslationId c) {
  std::vector<TranslationId> ids = star;
  std::shuffle(ids.begin(), ids.end(), rng);
  Quad q{{}, Kind::star};
  for (int i = 0; i < 4; ++i) {
    const TranslationId id = kernel.surface().table().intern(concat(kernel.surface().table().word(c), kernel.surface().table().word(ids[i])));
    q.p[i] = {0.0, 0.0, id};
  }
  return q;
}

// Four distinct points of a diameter at angle 0 or pi/2 (also pi/4, 3pi/4
// when g is even), translated by powers of the generator whose axis it is
// (g_k has its axis at angle k pi/2g), then by c.
Quad geodesic_quad(Rng &rng, Kernel &kernel, TranslationId c) {
  const Presentation &p = kernel.surface().presentation();
  const int g = p.genus();
  const int choices = (g % 2 == 0) ? 4 : 2;
  const int line = std::uniform_int_distribution<int>(0, choices - 1)(rng);
  // direction (dx, dy) and the letter k with k pi / 2g = the angle
  int dx, dy, across;
  Letter k;
  switch (line) {
    case 0: dx = 1, dy = 0, k = 0, across = 1; break;
    case 1: dx = 0, dy = 1, k = g, across = 0; break;
    case 2: dx = 1, dy = 1, k = g / 2, across = -1; break;
    default: dx = -1, dy = 1, k = 3 * g / 2, across = -1; break;
  }
  Quad q{{}, Kind::geodesic, across};
  std::vector<std::pair<double, int>> used;
  for (int i = 0; i < 4;) {
    const double t = dyadic(rng, 700);
    const int n = std::uniform_int_distribution<int>(-1, 1)(rng);
    if (std::find(used.begin(), used.end(), std::make_pair(t, n)) != used.end()) continue;
    used.emplace_back(t, n);
    q.p[i++] = {t * dx, t * dy, translate_power(kernel, c, Word{k}, n)};
  }
  return q;
}

double nudge(double v, int ulps) {
  const double to = ulps > 0 ? INFINITY : -INFINITY;
  for (int i = 0; i < std::abs(ulps); ++i) v = std::nextafter(v, to);
  return v;
}

// v moved by about `steps` ulps (of 2^-4 when v is 0): a wider range than
// nudge, so that some values land near the filter's error bound.
double shift(double v, long steps) {
  const double ulp = v == 0 ? std::ldexp(1.0, -57) : std::nextafter(std::abs(v), INFINITY) - std::abs(v);
  return v + double(steps) * ulp;
}

// One point of the quad moved in one coordinate (never along a geodesic the
// quad lies on): by 1..4 ulps, or (when wide) by +-2^e ulps, e in 2..24.
Quad perturbed(Rng &rng, const Quad &q, int &moved, bool wide = false) {
  Quad r = q;
  moved = int(rng() % 4);
  const bool up = rng() % 2;
  const int coordinate = q.coordinate_across >= 0 ? q.coordinate_across : int(rng() % 2);
  double &v = coordinate == 0 ? r.p[moved].x : r.p[moved].y;
  if (wide) {
    const long steps = 1L << (2 + rng() % 23);
    v = shift(v, up ? steps : -steps);
  } else {
    const int ulps = 1 + int(rng() % 4);
    v = nudge(v, up ? ulps : -ulps);
  }
  return r;
}

Quad random_quad(Rng &rng, Kernel &kernel, const std::vector<TranslationId> &star, bool common_translation) {
  const TranslationId c = common_translation ? random_neighbour(rng, kernel) : 0;
  switch (rng() % 4) {
    case 0: return circle_quad(rng, kernel, c);
    case 1: return hypercycle_quad(rng, kernel, c);
    case 2: return star_quad(rng, kernel, star, c);
    default: return geodesic_quad(rng, kernel, c);
  }
}

}  // namespace

// ---------------------------------------------------------------------------

// The sign conventions of the header, on inputs whose answer is known.
START_TEST(sign_conventions) {
  surface::Surface M(2);
  Kernel kernel{M};
  Reference ref(kernel);
  const TranslatedPoint a{0.5, 0.0, 0}, b{0.0, 0.5, 0}, c{-0.5, 0.0, 0}, o{0.0, 0.0, 0}, far{0.0, -0.75, 0};
  ck_assert_int_eq(check_orientation(kernel, ref, {a, b, c}, "ccw"), 1);
  ck_assert_int_eq(check_orientation(kernel, ref, {b, a, c}, "cw"), -1);
  ck_assert_int_eq(check_in_circle(kernel, ref, {a, b, c, o}, "centre"), 1);
  ck_assert_int_eq(check_in_circle(kernel, ref, {a, b, c, far}, "outside"), -1);
  ck_assert_int_eq(check_in_circle(kernel, ref, {b, a, c, o}, "centre, cw"), -1);
  // O is on F's side of every side; g_k(O) beyond s_k; g_k^-1(O) not beyond s_k.
  const Presentation &p = kernel.surface().presentation();
  for (int k = 0; k < p.letter_count(); ++k) {
    const TranslationId gk = kernel.surface().table().intern(Word{k});
    const TranslationId gk_inv = kernel.surface().table().intern(Word{p.inverse(k)});
    ck_assert_int_eq(check_beyond_side(kernel, ref, o, k, "O"), -1);
    ck_assert_int_eq(check_beyond_side(kernel, ref, {0.0, 0.0, gk}, k, "g_k O"), 1);
    ck_assert_int_eq(check_beyond_side(kernel, ref, {0.0, 0.0, gk_inv}, k, "g_k^-1 O"), -1);
  }
}
END_TEST

// 1. Random configurations against the MPFR reference.
static const int kGenera[] = {2, 3, 4};
static const int kRandomConfigs[] = {20000, 8000, 4000};

START_TEST(random_configurations_agree_with_reference) {
  const int g = kGenera[_i], configs = kRandomConfigs[_i];
  const auto t0 = std::chrono::steady_clock::now();
  surface::Surface M(g);
  Kernel kernel{M};
  Reference ref(kernel);
  const group::GeneratorSet<double> gens{Presentation(g)};
  Rng rng(1000 + g);
  int signs[3][3] = {};  // [predicate][sign + 1]
  for (int i = 0; i < configs; ++i) {
    const std::array<TranslatedPoint, 4> t{random_point(rng, kernel, gens), random_point(rng, kernel, gens),
                                           random_point(rng, kernel, gens), random_point(rng, kernel, gens)};
    // The exact path alone on every second configuration (it is the slow one).
    const bool exact_too = i % 2 == 0;
    ++signs[0][check_orientation(kernel, ref, {t[0], t[1], t[2]}, "random", exact_too) + 1];
    ++signs[1][check_in_circle(kernel, ref, t, "random", exact_too) + 1];
    const int k = int(rng() % unsigned(4 * g));
    ++signs[2][check_beyond_side(kernel, ref, t[3], k, "random", exact_too) + 1];
  }
  // Both signs occur, and random inputs are never degenerate.
  for (auto &s : signs) {
    ck_assert_int_eq(s[1], 0);
    ck_assert_int_gt(s[0], configs / 20);
    ck_assert_int_gt(s[2], configs / 20);
  }
  std::printf("random g=%d: %d configurations in %.1f s\n", g, configs, seconds_since(t0));
}
END_TEST

// 1. Near-degenerate configurations: exactly degenerate ones, and the same
// with one coordinate moved by 1..4 ulps.
static const int kDegenerateQuads[] = {2500, 1200, 700};

START_TEST(near_degenerate_configurations_agree_with_reference) {
  const int g = kGenera[_i], quads = kDegenerateQuads[_i];
  const auto t0 = std::chrono::steady_clock::now();
  surface::Surface M(g);
  Kernel kernel{M};
  Reference ref(kernel);
  const auto star = vertex_star(kernel);
  Rng rng(2000 + g);
  for (int i = 0; i < quads; ++i) {
    const Quad q = random_quad(rng, kernel, star, i % 2 == 1);
    // Exactly degenerate: the reference sees 0 (a check of the construction).
    ck_assert_int_eq(check_in_circle(kernel, ref, q.p, "degenerate"), 0);
    if (q.kind == Kind::geodesic)
      ck_assert_int_eq(check_orientation(kernel, ref, {q.p[0], q.p[1], q.p[2]}, "collinear"), 0);
    else
      ck_assert_int_ne(check_orientation(kernel, ref, {q.p[0], q.p[1], q.p[2]}, "on a circle"), 0);
    int moved;
    const Quad m = perturbed(rng, q, moved);
    ck_assert_int_ne(check_in_circle(kernel, ref, m.p, "moved"), 0);
    for (int wide = 0; wide < 4; ++wide) {
      int moved_far;
      const Quad f = perturbed(rng, q, moved_far, true);
      ck_assert_int_ne(check_in_circle(kernel, ref, f.p, "moved by 2^e ulps", false), 0);
      if (q.kind == Kind::geodesic)
        ck_assert_int_ne(check_orientation(kernel, ref, {f.p[(moved_far + 1) % 4], f.p[moved_far],
                                                          f.p[(moved_far + 3) % 4]},
                                           "moved off a line by 2^e ulps", false),
                         0);
    }
    // The moved point in every position (the determinant's rows differ).
    std::array<TranslatedPoint, 4> rotated = m.p;
    std::rotate(rotated.begin(), rotated.begin() + 1, rotated.end());
    ck_assert_int_ne(check_in_circle(kernel, ref, rotated, "moved, rotated", false), 0);
    if (q.kind == Kind::geodesic) {
      const int other1 = (moved + 1) % 4, other2 = (moved + 2) % 4;
      ck_assert_int_ne(check_orientation(kernel, ref, {m.p[other1], m.p[moved], m.p[other2]}, "moved off a line"), 0);
    }
  }
  // Points close to the lines of the sides: rounded midpoints and vertices,
  // translated by neighbours (g_k maps m_{k+2g} onto m_k, so {m_{k+2g}, g_k}
  // is within rounding of s_k), and moved by a few ulps.
  const Presentation &p = kernel.surface().presentation();
  const int n = p.letter_count();
  for (int j = 0; j < n; ++j) {
    const auto mid = surface::polygon_side_midpoint<double>(g, j);
    const auto v = surface::polygon_vertex<double>(g, j);
    const TranslationId gk = kernel.surface().table().intern(Word{Letter(j)});
    const auto opposite = surface::polygon_side_midpoint<double>(g, p.inverse(j));
    std::vector<long> moves{-2, -1, 0, 1, 2};
    for (int e = 3; e <= 24; e += 3) moves.insert(moves.end(), {1L << e, -(1L << e)});
    for (const long ulps : moves) {
      const auto move = [ulps](double c) { return std::abs(ulps) <= 2 ? nudge(c, int(ulps)) : shift(c, ulps); };
      const TranslatedPoint pts[] = {{move(mid.re), mid.im, 0},
                                     {mid.re, move(mid.im), 0},
                                     {move(v.re), v.im, 0},
                                     {v.re, move(v.im), 0},
                                     {move(opposite.re), opposite.im, gk},
                                     {opposite.re, move(opposite.im), gk}};
      for (const auto &pt : pts)
        for (int k = 0; k < n; ++k) check_beyond_side(kernel, ref, pt, k, "near a side");
    }
    for (int trial = 0; trial < 6; ++trial) {
      const TranslationId c = random_neighbour(rng, kernel);
      for (int k = 0; k < n; ++k) {
        check_beyond_side(kernel, ref, {mid.re, mid.im, c}, k, "translated midpoint");
        check_beyond_side(kernel, ref, {v.re, v.im, c}, k, "translated vertex");
      }
    }
  }
  // Rounded polygon vertices: near-cocircular about 0, and about v_0 with
  // the tiles' centres.
  for (int trial = 0; trial < 40; ++trial) {
    std::array<TranslatedPoint, 4> t;
    std::vector<int> ks(n);
    for (int k = 0; k < n; ++k) ks[k] = k;
    std::shuffle(ks.begin(), ks.end(), rng);
    const TranslationId c = random_neighbour(rng, kernel);
    for (int i = 0; i < 4; ++i) {
      const auto v = surface::polygon_vertex<double>(g, ks[i]);
      t[i] = {v.re, v.im, c};
    }
    check_in_circle(kernel, ref, t, "rounded vertices");
  }
  std::printf("near-degenerate g=%d: %d sets in %.1f s\n", g, quads, seconds_since(t0));
}
END_TEST

// 2. Exact zeros, each made of exact double inputs.
START_TEST(exact_zeros) {
  const int g = kGenera[_i];
  surface::Surface M(g);
  Kernel kernel{M};
  Reference ref(kernel);
  const Presentation &p = kernel.surface().presentation();
  const auto star = vertex_star(kernel);
  Rng rng(3000 + g);

  // (a) Circles about 0 (and their translates): every choice of 4 of the 8
  // images, in every order of a few.
  for (int trial = 0; trial < 30; ++trial) {
    const TranslationId c = trial < 10 ? 0 : random_neighbour(rng, kernel);
    const Quad q = circle_quad(rng, kernel, c);
    ck_assert_int_eq(check_in_circle(kernel, ref, q.p, "circle"), 0);
    std::array<TranslatedPoint, 4> t = q.p;
    std::swap(t[0], t[3]);
    ck_assert_int_eq(kernel.in_circle(t[0], t[1], t[2], t[3]), 0);
    int moved;
    const Quad m = perturbed(rng, q, moved);
    ck_assert_int_ne(check_in_circle(kernel, ref, m.p, "circle, one ulp off"), 0);
  }
  // Hypercycles and the tiles around v_0: cocircular points with different
  // translations.
  for (int trial = 0; trial < 30; ++trial) {
    const TranslationId c = trial % 2 ? 0 : random_neighbour(rng, kernel);
    ck_assert_int_eq(check_in_circle(kernel, ref, hypercycle_quad(rng, kernel, c).p, "hypercycle"), 0);
    ck_assert_int_eq(check_in_circle(kernel, ref, star_quad(rng, kernel, star, c).p, "star of v_0"), 0);
  }

  // (b) Geodesics: three or four points of a diameter (and translates).
  for (const double t : {-0.625, 0.0, 0.25, 0.5, 0.875}) {
    for (const double u : {-0.375, 0.125}) {
      for (const double w : {-0.9375, 0.75}) {
        const TranslationId c = random_neighbour(rng, kernel);
        for (const TranslationId h : {TranslationId(0), c}) {
          ck_assert_int_eq(check_orientation(kernel, ref, {{{t, 0, h}, {u, 0, h}, {w, 0, h}}}, "real axis"), 0);
          ck_assert_int_eq(check_orientation(kernel, ref, {{{0, t, h}, {0, u, h}, {0, w, h}}}, "imaginary axis"), 0);
          ck_assert_int_eq(check_orientation(kernel, ref, {{{t / 2, t / 2, h}, {u, u, h}, {w / 2, w / 2, h}}},
                                             "diagonal"),
                           0);
          // Four points of one geodesic: det[N 1] vanishes too.
          ck_assert_int_eq(check_in_circle(kernel, ref, {{{t, 0, h}, {u, 0, h}, {w, 0, h}, {0.0625, 0, h}}},
                                           "four on a geodesic"),
                           0);
        }
      }
    }
  }
  // Translated points on the axis of g_0 (the real axis), g_g (the imaginary axis).
  for (int trial = 0; trial < 30; ++trial) {
    const Quad q = geodesic_quad(rng, kernel, trial < 10 ? 0 : random_neighbour(rng, kernel));
    ck_assert_int_eq(check_orientation(kernel, ref, {q.p[0], q.p[1], q.p[2]}, "translated collinear"), 0);
    ck_assert_int_eq(check_orientation(kernel, ref, {q.p[3], q.p[1], q.p[0]}, "translated collinear"), 0);
    ck_assert_int_eq(check_in_circle(kernel, ref, q.p, "translated, four on a geodesic"), 0);
  }
  // The centres 0, g_k(0), g_k^2(0), g_k^-1(0) lie on the axis of g_k.
  for (Letter k = 0; k < p.letter_count(); ++k) {
    const TranslationId a = kernel.surface().table().intern(Word{k}), b = kernel.surface().table().intern(Word{k, k}),
                        c = kernel.surface().table().intern(Word{p.inverse(k)});
    ck_assert_int_eq(check_orientation(kernel, ref, {{{0, 0, 0}, {0, 0, a}, {0, 0, b}}}, "axis of g_k"), 0);
    ck_assert_int_eq(check_in_circle(kernel, ref, {{{0, 0, c}, {0, 0, 0}, {0, 0, a}, {0, 0, b}}}, "axis of g_k"), 0);
  }

  // (c) A repeated point: orientation and in_circle vanish.
  const group::GeneratorSet<double> gens(p);
  for (int trial = 0; trial < 30; ++trial) {
    const TranslatedPoint a = random_point(rng, kernel, gens), b = random_point(rng, kernel, gens),
                          c = random_point(rng, kernel, gens);
    ck_assert_int_eq(check_orientation(kernel, ref, {a, b, a}, "repeated"), 0);
    ck_assert_int_eq(check_in_circle(kernel, ref, {a, b, c, b}, "repeated"), 0);
    ck_assert_int_eq(check_in_circle(kernel, ref, {c, c, a, b}, "repeated"), 0);
  }

  // (d) beyond_side == 0 would need a point exactly on a side's line, which
  // no double point is (the lines' Euclidean centres are irrational, and a
  // rational point on |z - c|^2 = c^2 - 1 would make c rational for s_0 and
  // s_g), nor a tile centre h(0) (the lines of the tiling are edges, and no
  // centre is on an edge). The signs at O and g_k(O) are checked in
  // sign_conventions; near-zero cases in the near-degenerate test.
}
END_TEST

// The structural-zero stage (predicates/stage_structural.cpp): points on the
// real or imaginary axis under powers of the generator along it have an
// exactly zero row coordinate, so the stage decides their orientation and
// in-circle zeros; points just off the axis, or moved off it by another
// translation, must not be taken for zeros.
START_TEST(structural_zeros) {
  const int g = kGenera[_i];
  surface::Surface M(g);
  Kernel kernel{M};
  Reference ref(kernel);
  const Presentation &p = kernel.surface().presentation();
  Rng rng(5000 + g);
  kernel.reset_statistics();
  for (int trial = 0; trial < 40; ++trial) {
    const bool real = trial % 2 == 0;
    const Letter k = real ? 0 : Letter(g);  // the generator along the axis
    std::array<TranslatedPoint, 4> on, off, moved;
    for (int i = 0; i < 4; ++i) {
      const double t = dyadic(rng, 900) + (i + 1) * 0x1p-20;  // distinct points
      const int n = std::uniform_int_distribution<int>(-2, 2)(rng);
      const TranslationId h = translate_power(kernel, 0, Word{k}, n);
      const TranslationId other = translate_power(kernel, 0, Word{Letter((k + 1) % p.letter_count())}, n == 0 ? 1 : n);
      on[i] = real ? TranslatedPoint{t, 0, h} : TranslatedPoint{0, t, h};
      off[i] = real ? TranslatedPoint{t, 0x1p-40, h} : TranslatedPoint{0x1p-40, t, h};
      moved[i] = i == 3 ? (real ? TranslatedPoint{t, 0, other} : TranslatedPoint{0, t, other}) : on[i];
    }
    ck_assert_int_eq(check_orientation(kernel, ref, {on[0], on[1], on[2]}, "on an axis"), 0);
    ck_assert_int_eq(check_in_circle(kernel, ref, on, "on an axis"), 0);
    check_orientation(kernel, ref, {off[0], off[1], off[2]}, "just off an axis");
    check_in_circle(kernel, ref, off, "just off an axis");
    check_orientation(kernel, ref, {moved[3], moved[1], moved[2]}, "moved off an axis");
    check_in_circle(kernel, ref, moved, "moved off an axis");
  }
  // Most of the zeros above have points in different frames: the stage, not
  // the field, decides them.
  ck_assert_uint_gt(kernel.statistics()[predicates::Stage::structural], 40);
}
END_TEST

// 3. in_circle_perturbed: the symbolic perturbation.
static int permutation_sign(const std::array<int, 4> &perm) {
  int s = 1;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if (perm[i] > perm[j]) s = -s;
  return s;
}

START_TEST(in_circle_perturbed_policy) {
  const int g = kGenera[_i];
  surface::Surface M(g);
  Kernel kernel{M};
  Reference ref(kernel);
  const auto star = vertex_star(kernel);
  Rng rng(4000 + g);
  for (int trial = 0; trial < 120; ++trial) {
    Quad q = random_quad(rng, kernel, star, trial % 2 == 1);
    // Four points on one geodesic are left out: there every 3x3 minor
    // vanishes, so no first-order coefficient decides and the kernel throws
    // std::logic_error. This cannot happen for a face p, q, r of a
    // triangulation (never collinear), but the header's "never 0 for four
    // points of which one vertex occurs once" needs that precondition.
    if (q.kind == Kind::geodesic) q = circle_quad(rng, kernel, random_neighbour(rng, kernel));
    // Distinct vertex ids, or (every third trial) a pattern in which one
    // vertex occurs twice and the others once.
    std::array<uint32_t, 4> vertex;
    std::array<uint32_t, 4> pool{3, 17, 40, 1000};
    std::shuffle(pool.begin(), pool.end(), rng);
    vertex = pool;
    if (trial % 3 == 2) {
      const unsigned i = unsigned(rng() % 4), j = (i + 1 + unsigned(rng() % 3)) % 4;
      vertex[i] = vertex[j];  // may repeat any id, the maximum included
    }
    ck_assert_int_eq(kernel.in_circle(q.p[0], q.p[1], q.p[2], q.p[3]), 0);
    const int result = kernel.in_circle_perturbed(q.p, vertex);
    ck_assert_msg(result == 1 || result == -1, "in_circle_perturbed %d, %s", result, show(kernel, q.p).c_str());
    // The perturbed determinant is alternating in its rows (each row carries
    // its vertex's epsilon): every permutation multiplies by its sign, so
    // cyclic permutations of p, q, r change nothing.
    std::array<int, 4> perm{0, 1, 2, 3};
    do {
      std::array<TranslatedPoint, 4> pts;
      std::array<uint32_t, 4> ids;
      for (int i = 0; i < 4; ++i) pts[i] = q.p[perm[i]], ids[i] = vertex[perm[i]];
      const int r = kernel.in_circle_perturbed(pts, ids);
      ck_assert_msg(r == permutation_sign(perm) * result,
                    "in_circle_perturbed: permutation %d%d%d%d gives %d, identity %d, %s", perm[0], perm[1], perm[2],
                    perm[3], r, result, show(kernel, q.p).c_str());
    } while (std::next_permutation(perm.begin(), perm.end()));
    // The documented policy: p, q, r counterclockwise and the newest vertex
    // (occurring once) as s: s is inside.
    const int newest = int(std::max_element(vertex.begin(), vertex.end()) - vertex.begin());
    if (std::count(vertex.begin(), vertex.end(), vertex[newest]) == 1) {
      std::array<TranslatedPoint, 4> pts;
      std::array<uint32_t, 4> ids;
      for (int i = 0, j = 0; i < 4; ++i)
        if (i != newest) pts[j] = q.p[i], ids[j] = vertex[i], ++j;
      pts[3] = q.p[newest], ids[3] = vertex[newest];
      const int o = check_orientation(kernel, ref, {pts[0], pts[1], pts[2]}, "face", false);
      ck_assert_int_ne(o, 0);
      if (o < 0) std::swap(pts[0], pts[1]), std::swap(ids[0], ids[1]);
      ck_assert_int_eq(kernel.in_circle_perturbed(pts, ids), 1);
      // Cyclic permutations of the face change nothing.
      std::rotate(pts.begin(), pts.begin() + 1, pts.begin() + 3);
      std::rotate(ids.begin(), ids.begin() + 1, ids.begin() + 3);
      ck_assert_int_eq(kernel.in_circle_perturbed(pts, ids), 1);
    }
    // Off the circle, the perturbation changes nothing.
    int moved;
    const Quad m = perturbed(rng, q, moved);
    const int e = check_in_circle(kernel, ref, m.p, "perturbed, moved", false);
    ck_assert_int_ne(e, 0);
    ck_assert_int_eq(kernel.in_circle_perturbed(m.p, vertex), e);
  }
  // Random non-degenerate quadruples: the same as in_circle.
  const group::GeneratorSet<double> gens(kernel.surface().presentation());
  for (int trial = 0; trial < 500; ++trial) {
    const std::array<TranslatedPoint, 4> t{random_point(rng, kernel, gens), random_point(rng, kernel, gens),
                                           random_point(rng, kernel, gens), random_point(rng, kernel, gens)};
    ck_assert_int_eq(kernel.in_circle_perturbed(t, {1, 2, 3, 4}), kernel.in_circle(t[0], t[1], t[2], t[3]));
  }
}
END_TEST

// 4. The canonical representative.
namespace {

// Checks R against the half-open domain: h(z) in the closed F_g, with the
// reported sides exactly zero (reference signs, independent of the kernel).
void check_in_domain(Kernel &kernel, Reference &ref, double x, double y, const predicates::Representative &R) {
  const int n = kernel.surface().presentation().letter_count(), half = n / 2;
  const TranslatedPoint pt{x, y, R.translation};
  std::vector<int> on;
  for (int k = 0; k < n; ++k) {
    const int s = ref.beyond_side(pt, k);
    ck_assert_msg(s <= 0, "representative of (%a, %a) beyond side %d: %s", x, y, k, show(kernel, pt).c_str());
    ck_assert_int_eq(kernel.beyond_side(pt, k), s);
    if (s == 0) on.push_back(k);
  }
  switch (R.where) {
    case predicates::Representative::interior: ck_assert_uint_eq(on.size(), 0); break;
    case predicates::Representative::side:
      ck_assert_uint_eq(on.size(), 1);
      ck_assert_int_eq(on[0], R.side_index);
      ck_assert_int_lt(R.side_index, half);
      break;
    case predicates::Representative::vertex:
      ck_assert_uint_eq(on.size(), 2);
      ck_assert_int_eq(on[0], 0);
      ck_assert_int_eq(on[1], 1);
      break;
  }
}

double distance(const Complex<double> &a, const Complex<double> &b) { return std::hypot(a.re - b.re, a.im - b.im); }

}  // namespace

START_TEST(representative_is_canonical) {
  const auto t0 = std::chrono::steady_clock::now();
  long images_compared = 0, paired = 0;
  for (int g = 2; g <= 8; ++g) {
    surface::Surface M(g);
    Kernel kernel{M};
    Reference ref(kernel);
    const Presentation &p = kernel.surface().presentation();
    const group::GeneratorSet<Mid> mid(p);
    Rng rng(5000 + g);
    ck_assert_int_eq(predicates::representative(kernel, 0, 0).translation, 0);
    ck_assert(predicates::representative(kernel, 0, 0).where == predicates::Representative::interior);
    const int points = 160;
    for (int i = 0; i < points; ++i) {
      // Uniform in |z| < 0.999, or at 1 - 10^-e along a random direction.
      Complex<double> z;
      if (i % 4 == 0 || i % 4 == 1) {
        z = random_in_disk(rng, 0.999);
      } else if (i % 4 == 2) {
        // Within about 1e-13 of a side of F_g (either way): its images'
        // representatives may land on the paired side.
        const auto m = surface::polygon_side_midpoint<double>(g, int(rng() % unsigned(4 * g)));
        const double a = std::uniform_real_distribution<double>(-0.2, 0.2)(rng) / g;
        const double r = 1 + std::uniform_real_distribution<double>(-1e-13, 1e-13)(rng);
        const Complex<double> rotated{m.re * std::cos(a) - m.im * std::sin(a), m.re * std::sin(a) + m.im * std::cos(a)};
        // Along the side (approximately): the side bends away from 0, so
        // move outwards by the side's sagitta at that angle.
        const double A = 1 / std::tan(M_PI / (4 * g)), c = A / std::sqrt(A * A - 1);  // centre of the side's circle
        const double rho = std::sqrt(c * c - 1);
        // |z| on the side circle at angle a from the midpoint direction.
        const double t = c * std::cos(a) - std::sqrt(rho * rho - c * c * std::sin(a) * std::sin(a));
        const double scale = r * t / std::hypot(m.re, m.im);
        z = {rotated.re * scale, rotated.im * scale};
      } else {
        static const double gaps[] = {1e-3, 1e-6, 1e-9, 1e-12, 1e-15};
        const double r = 1 - gaps[(i / 4) % 5];
        const double angle = std::uniform_real_distribution<double>(0, 2 * M_PI)(rng);
        z = {r * std::cos(angle), r * std::sin(angle)};
        if (!exact::inside_unit_disk(z.re, z.im)) continue;
      }
      const auto R = predicates::representative(kernel, z.re, z.im);
      check_in_domain(kernel, ref, z.re, z.im, R);
      // A point in the interior of F_g is its own representative.
      bool inside = true;
      for (int k = 0; k < p.letter_count() && inside; ++k) inside = ref.beyond_side({z.re, z.im, 0}, k) < 0;
      ck_assert_int_eq(inside, R.translation == 0 && R.where == predicates::Representative::interior);
      const Complex<double> P = ref.image(R.translation, z.re, z.im);
      // Images of z under random words: the same representative point up to
      // the side pairing. The image is rounded to doubles, which moves it by
      // up to 2u / (1 - |w|) hyperbolically; keep 1 - |w| >= 1e-6 so that this
      // stays far below the tolerance.
      for (int trial = 0; trial < 3; ++trial) {
        Word w(std::uniform_int_distribution<int>(1, 8)(rng));
        for (Letter &k : w) k = Letter(rng() % unsigned(p.letter_count()));
        const auto m = mid.moebius(w);
        const Complex<Mid> image = m.apply(Complex<Mid>{Mid(z.re), Mid(z.im)});
        const Complex<double> wz{static_cast<double>(image.re), static_cast<double>(image.im)};
        if (!(std::hypot(wz.re, wz.im) < 1 - 1e-6)) continue;
        const auto R2 = predicates::representative(kernel, wz.re, wz.im);
        check_in_domain(kernel, ref, wz.re, wz.im, R2);
        const Complex<double> P2 = ref.image(R2.translation, wz.re, wz.im);
        ++images_compared;
        if (distance(P, P2) < 1e-9) continue;
        // Otherwise both are near the boundary of F_g, related by a neighbour.
        ++paired;
        double best = INFINITY;
        for (TranslationId id = 1; std::size_t(id) < kernel.surface().table().neighbour_count(); ++id)
          best = std::min(best, distance(ref.image(id, P.re, P.im), P2));
        ck_assert_msg(best < 1e-9, "g=%d: representatives %.17g%+.17gi of (%a, %a) and %.17g%+.17gi of (%a, %a) differ",
                      g, P.re, P.im, z.re, z.im, P2.re, P2.im, wz.re, wz.im);
      }
    }
    // Rounded vertices and midpoints: near v_0's cycle or the midpoint's
    // pair. (No double point lies exactly on a side line, see exact_zeros,
    // so where == side / vertex cannot be reached from doubles.)
    for (int k = 0; k < p.letter_count(); ++k) {
      const auto v = surface::polygon_vertex<double>(g, k);
      const auto Rv = predicates::representative(kernel, v.re, v.im);
      check_in_domain(kernel, ref, v.re, v.im, Rv);
      const auto Pv = ref.image(Rv.translation, v.re, v.im);
      double best = INFINITY;
      for (int j = 0; j < p.letter_count(); ++j)
        best = std::min(best, distance(Pv, surface::polygon_vertex<double>(g, j)));
      ck_assert_msg(best < 1e-12, "g=%d: rounded v_%d maps %g from every vertex", g, k, best);
      const auto m = surface::polygon_side_midpoint<double>(g, k);
      const auto Rm = predicates::representative(kernel, m.re, m.im);
      check_in_domain(kernel, ref, m.re, m.im, Rm);
      const auto Pm = ref.image(Rm.translation, m.re, m.im);
      const double to_m = distance(Pm, m), to_pair = distance(Pm, surface::polygon_side_midpoint<double>(g, p.inverse(k)));
      ck_assert_msg(std::min(to_m, to_pair) < 1e-12, "g=%d: rounded m_%d maps to %.17g%+.17gi", g, k, Pm.re, Pm.im);
      // Off F: m_k stays when it rounded inside, else it moves to m_{k+2g}.
      ck_assert_int_eq(Rm.translation == 0, to_m < 1e-12);
    }
  }
  ck_assert_int_gt(images_compared, 300);
  std::printf("representative: %ld images compared (%ld via the side pairing) in %.1f s\n", images_compared, paired,
              seconds_since(t0));
}
END_TEST

// 5. The filter decides almost every non-degenerate input.
START_TEST(filter_decides_random_inputs) {
  for (const int g : {2, 4, 8}) {
    surface::Surface M(g);
    Kernel kernel{M};
    const group::GeneratorSet<double> gens{Presentation(g)};
    Rng rng(6000 + g);
    const int calls = 20000;
    kernel.reset_statistics();
    for (int i = 0; i < calls; ++i)
      kernel.orientation(random_point(rng, kernel, gens), random_point(rng, kernel, gens),
                         random_point(rng, kernel, gens));
    const auto o = kernel.statistics();
    kernel.reset_statistics();
    for (int i = 0; i < calls; ++i)
      kernel.in_circle(random_point(rng, kernel, gens), random_point(rng, kernel, gens),
                       random_point(rng, kernel, gens), random_point(rng, kernel, gens));
    const auto c = kernel.statistics();
    kernel.reset_statistics();
    for (int i = 0; i < calls; ++i) kernel.beyond_side(random_point(rng, kernel, gens), int(rng() % unsigned(4 * g)));
    const auto b = kernel.statistics();
    const double ro = double(o.past_filters()) / double(o.calls());
    const double rc = double(c.past_filters()) / double(c.calls());
    const double rb = double(b.past_filters()) / double(b.calls());
    std::printf("filter g=%d: exact fraction orientation %.5f (%lu/%d), in_circle %.5f (%lu/%d), beyond_side %.5f (%lu/%d)\n",
                g, ro, o.past_filters(), calls, rc, c.past_filters(), calls, rb, b.past_filters(), calls);
    ck_assert_uint_eq(o.calls(), calls);
    ck_assert_uint_eq(c.calls(), calls);
    ck_assert_msg(ro < 0.001, "g=%d: orientation exact fraction %g", g, ro);
    ck_assert_msg(rc < 0.001, "g=%d: in_circle exact fraction %g", g, rc);
    ck_assert_msg(rb < 0.001, "g=%d: beyond_side exact fraction %g", g, rb);
  }
}
END_TEST

// 6. The disk filters (untranslated points: the common case of a
// triangulation inside F_g) on their own degenerate inputs, at the scales a
// triangulation of 10^3..10^9 points meets: the corners of a rectangle are
// cocircular (and exact in doubles for dyadic centre and half-sides), points
// on a diameter are on a geodesic. Moved by a few ulps, or by 2^e ulps so
// that some land near the bound, every decision must match the reference.
START_TEST(disk_filter_near_degenerate) {
  surface::Surface M(2);
  Kernel kernel{M};
  Reference ref(kernel);
  Rng rng(7000);
  std::uniform_real_distribution<double> unit(-1, 1);
  kernel.reset_statistics();
  int decided_by_filter = 0, sets = 0;
  for (int i = 0; i < 3000; ++i) {
    // A dyadic centre anywhere in the disk, up to 1 - 2^-20 from 0.
    const double radius = i % 3 == 0 ? 1 - std::ldexp(1.0, -int(rng() % 20) - 1) : std::abs(unit(rng));
    const double angle = unit(rng) * M_PI;
    const double cx = std::ldexp(std::round(std::ldexp(radius * std::cos(angle), 40)), -40);
    const double cy = std::ldexp(std::round(std::ldexp(radius * std::sin(angle), 40)), -40);
    const int scale = 2 + int(rng() % 40);  // half-sides near 2^-scale
    const double a = std::ldexp(1 + double(rng() % 255) / 256, -scale), b = std::ldexp(1 + double(rng() % 255) / 256, -scale);
    if (std::hypot(std::abs(cx) + a, std::abs(cy) + b) >= 1) continue;
    ++sets;
    std::array<TranslatedPoint, 4> t{TranslatedPoint{cx + a, cy + b, 0}, TranslatedPoint{cx - a, cy + b, 0},
                                     TranslatedPoint{cx - a, cy - b, 0}, TranslatedPoint{cx + a, cy - b, 0}};
    ck_assert_int_eq(check_in_circle(kernel, ref, t, "rectangle", false), 0);
    const int moved = int(rng() % 4);
    const long steps = i % 2 ? long(rng() % 9) - 4 : (rng() % 2 ? 1L : -1L) << (rng() % 30);
    if (steps == 0) continue;
    double &c = rng() % 2 ? t[moved].x : t[moved].y;
    c = std::abs(steps) <= 4 ? nudge(c, int(steps)) : shift(c, steps);
    for (int r = 0; r < 4; ++r) {
      const auto before = kernel.statistics().past_filters();
      ck_assert_int_ne(check_in_circle(kernel, ref, t, "rectangle, moved", false), 0);
      decided_by_filter += kernel.statistics().past_filters() == before;
      std::rotate(t.begin(), t.begin() + 1, t.end());
    }
    // Three points on a diameter, one moved off it.
    const double d = std::ldexp(1.0, -scale), s = radius * 0.7;
    const bool diagonal = rng() % 2;
    std::array<TranslatedPoint, 3> l{TranslatedPoint{s - d, diagonal ? s - d : 0, 0},
                                     TranslatedPoint{s, diagonal ? s : 0, 0},
                                     TranslatedPoint{s + 2 * d, diagonal ? s + 2 * d : 0, 0}};
    if (std::hypot(l[2].x, l[2].y) >= 1) continue;
    ck_assert_int_eq(check_orientation(kernel, ref, l, "diameter", false), 0);
    l[moved % 3].y = std::abs(steps) <= 4 ? nudge(l[moved % 3].y, int(steps)) : shift(l[moved % 3].y, steps);
    for (int r = 0; r < 3; ++r) {
      ck_assert_int_ne(check_orientation(kernel, ref, l, "diameter, moved", false), 0);
      std::rotate(l.begin(), l.begin() + 1, l.end());
    }
  }
  std::printf("disk filters: %d sets, %d moved in-circle tests decided by the double filter\n", sets, decided_by_filter);
  ck_assert_int_gt(sets, 2000);
  ck_assert_int_gt(decided_by_filter, 100);  // the filter is exercised, not bypassed
}
END_TEST

int main(void) {
  return run_suite("predicates", 600, [](TCase *tc) {
    tcase_add_test(tc, sign_conventions);
    tcase_add_loop_test(tc, random_configurations_agree_with_reference, 0, 3);
    tcase_add_loop_test(tc, near_degenerate_configurations_agree_with_reference, 0, 3);
    tcase_add_loop_test(tc, exact_zeros, 0, 3);
    tcase_add_loop_test(tc, structural_zeros, 0, 3);
    tcase_add_loop_test(tc, in_circle_perturbed_policy, 0, 3);
    tcase_add_test(tc, representative_is_canonical);
    tcase_add_test(tc, filter_decides_random_inputs);
    tcase_add_test(tc, disk_filter_near_degenerate);
  });
}
