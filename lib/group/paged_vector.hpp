// A vector indexed by translation id whose memory follows the ids in use.
//
// Ids 0..|N|-1 are fixed for a genus, and |N| = (4g-1)^2 is 16.8 million at
// genus 1024: a flat array over all of them would cost gigabytes where a
// triangulation or a representative meets a few thousand. Pages of 256
// entries are allocated when an entry in them is first written; reading an
// entry of a missing page gives a default value without allocating.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

namespace hdt::group {

template <class T>
class PagedVector {
 public:
  static constexpr std::size_t kPageBits = 8;
  static constexpr std::size_t kPageSize = std::size_t(1) << kPageBits;

  // The entry of id, default-constructed when never written.
  const T &get(std::size_t id) const {
    const std::size_t page = id >> kPageBits;
    if (page >= pages_.size() || !pages_[page]) return empty_;
    return (*pages_[page])[id & (kPageSize - 1)];
  }
  // The entry of id for writing; allocates its page when missing.
  T &at(std::size_t id) {
    const std::size_t page = id >> kPageBits;
    if (page >= pages_.size()) pages_.resize(page + 1);
    if (!pages_[page]) pages_[page] = std::make_unique<std::array<T, kPageSize>>();
    return (*pages_[page])[id & (kPageSize - 1)];
  }

 private:
  std::vector<std::unique_ptr<std::array<T, kPageSize>>> pages_;
  T empty_{};
};

}  // namespace hdt::group
