// Word products through the 4g-fold rotation symmetry of F_g.
//
// The rotation R_k by k pi/2g about O conjugates g_j to g_{j+k} (B_j is
// |B| e^{i j pi/2g}, and g_{j+2g} = g_j^-1 fits: B_{j+2g} = -B_j). So the
// word w + k (every letter plus k, mod 4g) is R_k w R_k^-1: its Moebius
// matrix keeps a and turns b by e^{i k pi/2g}, its Lorentz matrix is w's
// turned about the n_0 axis. The elements of N are relator runs, and a
// rotation of a run is a run: all of N's (4g-1)^2 matrices come from about
// 4g products of words starting with letter 0. Those are cached, so that a
// new matrix costs one rotation instead of a product of up to 2g letters at
// up to thousands of bits (28% of an insertion at genus 32 went there).
//
// Rounding: the rotation's cos and sin are B_k / |B|, each within a few
// units of the rung (GeneratorSet), so turning b adds a few units of |b| to
// the product's error; the callers' precision bounds have that slack.
#pragma once

#include <cstddef>
#include <map>
#include <mutex>
#include <utility>

#include "group/generators.hpp"

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

// g_w0 g_w1 ... as GeneratorSet::moebius, through the rotation of a cached product.
template <class T>
Moebius<T> rotated_moebius(const GeneratorSet<T> &gens, const Letter *w, std::size_t length) {
  const Presentation &p = gens.presentation();
  int k;
  const Word u = rotation_detail::normalised(p, w, length, &k);
  Moebius<T> m = rotation_detail::cached<Moebius<T>>(p.genus(), u, [&] { return gens.moebius(u); });
  if (k != 0) m.b = m.b * gens.rotation(k);
  return m;
}

// The same for GeneratorSet::lorentz: R L R^-1 with R the rotation of the
// (n_1, n_2) plane by k pi/2g.
template <class T>
Lorentz<T> rotated_lorentz(const GeneratorSet<T> &gens, const Letter *w, std::size_t length) {
  const Presentation &p = gens.presentation();
  int k;
  const Word u = rotation_detail::normalised(p, w, length, &k);
  Lorentz<T> L = rotation_detail::cached<Lorentz<T>>(p.genus(), u, [&] { return gens.lorentz(u); });
  if (k == 0) return L;
  const Complex<T> &r = gens.rotation(k);
  const T &c = r.re, &s = r.im;
  Lorentz<T> M;
  for (int j = 0; j < 3; ++j) {  // rows: R L
    M.m[0][j] = L.m[0][j];
    M.m[1][j] = c * L.m[1][j] - s * L.m[2][j];
    M.m[2][j] = s * L.m[1][j] + c * L.m[2][j];
  }
  for (int i = 0; i < 3; ++i) {  // columns: (R L) R^-1
    const T a = M.m[i][1], b = M.m[i][2];
    M.m[i][1] = c * a - s * b;
    M.m[i][2] = s * a + c * b;
  }
  return M;
}

}  // namespace hdt::group
