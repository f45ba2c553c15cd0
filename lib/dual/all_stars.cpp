// Every star at once: one pass over the faces puts each corner into its
// vertex's slots (with the next face about the vertex, read off the
// corner's own face), then each row is ordered by following those links
// from the vertex's stored face, as vertex_star walks.
#include "dual/all_stars.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#if defined(__SSE2__)
#include <emmintrin.h>
#include "mesh/polygon_triangulation.hpp"
#endif

namespace hdt::dual {

// Faces ahead of the scatter to fetch their vertices' counts and slots
// for: it writes by vertex id, which does not follow the faces' order.
// (32 rather than 16 or 64: far enough ahead that a fetch from memory is
// done when its face comes, near enough that it is still in cache.)
constexpr std::size_t kAhead = 32;

namespace {

// The matrices of the vertices' homes, which the writing applies to go back
// to each vertex's representative: made here, where ids may be added.
template <class Tri>
void warm_home_matrices(const Tri &tri) {
  auto &T = tri.table();
  for (const mesh::Vertex &u : tri.vertices())
    if (u.alive() && u.home != 0) T.moebius(u.home);
}

}  // namespace

template <class U, class Tri>
void AllStars::build_rows(const Tri &tri, bool matrices, CentreCache *cache, Rows<U> &rows) {
  constexpr U top = U(1) << (std::numeric_limits<U>::digits - 1);
  const std::vector<mesh::Face> &F = tri.faces();
  const std::vector<mesh::Vertex> &V = tri.vertices();
  auto &T = tri.table();
  const std::size_t n = V.size(), nf = F.size();
  // The degrees (count[n] ends up the entry count after the ordering, which
  // turns the counts into the rows' starts).
  rows.count.assign(n + 1, 0);
  moved_.clear();
  rows.overflow.clear();
  // Kept from call to call (its pages stay mapped); grown when too small.
  // A vertex's slots are one cache line (for 32 bits), aligned.
  if (rows.slot_capacity < n) {
    rows.slot_store.reset(new U[2 * kSlots * (n + 1)]());  // (zeros: the ordering reads whole lines)
    rows.slot_capacity = n;
    const std::size_t line = 2 * kSlots * sizeof(U);
    const std::size_t skip = (line - reinterpret_cast<std::uintptr_t>(rows.slot_store.get()) % line) % line;
    rows.slots = rows.slot_store.get() + skip / sizeof(U);
  }
  U *slots = rows.slots;
  U *count = rows.count.data();
  bool block_missing = false;
  const mesh::Face *faces = F.data();
  for (std::size_t f = 0; f < nf; ++f) {
    // A copy: the stores into the slots and counts below are of the
    // faces' own type, and through a reference the compiler read the face
    // again after each of them.
    const mesh::Face A = faces[f];
    if (f + kAhead < nf)
      for (int c = 0; c < 3; ++c) {
        const uint32_t w = faces[f + kAhead].v[c];
        if (w < n) __builtin_prefetch(slots + 2 * kSlots * std::size_t(w), 1), __builtin_prefetch(count + w, 1);
      }
    // The cells' centres in the same pass over the faces, through the
    // cache as hdt_voronoi_cell (the same bits): a hit here; the misses by
    // blocks of faces just passed, still in cache (a call a face to
    // compute one would pay the call's overhead on every face).
    if (cache) {
      if (!cache->holds(tri, uint32_t(f))) block_missing = true;
      if (block_missing && ((f + 1) % 256 == 0 || f + 1 == nf)) {
        face_centres(tri, nullptr, cache, false, f - f % 256, f + 1);
        block_missing = false;
      }
    }
    if ((A.t[0] | A.t[1] | A.t[2]) != 0) {
      // A translated corner (few: the faces across F_g's sides): vertex_star's
      // translation, computed now, where it may add ids; with matrices, the
      // corner's matrix too, as warm_corner_matrices would.
      for (int c = 0; c < 3; ++c) {
        if (A.t[c] == 0 || A.v[c] >= n) continue;
        const mesh::TranslationId home = V[A.v[c]].home;
        const mesh::TranslationId t = T.inverse(T.compose(A.t[c], T.inverse(home)));
        moved_.push_back({4 * f + c, t});
        if (matrices) {
          T.moebius(A.t[c]);
          if (t != 0) T.moebius(t);
        }
      }
    }
    // Each corner into its vertex's next slot, in face order: its corner
    // index k = 4f + c and the next face about the vertex. (Spelled out
    // corner by corner: GCC does not unroll the loop.)
    if (A.v[0] >= n || A.v[1] >= n || A.v[2] >= n)
      throw std::logic_error("all stars: face " + std::to_string(f) + " names no vertex");
    const U base = U(4 * f);
    const auto put = [&](uint32_t w, U k, U next) {
      const U d = count[w]++;
      if (d < kSlots) {
        U *e = slots + 2 * (kSlots * std::size_t(w) + d);
        e[0] = k, e[1] = next;
      } else {
        rows.overflow.push_back({w, k, next});
      }
    };
    put(A.v[0], base | (A.t[0] != 0 ? top : U(0)), U(A.n[1]));
    put(A.v[1], (base + 1) | (A.t[1] != 0 ? top : U(0)), U(A.n[2]));
    put(A.v[2], (base + 2) | (A.t[2] != 0 ? top : U(0)), U(A.n[0]));
  }
  if (matrices) warm_home_matrices(tri);
  // The overflow by vertex, each vertex's entries still in face order.
  std::stable_sort(rows.overflow.begin(), rows.overflow.end(),
                   [](const Overflow<U> &x, const Overflow<U> &y) { return x.v < y.v; });
  if (rows.order_capacity < entries_) {
    rows.order.reset(new U[entries_]);
    rows.order_capacity = entries_;
  }
}

template <class U, class Tri>
void AllStars::order_rows(const Tri &tri, Rows<U> &rows) {
  constexpr U top = U(1) << (std::numeric_limits<U>::digits - 1);
  const std::vector<mesh::Vertex> &V = tri.vertices();
  U *count = rows.count.data();
  const U *slots = rows.slots;
  U *order = rows.order.get();
  const std::size_t n = V.size();
  const auto broken = [](std::size_t v) {
    return std::logic_error("all stars: the star of vertex " + std::to_string(v) + " is broken");
  };
  std::size_t m = 0, spill = 0;  // entries ordered; overflow entries used
  std::vector<U> &long_row = rows.long_row;
  for (std::size_t v = 0; v < n; ++v) {
    const std::size_t d = count[v];
    count[v] = U(m);  // now the row's start
    if (!V[v].alive()) {
      if (d != 0) throw broken(v);
      continue;
    }
    if (d == 0 || m + d > entries_) throw broken(v);
    // The row: the vertex's slots, then its overflow entries (k at
    // row[2i], the next face at row[2i + 1]), in face order.
    const U *row = slots + 2 * kSlots * v;
    if (d > kSlots) {
      long_row.resize(2 * d);
      std::copy(row, row + 2 * kSlots, long_row.begin());
      for (std::size_t i = kSlots; i < d; ++i, ++spill) {
        if (spill == rows.overflow.size() || rows.overflow[spill].v != v) throw broken(v);
        long_row[2 * i] = rows.overflow[spill].k, long_row[2 * i + 1] = rows.overflow[spill].next;
      }
      row = long_row.data();
    }
    U *out = order + m;
    m += d;
    // In star order: from the vertex's stored face, the entry of the face
    // the previous one leads to, found by comparing the face with the
    // row's (at most 8: two vector comparisons). A face not in the row
    // gives lane 8, and an entry met twice shows in the used mask.
    // (Intrinsics, because a portable loop over the 8 lanes, which GCC
    // vectorises too, made hdt_vertex_stars markedly slower at large V.)
    const uint32_t first = V[v].face;
    uint32_t f = first;
#if defined(__SSE2__)
    if constexpr (sizeof(U) == 4) if (d <= kSlots) {
      // The row's k and next faces apart, the faces k >> 2 (without the
      // flag); lanes d .. 7 (not written by the scatter) made no face.
      const __m128i *r = reinterpret_cast<const __m128i *>(row);
      const __m128 r0 = _mm_castsi128_ps(_mm_loadu_si128(r)), r1 = _mm_castsi128_ps(_mm_loadu_si128(r + 1)),
                   r2 = _mm_castsi128_ps(_mm_loadu_si128(r + 2)), r3 = _mm_castsi128_ps(_mm_loadu_si128(r + 3));
      alignas(16) uint32_t k[12], x[12];
      const __m128i k0 = _mm_castps_si128(_mm_shuffle_ps(r0, r1, _MM_SHUFFLE(2, 0, 2, 0))),
                    k1 = _mm_castps_si128(_mm_shuffle_ps(r2, r3, _MM_SHUFFLE(2, 0, 2, 0)));
      _mm_store_si128(reinterpret_cast<__m128i *>(k), k0), _mm_store_si128(reinterpret_cast<__m128i *>(k + 4), k1);
      _mm_store_si128(reinterpret_cast<__m128i *>(x), _mm_castps_si128(_mm_shuffle_ps(r0, r1, _MM_SHUFFLE(3, 1, 3, 1))));
      _mm_store_si128(reinterpret_cast<__m128i *>(x + 4), _mm_castps_si128(_mm_shuffle_ps(r2, r3, _MM_SHUFFLE(3, 1, 3, 1))));
      k[8] = 0, x[8] = mesh::kNone;
      const __m128i low = _mm_set1_epi32(0x7fffffff), lane = _mm_set_epi32(3, 2, 1, 0);
      const __m128i dv = _mm_set1_epi32(int32_t(d));
      // Lane i < d keeps its face; the others become kNone, which no face is.
      const __m128i fc0 = _mm_or_si128(_mm_srli_epi32(_mm_and_si128(k0, low), 2),
                                       _mm_xor_si128(_mm_cmplt_epi32(lane, dv), _mm_set1_epi32(-1)));
      const __m128i fc1 =
          _mm_or_si128(_mm_srli_epi32(_mm_and_si128(k1, low), 2),
                       _mm_xor_si128(_mm_cmplt_epi32(_mm_add_epi32(lane, _mm_set1_epi32(4)), dv), _mm_set1_epi32(-1)));
      unsigned used = 0;
      for (std::size_t j = 0; j < d; ++j) {
        const __m128i fv = _mm_set1_epi32(int32_t(f));
        const unsigned hit = unsigned(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(fc0, fv)))) |
                             unsigned(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(fc1, fv)))) << 4 | 0x100u;
        const unsigned i = unsigned(__builtin_ctz(hit));
        used |= 1u << i;
        out[j] = U(k[i]);
        f = x[i];
      }
      if (used != (1u << d) - 1 || f != first) throw broken(v);
      continue;
    }
