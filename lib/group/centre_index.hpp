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
// double matrices it already has, instead of canonicalising a word (a Dehn
// reduction and a multiprecision check, for products that nearly all lie
// in N).
//
// The cells are a flat open-addressing table whose slots hold the centre
// itself: a query costs one or two cache lines per cell, where a hash map
// of cells to ids with a per-id entry beside it costs a division and four
// pointer chases. A cell may keep an older,
// less accurate centre of its element when a better one falls in the next
// cell: both are centres of the same element within their errors, so either
// names it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "group/presentation.hpp"

namespace hdt::group {

class CentreIndex {
 public:
  explicit CentreIndex(const Presentation &p);

  // The largest error, in each of P1 and P2, of a centre given to add or find.
  double max_error() const { return max_error_; }
  // Records (p1, p2), within error in each coordinate, as the centre of id
  // (a more accurate centre replaces a less accurate one in its cell).
  // Ignored when the error exceeds max_error() or the centre is beyond the
  // index's range.
  void add(int32_t id, double p1, double p2, double error);
  // The indexed id whose centre (p1, p2) is, within error <= max_error(),
  // or -1 when no indexed element has that centre.
  int32_t find(double p1, double p2, double error) const;

 private:
  // A cell and the centre it holds (id < 0: an empty slot). 32 bytes.
  struct Slot {
    uint64_t key;
    double p1, p2;
    float error;  // rounded up from the double bound
    int32_t id;
  };
  bool cell_of(double p1, double p2, int64_t *i, int64_t *j) const;
  static uint64_t key(int64_t i, int64_t j) { return (uint64_t(i) << 32) ^ uint64_t(uint32_t(j)); }
  // The slot of cell key (linear probing): its own, or the empty one where
  // it would go.
  std::size_t slot_of(uint64_t k) const {
    std::size_t s = std::size_t((k * 0x9E3779B97F4A7C15ull) >> shift_);
    while (slots_[s].id >= 0 && slots_[s].key != k) s = (s + 1) & (slots_.size() - 1);
    return s;
  }
  void grow();

  double cell_, max_error_;
  std::vector<Slot> slots_;  // a power of two, at most half full
  std::size_t size_ = 0;
  int shift_ = 64;
};

}  // namespace hdt::group
