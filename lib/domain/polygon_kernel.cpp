#include "domain/polygon_kernel.hpp"

#include <algorithm>
#include <functional>
#include <stdexcept>

namespace hdt::domain {

namespace {

constexpr int kUndecided = 2;

// A ball's sign only when it excludes 0 (a NaN or infinite ball never does).
int sign_of(const RealBall &x) {
  if (arb_is_positive(x.get())) return 1;
  if (arb_is_negative(x.get())) return -1;
  return kUndecided;
}
int sign_of(const Number &x) { return x.sgn(); }

// The formulas, once for balls and once for K: T is RealBall or Number, a
// row any array of four T (only the columns named are read).
template <class T, class Row>
T det3(const Row &a, const Row &b, const Row &c, const std::array<int, 3> &col = {0, 1, 2}) {
  const int i = col[0], j = col[1], k = col[2];
  return a[i] * (b[j] * c[k] - b[k] * c[j]) - a[j] * (b[i] * c[k] - b[k] * c[i]) + a[k] * (b[i] * c[j] - b[j] * c[i]);
}

// Laplace expansion along rows 0 and 1 (as predicates/stage_exact.cpp).
template <class T, class Row>
T det4(const std::array<Row, 4> &r) {
  auto minor = [&](int row, int j, int k) { return r[row][j] * r[row + 1][k] - r[row][k] * r[row + 1][j]; };
  static constexpr int pairs[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2}, {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  T sum = minor(0, 0, 1) * minor(2, 2, 3);  // the first pair, odd: added
  for (int q = 1; q < 6; ++q) {
    const auto &c = pairs[q];
    const T term = minor(0, c[0], c[1]) * minor(2, c[2], c[3]);
    sum = (c[0] + c[1]) % 2 == 1 ? sum + term : sum - term;
  }
  return sum;
}

// [u, v] = u0 v0 - u1 v1 - u2 v2: cosh d = [R_u, R_v] / (R_u3 R_v3).
template <class T, class Row>
T lorentz(const Row &u, const Row &v) {
  return u[0] * v[0] - (u[1] * v[1] + u[2] * v[2]);
}

template <class T, class Row>
T distance_difference(const Row &p, const Row &a, const Row &b) {
  return lorentz<T>(p, a) * b[3] - lorentz<T>(p, b) * a[3];
}

// c3^2 - k [m, m] for the plane c through the three rows: c_j is (-1)^j the
// minor without column j.
template <class T, class Row>
T circumdisk_excess(const Row &p, const Row &q, const Row &r, const T &k) {
  const T c0 = det3<T>(p, q, r, {1, 2, 3}), c1 = det3<T>(p, q, r, {0, 2, 3});
  const T c2 = det3<T>(p, q, r, {0, 1, 3}), c3 = det3<T>(p, q, r, {0, 1, 2});
  // The signs of c1 and c3 do not matter: each enters squared.
  return c3 * c3 - k * (c0 * c0 - (c1 * c1 + c2 * c2));
}

template <class T, class Normal, class Row>
T side_value(const Normal &n, const Row &r) {
  return n[0] * r[0] + n[1] * r[1] + n[2] * r[2];
}

}  // namespace

PolygonKernel::PolygonKernel(const FundamentalPolygon &polygon, ElementTable &table)
    : polygon_(polygon), table_(table) {
  for (int k = 0; k < polygon.side_count(); ++k) {
    const ExactRow a = exact_row(polygon.vertex(k)), b = exact_row(polygon.vertex(k + 1));
    const std::array<Number, 3> n{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    side_normal_.push_back(n);
    side_normal_ball_.push_back({ball_of(n[0]), ball_of(n[1]), ball_of(n[2])});
  }
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

template <class BallSign, class ExactSign>
int PolygonKernel::staged(PolygonPredicate predicate, BallSign ball, ExactSign exact) {
  if (!exact_only_)
    if (const int s = ball(); s != kUndecided) return count(predicate, PolygonStage::ball, s);
  return count(predicate, PolygonStage::exact, exact());
}

int PolygonKernel::orientation(const PolygonPoint &p, const PolygonPoint &q, const PolygonPoint &r) {
  return staged(
      PolygonPredicate::orientation, [&] { return sign_of(det3<RealBall>(ball_row(p), ball_row(q), ball_row(r))); },
      [&] { return sign_of(det3<Number>(exact_row(p), exact_row(q), exact_row(r))); });
}

int PolygonKernel::in_circle(const PolygonPoint &p, const PolygonPoint &q, const PolygonPoint &r,
                             const PolygonPoint &s) {
  return staged(
      PolygonPredicate::in_circle,
      [&] { return sign_of(det4<RealBall>(std::array<BallRow, 4>{ball_row(p), ball_row(q), ball_row(r), ball_row(s)})); },
      [&] {
        return sign_of(det4<Number>(std::array<ExactRow, 4>{exact_row(p), exact_row(q), exact_row(r), exact_row(s)}));
      });
}

int PolygonKernel::in_circle_perturbed(const std::array<PolygonPoint, 4> &pt,
                                       const std::array<std::uint32_t, 4> &vertex) {
  constexpr PolygonPredicate predicate = PolygonPredicate::in_circle_perturbed;
  if (!exact_only_) {
    const std::array<BallRow, 4> balls{ball_row(pt[0]), ball_row(pt[1]), ball_row(pt[2]), ball_row(pt[3])};
    if (const int s = sign_of(det4<RealBall>(balls)); s != kUndecided) return count(predicate, PolygonStage::ball, s);
  }
  // The exact rows, kept for a tie's perturbation coefficients.
  const std::array<ExactRow, 4> rows{exact_row(pt[0]), exact_row(pt[1]), exact_row(pt[2]), exact_row(pt[3])};
  if (const int s = count(predicate, PolygonStage::exact, sign_of(det4<Number>(rows))); s != 0) return s;
  return perturbed_tie(pt, vertex, rows);
}

// The coefficients of eps_v, largest v first (see the header).
int PolygonKernel::perturbed_tie(const std::array<PolygonPoint, 4> &pt, const std::array<std::uint32_t, 4> &vertex,
                                 const std::array<ExactRow, 4> &rows) {
  std::array<std::uint32_t, 4> order = vertex;
  std::sort(order.begin(), order.end(), std::greater<std::uint32_t>());
  for (int k = 0; k < 4; ++k) {
    if (k > 0 && order[k] == order[k - 1]) continue;
    int rows_of_vertex = 0, row = -1;
    for (int r = 0; r < 4; ++r)
      if (vertex[r] == order[k]) ++rows_of_vertex, row = r;
    int s;
    if (rows_of_vertex == 1) {
      std::array<PolygonPoint, 3> others;
      for (int i = 0, j = 0; i < 4; ++i)
        if (i != row) others[j++] = pt[i];
      s = (row % 2 == 1 ? 1 : -1) * orientation(others[0], others[1], others[2]);
    } else {
      Number coefficient(rows[0][0].parent(), 0);
      for (int r = 0; r < 4; ++r) {
        if (vertex[r] != order[k]) continue;
        std::array<const ExactRow *, 3> o;
        for (int i = 0, j = 0; i < 4; ++i)
          if (i != r) o[j++] = &rows[i];
        const Number term = rows[r][3] * det3<Number>(*o[0], *o[1], *o[2]);
        coefficient = r % 2 == 1 ? coefficient + term : coefficient - term;
      }
      s = sign_of(coefficient);
    }
    if (s) return s;
  }
  throw std::logic_error(
      "PolygonKernel::in_circle_perturbed: every perturbation coefficient vanishes (points on one geodesic, or "
      "each vertex repeated)");
}

int PolygonKernel::compare_distance(const PolygonPoint &p, const PolygonPoint &a, const PolygonPoint &b) {
  return staged(
      PolygonPredicate::compare_distance,
      [&] { return sign_of(distance_difference<RealBall>(ball_row(p), ball_row(a), ball_row(b))); },
      [&] { return sign_of(distance_difference<Number>(exact_row(p), exact_row(a), exact_row(b))); });
}

// One element: t is injective, so the doubles decide. Else the ball images
// may be certainly apart; equality needs K(i): n_p d_q = n_q d_p.
bool PolygonKernel::same_point(const PolygonPoint &p, const PolygonPoint &q) {
  constexpr PolygonPredicate predicate = PolygonPredicate::same_point;
  if (p.t == q.t) return count(predicate, PolygonStage::structural, p.x == q.x && p.y == q.y);
  if (!exact_only_) {
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
      [&] { return sign_of(side_value<RealBall>(side_normal_ball_[k], ball_row(p))); },
      [&] { return sign_of(side_value<Number>(side_normal_[k], exact_row(p))); });
}

int PolygonKernel::large_circumdisk(const PolygonPoint &p, const PolygonPoint &q, const PolygonPoint &r,
                                    const Number &cosh2_half_diameter) {
  const RealBall &kb = threshold_ball(cosh2_half_diameter);
  const int s = staged(
      PolygonPredicate::large_circumdisk,
      [&] { return sign_of(circumdisk_excess<RealBall>(ball_row(p), ball_row(q), ball_row(r), kb)); },
      [&] { return sign_of(circumdisk_excess<Number>(exact_row(p), exact_row(q), exact_row(r), *threshold_)); });
  return s >= 0 ? 1 : -1;
}

// The threshold in the polygon's field (a rational one is moved there, so
// that every product has one parent) and its ball, kept for the next call.
const RealBall &PolygonKernel::threshold_ball(const Number &k) {
  if (!threshold_given_ || *threshold_given_ != k) {
    const auto &parent = polygon_.vertex(0).re.parent();
    threshold_given_ = k;
    threshold_ = k.is_rational() ? Number(parent, static_cast<mpq_class>(k)) : k;
    threshold_ball_ = ball_of(*threshold_);
  }
  return threshold_ball_;
}

}  // namespace hdt::domain
