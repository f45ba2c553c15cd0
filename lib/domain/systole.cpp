#include "domain/systole.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <map>
#include <string>
#include <utility>

#include "domain/ball_isometry.hpp"
#include "domain/base_point.hpp"
#include "domain/hyperboloid_ball.hpp"
#include "domain/polygon_cover.hpp"
#include "exact/unsupported.hpp"

namespace hdt::domain {

namespace {

// The cover's target radius: smaller balls accept fewer tiles (about the
// area of P's (L + 2r)-neighbourhood over P's) but cost more tests a tile.
constexpr double kCoverRadius = 0.35;

struct Tile {
  int parent, letter;  // the tile is parent's isometry followed by pairing `letter`
  BallIsometry h;
  HyperboloidBall image;  // h(c)
  bool accepted;
};

class Walk {
 public:
  Walk(const FundamentalPolygon &P, std::size_t tile_limit)
      : P_(P), tile_limit_(tile_limit), cover_(polygon_cover(P, kCoverRadius)) {
    const Complex c = base_point(P);
    centre_ = ball_of(c);
    C_ = hyperboloid(centre_);
    for (int k = 0; k < P.side_count(); ++k) g_.push_back(ball_isometry(P.pairing(k)));
    for (int k = 0; k < P.side_count(); ++k) {
      const ComplexBall v = ball_of(P.vertex(k));
      normals_.push_back(line_normal(v, ball_of(P.vertex(k + 1)), C_));
      radius_ = std::max(radius_, acosh(RealBall(0.0) - minkowski(C_, hyperboloid(v))).upper());
    }
    for (const HyperboloidBall &n : normals_) side_forms_.push_back(vector_of({RealBall(0.0) - n.x0, n.x1, n.x2}));
    for (const CoverBall &b : cover_) centres_.push_back(std::isfinite(b.radius) ? vector_of(hyperboloid(b.centre)) : Vector{});
    set_gap();
  }

  // The bound L from the pairings and their products of two, and the
  // estimate of the walk's size, refused up front when past the limit.
  void start() {
    for (const BallIsometry &a : g_) {
      improve(a.cosh_half_translation());
      for (const BallIsometry &b : g_) improve((a * b).cosh_half_translation());
    }
    set_reach();
    refuse_long_walks();
  }

  void run() {
    add(-1, -1, ball_identity());
    for (std::size_t next = 0; next < queue_.size(); ++next) {
      const int t = queue_[next];
      for (int k = 0; k < int(g_.size()); ++k) add(t, k, tiles_[std::size_t(t)].h * g_[std::size_t(k)]);
    }
  }

  // The accepted non-identity tiles whose cosh(l/2) may be the least.
  std::vector<std::vector<int>> candidates() const {
    std::vector<std::vector<int>> words;
    for (std::size_t i = 1; i < tiles_.size(); ++i)
      if (tiles_[i].accepted && tiles_[i].h.cosh_half_translation().lower() <= best_upper_)
        words.push_back(letters(int(i)));
    return words;
  }

  std::size_t accepted() const { return queue_.size(); }

 private:
  const FundamentalPolygon &P_;
  std::size_t tile_limit_;
  std::vector<CoverBall> cover_;
  ComplexBall centre_;
  HyperboloidBall C_;
  std::vector<BallIsometry> g_;
  std::vector<HyperboloidBall> normals_;
  double best_upper_ = INFINITY, L_ = INFINITY;  // >= the least cosh(l/2) met; >= its l
  std::vector<RealBall> reach_;                  // sinh(r_j + L) per cover ball
  std::vector<ErrorDouble> reach_double_;        // the same, for the double tests
  using Vector = std::array<ErrorDouble, 3>;
  std::vector<Vector> centres_;                  // the hyperboloid vector of each cover ball's centre
  std::vector<Vector> side_forms_;               // (-n0, n1, n2): <X, n> = side_forms_ . X
  double radius_ = 0;                            // >= d(c, v) for every vertex v: P is in B(c, radius_)
  RealBall reach_whole_;                         // sinh(radius_ + L)
  RealBall same_;                                // between cosh of 0 and of the least gap
  double cell_ = 0;                              // side of a cell of the tiles' index
  std::vector<Tile> tiles_;
  std::deque<int> queue_;
  std::map<std::pair<long, long>, std::vector<int>> cells_;

