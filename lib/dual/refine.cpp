// Refinement with a stack of bad faces: a face is pushed with its
// circumcentre and its identity (vertices and corner translations); an
// entry whose slot holds another face by the time it comes out is dropped.
// A face that is still there is still a face of the Delaunay triangulation,
// so its circle is still empty, which is all the termination proof needs of
// a Steiner point (docs/refinement.md): the order is free. Last in, first
// out keeps the work local: the faces a Steiner point creates (exactly its
// star) are handled next, in memory that is still in the caches, and the
// circumcentre is inserted straight into the face's cavity (it lies inside
// the face's circle), with no walk.
#include "dual/refine.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <new>
#include <stdexcept>
#include <vector>

#include "dual/quality.hpp"
#include "mesh/polygon_triangulation.hpp"

namespace hdt::dual {

template <class Tri>
bool is_bad(const Tri &tri, const mesh::Face &f, const RefineBounds &b, Circle *circle) {
  const Point p[3] = {face_corner(tri, f, 0), face_corner(tri, f, 1), face_corner(tri, f, 2)};
  *circle = coarse_circumcircle(tri, f, p);
  const double r = circle->radius * (1 + kRefineMargin);
  if (r > b.max_radius) return true;
  // No shape bound (epsilon-nets): no edge lengths needed.
  return b.max_ratio != HUGE_VAL && r > b.max_ratio * shortest_edge(p);
}

namespace {

struct Entry {
  Point centre;
  uint32_t slot;
  std::array<uint32_t, 3> v;
  std::array<mesh::TranslationId, 3> t;
};

// Bad faces by circumradius in classes of ratio 2^(1/kSteps): the largest
// class first, last in first out within a class. Close to largest first
// (which spreads the points evenly, so fewer of them), and local: the new
// faces of a Steiner point are mostly handled next, while their memory is
// still in the caches.
class Buckets {
 public:
  void push(double radius, const Entry &e) {
    const int k = std::clamp(int(std::floor(std::log2(radius) * kSteps)) + kLevels / 2, 0, kLevels - 1);
    level_[k].push_back(e);
    top_ = std::max(top_, k);
  }
  bool pop(Entry *e) {
    for (; top_ >= 0; --top_)
      if (!level_[top_].empty()) {
        *e = level_[top_].back();
        level_[top_].pop_back();
        return true;
      }
    return false;
  }
  bool empty() const {
    for (int k = 0; k <= top_; ++k)
      if (!level_[k].empty()) return false;
    return true;
  }

 private:
  static constexpr int kSteps = 2, kLevels = 256;
  std::array<std::vector<Entry>, kLevels> level_;
  int top_ = -1;
};

void check(const RefineBounds &b) {
  if (!(b.max_radius > 0)) throw std::invalid_argument("max_radius must be > 0 (not NaN)");
  if (!(b.max_ratio >= 1)) throw std::invalid_argument("max_ratio must be >= 1 (not NaN)");
}

// The faces still breaking the bounds; all of them when memory is too short
// even to look (an upper bound, as refine.hpp promises).
template <class Tri>
std::size_t count_unmet(const Tri &tri, const RefineBounds &b) noexcept {
  try {
    std::size_t unmet = 0;
    Circle c;
    for (const mesh::Face &f : tri.faces()) unmet += is_bad(tri, f, b, &c) ? 1 : 0;
    return unmet;
  } catch (const std::bad_alloc &) {
    return tri.faces().size();
  }
}

}  // namespace

double vertices_needed(int genus, double max_radius) {
  if (std::isinf(max_radius)) return 0;
  const double s = std::sinh(max_radius / 2);
  return (genus - 1) / (s * s);
}

double bytes_needed(double vertices) { return vertices * (sizeof(mesh::Vertex) + 1 + 2 * sizeof(mesh::Face)); }

bool resolvable(const Circle &c) {
  // The Euclidean radius of the hyperbolic circle of centre c and radius R
  // is (1 - |c|^2) t / (1 - |c|^2 t^2) >= (1 - |c|^2) t, t = tanh(R / 2),
  // and t >= R / 4 for R <= 2: most faces pass without the tanh, which
  // would otherwise run for every new face of a refinement.
  const double c2 = c.centre.re * c.centre.re + c.centre.im * c.centre.im, w = 1 - c2;
  if (c.radius <= 2 && w * c.radius >= 4 * kResolution) return true;
  const double t = std::tanh(c.radius / 2);
  return w * t / (1 - c2 * t * t) >= kResolution;
}

template <class Tri>
Refined refine(Tri &tri, const RefineBounds &b, std::size_t max_points, const mesh::Progress *progress) {
  check(b);
  Refined out{0, 0, false};
  const std::size_t ids_before = tri.vertices().size();  // ids are never reused: the count of points added
  bool left = false;  // a bad face left for good (below the resolution, or its centre not inside)
  std::vector<uint32_t> created;
  mesh::ProgressTicker ticker(progress, 0);
  bool stopped = false;
  try {
    Buckets bad;
    auto offer = [&](uint32_t slot) {
      const mesh::Face &f = tri.faces()[slot];
      Circle c;
      if (!is_bad(tri, f, b, &c)) return;
      if (resolvable(c)) bad.push(c.radius, {c.centre, slot, f.v, f.t});
      else left = true;
    };
    for (uint32_t s = 0; s < tri.faces().size(); ++s) offer(s);
    Entry e;
    while (out.added < max_points && !stopped && bad.pop(&e)) {
      if (e.slot >= tri.faces().size()) continue;
      const mesh::Face &f = tri.faces()[e.slot];
      if (f.v != e.v || f.t != e.t) continue;  // replaced since it was pushed
      // The rounded circumcentre of the face's canonical copy, in that
      // copy's frame; the insertion decides everything with exact
      // predicates, and refuses a centre that rounded onto the circle or
      // out of it (a face that double cannot refine: it stays bad).
      const std::size_t before = tri.vertices().size();
      const typename Tri::Inserted in = tri.insert_in_circle(e.centre.re, e.centre.im, e.slot, &created);
      if (in.vertex == mesh::kNone) {
        left = true;
        continue;
      }
      if (in.existed || in.vertex < before) throw std::logic_error("refine: a point strictly inside an empty circle was a vertex");
      ++out.added;
      for (const uint32_t s : created) offer(s);
      stopped = ticker.stop(out.added);
    }
    if (!stopped) ticker.finish(out.added);
    if (!bad.empty() || left) out.unmet = count_unmet(tri, b);
  } catch (const std::bad_alloc &) {
    // Each insertion either completes or changes nothing (insert.cpp), so
    // the points added so far stay, in a valid triangulation.
    out.out_of_memory = true;
    out.added = tri.vertices().size() - ids_before;  // one may have been inserted before *created failed
    out.unmet = count_unmet(tri, b);
  }
  return out;
}

// Both kinds of triangulation: M_g's and a polygon surface's.
#define HDT_DUAL_INSTANTIATE(Tri) \
  template bool is_bad(const Tri &, const mesh::Face &, const RefineBounds &, Circle *); \
  template Refined refine(Tri &, const RefineBounds &, std::size_t, const mesh::Progress *);
HDT_DUAL_INSTANTIATE(mesh::Triangulation)
HDT_DUAL_INSTANTIATE(mesh::PolygonTriangulation)
#undef HDT_DUAL_INSTANTIATE

}  // namespace hdt::dual
