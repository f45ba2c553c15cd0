// Word products through the 4g-fold rotation symmetry of F_g.
//
// The rotation R_k by k pi/2g about O conjugates g_j to g_{j+k} (B_j is
// |B| e^{i j pi/2g}, and g_{j+2g} = g_j^-1 fits: B_{j+2g} = -B_j). So the
// word w + k (every letter plus k, mod 4g) is R_k w R_k^-1: its Moebius
// matrix keeps a and turns b by e^{i k pi/2g}, its Lorentz matrix is w's
// turned about the n_0 axis. The elements of N are relator runs, and a
// rotation of a run is a run: all of N's (4g-1)^2 matrices come from about
// 4g products of words starting with letter 0. Those are cached, so that a
// new matrix costs one rotation instead of a product of up to 2g letters,
// which insertion at large genus pays for every new translation.
//
// The turn (word_matrix.cpp's with_bounded_product) multiplies b by
// B_k / B_0 from the generator set of the rung and counts its error.
#pragma once

#include <cstddef>
#include <map>
#include <mutex>
#include <utility>

#include "group/presentation.hpp"

namespace hdt::group {

namespace rotation_detail {

// w - w[0], so that it starts with letter 0; the shift into *k.
inline Word normalised(const Presentation &p, const Letter *w, std::size_t length, int *k) {
  const int n = p.letter_count();
  *k = length == 0 ? 0 : w[0];
  Word u(w, w + length);
  for (Letter &l : u) l = Letter((l - *k + n) % n);
  return u;
}

// Cached products per genus and rung, for the life of the process like the
// generator sets; bounded, beyond it products are computed and not kept.
constexpr std::size_t kCacheMax = std::size_t(1) << 16;

template <class M, class F>
M cached(int genus, const Word &u, F &&product) {
  static std::mutex mutex;
  static std::map<std::pair<int, Word>, M> cache;
  {
    std::lock_guard<std::mutex> lock(mutex);
    auto it = cache.find({genus, u});
    if (it != cache.end()) return it->second;
  }
  M m = product();  // outside the lock: two threads may compute it, the first stays
  std::lock_guard<std::mutex> lock(mutex);
  if (cache.size() < kCacheMax) cache.emplace(std::make_pair(genus, u), m);
  return m;
}

}  // namespace rotation_detail

}  // namespace hdt::group
