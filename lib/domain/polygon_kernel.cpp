#include "domain/polygon_kernel.hpp"

#include <algorithm>
#include <cstring>
#include <functional>
#include <initializer_list>
#include <stdexcept>

#include "exact/perturbation.hpp"

namespace hdt::domain {

namespace {

constexpr int kUndecided = 2;

int sign_of(const ErrorDouble &x) {
  const int s = certain_sign(x);
  return s ? s : kUndecided;
}

// A ball's sign only when it excludes 0 (a NaN or infinite ball never does).
int sign_of(const RealBall &x) {
  if (arb_is_positive(x.get())) return 1;
  if (arb_is_negative(x.get())) return -1;
  return kUndecided;
}
int sign_of(const Number &x) { return x.sgn(); }

// The formulas, once for every stage: T is ErrorDouble, RealBall or Number,
// a row any array of four T (only the first three columns, or all four, read).
template <class T, class Row>
T det3(const Row &a, const Row &b, const Row &c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

template <class T>
using Vec3 = std::array<T, 3>;

template <class T, class A, class B>
T dot(const A &a, const B &b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

template <class T>
Vec3<T> cross(const Vec3<T> &a, const Vec3<T> &b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// R_o3 R - R_3 R_o = (R_3 R_o3) (N - N_o, 0): the row of N relative to N_o,
// a positive multiple. The determinants below subtract such multiples of
// the first row from the others, which leaves them unchanged, and scale rows
// by positive numbers: the same signs, and far sharper balls for close
// points (the differences are computed before the products that would bury
// them).
template <class T, class Row>
Vec3<T> relative(const Row &r, const Row &o) {
  return {r[0] * o[3] - o[0] * r[3], r[1] * o[3] - o[1] * r[3], r[2] * o[3] - o[2] * r[3]};
}

// det[N_p; N_q; N_r], up to a positive factor: det[R_p; R_q; R_r] =
// det[R_p; D_q; D_r] / R_p3^2.
template <class T, class Row>
T orientation_value(const Row &p, const Row &q, const Row &r) {
  return dot<T>(p, cross<T>(relative<T>(q, p), relative<T>(r, p)));
}

// det[N_i 1], up to a positive factor: with rows 1..3 replaced by D_i and
// column 3 of them then 0, det[R_i] = -det[D_q; D_r; D_s] / R_p3^2, and
// -(D_q x D_r) = D_r x D_q.
template <class T, class Row>
T in_circle_value(const Row &p, const Row &q, const Row &r, const Row &s) {
  return dot<T>(cross<T>(relative<T>(r, p), relative<T>(q, p)), relative<T>(s, p));
}

// [p, a] = p0 a0 - p1 a1 - p2 a2: cosh d = [R_p, R_a] / (R_p3 R_a3).
template <class T, class Row>
T lorentz(const Row &u, const Row &v) {
  return u[0] * v[0] - (u[1] * v[1] + u[2] * v[2]);
}

template <class T, class Row>
T distance_difference(const Row &p, const Row &a, const Row &b) {
  return lorentz<T>(p, a) * b[3] - lorentz<T>(p, b) * a[3];
}

// c3^2 - k [m, m] for the plane c through [R_p; D_q; D_r] (R_p3^2 times that
// through the rows, so the sign is unchanged): with X = D_q x D_r and D's
// column 3 zero, (c0, c1, c2) = R_p3 (X0, X1, X2) and c3 = -R_p . X.
template <class T, class Row>
T circumdisk_excess(const Row &p, const Row &q, const Row &r, const T &k) {
  const Vec3<T> X = cross<T>(relative<T>(q, p), relative<T>(r, p));
  const T c3 = dot<T>(p, X), m = X[0] * X[0] - (X[1] * X[1] + X[2] * X[2]);
  return c3 * c3 - k * (p[3] * p[3]) * m;
}

// One frame: every predicate but beyond_side is invariant under an isometry
// applied to all its points (det L = 1 on the hyperboloid, distances and
// circles kept), so points of one element t are read as z untranslated:
// every stage then runs on rationals and small numbers.
bool one_frame(std::initializer_list<const PolygonPoint *> points) {
  const ElementId t = (*points.begin())->t;
  if (t == kIdentityId) return false;
  for (const PolygonPoint *p : points)
    if (p->t != t) return false;
  return true;
}

PolygonPoint untranslated(const PolygonPoint &p) { return {p.x, p.y, kIdentityId}; }

}  // namespace

PolygonKernel::PolygonKernel(const FundamentalPolygon &polygon, ElementTable &table)
    : polygon_(polygon), table_(table) {
  for (int k = 0; k < polygon.side_count(); ++k) {
    const ExactRow a = exact_row(polygon.vertex(k)), b = exact_row(polygon.vertex(k + 1));
    const std::array<Number, 3> n{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    side_normal_.push_back(n);
    side_normal_ball_.push_back({ball_of(n[0]), ball_of(n[1]), ball_of(n[2])});
    const auto &nb = side_normal_ball_.back();
    side_normal_double_.push_back({error_double(nb[0]), error_double(nb[1]), error_double(nb[2])});
  }
}

// From the table's ball matrix, once per element.
const PolygonKernel::DoubleIsometry &PolygonKernel::double_isometry(ElementId t) {
  while (doubles_.size() <= t) {
    const BallIsometry &U = table_.ball(ElementId(doubles_.size()));
    doubles_.push_back({error_double(real(U.a)), error_double(imag(U.a)), error_double(real(U.b)),
                        error_double(imag(U.b))});
  }
  return doubles_[t];
}

PolygonKernel::DoubleRow PolygonKernel::double_row(const PolygonPoint &p) {
  std::uint64_t bx, by;
  std::memcpy(&bx, &p.x, sizeof bx);
  std::memcpy(&by, &p.y, sizeof by);
  const std::uint64_t h = (bx * 0x9E3779B97F4A7C15ull) ^ ((by + std::uint64_t(p.t) * 0xC2B2AE3D27D4EB4Full) * 0x165667B19E3779F9ull);
  RowSlot &slot = row_cache_[std::size_t(h >> (64 - kRowCacheBits))];
  if (slot.x != p.x || slot.y != p.y || slot.t != p.t) {
    slot.row = computed_double_row(p);
    slot.x = p.x, slot.y = p.y, slot.t = p.t;
  }
  return slot.row;
}

// As ball_row, written out in real and imaginary parts; z is exact.
PolygonKernel::DoubleRow PolygonKernel::computed_double_row(const PolygonPoint &p) {
  const DoubleIsometry &U = double_isometry(p.t);
  const ErrorDouble x(p.x), y(p.y);
  const ErrorDouble nr = U.ar * x - U.ai * y + U.br, ni = U.ar * y + U.ai * x + U.bi;
  const ErrorDouble dr = U.br * x + U.bi * y + U.ar, di = U.br * y - U.bi * x - U.ai;
  const ErrorDouble re = nr * dr + ni * di, im = ni * dr - nr * di;
  return {nr * nr + ni * ni + (dr * dr + di * di), re + re, im + im, ErrorDouble(1.0) - (x * x + y * y)};
}

// n = a z + b, d = conj(b) z + conj(a) for t's SU(1,1) matrix (either sign:
// the row is quadratic in it), and |d|^2 - |n|^2 = 1 - |z|^2 for it exactly.
PolygonKernel::BallRow PolygonKernel::ball_row(const PolygonPoint &p) const {
  const BallIsometry &U = table_.ball(p.t);
  const ComplexBall z = complex_ball(p.x, p.y);
  const ComplexBall n = U.a * z + U.b, d = conj(U.b) * z + conj(U.a);
  const ComplexBall nd = n * conj(d);
  const RealBall re = real(nd), im = imag(nd);
  return {norm2(n) + norm2(d), re + re, im + im, RealBall(1.0) - norm2(z)};
}

// The canonical matrix has top-left entry 1: n = z + b, d = c z + d'.
PolygonKernel::ExactRow PolygonKernel::exact_row(const PolygonPoint &p) const {
  const Complex z = polygon_.exact_point(p.x, p.y);
  const Moebius &m = table_.element(p.t).matrix();
  const Complex n = z + m.b, d = m.c * z + m.d;
  const Complex nd = n * conj(d);
  const Number nn = norm2(n), dd = norm2(d);
  return {nn + dd, nd.re + nd.re, nd.im + nd.im, dd - nn};
}

PolygonKernel::ExactRow PolygonKernel::exact_row(const Complex &w) const {
  const Number one(w.re.parent(), 1), ww = norm2(w);
  return {one + ww, w.re + w.re, w.im + w.im, one - ww};
}

template <class DoubleSign, class BallSign, class ExactSign>
int PolygonKernel::staged(PolygonPredicate predicate, DoubleSign dbl, BallSign ball, ExactSign exact) {
  if (first_ <= PolygonStage::double_filter)
    if (const int s = dbl(); s != kUndecided) return count(predicate, PolygonStage::double_filter, s);
  if (first_ <= PolygonStage::ball)
    if (const int s = ball(); s != kUndecided) return count(predicate, PolygonStage::ball, s);
  return count(predicate, PolygonStage::exact, exact());
}

int PolygonKernel::orientation(const PolygonPoint &p, const PolygonPoint &q, const PolygonPoint &r) {
  if (one_frame({&p, &q, &r})) return orientation(untranslated(p), untranslated(q), untranslated(r));
  return staged(
      PolygonPredicate::orientation,
      [&] { return sign_of(orientation_value<ErrorDouble>(double_row(p), double_row(q), double_row(r))); },
      [&] { return sign_of(orientation_value<RealBall>(ball_row(p), ball_row(q), ball_row(r))); },
      [&] { return sign_of(orientation_value<Number>(exact_row(p), exact_row(q), exact_row(r))); });
}

int PolygonKernel::in_circle(const PolygonPoint &p, const PolygonPoint &q, const PolygonPoint &r,
                             const PolygonPoint &s) {
  if (one_frame({&p, &q, &r, &s})) return in_circle(untranslated(p), untranslated(q), untranslated(r), untranslated(s));
  return staged(
      PolygonPredicate::in_circle,
      [&] { return sign_of(in_circle_value<ErrorDouble>(double_row(p), double_row(q), double_row(r), double_row(s))); },
      [&] { return sign_of(in_circle_value<RealBall>(ball_row(p), ball_row(q), ball_row(r), ball_row(s))); },
      [&] { return sign_of(in_circle_value<Number>(exact_row(p), exact_row(q), exact_row(r), exact_row(s))); });
}

// The floating stages decide only non-zero signs; a zero is the exact
// stage's, whose rows the perturbation then reuses.
int PolygonKernel::in_circle_perturbed(const std::array<PolygonPoint, 4> &pt,
                                       const std::array<std::uint32_t, 4> &vertex) {
  if (one_frame({&pt[0], &pt[1], &pt[2], &pt[3]}))
    return in_circle_perturbed({untranslated(pt[0]), untranslated(pt[1]), untranslated(pt[2]), untranslated(pt[3])},
                               vertex);
  constexpr PolygonPredicate predicate = PolygonPredicate::in_circle_perturbed;
  if (first_ <= PolygonStage::double_filter)
    if (const int s = sign_of(in_circle_value<ErrorDouble>(double_row(pt[0]), double_row(pt[1]), double_row(pt[2]),
                                                           double_row(pt[3])));
        s != kUndecided)
      return count(predicate, PolygonStage::double_filter, s);
  if (first_ <= PolygonStage::ball)
    if (const int s = sign_of(in_circle_value<RealBall>(ball_row(pt[0]), ball_row(pt[1]), ball_row(pt[2]),
                                                        ball_row(pt[3])));
        s != kUndecided)
      return count(predicate, PolygonStage::ball, s);
  const std::array<ExactRow, 4> rows{exact_row(pt[0]), exact_row(pt[1]), exact_row(pt[2]), exact_row(pt[3])};
  if (const int s = count(predicate, PolygonStage::exact, sign_of(in_circle_value<Number>(rows[0], rows[1], rows[2], rows[3])));
      s != 0)
    return s;
  return perturbed_tie(pt, vertex, rows);
}
// The coefficients of eps_v, largest v first (exact/perturbation.hpp).
int PolygonKernel::perturbed_tie(const std::array<PolygonPoint, 4> &pt, const std::array<std::uint32_t, 4> &vertex,
                                 const std::array<ExactRow, 4> &rows) {
  return exact::perturbed_sign(
      vertex, [&](int i, int j, int k) { return orientation(pt[i], pt[j], pt[k]); },
      [&](std::uint32_t v) {
        Number coefficient(rows[0][0].parent(), 0);
        for (int r = 0; r < 4; ++r) {
          if (vertex[r] != v) continue;
          std::array<const ExactRow *, 3> o;
          for (int i = 0, j = 0; i < 4; ++i)
            if (i != r) o[j++] = &rows[i];
          const Number term = rows[r][3] * det3<Number>(*o[0], *o[1], *o[2]);
          coefficient = r % 2 == 1 ? coefficient + term : coefficient - term;
        }
        return sign_of(coefficient);
      },
      "PolygonKernel::in_circle_perturbed");
}

int PolygonKernel::compare_distance(const PolygonPoint &p, const PolygonPoint &a, const PolygonPoint &b) {
  if (one_frame({&p, &a, &b})) return compare_distance(untranslated(p), untranslated(a), untranslated(b));
  return staged(
      PolygonPredicate::compare_distance,
      [&] { return sign_of(distance_difference<ErrorDouble>(double_row(p), double_row(a), double_row(b))); },
      [&] { return sign_of(distance_difference<RealBall>(ball_row(p), ball_row(a), ball_row(b))); },
      [&] { return sign_of(distance_difference<Number>(exact_row(p), exact_row(a), exact_row(b))); });
}

// One element: t is injective, so the doubles decide. Else the floating
// stages may find the images certainly apart (n_p d_q != n_q d_p, or balls
// that do not overlap); equality needs K(i): n_p d_q = n_q d_p.
bool PolygonKernel::same_point(const PolygonPoint &p, const PolygonPoint &q) {
  constexpr PolygonPredicate predicate = PolygonPredicate::same_point;
  if (p.t == q.t) return count(predicate, PolygonStage::structural, p.x == q.x && p.y == q.y);
  if (first_ <= PolygonStage::double_filter) {
    const DoubleIsometry &f = double_isometry(p.t), &g = double_isometry(q.t);
    auto image = [](const DoubleIsometry &U, const PolygonPoint &z) {  // n and d, as in double_row
      const ErrorDouble x(z.x), y(z.y);
      return std::array<ErrorDouble, 4>{U.ar * x - U.ai * y + U.br, U.ar * y + U.ai * x + U.bi,
                                        U.br * x + U.bi * y + U.ar, U.br * y - U.bi * x - U.ai};
    };
    const auto P = image(f, p), Q = image(g, q);
    const ErrorDouble re = (P[0] * Q[2] - P[1] * Q[3]) - (Q[0] * P[2] - Q[1] * P[3]);
    const ErrorDouble im = (P[0] * Q[3] + P[1] * Q[2]) - (Q[0] * P[3] + Q[1] * P[2]);
    if (certain_sign(re) || certain_sign(im)) return count(predicate, PolygonStage::double_filter, false);
  }
  if (first_ <= PolygonStage::ball) {
    const ComplexBall wp = table_.ball(p.t).apply(complex_ball(p.x, p.y));
    const ComplexBall wq = table_.ball(q.t).apply(complex_ball(q.x, q.y));
    if (!acb_overlaps(wp.get(), wq.get())) return count(predicate, PolygonStage::ball, false);
  }
  const Complex zp = polygon_.exact_point(p.x, p.y), zq = polygon_.exact_point(q.x, q.y);
  const Moebius &f = table_.element(p.t).matrix(), &g = table_.element(q.t).matrix();
  const Complex np = zp + f.b, dp = f.c * zp + f.d, nq = zq + g.b, dq = g.c * zq + g.d;
  return count(predicate, PolygonStage::exact, np * dq == nq * dp);
}

int PolygonKernel::beyond_side(const PolygonPoint &p, int side) {
  const int k = ((side % polygon_.side_count()) + polygon_.side_count()) % polygon_.side_count();
  return -staged(
      PolygonPredicate::beyond_side,
      [&] { return sign_of(dot<ErrorDouble>(side_normal_double_[k], double_row(p))); },
      [&] { return sign_of(dot<RealBall>(side_normal_ball_[k], ball_row(p))); },
      [&] { return sign_of(dot<Number>(side_normal_[k], exact_row(p))); });
}

int PolygonKernel::large_circumdisk(const PolygonPoint &p, const PolygonPoint &q, const PolygonPoint &r,
                                    const Number &cosh2_half_diameter) {
  if (one_frame({&p, &q, &r}))
    return large_circumdisk(untranslated(p), untranslated(q), untranslated(r), cosh2_half_diameter);
  set_threshold(cosh2_half_diameter);
  const int s = staged(
      PolygonPredicate::large_circumdisk,
      [&] {
        return sign_of(circumdisk_excess<ErrorDouble>(double_row(p), double_row(q), double_row(r), threshold_double_));
      },
      [&] { return sign_of(circumdisk_excess<RealBall>(ball_row(p), ball_row(q), ball_row(r), threshold_ball_)); },
      [&] { return sign_of(circumdisk_excess<Number>(exact_row(p), exact_row(q), exact_row(r), *threshold_)); });
  return s >= 0 ? 1 : -1;
}

// The threshold in the polygon's field (a rational one is moved there, so
// that every product has one parent), its ball and double, kept for the
// next call.
void PolygonKernel::set_threshold(const Number &k) {
  if (threshold_given_ && *threshold_given_ == k) return;
  const auto &parent = polygon_.vertex(0).re.parent();
  threshold_given_ = k;
  threshold_ = k.is_rational() ? Number(parent, static_cast<mpq_class>(k)) : k;
  threshold_ball_ = ball_of(*threshold_);
  threshold_double_ = error_double(threshold_ball_);
}

}  // namespace hdt::domain
