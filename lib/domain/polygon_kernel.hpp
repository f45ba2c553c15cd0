// Exact predicates on points of a polygon surface's disk: a point is a pair
// of doubles z = x + iy and an interned group element t (element_table.hpp),
// meaning t(z). The same predicates as the M_g kernel
// (predicates/kernel.hpp), for any FundamentalPolygon.
//
// Rows. A disk point w has the hyperboloid vector
// N = (1 + |w|^2, 2 Re w, 2 Im w) / (1 - |w|^2); every formula uses a row
// R = lambda (N, 1) with lambda > 0, which leaves every sign below unchanged
// (each value is homogeneous in each row, of degree 1, or 2 in
// large_circumdisk; compare_distance is cleared of the lambdas by positive
// factors). For w = n / d, n = z + b, d = c z + d' (t's
// canonical matrix [[1, b], [c, d']]), lambda = |d|^2 (1 - |w|^2) gives
//   R = (|n|^2 + |d|^2, 2 Re(n conj d), 2 Im(n conj d), |d|^2 - |n|^2):
// no division, so in K when z is (doubles are rationals).
//
// Formulas, each the sign of a polynomial in the rows:
//   orientation(p, q, r) = sign det[N_p; N_q; N_r] (+1: counterclockwise).
//     det[N] = x0_p x0_q x0_r det[1 k_x k_y] for the Klein points
//     k = (x1, x2) / x0, x0 > 0: the Euclidean orientation of the Klein
//     points, whose geodesics are straight. NOT that of the Poincare disk
//     points: their geodesics are arcs, and a point between the chord pq and
//     the arc pq is on different sides of the two (the suite has one).
//   in_circle(p, q, r, s) = sign det[N_i 1] (+1: s inside, for p, q, r
//     counterclockwise). Column operations show
//     det[1 + |w|^2, 2x, 2y, 1 - |w|^2] = 8 det[x, y, x^2 + y^2, 1]: the same
//     sign as the Euclidean in-circle determinant of the disk points. The
//     Euclidean circle through three disk points, cut by the disk, is their
//     hyperbolic circle, horocycle or hypercycle, so both tests agree (for
//     a horocycle or hypercycle the sign names a side of it, as in M_g's).
//   compare_distance(p, a, b) = sign(cosh d(p, a) - cosh d(p, b)), with
//     cosh d(p, a) = [p, a] / (R_p3 R_a3), [u, v] = u0 v0 - u1 v1 - u2 v2.
//   beyond_side(p, k) = -orientation(v_k, v_{k+1}, p): the polygon is on the
//     left of its counterclockwise sides.
//   large_circumdisk(p, q, r, k): the plane c . (X, 1) = 0 through the three
//     rows, m = (c0, -c1, -c2): a circle of radius rho has
//     cosh rho = |c3| / sqrt[m, m] when [m, m] > 0 (<= 0: horocycle,
//     hypercycle). With k = cosh^2(D / 2) >= 1 for a diameter threshold D,
//     the answer is +1 iff c3^2 - k [m, m] >= 0 (for [m, m] <= 0 it is
//     >= 0 anyway, k > 0). The M_g kernel's test is k = cosh^2(sys / 4).
//
// Stages, each deciding only when its certified enclosure of the value
// excludes 0, so that its sign is the exact one. (1) Doubles with a running
// error bound (error_double.hpp): t's SU(1,1) matrix as doubles with the
// error of its ball, z exact. (2) Arb balls at kBallBits: t's SU(1,1) ball
// matrix, computed once per element, applied to the exact ball of z. For an
// SU(1,1) matrix |d|^2 - |n|^2 = 1 - |z|^2 exactly, so R_3 is that in both.
// (3) Otherwise e-antic in K(i): the rows exactly, the sign exactly. No
// epsilon anywhere. The determinants are taken on R_p and the rows of the
// other points relative to it (R_p3 R - R_3 R_p, a positive multiple of
// (N - N_p, 0)), which keeps (1) and (2) sharp for close points; points that
// all carry one element t are read untranslated (every predicate but
// beyond_side is invariant under a common isometry).
//
// in_circle_perturbed breaks ties like the M_g kernel: vertex v's rows get
// the last coordinate 1 + eps_v (lambda (1 + eps_v) here), eps of a larger id
// infinitely larger; the first non-zero coefficient, largest id first,
// decides. The coefficient of eps_v is the sum over v's rows r of
// (-1)^(r+1) R_r3 minor(r, 3), for a vertex in one row (-1)^(r+1) times a
// positive multiple of the orientation of the other three points.
//
// The caller holds the field lock (field_lock.hpp) on a number field.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "domain/ball.hpp"
#include "domain/element_table.hpp"
#include "domain/error_double.hpp"
#include "domain/fundamental_polygon.hpp"

