// Every star at once: one pass over the faces puts each corner into its
// vertex's slots (with the next face about the vertex, read off the
// corner's own face), then each row is ordered by following those links
// from the vertex's stored face, as vertex_star walks.
#include "triangulation/all_stars.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace hdt::triangulation {

namespace {

// The ranks of values among a row's d faces fc[0..d) (how many faces lie
// below each): out[i] for x[i], i up to 8 when d < 8, else up to 16 (x
// set there). All at once, a vector comparison of every x with each face
// in turn, where the compiler has vector extensions (a fifth of the
// instructions of one rank at a time), else by loops. Compared as signed
// after flipping the top bit, which SSE2 compares directly.
#if defined(__GNUC__)
template <int L>  // 4 L values
inline void ranks_of(const uint32_t fc[16], std::size_t d, const uint32_t x[16], int32_t out[16]) {
  typedef uint32_t u4 __attribute__((vector_size(16)));
  typedef int32_t v4 __attribute__((vector_size(16)));
  const u4 flip = {0x80000000u, 0x80000000u, 0x80000000u, 0x80000000u};
  v4 xv[L], acc[L] = {};
  for (int q = 0; q < L; ++q) {
    u4 w;
    std::memcpy(&w, x + 4 * q, sizeof w);
    xv[q] = v4(w ^ flip);
  }
  for (std::size_t j = 0; j < d; ++j) {
    const int32_t y = int32_t(fc[j] ^ 0x80000000u);
    const v4 yv = {y, y, y, y};
    for (int q = 0; q < L; ++q) acc[q] -= yv < xv[q];  // the comparison gives -1 where the face is below
  }
  std::memcpy(out, acc, sizeof acc);
}
#endif

inline void ranks(const uint32_t fc[16], std::size_t d, const uint32_t x[16], int32_t out[16]) {
#if defined(__GNUC__)
  // Eight values (nearly every row) need half the comparisons.
  if (d < 8) ranks_of<2>(fc, d, x, out);
  else ranks_of<4>(fc, d, x, out);
#else
  for (std::size_t i = 0; i <= d; ++i) {  // the lanes the caller reads
    int32_t r = 0;
    for (std::size_t j = 0; j < d; ++j) r += fc[j] < x[i];
    out[i] = r;
  }
#endif
}

}  // namespace

// Faces ahead of the scatter to fetch their vertices' counts and slots
// for: it writes by vertex id, which does not follow the faces' order.
constexpr std::size_t kAhead = 16;

