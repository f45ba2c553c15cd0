// Asking the kernel for huge pages under a large buffer about to be filled.
//
// Insertion of 10^6 points first touches about 200 MB: the faces, the
// vertices, the sorted copies of the points. With 4 KiB pages that is some
// 50,000 page faults, and in a virtual machine a fault costs microseconds:
// a sixth of hdt_insert_many's time at 10^6 points on our 2-core VM. Under
// transparent huge pages (Linux, in "madvise" mode as Debian ships it) one
// fault maps 2 MiB. The advice changes no byte of the buffer, only how its
// untouched pages are mapped, and is ignored where it does not apply.
#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace hdt::triangulation {

// Advises huge pages for the 2 MiB-aligned part of [data, data + bytes);
// nothing below 4 MiB (the aligned part may be empty) or off Linux.
inline void advise_huge_pages(const void *data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t huge = std::uintptr_t(1) << 21;
  if (bytes < 2 * huge) return;
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(data) + huge - 1) & ~(huge - 1);
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(huge - 1);
  if (end > begin) madvise(reinterpret_cast<void *>(begin), end - begin, MADV_HUGEPAGE);  // advice: failure is fine
#else
  (void)data, (void)bytes;
#endif
}

// The same for a vector's whole capacity.
template <class Vector>
void advise_huge_pages(const Vector &v) {
  advise_huge_pages(v.data(), v.capacity() * sizeof(typename Vector::value_type));
}

// Bits have no data(); they are a 64th of what they stand for.
inline void advise_huge_pages(const std::vector<bool> &) {}

// v.reserve(n), with the advice given before the elements are moved into
// the new storage (a plain reserve would touch their pages first). As
// strong as reserve: on failure v is unchanged.
template <class Vector>
void reserve_on_huge_pages(Vector &v, std::size_t n) {
  if (n <= v.capacity()) return;
  Vector bigger;
  bigger.reserve(n);
  advise_huge_pages(bigger);
  bigger.insert(bigger.end(), std::make_move_iterator(v.begin()), std::make_move_iterator(v.end()));
  v.swap(bigger);
}

// n value-initialised elements, on huge pages when large.
template <class Vector>
Vector sized_on_huge_pages(std::size_t n) {
  Vector v;
  v.reserve(n);
  advise_huge_pages(v);
  v.resize(n);
  return v;
}

}  // namespace hdt::triangulation
