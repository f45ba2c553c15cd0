#include "domain/floating_walk.hpp"

#include <cmath>

#include "domain/ball.hpp"
#include "domain/ball_isometry.hpp"
#include "domain/klein_polygon.hpp"

namespace hdt::domain {

namespace {

// More crossings than the exact walk meets from any double point: past
// them the bounds have long stopped deciding.
constexpr int kCrossingLimit = 1000;

}  // namespace

FloatingWalk::FloatingWalk(const FundamentalPolygon &P, const Complex &base) {
  // side_value(k, X) = Im(conj(d) (X - u)) = -d_im X_re + d_re X_im + (d_im u_re - d_re u_im),
  // d = u' - u for the side's Klein ends u, u'.
  const KleinPolygon klein(P);
  for (int k = 0; k < P.side_count(); ++k) {
    const Complex &u = klein.vertex(k), d = klein.vertex(k + 1) - u;
    const Number c0 = d.im * u.re - d.re * u.im;
    side_forms_.push_back({error_double(ball_of(c0)), error_double(ball_of(-d.im)), error_double(ball_of(d.re))});
    const std::array<ErrorDouble, 3> &c = side_forms_.back();
    interior_margin_.push_back(0x1p-48 * (std::abs(c[0].v) + std::abs(c[1].v) + std::abs(c[2].v)) +
                               2 * (c[0].e + c[1].e + c[2].e) + error_double_constants::kTiny);
    paired_.push_back(P.paired(k));
    const BallIsometry g = ball_isometry(P.pairing(k));
    g_.push_back({{error_double(real(g.a)), error_double(imag(g.a))}, {error_double(real(g.b)), error_double(imag(g.b))}});
  }
  const ErrorDouble zero(0.0), one(1.0);
  base_ = {{error_double(ball_of(base.re)), error_double(ball_of(base.im))}, {one, zero}};
}

ErrorDouble FloatingWalk::scale(const Point &w) {
  return (w.n.re * w.n.re + w.n.im * w.n.im) + (w.d.re * w.d.re + w.d.im * w.d.im);
}

ErrorDouble FloatingWalk::side(int k, const Point &w, const ErrorDouble &s_w) const {
  const std::array<ErrorDouble, 3> &c = side_forms_[std::size_t(k)];
  // n conj(d) = (n_re d_re + n_im d_im) + i (n_im d_re - n_re d_im)
  const ErrorDouble re = w.n.re * w.d.re + w.n.im * w.d.im, im = w.n.im * w.d.re - w.n.re * w.d.im;
  const ErrorDouble two(2.0);
  return c[0] * s_w + two * (c[1] * re + c[2] * im);
}

FloatingWalk::Point FloatingWalk::moved(int k, const Point &w) const {
  const Isometry &g = g_[std::size_t(k)];
  // a n + b d and conj(b) n + conj(a) d
  const auto mul = [](const Value &x, const Value &y) {
    return Value{x.re * y.re - x.im * y.im, x.re * y.im + x.im * y.re};
  };
  const auto add = [](const Value &x, const Value &y) { return Value{x.re + y.re, x.im + y.im}; };
  const Value conj_a{g.a.re, ErrorDouble(0.0) - g.a.im}, conj_b{g.b.re, ErrorDouble(0.0) - g.b.im};
  return {add(mul(g.a, w.n), mul(g.b, w.d)), add(mul(conj_b, w.n), mul(conj_a, w.d))};
}

// s_z f_k = c0 (1 + |z|^2) + 2 (c1 x + c2 y) for z = x + iy in the disk: a
// chain of at most 7 roundings per monomial, whose magnitudes sum to at most
// 2 (|c0| + |c1| + |c2|), so the double value errs by at most 16 u times
// that; with the coefficients' own errors, below the static margin of each
// side (which doubles the rounding term).
bool FloatingWalk::clearly_interior(double x, double y) const {
  const double t = 1 + (x * x + y * y);
  if (!(t < 2)) return false;  // the bound takes |z| < 1
  for (std::size_t k = 0; k < side_forms_.size(); ++k) {
    const std::array<ErrorDouble, 3> &c = side_forms_[k];
    if (!(c[0].v * t + 2 * (c[1].v * x + c[2].v * y) > interior_margin_[k])) return false;
  }
  return true;
}

bool FloatingWalk::certainly_interior(double x, double y) const {
  if (clearly_interior(x, y)) return true;
  const Point z{{ErrorDouble(x), ErrorDouble(y)}, {ErrorDouble(1.0), ErrorDouble(0.0)}};
  const ErrorDouble s_z = scale(z);
  for (int k = 0; k < int(side_forms_.size()); ++k)
    if (certain_sign(side(k, z, s_z)) <= 0) return false;
  return true;
}

std::optional<int> FloatingWalk::exit_side(const Point &A, const Point &B) const {
  const ErrorDouble sA = scale(A), sB = scale(B);
  bool inside = true;
  int best = -1;
  ErrorDouble best_a, best_b;
  for (int k = 0; k < int(side_forms_.size()); ++k) {
    const ErrorDouble fb = side(k, B, sB);
    const int sign_b = certain_sign(fb);
    if (sign_b == 0) return std::nullopt;  // B near side k's line: the exact walk decides
    inside = inside && sign_b > 0;
    const ErrorDouble a = side(k, A, sA) * sB, b = fb * sA;
    const int decreasing = certain_sign(a - b);
    if (decreasing == 0) return std::nullopt;
    if (decreasing < 0) continue;
    if (best >= 0) {
      const int order = certain_sign(a * best_b - best_a * b);  // > 0: root_k < root_best
      if (order == 0) return std::nullopt;                    // a tie (a vertex) or too close to tell
      if (order < 0) continue;
    }
    best = k, best_a = a, best_b = b;
  }
  if (inside) return -1;
  if (best < 0) return std::nullopt;  // no decreasing side: left to the exact walk's own error
  return best;
}

std::optional<std::vector<int>> FloatingWalk::pairings_applied(double x, double y) const {
  if (clearly_interior(x, y)) return std::vector<int>{};
  Point from = base_, to{{ErrorDouble(x), ErrorDouble(y)}, {ErrorDouble(1.0), ErrorDouble(0.0)}};
  std::vector<int> applied;
  for (int crossings = 0; crossings < kCrossingLimit; ++crossings) {
    const std::optional<int> k = exit_side(from, to);
    if (!k) return std::nullopt;
    if (*k < 0) return applied;
    const int back = paired_[std::size_t(*k)];
    from = moved(back, from), to = moved(back, to);
    applied.push_back(back);
  }
  return std::nullopt;
}

}  // namespace hdt::domain