template <class U>
void AllStars::build_rows(const Triangulation &tri, bool matrices, CentreCache *cache, Point *centre, Rows<U> &rows) {
  constexpr U top = U(1) << (std::numeric_limits<U>::digits - 1);
  const std::vector<Face> &F = tri.faces();
  const std::vector<Vertex> &V = tri.vertices();
  group::TranslationTable &T = tri.table();
  const std::size_t n = V.size(), nf = F.size();
  // The degrees (count[n] ends up the entry count after the ordering, which
  // turns the counts into the rows' starts).
  rows.count.assign(n + 1, 0);
  moved_.clear();
  rows.overflow.clear();
  // Kept from call to call (its pages stay mapped); grown when too small.
  // A vertex's slots are one cache line (for 32 bits), aligned.
  if (rows.slot_capacity < n) {
    rows.slot_store.reset(new U[2 * kSlots * (n + 1)]);
    rows.slot_capacity = n;
    const std::size_t line = 2 * kSlots * sizeof(U);
    const std::size_t skip = (line - reinterpret_cast<std::uintptr_t>(rows.slot_store.get()) % line) % line;
    rows.slots = rows.slot_store.get() + skip / sizeof(U);
  }
  U *slots = rows.slots;
  U *count = rows.count.data();
  bool block_missing = false;
  for (std::size_t f = 0; f < nf; ++f) {
    const Face &A = F[f];
    if (f + kAhead < nf)
      for (int c = 0; c < 3; ++c) {
        const uint32_t w = F[f + kAhead].v[c];
        if (w < n) __builtin_prefetch(slots + 2 * kSlots * std::size_t(w), 1), __builtin_prefetch(count + w, 1);
      }
    // The cells' centres in the same pass over the faces, through the
    // cache as hdt_voronoi_cell (the same bits): a hit here; the misses by
    // blocks of faces just passed, still in cache (a call a face to
    // compute one cost 40 instructions a face more).
    if (centre) {
      if (cache->holds(tri, uint32_t(f))) centre[f] = cache->centre_held(uint32_t(f), nullptr);
      else block_missing = true;
      if (block_missing && ((f + 1) % 256 == 0 || f + 1 == nf)) {
        face_centres(tri, centre, cache, false, f - f % 256, f + 1);
        block_missing = false;
      }
    }
    if ((A.t[0] | A.t[1] | A.t[2]) != 0) {
      // A translated corner (few: the faces across F_g's sides): vertex_star's
      // translation, computed now, where it may add ids; with matrices, the
      // corner's matrix too, as warm_corner_matrices would.
      for (int c = 0; c < 3; ++c) {
        if (A.t[c] == 0 || A.v[c] >= n) continue;
        const TranslationId home = V[A.v[c]].home;
        const TranslationId t = T.inverse(T.compose(A.t[c], T.inverse(home)));
        moved_.push_back({3 * f + c, t});
        if (matrices) {
          T.moebius(A.t[c]);
          if (t != 0) T.moebius(t);
        }
      }
    }
    // Each corner into its vertex's next slot, in face order: its corner
    // index k = 3f + c and the next face about the vertex.
    for (int c = 0; c < 3; ++c) {
      const uint32_t w = A.v[c];
      if (w >= n) throw std::logic_error("all stars: face " + std::to_string(f) + " names no vertex");
      const U k = U(3 * f + c) | (A.t[c] != 0 ? top : U(0));
      const U next = U(A.n[c == 2 ? 0 : c + 1]);
      const U d = count[w]++;
      if (d < kSlots) {
        U *e = slots + 2 * (kSlots * std::size_t(w) + d);
        e[0] = k, e[1] = next;
      } else {
        rows.overflow.push_back({w, k, next});
      }
    }
  }
  if (matrices)
    for (const Vertex &u : V)
      if (u.alive() && u.home != 0) T.moebius(u.home);
  // The overflow by vertex, each vertex's entries still in face order.
  std::stable_sort(rows.overflow.begin(), rows.overflow.end(),
                   [](const Overflow<U> &x, const Overflow<U> &y) { return x.v < y.v; });
  if (rows.order_capacity < entries_) {
    rows.order.reset(new U[entries_]);
    rows.order_capacity = entries_;
  }
}

template <class U>
void AllStars::order_rows(const Triangulation &tri, Rows<U> &rows) {
  constexpr U top = U(1) << (std::numeric_limits<U>::digits - 1);
  const std::vector<Vertex> &V = tri.vertices();
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
    // the previous one leads to. A row lists its faces in increasing order
    // (the scatter ran in face order), so in a small row (nearly all) the
    // entry of face x is at the rank of x, the count of the row's faces
    // below it: a sum of comparisons, without a branch, computed for every
    // entry before the walk, which is then a chain of byte loads. A used
    // mask catches an entry met twice.
    const uint32_t first = V[v].face;
    uint32_t f = first;
    if (d < 16) {
      // The successors' ranks in lanes 0..d-1, the stored face's in lane d.
      uint32_t fc[16], x[16];
      U k[16];
      int32_t succ[16];
      // The lanes ranks reads beyond the row: a fixed-size fill (four
      // vector stores; a fill to d became a call to memset per row).
      for (std::size_t i = 0; i < 16; ++i) x[i] = kNone;
      for (std::size_t i = 0; i < d; ++i)
        k[i] = row[2 * i], fc[i] = uint32_t((k[i] & ~top) / 3), x[i] = uint32_t(row[2 * i + 1]);
      x[d] = first, fc[d] = kNone;  // (a rank of d, a face not in the row, then fails the check)
      ranks(fc, d, x, succ);
      // Checked at the end: each face reached is the one sought (a face
      // not in the row gets the rank of another), and every entry used
      // once.
      int32_t i = succ[d];
      unsigned used = 0;
      uint32_t wrong = 0;
      for (std::size_t j = 0; j < d; ++j) {
        wrong |= fc[i] ^ f;
        used |= 1u << i;
        out[j] = k[i];
        f = x[i];
        i = succ[i];
      }
      if (wrong != 0 || used != (1u << d) - 1 || f != first) throw broken(v);
      continue;
    }
    // A long row: walked by search.
    for (std::size_t j = 0; j < d; ++j) {
      std::size_t i = 0;
      while (i < d && uint32_t((row[2 * i] & ~top) / 3) != f) ++i;
      if (i == d) throw broken(v);
      out[j] = row[2 * i];
      f = uint32_t(row[2 * i + 1]);
    }
    if (f != first) throw broken(v);
  }
  // Every corner in a row (each face names live vertices only).
  if (m != entries_ || spill != rows.overflow.size()) throw broken(n);
  count[n] = U(m);
}