  // Distinct tiles have centres at least 2 rho apart, rho the distance from
  // c to P's boundary (the tiles' interiors are disjoint), so at least
  // 2 sinh(rho) apart in the hyperboloid's (x1, x2): |dx1|^2 + |dx2|^2 -
  // |dx0|^2 = 2 (cosh d - 1) = 4 sinh^2(d/2).
  void set_gap() {
    RealBall rho;
    bool first = true;
    for (const HyperboloidBall &n : normals_) {
      const RealBall d = asinh(abs(minkowski(C_, n)));
      if (first || d.lower() < rho.lower()) rho = d, first = false;
    }
    const RealBall low(rho.lower());
    same_ = (RealBall(1.0) + cosh(RealBall(2.0) * low)) / RealBall(2.0);
    cell_ = sinh(low).lower() / 2;
    if (!(cell_ > 0)) throw exact::Unsupported("domain::systole: the base point is too near a side");
  }

  void improve(const RealBall &cosh_half) {
    if (cosh_half.lower() > 1) best_upper_ = std::min(best_upper_, cosh_half.upper());
  }

  void set_reach() {
    L_ = (RealBall(2.0) * acosh(RealBall(best_upper_))).upper();
    reach_whole_ = sinh(RealBall(radius_) + RealBall(L_));
    reach_.clear();
    for (const CoverBall &b : cover_)
      reach_.push_back(std::isfinite(b.radius) ? sinh(RealBall(b.radius) + RealBall(L_)) : RealBall(0.0));
    reach_double_.clear();
    for (const RealBall &r : reach_) reach_double_.push_back(error_double(r));
  }

  // The walk accepts about the area of the (L + 2r)-neighbourhood of P
  // (area A, perimeter p), A + p sinh t + 2 pi (cosh t - 1), over A.
  void refuse_long_walks() const {
    double perimeter = 0, r = 0;
    for (int k = 0; k < P_.side_count(); ++k)
      perimeter += acosh(RealBall(0.0) - minkowski(hyperboloid(ball_of(P_.vertex(k))),
                                                  hyperboloid(ball_of(P_.vertex(k + 1)))))
                       .upper();
    for (const CoverBall &b : cover_)
      if (b.children.empty() && std::isfinite(b.radius)) r = std::max(r, b.radius);
    const double t = L_ + 2 * r, area = 4 * M_PI * (P_.genus() - 1);
    const double estimate = 1 + (perimeter * std::sinh(t) + 2 * M_PI * (std::cosh(t) - 1)) / area;
    if (!(estimate <= double(tile_limit_)))
      throw exact::Unsupported("the certified systole would walk about " + std::to_string(std::llround(estimate)) +
                               " tiles, more than the limit " + std::to_string(tile_limit_));
  }

  // h(P) may meet the L-neighbourhood N of P: some cover ball B(c_j, r_j) has
  // its image within r_j + L of every side's half-plane. (A point q of h(P)
  // within L of P lies in some h(B(c_j, r_j)); then d(h c_j, P) <= r_j + L,
  // and the distance to P is at least the distance to each half-plane.)
  // First the whole of P's ball B(c, R) is tried (its image is h(c)), then
  // the test runs down the cover's quadtree: a node whose ball's image is
  // beyond r + L of some half-plane holds no such point (its square is in
  // that ball), and its subtree is dropped.
  bool may_meet(const BallIsometry &h) const { return may_meet(h, pulled_back_forms(h), 0); }

  bool may_meet(const BallIsometry &h, const std::vector<Vector> &forms, int node) const {
    const CoverBall &b = cover_[std::size_t(node)];
    if (std::isfinite(b.radius)) {
      if (node_beyond(h, forms, node)) return false;
      if (b.children.empty()) return true;
    }
    return std::any_of(b.children.begin(), b.children.end(), [&](int c) { return may_meet(h, forms, c); });
  }

  // <h(X), n_k> = (L^T n~_k) . X for h's Lorentz matrix L, n~_k = (-n0, n1, n2):
  // the side forms pulled back by h once a tile, so that each ball's test
  // is one dot product with its fixed centre.
  std::vector<Vector> pulled_back_forms(const BallIsometry &h) const {
    const std::array<RealBall, 9> L = h.lorentz();
    Vector column[3];
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) column[j][std::size_t(i)] = error_double(L[std::size_t(3 * i + j)]);
    std::vector<Vector> forms;
    for (const Vector &n : side_forms_) forms.push_back({dot(column[0], n), dot(column[1], n), dot(column[2], n)});
    return forms;
  }

