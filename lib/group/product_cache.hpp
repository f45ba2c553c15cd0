// The translation table's cache of products of ids: an open-addressing
// hash table of (a, b) -> id a * b.
//
// Insertion asks it for a few products per new face, more at large genus
// where more faces cross the sides of F_g; std::unordered_map spent a
// division and a pointer chase per lookup there. Here a lookup is one
// multiplication and, at a load of at most a half, one or two probes in a
// flat array. Keys are never removed.
#pragma once

#include <cstdint>
#include <vector>

namespace hdt::group {

class ProductCache {
 public:
  // The cached product of (a, b), or -1.
  int32_t find(int32_t a, int32_t b) const {
    if (slots_.empty()) return -1;
    const uint64_t k = key(a, b);
    for (std::size_t s = home(k);; s = (s + 1) & mask_) {
      const Slot &slot = slots_[s];
      if (slot.key == k) return slot.id;
      if (slot.key == kEmpty) return -1;
    }
  }
  // Records a * b = id (a and b not cached yet).
  void add(int32_t a, int32_t b, int32_t id) {
    if (2 * (size_ + 1) > slots_.size()) grow();
    place(key(a, b), id);
    ++size_;
  }

 private:
  struct Slot {
    uint64_t key;
    int32_t id;
  };
  // Ids are non-negative, so no pair has the key of all ones.
  static constexpr uint64_t kEmpty = ~uint64_t(0);
  static uint64_t key(int32_t a, int32_t b) { return uint64_t(uint32_t(a)) << 32 | uint32_t(b); }
  std::size_t home(uint64_t k) const { return std::size_t((k * 0x9E3779B97F4A7C15ull) >> shift_); }
  void place(uint64_t k, int32_t id) {
    std::size_t s = home(k);
    while (slots_[s].key != kEmpty) s = (s + 1) & mask_;
    slots_[s] = {k, id};
  }
  void grow() {
    std::vector<Slot> old(slots_.size() < 512 ? 1024 : 2 * slots_.size(), Slot{kEmpty, -1});
    old.swap(slots_);
    mask_ = slots_.size() - 1;
    shift_ = 64;
    for (std::size_t n = slots_.size(); n > 1; n >>= 1) --shift_;
    for (const Slot &slot : old)
      if (slot.key != kEmpty) place(slot.key, slot.id);
  }

  std::vector<Slot> slots_;  // a power of two, or empty
  std::size_t mask_ = 0, size_ = 0;
  int shift_ = 64;
};

}  // namespace hdt::group
