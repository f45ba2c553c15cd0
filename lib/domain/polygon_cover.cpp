#include "domain/polygon_cover.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "exact/unsupported.hpp"

namespace hdt::domain {

namespace {

constexpr int kMaxDepth = 50;

struct KleinBall {
  RealBall x, y;
};

KleinBall klein_ball(const Complex &z) {
  const ComplexBall w = ball_of(z);
  const RealBall s = RealBall(2.0) / (RealBall(1.0) + norm2(w));
  return {real(w) * s, imag(w) * s};
}

// cosh of the distance between Klein points p and q:
// (1 - p.q) / sqrt((1 - |p|^2)(1 - |q|^2)).
RealBall klein_cosh_distance(const KleinBall &p, const KleinBall &q) {
  const RealBall one(1.0);
  const RealBall pq = p.x * q.x + p.y * q.y, pp = p.x * p.x + p.y * p.y, qq = q.x * q.x + q.y * q.y;
  return (one - pq) / sqrt((one - pp) * (one - qq));
}

class Quadtree {
 public:
  Quadtree(const FundamentalPolygon &P, double target) : target_(target) {
    for (int k = 0; k < P.side_count(); ++k) vertices_.push_back(klein_ball(P.vertex(k)));
  }

  // The node of the square at (x, y) of this side, or -1 when the square is
  // certainly outside P.
  int cover(double x, double y, double side, int depth) {
    const std::array<KleinBall, 4> corners{point(x, y), point(x + side, y), point(x, y + side),
                                           point(x + side, y + side)};
    if (outside(corners)) return -1;
    const int index = int(balls_.size());
    balls_.emplace_back();
    if (inside_disk(corners)) {
      const KleinBall centre = point(x + side / 2, y + side / 2);
      double r = 0;
      for (const KleinBall &c : corners) r = std::max(r, acosh(klein_cosh_distance(centre, c)).upper());
      balls_[std::size_t(index)].centre = disk_point(centre);
      balls_[std::size_t(index)].radius = r;
      if (r <= target_) return index;
    }
    if (depth == kMaxDepth)
      throw exact::Unsupported("domain::polygon_cover: a vertex is too near the circle to cover the polygon");
    const double h = side / 2;
    for (double dx : {0.0, h})
      for (double dy : {0.0, h}) {
        const int child = cover(x + dx, y + dy, h, depth + 1);
        if (child >= 0) balls_[std::size_t(index)].children.push_back(child);
      }
    return index;
  }

  std::vector<CoverBall> take() { return std::move(balls_); }
  const std::vector<KleinBall> &vertices() const { return vertices_; }

 private:
  double target_;
  std::vector<KleinBall> vertices_;
  std::vector<CoverBall> balls_;

  static KleinBall point(double x, double y) { return {RealBall(x), RealBall(y)}; }

  // All corners strictly right of some side (P is counterclockwise).
  bool outside(const std::array<KleinBall, 4> &corners) const {
    const RealBall zero(0.0);
    const std::size_t n = vertices_.size();
    for (std::size_t k = 0; k < n; ++k) {
      const KleinBall &p = vertices_[k], &q = vertices_[(k + 1) % n];
      const RealBall ex = q.x - p.x, ey = q.y - p.y;
      if (std::all_of(corners.begin(), corners.end(), [&](const KleinBall &c) {
            return certainly_less(ex * (c.y - p.y) - ey * (c.x - p.x), zero);
          }))
        return true;
    }
    return false;
  }

  static bool inside_disk(const std::array<KleinBall, 4> &corners) {
    const RealBall one(1.0);
    return std::all_of(corners.begin(), corners.end(),
                       [&](const KleinBall &c) { return certainly_less(c.x * c.x + c.y * c.y, one); });
  }

  // z = k / (1 + sqrt(1 - |k|^2)).
  static ComplexBall disk_point(const KleinBall &k) {
    const RealBall one(1.0);
    const RealBall s = one / (one + sqrt(one - (k.x * k.x + k.y * k.y)));
    ComplexBall z;
    arb_mul(acb_realref(z.get()), k.x.get(), s.get(), kBallBits);
    arb_mul(acb_imagref(z.get()), k.y.get(), s.get(), kBallBits);
    return z;
  }
};

}  // namespace

std::vector<CoverBall> polygon_cover(const FundamentalPolygon &P, double target_radius) {
  Quadtree tree(P, target_radius);
  double lo_x = 1, hi_x = -1, lo_y = 1, hi_y = -1;
  for (const KleinBall &v : tree.vertices()) {
    lo_x = std::min(lo_x, v.x.lower()), hi_x = std::max(hi_x, v.x.upper());
    lo_y = std::min(lo_y, v.y.lower()), hi_y = std::max(hi_y, v.y.upper());
  }
  // A dyadic square (side 2^e, corners multiples of 2^(e-1)) over the box:
  // every corner of the quadtree to depth 50 is then a double exactly, so the
  // four squares of a split tile their parent.
  const double side = std::ldexp(1.0, std::ilogb(std::max(hi_x - lo_x, hi_y - lo_y)) + 2), half = side / 2;
  tree.cover(std::floor(lo_x / half) * half, std::floor(lo_y / half) * half, side, 0);
  return tree.take();
}

}  // namespace hdt::domain
