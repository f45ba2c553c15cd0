#include "group/centre_index.hpp"

#include <cmath>

#include "group/generators.hpp"

namespace hdt::group {

namespace {

// Cell coordinates stay well inside int32 (the key packs two of them).
constexpr double kMaxCell = 0x1p30;

}  // namespace

CentreIndex::CentreIndex(const Presentation &p) {
  // K = 2 sqrt(A^2 - 1), rounded down with room for the few roundings of
  // cot and sqrt (a few u, against the 1e-9 taken off).
  const double A = half_trace<double>(p.genus());
  const double K = 2 * std::sqrt(A * A - 1) * (1 - 1e-9);
  cell_ = K / 2;
  max_error_ = K / 16;
}

bool CentreIndex::cell_of(double p1, double p2, int64_t *i, int64_t *j) const {
  const double x = std::floor(p1 / cell_), y = std::floor(p2 / cell_);
  if (!(std::abs(x) < kMaxCell && std::abs(y) < kMaxCell)) return false;  // also NaN
  *i = int64_t(x), *j = int64_t(y);
  return true;
}

void CentreIndex::grow() {
  std::vector<Slot> old(slots_.size() < 512 ? 1024 : 2 * slots_.size(), Slot{0, 0, 0, 0, -1});
  old.swap(slots_);
  shift_ = 64;
  for (std::size_t n = slots_.size(); n > 1; n >>= 1) --shift_;
  for (const Slot &s : old)
    if (s.id >= 0) slots_[slot_of(s.key)] = s;
}

void CentreIndex::add(int32_t id, double p1, double p2, double error) {
  if (id < 0 || !(error >= 0 && error <= max_error_)) return;
  int64_t i, j;
  if (!cell_of(p1, p2, &i, &j)) return;
  float rounded = float(error);  // up, so that it still bounds the error
  if (double(rounded) < error) rounded = std::nextafter(rounded, HUGE_VALF);
  if (2 * (size_ + 1) > slots_.size()) grow();
  const uint64_t k = key(i, j);
  Slot &s = slots_[slot_of(k)];
  if (s.id < 0) {
    s = Slot{k, p1, p2, rounded, id};
    ++size_;
    return;
  }
  // Another element in the cell would be closer than 0.8 K to this one: not
  // possible for correct centres, so a clash leaves the index as it was.
  if (s.id == id && rounded < s.error) s.p1 = p1, s.p2 = p2, s.error = rounded;
}

int32_t CentreIndex::find(double p1, double p2, double error) const {
  if (!(error >= 0 && error <= max_error_) || slots_.empty()) return -1;
  // An indexed centre of the same element is within error + its own error
  // (<= 2 max_error = K/8, a quarter cell) in each coordinate: in one of the
  // cells this square meets (rounding is monotone, so the computed corners
  // still bracket it). For a different element both differences cannot be
  // within that sum: they would put the exact centres less than
  // 2 sqrt2 K/8 < K apart. (Stored errors are rounded up to float: 2^-20
  // of max_error covers that.)
  const double reach = error + max_error_ * (1 + 0x1p-20);
  int64_t i0, j0, i1, j1;
  if (!cell_of(p1 - reach, p2 - reach, &i0, &j0) || !cell_of(p1 + reach, p2 + reach, &i1, &j1)) return -1;
  for (int64_t i = i0; i <= i1; ++i)
    for (int64_t j = j0; j <= j1; ++j) {
      const Slot &s = slots_[slot_of(key(i, j))];
      if (s.id < 0) continue;
      if (std::abs(p1 - s.p1) <= error + s.error && std::abs(p2 - s.p2) <= error + s.error) return s.id;
    }
  return -1;
}

}  // namespace hdt::group