void AllStars::build(const Triangulation &tri, bool matrices, bool wide) { build(tri, matrices, nullptr, nullptr, wide); }

void AllStars::build_cells(const Triangulation &tri, CentreCache &cache, Point *centre, bool wide) {
  cache.reserve(tri);
  build(tri, true, &cache, centre, wide);
}

void AllStars::build(const Triangulation &tri, bool matrices, CentreCache *cache, Point *centre, bool wide) {
  entries_ = 3 * tri.faces().size();
  // Corner indices and the flag in 32 bits while they fit.
  wide_ = wide || entries_ >= (std::size_t(1) << 31);
  if (wide_) {
    small_ = {};
    build_rows(tri, matrices, cache, centre, large_);
    order_rows(tri, large_);
  } else {
    large_ = {};
    build_rows(tri, matrices, cache, centre, small_);
    order_rows(tri, small_);
  }
}

template <class U, class Emit>
void AllStars::each(const Triangulation &tri, const Rows<U> &rows, std::size_t *offsets, const Point *prefetch,
                    Emit &&emit) const {
  constexpr U top = U(1) << (std::numeric_limits<U>::digits - 1);
  const std::vector<Vertex> &V = tri.vertices();
  const U *order = rows.order.get();
  const U *start = rows.count.data();
  const std::size_t n = V.size();
  constexpr std::size_t ahead = 64;  // entries
  for (std::size_t v = 0; v < n; ++v) {
    const std::size_t b = start[v], e = start[v + 1];
    if (offsets) offsets[v] = b;
    const TranslationId home = V[v].home;
    for (std::size_t j = b; j < e; ++j) {
      // The centres of the entries some way on: the cells read them in
      // the vertices' order, scattered over the faces.
      if (prefetch && j + ahead < entries_) __builtin_prefetch(prefetch + (order[j + ahead] & ~top) / 3);
      U k = order[j];
      TranslationId t = home;
      if (k & top) {
        k &= ~top;
        const auto it = std::lower_bound(moved_.begin(), moved_.end(), std::pair<uint64_t, TranslationId>{k, 0},
                                         [](const auto &x, const auto &y) { return x.first < y.first; });
        t = it->second;
      }
      const uint32_t f = uint32_t(k / 3);
      emit(j, f, int(k - 3 * U(f)), t);
    }
  }
  if (offsets) offsets[n] = start[n];
}

template <class Emit>
void AllStars::dispatch(const Triangulation &tri, std::size_t *offsets, const Point *prefetch, Emit &&emit) const {
  if (wide_) each(tri, large_, offsets, prefetch, emit);
  else each(tri, small_, offsets, prefetch, emit);
}

void AllStars::write(const Triangulation &tri, std::size_t *offsets, uint32_t *faces, uint8_t *corners,
                     int32_t *translations) const {
  if (!faces && !corners && !translations) {
    dispatch(tri, offsets, nullptr, [](std::size_t, uint32_t, int, TranslationId) {});
    return;
  }
  if (faces && corners && translations) {  // the usual call: no test per entry
    dispatch(tri, offsets, nullptr, [&](std::size_t j, uint32_t f, int c, TranslationId t) {
      faces[j] = f, corners[j] = uint8_t(c), translations[j] = t;
    });
    return;
  }
  dispatch(tri, offsets, nullptr, [&](std::size_t j, uint32_t f, int c, TranslationId t) {
    if (faces) faces[j] = f;
    if (corners) corners[j] = uint8_t(c);
    if (translations) translations[j] = t;
  });
}

void AllStars::write_cells(const Triangulation &tri, std::size_t *offsets, double *xy, const Point *centre) const {
  group::TranslationTable &T = tri.table();
  // hdt_voronoi_cell's expression, for the same bits. The centres are read
  // in the rows' order, scattered: each() prefetches them some entries on.
  dispatch(tri, offsets, centre, [&](std::size_t j, uint32_t f, int, TranslationId t) {
    const Point p = t == 0 ? centre[f] : T.moebius(t).apply(centre[f]);
    xy[2 * j] = p.re, xy[2 * j + 1] = p.im;
  });
}

}  // namespace hdt::triangulation
