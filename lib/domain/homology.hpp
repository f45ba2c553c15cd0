// H_1 of a surface given by a fundamental polygon, as Z^{2g}: the
// abelianisation of its group, presented by the side pairings with one
// relation per vertex cycle (the pairings around it compose to the
// identity; Poincare's polygon theorem). Generators: one per pair of sides
// {k, paired(k)}, g_k counting +1 for the smaller side k and g_paired(k) =
// g_k^-1 counting -1; relations: the cycles' sums. The quotient of Z^{n/2}
// by the relations is free of rank 2g (a closed orientable surface's H_1):
// a Smith normal form of the relation matrix, R = A D B with D's r nonzero
// entries all 1, gives the basis, and a class is the last 2g coordinates
// of v B^-1, v the word's count of generators.
#pragma once

#include <cstdint>
#include <vector>

#include "domain/fundamental_polygon.hpp"

namespace hdt::domain {

class Homology {
 public:
  explicit Homology(const FundamentalPolygon &P);
  // [w] in Z^{2g} for the word w in the pairings (letters 0 .. n-1).
  std::vector<int64_t> of(const std::vector<int> &letters) const;
  int rank() const { return rank_; }  // 2g

 private:
  std::vector<int> pair_;    // by side: its pair's index, 0 .. n/2 - 1
  std::vector<int> sign_;    // by side: +1 for the smaller side of its pair, -1 for the other
  std::vector<std::vector<int64_t>> basis_;  // B^-1's last 2g columns, m rows: a class is v times them
  int rank_ = 0;
};

}  // namespace hdt::domain