#endif
    // Else (a long row, 64-bit entries, no SSE2): searched entry by entry,
    // each marked when met (a walk that came back to its start too soon
    // would otherwise end there after d steps, its other entries unmet).
    std::vector<uint8_t> &met = rows.met;
    met.assign(d, 0);
    for (std::size_t j = 0; j < d; ++j) {
      std::size_t i = 0;
      while (i < d && uint32_t((row[2 * i] & ~top) >> 2) != f) ++i;
      if (i == d || met[i]++) throw broken(v);
      out[j] = row[2 * i];
      f = uint32_t(row[2 * i + 1]);
    }
    if (f != first) throw broken(v);
  }
  // Every corner in a row (each face names live vertices only).
  if (m != entries_ || spill != rows.overflow.size()) throw broken(n);
  count[n] = U(m);
}

template <class Tri>
void AllStars::build(const Tri &tri, bool matrices, bool wide) { build(tri, matrices, nullptr, wide); }

template <class Tri>
void AllStars::build_cells(const Tri &tri, CentreCache &cache, bool wide) {
  cache.reserve(tri);
  build(tri, true, &cache, wide);
}

template <class Tri>
void AllStars::prepare_cells(const Tri &tri, CentreCache &cache) {
  cache.reserve(tri);
  // The centres (with the matrices of the corners they compute), then the
  // matrices of the translations the writing applies, as build_rows makes
  // them with matrices.
  face_centres(tri, nullptr, &cache, false);
  auto &T = tri.table();
  for (const auto &m : moved_)
    if (m.second != 0) T.moebius(m.second);
  warm_home_matrices(tri);
}

