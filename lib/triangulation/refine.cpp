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

bool is_bad(const Triangulation &tri, const Face &f, const RefineBounds &b, Circle *circle) {
  const Point p[3] = {face_corner(tri, f, 0), face_corner(tri, f, 1), face_corner(tri, f, 2)};
  *circle = circumcircle(tri, f, p);
  const double r = circle->radius * (1 + kRefineMargin);
  if (r > b.max_radius) return true;
  // No shape bound (epsilon-nets): no edge lengths needed.
  return b.max_ratio != HUGE_VAL && r > b.max_ratio * shortest_edge(p);
}

namespace {

struct Entry {
  double radius;
  Point centre;
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

Refined refine(Triangulation &tri, const RefineBounds &b, std::size_t max_points, const Progress *progress) {
  check(b);
  std::priority_queue<Entry> queue;
  auto offer = [&](uint32_t slot) {
    const Face &f = tri.faces()[slot];
    Circle c;
    if (is_bad(tri, f, b, &c)) queue.push({c.radius, c.centre, slot, f.v, f.t});
  };
  for (uint32_t s = 0; s < tri.faces().size(); ++s) offer(s);

  Refined out{0, 0};
  std::vector<StarEntry> star;
  ProgressTicker ticker(progress, 0);
  bool stopped = false;
  while (!queue.empty() && out.added < max_points && !stopped) {
    const Entry e = queue.top();
    queue.pop();
    if (e.slot >= tri.faces().size()) continue;
    const Face &f = tri.faces()[e.slot];
    if (f.v != e.v || f.t != e.t) continue;  // replaced since it was queued
    // The rounded circumcentre of the face's canonical copy: insert() finds
    // its representative and decides everything with exact predicates; its
    // walk starts at the face's corner, a circumradius away.
    const Point c = e.centre;
    const std::size_t before = tri.vertices().size();
    const Triangulation::Inserted in = tri.insert_near(c.re, c.im, f.v[0]);
    if (in.existed || in.vertex < before)
      throw std::logic_error("refine: a circumcentre fell on a vertex (its circle is not empty)");
    ++out.added;
    vertex_star(tri, in.vertex, &star);
    for (const StarEntry &s : star) offer(s.face);
    stopped = ticker.stop(out.added);
  }
  if (!stopped) ticker.finish(out.added);
  if (!queue.empty()) {
    Circle c;
    for (const Face &f : tri.faces()) out.unmet += is_bad(tri, f, b, &c) ? 1 : 0;
  }
  return out;
}

}  // namespace hdt::triangulation
