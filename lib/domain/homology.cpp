#include "domain/homology.hpp"

#include <cstdlib>
#include <stdexcept>
#include <utility>

namespace hdt::domain {

namespace {

using Matrix = std::vector<std::vector<int64_t>>;

// The Smith normal form's column side: R E = F^-1 D with E unimodular,
// from row and column operations on R (rows: relations, columns:
// generators); returns E and the number r of nonzero diagonal entries,
// each checked to be +-1 (H_1 is torsion-free). Entries stay small: the
// relations count letters of cycles.
Matrix column_transform(Matrix R, std::size_t m, std::size_t *r) {
  Matrix E(m, std::vector<int64_t>(m, 0));
  for (std::size_t i = 0; i < m; ++i) E[i][i] = 1;
  const std::size_t rows = R.size();
  const auto swap_columns = [&](std::size_t a, std::size_t b) {
    for (auto &row : R) std::swap(row[a], row[b]);
    for (auto &row : E) std::swap(row[a], row[b]);
  };
  const auto add_column = [&](std::size_t to, std::size_t from, int64_t q) {  // col[to] -= q col[from]
    for (auto &row : R) row[to] -= q * row[from];
    for (auto &row : E) row[to] -= q * row[from];
  };
  std::size_t t = 0;
  while (t < rows && t < m) {
    // The smallest nonzero entry of the rest, moved to (t, t).
    std::size_t bi = rows, bj = m;
    for (std::size_t i = t; i < rows; ++i)
      for (std::size_t j = t; j < m; ++j)
        if (R[i][j] != 0 && (bi == rows || std::llabs(R[i][j]) < std::llabs(R[bi][bj]))) bi = i, bj = j;
    if (bi == rows) break;
    std::swap(R[t], R[bi]);
    swap_columns(t, bj);
    bool clean = true;
    for (std::size_t j = t + 1; j < m; ++j)
      if (const int64_t q = R[t][j] / R[t][t]; q != 0 || R[t][j] != 0) {
        add_column(j, t, q);
        clean = clean && R[t][j] == 0;
      }
    for (std::size_t i = t + 1; i < rows; ++i)
      if (R[i][t] != 0) {
        const int64_t q = R[i][t] / R[t][t];
        for (std::size_t j = 0; j < m; ++j) R[i][j] -= q * R[t][j];
        clean = clean && R[i][t] == 0;
      }
    if (!clean) continue;  // a remainder: a smaller pivot next round
    if (std::llabs(R[t][t]) != 1) throw std::logic_error("domain::Homology: torsion in H_1 of a closed surface");
    ++t;
  }
  *r = t;
  return E;
}

}  // namespace

Homology::Homology(const FundamentalPolygon &P) {
  const int n = P.side_count();
  pair_.assign(std::size_t(n), -1);
  sign_.assign(std::size_t(n), 0);
  int pairs = 0;
  for (int k = 0; k < n; ++k)
    if (k < P.paired(k)) pair_[std::size_t(k)] = pair_[std::size_t(P.paired(k))] = pairs++, sign_[std::size_t(k)] = 1,
                                  sign_[std::size_t(P.paired(k))] = -1;
  const std::size_t m = std::size_t(pairs);
  // One relation a cycle: the letters paired(v) of the pairings around it.
  Matrix R;
  for (const std::vector<int> &cycle : P.cycles()) {
    std::vector<int64_t> row(m, 0);
    for (const int v : cycle) {
      const int k = P.paired(v);
      row[std::size_t(pair_[std::size_t(k)])] += sign_[std::size_t(k)];
    }
    R.push_back(std::move(row));
  }
  std::size_t r = 0;
  const Matrix E = column_transform(std::move(R), m, &r);
  rank_ = int(m - r);
  if (rank_ != 2 * P.genus()) throw std::logic_error("domain::Homology: H_1 of rank other than 2g");
  basis_.assign(m, std::vector<int64_t>(std::size_t(rank_), 0));
  for (std::size_t i = 0; i < m; ++i)
    for (int c = 0; c < rank_; ++c) basis_[i][std::size_t(c)] = E[i][r + std::size_t(c)];
}

std::vector<int64_t> Homology::of(const std::vector<int> &letters) const {
  std::vector<int64_t> v(basis_.size(), 0), out(std::size_t(rank_), 0);
  for (const int k : letters) v[std::size_t(pair_.at(std::size_t(k)))] += sign_[std::size_t(k)];
  for (std::size_t i = 0; i < v.size(); ++i)
    if (v[i] != 0)
      for (int c = 0; c < rank_; ++c) out[std::size_t(c)] += v[i] * basis_[i][std::size_t(c)];
  return out;
}

}  // namespace hdt::domain