namespace hdt::domain {

struct PolygonPoint {
  double x, y;  // z = x + iy, in the open disk
  ElementId t;  // the point is t(z)
};

// Which stage decided, in the order they run: structural (the description
// alone: same_point of one element), double, ball, exact.
enum class PolygonStage : std::uint8_t { structural, double_filter, ball, exact };
constexpr std::size_t kPolygonStageCount = 4;

enum class PolygonPredicate : std::uint8_t {
  orientation,
  in_circle,
  in_circle_perturbed,
  compare_distance,
  same_point,
  beyond_side,
  large_circumdisk
};
constexpr std::size_t kPolygonPredicateCount = 7;

struct PolygonStatistics {
  std::array<std::array<unsigned long, kPolygonStageCount>, kPolygonPredicateCount> decided{};

  unsigned long decided_by(PolygonPredicate p, PolygonStage s) const {
    return decided[std::size_t(p)][std::size_t(s)];
  }
  unsigned long calls(PolygonPredicate p) const {
    unsigned long n = 0;
    for (const unsigned long d : decided[std::size_t(p)]) n += d;
    return n;
  }
};

class PolygonKernel {
 public:
  // Both must outlive the kernel; the table may grow meanwhile.
  PolygonKernel(const FundamentalPolygon &polygon, ElementTable &table);

  int orientation(const PolygonPoint &p, const PolygonPoint &q, const PolygonPoint &r);
  int in_circle(const PolygonPoint &p, const PolygonPoint &q, const PolygonPoint &r, const PolygonPoint &s);
  // Never 0: throws std::logic_error when every perturbation coefficient
  // vanishes (four points on one geodesic, or every vertex repeated).
  // vertex[i] is point i's vertex id.
  int in_circle_perturbed(const std::array<PolygonPoint, 4> &points, const std::array<std::uint32_t, 4> &vertex);
  int compare_distance(const PolygonPoint &p, const PolygonPoint &a, const PolygonPoint &b);
  bool same_point(const PolygonPoint &p, const PolygonPoint &q);
  int beyond_side(const PolygonPoint &p, int side);
  // +1 when the circle through p, q, r has hyperbolic diameter >= D or is no
  // circle, -1 when smaller; cosh2_half_diameter = cosh^2(D / 2) >= 1 in the
  // polygon's field (or Q).
  int large_circumdisk(const PolygonPoint &p, const PolygonPoint &q, const PolygonPoint &r,
                       const Number &cosh2_half_diameter);

  const PolygonStatistics &statistics() const { return statistics_; }
  void reset_statistics() { statistics_ = {}; }
  // Tests: skip the floating stages before `first` (double_filter: run all),
  // so that each stage's signs can be checked.
  void set_first_stage(PolygonStage first) { first_ = first; }

 private:
  using DoubleRow = std::array<ErrorDouble, 4>;
  using BallRow = std::array<RealBall, 4>;
  using ExactRow = std::array<Number, 4>;
  struct DoubleIsometry {
    ErrorDouble ar, ai, br, bi;  // a and b of the SU(1,1) matrix
  };

  const DoubleIsometry &double_isometry(ElementId t);
  // p's double row, from a small direct-mapped cache by (x, y, t): a walk
  // and a conflict search ask for the same corners again and again. By
  // value: a later lookup may take the slot.
  DoubleRow double_row(const PolygonPoint &p);
  DoubleRow computed_double_row(const PolygonPoint &p);
  BallRow ball_row(const PolygonPoint &p) const;
  ExactRow exact_row(const PolygonPoint &p) const;
  ExactRow exact_row(const Complex &w) const;  // an exact point of the disk
  void set_threshold(const Number &k);
  int perturbed_tie(const std::array<PolygonPoint, 4> &points, const std::array<std::uint32_t, 4> &vertex,
                    const std::array<ExactRow, 4> &rows);
  // The first stage's sign that is not kUndecided: double, ball, exact.
  template <class DoubleSign, class BallSign, class ExactSign>
  int staged(PolygonPredicate predicate, DoubleSign dbl, BallSign ball, ExactSign exact);
  int count(PolygonPredicate p, PolygonStage s, int sign) {
    ++statistics_.decided[std::size_t(p)][std::size_t(s)];
    return sign;
  }

  const FundamentalPolygon &polygon_;
  ElementTable &table_;
  std::vector<std::array<Number, 3>> side_normal_;  // R_{v_k} x R_{v_{k+1}}, first three columns
  std::vector<std::array<RealBall, 3>> side_normal_ball_;
  std::vector<std::array<ErrorDouble, 3>> side_normal_double_;
  // By element id, as far as computed; a deque, so that a reference handed
  // out stays valid while a later id grows it (same_point holds two).
  std::deque<DoubleIsometry> doubles_;
  struct RowSlot {
    double x = NAN, y = NAN;  // NaN: equal to no point
    ElementId t = 0;
    DoubleRow row;
  };
  static constexpr int kRowCacheBits = 8;
  std::vector<RowSlot> row_cache_ = std::vector<RowSlot>(std::size_t(1) << kRowCacheBits);
  // The last large_circumdisk threshold, in the polygon's field, and its ball.
  std::optional<Number> threshold_given_, threshold_;
  RealBall threshold_ball_;
  ErrorDouble threshold_double_;
  PolygonStatistics statistics_;
  PolygonStage first_ = PolygonStage::double_filter;
};

}  // namespace hdt::domain
