// Names group elements by their tile centres.
//
// The centre of h in Gamma_g is P_h = h(O) on the hyperboloid. Distinct
// elements have centres at least 2r apart (r the inradius of F_g: the tiles'
// inscribed disks are disjoint, and adjacent tiles' centres are 2r apart),
// so v = P_h - P_h' has <v, v> = 2 - 2 cosh d <= -(2 cosh 2r - 2) = -K^2,
// and v1^2 + v2^2 = v0^2 - <v, v> >= K^2. With cosh 2r = 2A^2 - 1 and
// A = cot(pi/4g), K = 2 sqrt(A^2 - 1) (4.4 at genus 2, 81 at genus 32).
//
// So an approximation of (P1, P2) within K/16 in each coordinate names its
// element. The index keeps the centres it is given in square cells of side
// K/2, at most one element per cell (computed centres of distinct elements
// stay more than 0.8 K apart), and answers a query by the 2 x 2 cells around
// it: the element when it is indexed, -1 when it is not.
//
// The translation table uses it to name a product or an inverse from the
// double matrices it already has, instead of canonicalising a word (some
// 400,000 instructions at genus 32, where nearly every new product lies in N).
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "group/paged_vector.hpp"
#include "group/presentation.hpp"

namespace hdt::group {

class CentreIndex {
 public:
  explicit CentreIndex(const Presentation &p);

  // The largest error, in each of P1 and P2, of a centre given to add or find.
  double max_error() const { return max_error_; }
  // Records (p1, p2), within error in each coordinate, as the centre of id
  // (a more accurate centre replaces a less accurate one). Ignored when the
  // error exceeds max_error() or the centre is beyond the index's range.
  void add(int32_t id, double p1, double p2, double error);
  // The indexed id whose centre (p1, p2) is, within error <= max_error(),
  // or -1 when no indexed element has that centre.
  int32_t find(double p1, double p2, double error) const;

 private:
  struct Entry {
    double p1 = 0, p2 = 0, error = -1;  // error < 0: not indexed
  };
  bool cell_of(double p1, double p2, int64_t *i, int64_t *j) const;
  static uint64_t key(int64_t i, int64_t j) { return (uint64_t(i) << 32) ^ uint64_t(uint32_t(j)); }

  double cell_, max_error_;
  PagedVector<Entry> entries_;  // by id
  std::unordered_map<uint64_t, int32_t> cells_;
};

}  // namespace hdt::group
