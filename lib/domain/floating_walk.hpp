// The representative's walk (representative.hpp) in double, for points given
// as two doubles: every decision of the exact walk (is B in P, which sides
// decrease along the segment, which exit root is least) taken on values
// carried with a certified error bound (error_double.hpp), so that a
// decision taken is the exact walk's own. The first decision the bounds
// cannot take (a point near a side, a segment near a vertex, a walk so long
// that the bounds have grown too wide) gives up, and the exact walk runs
// instead; so the result never differs from it.
//
// Homogeneous points. A point w = n / d is kept as the pair (n, d), which
// a pairing [[a, b], [conj b, conj a]] moves to (a n + b d, conj b n +
// conj a d) with no division. Its Klein image is 2 n conj(d) / (|n|^2 +
// |d|^2), and the side value f_k (affine) times the positive
// s_w = |n|^2 + |d|^2 is c0 s_w + 2 (c1 Re(n conj d) + c2 Im(n conj d)).
// With sA, sB the factors of the segment's ends A, B and a_k = sA f_k(A) sB,
// b_k = sB f_k(B) sA (one positive factor sA sB for all sides): side k
// decreases when b_k < a_k, its exit root is a_k / (a_k - b_k), and root_i <
// root_j exactly when a_j b_i < a_i b_j.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "domain/error_double.hpp"
#include "domain/fundamental_polygon.hpp"

namespace hdt::domain {

class FloatingWalk {
 public:
  // base: the exact walk's base point c (base_point.hpp).
  FloatingWalk(const FundamentalPolygon &P, const Complex &base);

  // The pairings the exact walk applies to x + iy, first first, when every
  // decision was certain and the end lies in P's interior; nothing when the
  // exact walk must decide (or the end is on P's boundary).
  std::optional<std::vector<int>> pairings_applied(double x, double y) const;

  // x + iy certainly in P's interior.
  bool certainly_interior(double x, double y) const;

 private:
  struct Value {
    ErrorDouble re, im;
  };
  struct Point {
    Value n, d;
  };
  struct Isometry {
    Value a, b;
  };

  std::vector<int> paired_;
  std::vector<std::array<ErrorDouble, 3>> side_forms_;  // (c0, c1, c2) per side
  std::vector<double> interior_margin_;                 // clearly_interior's bound, per side
  std::vector<Isometry> g_;                             // the pairings, SU(1,1)
  Point base_;

  // x + iy (in the disk) inside P by a plain double test with a static
  // error bound per side: the common case, at a fraction of the cost.
  bool clearly_interior(double x, double y) const;
  // s_w f_k(klein(w)), given s_w = scale(w) (computed once a point).
  ErrorDouble side(int k, const Point &w, const ErrorDouble &s_w) const;
  static ErrorDouble scale(const Point &w);       // s_w
  Point moved(int k, const Point &w) const;       // g_k(w)
  // The exit side of the segment from A to B (-1: B certainly inside P),
  // or nothing when the bounds cannot tell.
  std::optional<int> exit_side(const Point &A, const Point &B) const;
};

}  // namespace hdt::domain