template <class Tri>
void AllStars::build(const Tri &tri, bool matrices, CentreCache *cache, bool wide) {
  entries_ = 3 * tri.faces().size();
  // Corner indices and the flag in 32 bits while they fit.
  wide_ = wide || tri.faces().size() >= (std::size_t(1) << 29);
  if (wide_) {
    small_ = {};
    build_rows(tri, matrices, cache, large_);
    order_rows(tri, large_);
  } else {
    large_ = {};
    build_rows(tri, matrices, cache, small_);
    order_rows(tri, small_);
  }
}

// each() and dispatch() are inlined into each writer, as GCC did by itself
// before they were templates on the triangulation too (hdt_voronoi_cells
// took 8% more instructions with the loop out of line).
template <class U, class Emit, class Tri>
__attribute__((always_inline)) inline void AllStars::each(const Tri &tri, const Rows<U> &rows, std::size_t *offsets, const Point *prefetch,
                    Emit &&emit) const {
  constexpr U top = U(1) << (std::numeric_limits<U>::digits - 1);
  const std::vector<mesh::Vertex> &V = tri.vertices();
  const U *order = rows.order.get();
  const U *start = rows.count.data();
  const std::size_t n = V.size();
  constexpr std::size_t ahead = 64;  // entries
  for (std::size_t v = 0; v < n; ++v) {
    const std::size_t b = start[v], e = start[v + 1];
    if (offsets) offsets[v] = b;
    const mesh::TranslationId home = V[v].home;
    for (std::size_t j = b; j < e; ++j) {
      // The centres of the entries some way on: the cells read them in
      // the vertices' order, scattered over the faces.
      if (prefetch && j + ahead < entries_) __builtin_prefetch(prefetch + ((order[j + ahead] & ~top) >> 2));
      U k = order[j];
      mesh::TranslationId t = home;
      if (k & top) {
        k &= ~top;
        const auto it = std::lower_bound(moved_.begin(), moved_.end(), std::pair<uint64_t, mesh::TranslationId>{k, 0},
                                         [](const auto &x, const auto &y) { return x.first < y.first; });
        t = it->second;
      }
      emit(j, uint32_t(k >> 2), int(k & 3), t);
    }
  }
  if (offsets) offsets[n] = start[n];
}

