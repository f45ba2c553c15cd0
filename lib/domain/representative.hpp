// The representative of a point z of the disk in the fundamental polygon P:
// the element t and the point t(z) in P's fundamental set, exactly.
//
// The fundamental set (half-open, so that each orbit meets it once): the
// interior of P; of two paired sides, the interior of the one of smaller
// index; of each vertex cycle, its smallest vertex. Every orbit meets the
// closed P; a point of the interior has no other image in P (the tiles do not
// overlap), a point inside a side has exactly one other, on the paired side,
// and a vertex has the other vertices of its cycle.
//
// The reduction walks the geodesic segment from the base point c (interior,
// base_point.hpp) to z through the tiling, always pulled back into P: with the
// current segment t[c, z], find where it leaves P, cross that side k (the tile
// beyond it is g_k(P)) and pull back by g_k^{-1} = g_{paired(k)}. In the Klein
// model the segment is a chord x(s) = A + s (B - A), s in [0, 1], and P the
// polygon {f_k >= 0} with f_k affine (klein_polygon.hpp), so the segment meets
// P in the parameters [max of the entry roots, min of the exit roots]; the
// exit side is the decreasing f_k of least root f_k(A) / (f_k(A) - f_k(B)),
// roots compared exactly. The walk stops when B is in the closed polygon.
//
// Why it ends. The parameter where the segment leaves the current tile never
// decreases, and each tile met is a convex set the segment crosses in one
// interval, so it is not met again once left; a compact segment meets
// finitely many tiles. The one degenerate case is a segment through a vertex
// x of the tiling. Leaving a tile at x, two sides tie (either may be crossed;
// the smaller index is). A tile that the segment only touches at x has, of its
// two sides at x, exactly one with f decreasing along the segment (both would
// put the segment inside the corner before x, neither after it); the side just
// crossed has f increasing, seen from this side of it, so the walk turns
// around x always the same way, and before a full turn reaches the tile
// that contains the segment beyond x (or B = x itself, where it stops).
//
// Finally a point on the boundary of P is moved into the fundamental set: on
// the interior of a side k with k > paired(k) by g_{paired(k)}, onto the
// paired side; at a vertex v along its cycle, g_{paired(v)} sending v_v to
// v_{paired(v)+1}, until the cycle's smallest vertex.
#pragma once

#include <cstddef>
#include <vector>

#include "domain/floating_walk.hpp"
#include "domain/fundamental_polygon.hpp"
#include "domain/klein_polygon.hpp"
#include "domain/word.hpp"

namespace hdt::domain {

struct Representative {
  Word word;              // t, with word_element(P, word.letters) == t
  Complex point;          // t(z), in the fundamental set
  std::size_t crossings;  // the sides crossed by the walk
};

class Reduction {
 public:
  explicit Reduction(const FundamentalPolygon &P);
  // z in the open unit disk (std::domain_error otherwise).
  Representative operator()(const Complex &z) const;
  // The same for the point x + iy: the walk's decisions taken in double
  // where their certified bounds allow (floating_walk.hpp), else exactly;
  // the same result either way. A point certainly inside P is its own
  // representative, with no exact arithmetic but its conversion.
  Representative operator()(double x, double y) const;
  // Only the walk's pairings for x + iy, first first (the word's letters
  // reversed): in double where the floating walk decides, with no exact
  // arithmetic at all then, else from the exact walk. x + iy must lie in
  // the open disk.
  std::vector<int> pairings_applied(double x, double y) const;

 private:
  struct Walk;
  FundamentalPolygon P_;
  KleinPolygon klein_;
  Complex base_;
  std::vector<Element> g_;
  FloatingWalk floating_;

  int exit_side(const Complex &from, const Complex &to) const;  // -1: `to` is in P
  void pull_back(Walk &w, int k) const;                         // by g_k
  void into_fundamental_set(Walk &w) const;
  void to_smallest_vertex(Walk &w, int v) const;
};

Representative representative(const FundamentalPolygon &P, const Complex &z);

}  // namespace hdt::domain
