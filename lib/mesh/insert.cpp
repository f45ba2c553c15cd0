// Bowyer-Watson insertion on the surface, and insertion in Hilbert order.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <new>
#include <stdexcept>
#include <string>

#include "exact/unsupported.hpp"
#include "mesh/polygon_triangulation.hpp"
#include "mesh/triangulation.hpp"

namespace hdt::mesh {

namespace {

// Makes the next push_back unable to throw, keeping geometric growth.
template <class Vector>
void grow_for_one(Vector &v) {
  if (v.size() == v.capacity()) v.reserve(v.size() < 8 ? 16 : 2 * v.size());
}

// Room for k more elements in v, growing at least twofold: a series of calls
// of a few points each copied everything at every call when each reserved
// just its own room. Where twice is not to be had, just the room asked for.
template <class Vector>
void grow_for(Vector &v, std::size_t k) {
  if (v.capacity() - v.size() >= k) return;
  try {
    v.reserve(std::max(v.size() + k, 2 * v.capacity()));
  } catch (const std::bad_alloc &) {
    v.reserve(v.size() + k);
  }
}

}  // namespace

template <class Geometry>
bool BasicTriangulation<Geometry>::met_vertex(uint32_t v) {
  last_vertex_ = v;
  if (!dummy_[v]) return false;
  dummy_[v] = false;  // the user's point is this dummy: it stays, as theirs
  --dummies_;
  ++revision_;
  return true;
}

template <class Geometry>
uint32_t BasicTriangulation<Geometry>::vertex_at(const Walk &at) const {
  // On the lines of two edges means at their common corner, exactly.
  if (at.zero_edges == 0 || (at.zero_edges & (at.zero_edges - 1)) == 0) return kNone;
  for (int i = 0; i < 3; ++i)
    if (!(at.zero_edges & (1 << i))) return faces_[at.face].v[i];
  throw std::logic_error("a point on all three edge lines of a face");
}

template <class Geometry>
typename BasicTriangulation<Geometry>::Inserted BasicTriangulation<Geometry>::insert(double x, double y) {
  const TranslationId home = geometry_->home(x, y);
  HomeImageScope image(*geometry_, x, y, home);
  const std::size_t before = vertices_.size();
  jump_near(x, y, home);
  const Inserted result = insert_walked(x, y, home, walk_from_hint({x, y, home, -1}));
  if (vertices_.size() > before) image.keep();
  return result;
}

template <class Geometry>
typename BasicTriangulation<Geometry>::Inserted BasicTriangulation<Geometry>::insert_in_circle(double x, double y, uint32_t face,
                                                        std::vector<uint32_t> *created) {
  if (face >= faces_.size()) throw std::invalid_argument("insert_in_circle: face " + std::to_string(face) + " is unknown");
  const Face &F = faces_[face];
  const TranslatedPoint q{x, y, 0, -1};  // in the frame of F's canonical copy
  created->clear();
  // Strictly inside the (empty) circle of a Delaunay face: q is no vertex,
  // and F conflicts with it, so the cavity search may start at F. Anything
  // else (a rounded circumcentre on the circle or beyond it) is refused
  // before anything changes: refinement leaves that face.
  if (kernel_->in_circle(corner(F, 0), corner(F, 1), corner(F, 2), q) <= 0) return {kNone, false};
  const TranslationId home = geometry_->home(x, y);
  HomeImageScope image(*geometry_, x, y, home);
  const uint32_t v = insert_located(x, y, home, false, {face, 0, 0});
  image.keep();
  created->assign(scratch_.new_ids.begin(), scratch_.new_ids.end());
  return {v, false};
}

template <class Geometry>
typename BasicTriangulation<Geometry>::Inserted BasicTriangulation<Geometry>::insert_walked(double x, double y, TranslationId home, const Walk &at) {
  const uint32_t existing = vertex_at(at);
  if (existing != kNone) {
    return {existing, !met_vertex(existing)};
  }
  return {insert_located(x, y, home, false, at), false};
}

template <class Geometry>
uint32_t BasicTriangulation<Geometry>::insert_located(double x, double y, TranslationId home, bool dummy, const Walk &at) {
  auto &T = table();
  const auto id = uint32_t(vertices_.size());
  if (id == kNone) throw exact::Unsupported("too many vertices");
  scratch_.old_faces.clear();
  scratch_.boundary.clear();
  scratch_.new_faces.clear();
  scratch_.cavity_stack.clear();

  // The conflict region: the face copies whose circle holds q (the query
  // sits in at.face's canonical frame, the common frame). In the disk it is
  // a topological disk with every vertex on its boundary (Bowyer-Watson's
  // cavity), so its dual graph is a tree: a depth-first search that leaves
  // each face by the edges after the one it came in by, counterclockwise,
  // meets each conflicting copy once, without marks, and lists the boundary
  // counterclockwise, which lets replace() link the new fan in one pass. A
  // face outside that borders the region twice is tested twice (cheaper
  // than looking it up). A face is in conflict in at most one copy (its
  // circle is smaller than sys/2), and reached once: the check of both also
  // bounds the search on a broken triangulation.
  scratch_.old_faces.push_back(at.face);
  scratch_.cavity_stack.push_back({at.face, 0, 0, 3});
  while (!scratch_.cavity_stack.empty()) {
    Scratch::CavityStep &top = scratch_.cavity_stack.back();
    if (top.left == 0) {
      scratch_.cavity_stack.pop_back();
      continue;
    }
    const uint32_t f = top.face;
    const TranslationId sigma = top.frame;
    const int i = top.edge;
    top.edge = int8_t(next(i)), --top.left;
    const Face &F = faces_[f];
    const uint32_t n = F.n[i];
    const TranslationId sn = T.compose(sigma, F.nt[i]);
    const int back = twin(f, i);
    const Face &N = faces_[n];
    const TranslatedPoint qn{x, y, T.compose(T.inverse(sn), at.query), -1};
    if (kernel_->in_circle_perturbed({corner(N, 0), corner(N, 1), corner(N, 2), qn}, {N.v[0], N.v[1], N.v[2], id}) >
        0) {
      for (const uint32_t o : scratch_.old_faces)
        if (o == n) throw std::logic_error("a face conflicts twice (in two copies, or the cavity is no disk)");
      scratch_.old_faces.push_back(n);
      scratch_.cavity_stack.push_back({n, sn, int8_t(next(back)), 2});
    } else {
      scratch_.boundary.push_back({{F.v[next(i)], T.compose(sigma, F.t[next(i)])},
                           {F.v[prev(i)], T.compose(sigma, F.t[prev(i)])},
                           n,
                           back,
                           sn});
    }
  }
  // Star the hole from q.
  for (const BoundaryEdge &e : scratch_.boundary) scratch_.new_faces.push_back({{e.a, e.b, Corner{id, at.query}}});
  // Room first, so that the two push_backs cannot fail halfway: an
  // allocation failure anywhere leaves the triangulation as it was.
  grow_for_one(vertices_);
  grow_for_one(dummy_);
  vertices_.push_back({x, y, home, kNone});
  dummy_.push_back(dummy);
  try {
    replace(scratch_.old_faces, scratch_.new_faces, scratch_.boundary, &scratch_.new_ids);
  } catch (...) {
    vertices_.pop_back();
    dummy_.pop_back();
    throw;
  }
  ++live_vertices_;
  if (dummy) ++dummies_;
  last_vertex_ = id;
  return id;
}

namespace {

// Index of (x, y) in [0, 2^15)^2 along a Hilbert curve (30 bits).
uint32_t hilbert_index(uint32_t x, uint32_t y) {
  uint32_t d = 0;
  for (uint32_t s = 1u << 14; s > 0; s >>= 1) {
    const uint32_t rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
    d += s * s * ((3 * rx) ^ ry);
    if (ry == 0) {
      if (rx == 1) x = (s - 1) - (x & (s - 1)) + (x & ~(s - 1)), y = (s - 1) - (y & (s - 1)) + (y & ~(s - 1));
      std::swap(x, y);
    }
  }
  return d;
}

// The image under a representative's translation is computed in double for
// the sort key only; within ulps of the circle it can be NaN (0/0: found by
// fuzzing), which std::clamp would pass on to an undefined conversion.
uint32_t grid(double c) { return std::isfinite(c) ? uint32_t(std::clamp((c + 1) * 16384.0, 0.0, 32767.0)) : 0; }

// Sorts items by their key (30 bits), stably: three passes of 10 bits (an
// LSD radix sort: linear in the items, where std::sort compares). The
// buffer is freed before the triangulation reserves room for the new faces,
// so it does not raise the peak memory.
template <class Item>
void sort_along_curve(std::vector<Item> &items) {
  // A few items: the passes' 3 x 1024 buckets would cost more than the
  // items (a call of hdt_insert_many with a few points); the same stable order.
  if (items.size() < 256) {
    std::stable_sort(items.begin(), items.end(), [](const Item &a, const Item &b) { return a.key < b.key; });
    return;
  }
  std::vector<Item> buffer(items.size());
  for (int shift = 0; shift < 30; shift += 10) {
    std::array<std::size_t, 1025> start{};
    for (const Item &item : items) ++start[((item.key >> shift) & 1023) + 1];
    for (int b = 0; b < 1024; ++b) start[b + 1] += start[b];
    for (const Item &item : items) buffer[start[(item.key >> shift) & 1023]++] = item;
    items.swap(buffer);
  }
}

// The round of point i in a biased randomized insertion order (Amenta, Choi
// and Rote): the last round gets about half the points, the one before a
// quarter, and so on, by a fixed hash of i (the same call gives the same
// triangulation ids every time). Inserted round by round, each round along
// the Hilbert curve, the first points form a sample spread over the whole
// surface, so that points given along a curve no longer come in the order
// along it, the bad case of incremental insertion: there each insertion
// destroyed about 10 faces, a few of them hundreds (5 for random points).
uint32_t brio_round(uint64_t i, uint32_t last) {
  uint64_t z = i + 0x9e3779b97f4a7c15ULL;  // splitmix64
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  const uint32_t ones = uint32_t(__builtin_ctzll(~z));  // geometric: P(ones >= k) = 2^-k
  return ones >= last ? 0 : last - ones;
}

// Stable partition of items sorted along the curve by their round.
template <class Item>
void order_by_round(std::vector<Item> &items, uint32_t rounds) {
  std::vector<std::size_t> start(rounds + 1, 0);
  for (const Item &item : items) ++start[item.round + 1];
  for (uint32_t r = 0; r < rounds; ++r) start[r + 1] += start[r];
  std::vector<Item> buffer(items.size());
  for (const Item &item : items) buffer[start[item.round]++] = item;
  items.swap(buffer);
}

}  // namespace

template <class Geometry>
void BasicTriangulation<Geometry>::insert_many(const double *xy, std::size_t n, uint32_t *out, const Progress *progress) {
  // Check every point first: a bad one rejects the call before any change.
  // The points are copied in Hilbert order of their representatives (reading
  // the caller's array in that order would miss the cache at every point),
  // each with its representative's translation: finding it again costs more
  // than moving 8 more bytes per point through the sort (for a point
  // outside F_g, as along a curve, finding it is a reduction into F_g).
  struct Item {
    uint32_t key, index;
    double x, y;
    TranslationId home;
    uint32_t round;
  };
  // Rounds of at least 1024 points (fewer points: one round, Hilbert order).
  uint32_t last = 0;
  while ((std::size_t(1024) << last) < n && last < 30) ++last;
  std::vector<Item> order(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = xy[2 * i], y = xy[2 * i + 1];
    TranslationId home;
    try {
      home = geometry_->home(x, y);
    } catch (const std::domain_error &) {
      char text[128];  // %.17g: the coordinates read back as the same doubles
      std::snprintf(text, sizeof text, "point %zu (%.17g, %.17g) is not a finite point of the open unit disk", i, x, y);
      throw std::domain_error(text);
    }
    double rx = x, ry = y;
    if (home != 0) {
      const auto z = geometry_->quick_image(x, y, home);
      rx = z.re, ry = z.im;
    }
    order[i] = {hilbert_index(grid(rx), grid(ry)), uint32_t(i), x, y, home, brio_round(i, last)};
  }
  sort_along_curve(order);
  if (last > 0) order_by_round(order, last + 1);
  grow_for(vertices_, n);
  grow_for(dummy_, n);
  grow_for(faces_, 2 * n);
  // From here on a failure (out of memory) keeps the points inserted so far;
  // the caller learns which ones from the ids.
  if (out) std::fill(out, out + n, kNone);
  ProgressTicker ticker(progress, n);
  std::size_t done = 0;
  // The first point of a round is in no relation to the last one inserted:
  // it jumps as insert() does (jump_near, by random samples: a round's grid
  // would cost more than it saves), and the others follow the curve. In a
  // call of n points among V vertices they are still about sqrt(2V / n)
  // faces apart, and below n = V / 8 (4 faces) every point jumps by the
  // grid instead.
  const bool jump_each = 8 * double(n) < double(live_vertices_);
  uint32_t round = ~0u;
  for (const Item &item : order) {
    const double x = item.x, y = item.y;
    const TranslationId home = item.home;
    HomeImageScope image(*geometry_, x, y, home);
    if (jump_each || item.round != round) round = item.round, jump_near(x, y, home, jump_each);
    const Walk at = walk_from_hint({x, y, home, -1});
    uint32_t v = vertex_at(at);
    if (v != kNone) {
      met_vertex(v);
    } else {
      v = insert_located(x, y, home, false, at);
      image.keep();
    }
    if (out) out[item.index] = v;
    if (ticker.stop(++done)) return;
  }
  ticker.finish(n);
}


template bool Triangulation::met_vertex(uint32_t);
template uint32_t Triangulation::vertex_at(const Walk &) const;
template Triangulation::Inserted Triangulation::insert(double, double);
template Triangulation::Inserted Triangulation::insert_in_circle(double, double, uint32_t, std::vector<uint32_t> *);
template Triangulation::Inserted Triangulation::insert_walked(double, double, TranslationId, const Walk &);
template uint32_t Triangulation::insert_located(double, double, TranslationId, bool, const Walk &);
template void Triangulation::insert_many(const double *, std::size_t, uint32_t *, const Progress *);

template bool PolygonTriangulation::met_vertex(uint32_t);
template uint32_t PolygonTriangulation::vertex_at(const Walk &) const;
template PolygonTriangulation::Inserted PolygonTriangulation::insert(double, double);
template PolygonTriangulation::Inserted PolygonTriangulation::insert_in_circle(double, double, uint32_t,
                                                                               std::vector<uint32_t> *);
template PolygonTriangulation::Inserted PolygonTriangulation::insert_walked(double, double, TranslationId, const Walk &);
template uint32_t PolygonTriangulation::insert_located(double, double, TranslationId, bool, const Walk &);
template void PolygonTriangulation::insert_many(const double *, std::size_t, uint32_t *, const Progress *);

}  // namespace hdt::mesh