template <class Emit, class Tri>
__attribute__((always_inline)) inline void AllStars::dispatch(const Tri &tri, std::size_t *offsets, const Point *prefetch, Emit &&emit) const {
  if (wide_) each(tri, large_, offsets, prefetch, emit);
  else each(tri, small_, offsets, prefetch, emit);
}

template <class Tri>
void AllStars::write(const Tri &tri, std::size_t *offsets, uint32_t *faces, uint8_t *corners,
                     int32_t *translations) const {
  if (!faces && !corners && !translations) {
    dispatch(tri, offsets, nullptr, [](std::size_t, uint32_t, int, mesh::TranslationId) {});
    return;
  }
  if (faces && corners && translations) {  // the usual call: no test per entry
    dispatch(tri, offsets, nullptr, [&](std::size_t j, uint32_t f, int c, mesh::TranslationId t) {
      faces[j] = f, corners[j] = uint8_t(c), translations[j] = t;
    });
    return;
  }
  dispatch(tri, offsets, nullptr, [&](std::size_t j, uint32_t f, int c, mesh::TranslationId t) {
    if (faces) faces[j] = f;
    if (corners) corners[j] = uint8_t(c);
    if (translations) translations[j] = t;
  });
}

template <class Tri>
void AllStars::write_cells(const Tri &tri, std::size_t *offsets, double *xy, const Point *centre) const {
  auto &T = tri.table();
  // hdt_voronoi_cell's expression, for the same bits. The centres are read
  // in the rows' order, scattered: each() prefetches them some entries on.
  dispatch(tri, offsets, centre, [&](std::size_t j, uint32_t f, int, mesh::TranslationId t) {
    const Point p = t == 0 ? centre[f] : T.moebius(t).apply(centre[f]);
    xy[2 * j] = p.re, xy[2 * j + 1] = p.im;
  });
}

// Both kinds of triangulation: M_g's and a polygon surface's.
#define HDT_DUAL_INSTANTIATE(Tri) \
  template void AllStars::build(const Tri &, bool, bool);                                             \
  template void AllStars::build_cells(const Tri &, CentreCache &, bool);                              \
  template void AllStars::prepare_cells(const Tri &, CentreCache &);                                  \
  template void AllStars::write(const Tri &, std::size_t *, uint32_t *, uint8_t *, int32_t *) const; \
  template void AllStars::write_cells(const Tri &, std::size_t *, double *, const Point *) const;
HDT_DUAL_INSTANTIATE(mesh::Triangulation)
HDT_DUAL_INSTANTIATE(mesh::PolygonTriangulation)
#undef HDT_DUAL_INSTANTIATE

}  // namespace hdt::dual