  // The ball's image is beyond its reach of some side's half-plane. Decided
  // in double where the bounds tell (every side certainly within reach, or
  // one certainly beyond); else on Arb's balls, as without the doubles.
  bool node_beyond(const BallIsometry &h, const std::vector<Vector> &forms, int node) const {
    const Vector &X = centres_[std::size_t(node)];
    const ErrorDouble &reach = reach_double_[std::size_t(node)];
    bool undecided = false;
    for (const Vector &m : forms) {
      const int beyond_reach = certain_sign(dot(m, X) - reach);
      if (beyond_reach > 0) return true;
      undecided = undecided || beyond_reach == 0;
    }
    return undecided && beyond(hyperboloid(h.apply(cover_[std::size_t(node)].centre)), reach_[std::size_t(node)]);
  }

  static Vector vector_of(const HyperboloidBall &X) { return {error_double(X.x0), error_double(X.x1), error_double(X.x2)}; }
  static ErrorDouble dot(const Vector &a, const Vector &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

  // X is beyond `reach` (a sinh) of some side's half-plane.
  bool beyond(const HyperboloidBall &X, const RealBall &reach) const {
    return std::any_of(normals_.begin(), normals_.end(),
                       [&](const HyperboloidBall &n) { return certainly_less(reach, minkowski(X, n)); });
  }

  std::pair<long, long> cell_of(const HyperboloidBall &X) const {
    if (!(X.x1.upper() - X.x1.lower() < cell_ / 4 && X.x2.upper() - X.x2.lower() < cell_ / 4))
      throw exact::Unsupported("domain::systole: a tile's ball is too wide to tell it from its neighbours");
    return {long(std::floor(X.x1.mid() / cell_)), long(std::floor(X.x2.mid() / cell_))};
  }

  // The tile whose centre is X, if one was met: the same tile's centre is
  // within a cell, a different one's at cosh-distance >= cosh(2 rho).
  bool met(const HyperboloidBall &X, std::pair<long, long> cell) const {
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy) {
        const auto it = cells_.find({cell.first + dx, cell.second + dy});
        if (it == cells_.end()) continue;
        for (const int t : it->second) {
          const RealBall d = RealBall(0.0) - minkowski(X, tiles_[std::size_t(t)].image);
          if (certainly_less(d, same_)) return true;
          if (!certainly_less(same_, d))
            throw exact::Unsupported("domain::systole: two tiles' centres too close for the balls to tell");
        }
      }
    return false;
  }

  void add(int parent, int letter, BallIsometry h) {
    HyperboloidBall X = hyperboloid(h.apply(centre_));
    const std::pair<long, long> cell = cell_of(X);
    if (met(X, cell)) return;
    const bool accepted = !beyond(X, reach_whole_) && may_meet(h);
    const int index = int(tiles_.size());
    cells_[cell].push_back(index);
    if (accepted) {
      if (queue_.size() == tile_limit_)
        throw exact::Unsupported("the certified systole's walk exceeds " + std::to_string(tile_limit_) + " tiles");
      queue_.push_back(index);
      if (parent >= 0) {
        const double before = best_upper_;
        improve(h.cosh_half_translation());
        if (best_upper_ < before) set_reach();
      }
    }
    tiles_.push_back({parent, letter, std::move(h), std::move(X), accepted});
  }

  std::vector<int> letters(int t) const {
    std::vector<int> w;
    for (; tiles_[std::size_t(t)].parent >= 0; t = tiles_[std::size_t(t)].parent) w.push_back(tiles_[std::size_t(t)].letter);
    std::reverse(w.begin(), w.end());
    return w;
  }
};

}  // namespace

Systole systole(const FundamentalPolygon &P, std::size_t tile_limit) {
  Walk walk(P, tile_limit);
  walk.start();
  walk.run();
  // The least translation among the candidates, decided exactly (a tie keeps
  // the first met, in the walk's order).
  bool found = false;
  Word best{{}, identity_element(P.vertex(0).re)};
  Number best_cosh2(P.vertex(0).re.parent(), 0);
  for (std::vector<int> &letters : walk.candidates()) {
    Element e = word_element(P, letters);
    if (e.is_identity()) continue;
    Number c2 = cosh2_half_translation(e);
    if (!found || c2 < best_cosh2) best = {std::move(letters), std::move(e)}, best_cosh2 = std::move(c2), found = true;
  }
  if (!found) throw exact::Unsupported("domain::systole: the walk found no non-identity element");
  return {best, best_cosh2, length_from_cosh2_half(best_cosh2), walk.accepted()};
}

}  // namespace hdt::domain
