// Refinement with a lazy priority queue: a face is queued with its shape
// and its identity (vertices and corner translations); an entry whose slot
// holds another face by the time it comes out is dropped. A face that is
// still there is still a face of the Delaunay triangulation, so its circle
// is still empty, which is what the termination proof needs of every
// Steiner point. The faces a Steiner point creates are exactly its star.
#include "triangulation/refine.hpp"

#include <cmath>
#include <queue>
#include <stdexcept>
#include <vector>

#include "triangulation/adjacency.hpp"
#include "triangulation/quality.hpp"

namespace hdt::triangulation {

bool is_bad(const Triangulation &tri, const Face &f, const RefineBounds &b, double *radius) {
  const FaceShape s = face_shape(tri, f);
  *radius = s.circle.radius;
  const double r = s.circle.radius * (1 + kRefineMargin);
  return r > b.max_radius || r > b.max_ratio * s.shortest_edge;
}

namespace {

struct Entry {
  double radius;
  uint32_t slot;
  std::array<uint32_t, 3> v;
  std::array<TranslationId, 3> t;
  bool operator<(const Entry &o) const { return radius < o.radius; }  // max-heap on the radius
};

void check(const RefineBounds &b) {
  if (!(b.max_radius > 0)) throw std::invalid_argument("max_radius must be > 0 (not NaN)");
  if (!(b.max_ratio >= 1)) throw std::invalid_argument("max_ratio must be >= 1 (not NaN)");
}

}  // namespace

Refined refine(Triangulation &tri, const RefineBounds &b, std::size_t max_points) {
  check(b);
  std::priority_queue<Entry> queue;
  auto offer = [&](uint32_t slot) {
    const Face &f = tri.faces()[slot];
    double radius;
    if (is_bad(tri, f, b, &radius)) queue.push({radius, slot, f.v, f.t});
  };
  for (uint32_t s = 0; s < tri.faces().size(); ++s) offer(s);

  Refined out{0, 0};
  std::vector<StarEntry> star;
  while (!queue.empty() && out.added < max_points) {
    const Entry e = queue.top();
    queue.pop();
    if (e.slot >= tri.faces().size()) continue;
    const Face &f = tri.faces()[e.slot];
    if (f.v != e.v || f.t != e.t) continue;  // replaced since it was queued
    // The rounded circumcentre of the face's canonical copy: insert() finds
    // its representative and decides everything with exact predicates.
    const Point c = face_shape(tri, f).circle.centre;
    const std::size_t before = tri.vertices().size();
    const Triangulation::Inserted in = tri.insert(c.re, c.im);
    if (in.existed || in.vertex < before)
      throw std::logic_error("refine: a circumcentre fell on a vertex (its circle is not empty)");
    ++out.added;
    vertex_star(tri, in.vertex, &star);
    for (const StarEntry &s : star) offer(s.face);
  }
  if (!queue.empty()) {
    double radius;
    for (const Face &f : tri.faces()) out.unmet += is_bad(tri, f, b, &radius) ? 1 : 0;
  }
  return out;
}

}  // namespace hdt::triangulation
