#include "mesh/hole.hpp"
#include "mesh/polygon_geometry.hpp"

#include <cmath>
#include <limits>
#include <queue>
#include <stdexcept>
#include <utility>

#include "predicates/filtered_point.hpp"

namespace hdt::mesh {

using predicates::Kernel;
using predicates::TranslatedPoint;

namespace {

using Vec3 = std::array<double, 3>;

double det3(const Vec3 &a, const Vec3 &b, const Vec3 &c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}
Vec3 minus(const Vec3 &a, const Vec3 &b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

// A face of the hole under construction: corners (polygon indices)
// counterclockwise and, per corner, the face across the opposite edge (-1:
// the hole's boundary, or not linked yet).
struct Triangle {
  std::array<int, 3> v;
  std::array<int, 3> n;
};

class HoleFiller {
 public:
  HoleFiller(Kernel &kernel, const std::vector<HoleVertex> &polygon, const HoleVertex &removed)
      : K_(kernel), polygon_(polygon), removed_(removed) {}

  bool run(std::vector<HoleFace> *faces) {
    if (!flip_out_removed_vertex() || !make_locally_delaunay()) return false;
    faces->clear();
    for (const Triangle &t : triangles_) faces->push_back(t.v);
    return true;
  }

 private:
  const TranslatedPoint &at(int i) const { return polygon_[std::size_t(i)].point; }
  const Vec3 &lift(int i) const { return polygon_[std::size_t(i)].lift; }
  // The polygon's lifts as certified double points, made once: the tests
  // below read them instead of the kernel's point cache (a hole of a dummy
  // on a curve has hundreds of vertices, each tested a few times).
  const predicates::FilteredPoint &certified(int i) const { return certified_[std::size_t(i)]; }
  int orientation(int a, int b, int c) {
    return K_.orientation(at(a), at(b), at(c), certified(a), certified(b), certified(c));
  }

  // The crossing of the ear at b: in_circle(a, b, c, v) / orientation(a, b,
  // c) in double; +infinity for an ear that is not convex.
  double crossing(int b) const {
    const int a = prev_[std::size_t(b)], c = next_[std::size_t(b)];
    const Vec3 &na = lift(a), &nb = lift(b), &nc = lift(c), &nv = removed_.lift;
    const double orient = det3(na, minus(nb, na), minus(nc, na));
    const double in_circle = det3(minus(na, nv), minus(nb, nv), minus(nc, nv));
    const double r = in_circle / orient;
    return orient > 0 && std::isfinite(r) ? r : std::numeric_limits<double>::infinity();
  }

  void push_ear(int b) {
    ++stamp_[std::size_t(b)];
    heap_.push({crossing(b), b, stamp_[std::size_t(b)]});
  }

  // Links the edge of triangle t opposite corner i with triangle u (or the
  // boundary, u < 0), on both sides.
  void link(int t, int i, int u) {
    triangles_[std::size_t(t)].n[std::size_t(i)] = u;
    if (u < 0) return;
    const Triangle &T = triangles_[std::size_t(t)];
    Triangle &U = triangles_[std::size_t(u)];
    const int a = T.v[std::size_t((i + 1) % 3)], b = T.v[std::size_t((i + 2) % 3)];
    for (int k = 0; k < 3; ++k)
      if (U.v[std::size_t(k)] != a && U.v[std::size_t(k)] != b) U.n[std::size_t(k)] = t;
  }

  int add_triangle(int a, int b, int c) {
    triangles_.push_back({{a, b, c}, {-1, -1, -1}});
    return int(triangles_.size() - 1);
  }

  // Flips the removed vertex's edges in the order of the ears' crossings
  // until it has degree 3, then closes the hole with the last triangle.
  bool flip_out_removed_vertex() {
    const std::size_t k = polygon_.size();
    prev_.resize(k), next_.resize(k), beyond_.assign(k, -1), stamp_.assign(k, 0);
    certified_.resize(k);
    for (std::size_t i = 0; i < k; ++i) certified_[i] = polygon_[i].certified();
    const predicates::FilteredPoint removed = removed_.certified();
    for (std::size_t i = 0; i < k; ++i) prev_[i] = int((i + k - 1) % k), next_[i] = int((i + 1) % k);
    triangles_.clear();
    triangles_.reserve(k - 2);
    for (std::size_t i = 0; i < k; ++i) push_ear(int(i));
    int first = 0;  // a vertex still on the link
    for (std::size_t left = k; left > 3;) {
      if (heap_.empty()) return false;
      const Ear e = heap_.top();
      heap_.pop();
      const int b = e.vertex;
      if (e.stamp != stamp_[std::size_t(b)]) continue;  // stale: a neighbour changed since
      const int a = prev_[std::size_t(b)], c = next_[std::size_t(b)];
      // Exactly: the ear is convex and v lies left of a -> c, so v-b flips.
      if (orientation(a, b, c) <= 0 ||
          K_.orientation(removed_.point, at(a), at(c), removed, certified(a), certified(c)) <= 0)
        continue;
      const int t = add_triangle(a, b, c);
      link(t, 0, beyond_[std::size_t(b)]);  // edge b -> c
      link(t, 2, beyond_[std::size_t(a)]);  // edge a -> b
      next_[std::size_t(a)] = c, prev_[std::size_t(c)] = a, beyond_[std::size_t(a)] = t;
      stamp_[std::size_t(b)] = -1;  // off the link
      if (b == first) first = a;
      --left;
      push_ear(a), push_ear(c);
    }
    const int p = first, q = next_[std::size_t(p)], r = next_[std::size_t(q)];
    if (orientation(p, q, r) <= 0) return false;
    const int t = add_triangle(p, q, r);
    link(t, 0, beyond_[std::size_t(q)]), link(t, 1, beyond_[std::size_t(r)]), link(t, 2, beyond_[std::size_t(p)]);
    return true;
  }

  // Lawson's flips with the exact predicates: each flip lowers the lifted
  // triangulation, so they end, with every inner edge locally Delaunay: the
  // Delaunay triangulation of the polygon.
  bool make_locally_delaunay() {
    std::vector<std::pair<int, int>> stack;
    for (int t = 0; t < int(triangles_.size()); ++t)
      for (int i = 0; i < 3; ++i)
        if (triangles_[std::size_t(t)].n[std::size_t(i)] > t) stack.push_back({t, i});
    while (!stack.empty()) {
      const auto [t, i] = stack.back();
      stack.pop_back();
      const int u = triangles_[std::size_t(t)].n[std::size_t(i)];
      if (u < 0) continue;
      const Triangle T = triangles_[std::size_t(t)], U = triangles_[std::size_t(u)];
      int j = 0;
      while (j < 3 && U.n[std::size_t(j)] != t) ++j;
      if (j == 3) return false;
      const int p = T.v[std::size_t(i)], q = T.v[std::size_t((i + 1) % 3)], r = T.v[std::size_t((i + 2) % 3)];
      const int d = U.v[std::size_t(j)];
      const std::array<TranslatedPoint, 4> points{at(p), at(q), at(r), at(d)};
      const std::array<uint32_t, 4> ids{polygon_[std::size_t(p)].vertex, polygon_[std::size_t(q)].vertex,
                                        polygon_[std::size_t(r)].vertex, polygon_[std::size_t(d)].vertex};
      if (K_.in_circle_perturbed(points, ids, {&certified(p), &certified(q), &certified(r), &certified(d)}) <= 0)
        continue;
      if (orientation(p, q, d) <= 0 || orientation(p, d, r) <= 0) return false;  // d in the circle: never so
      // The neighbours around the quadrilateral p q d r.
      const int across_pq = T.n[std::size_t((i + 2) % 3)], across_rp = T.n[std::size_t((i + 1) % 3)];
      const int across_qd = U.n[std::size_t((j + 1) % 3)], across_dr = U.n[std::size_t((j + 2) % 3)];
      triangles_[std::size_t(t)] = {{p, q, d}, {-1, -1, -1}};
      triangles_[std::size_t(u)] = {{p, d, r}, {-1, -1, -1}};
      link(t, 0, across_qd), link(t, 2, across_pq), link(u, 0, across_dr), link(u, 1, across_rp), link(t, 1, u);
      stack.push_back({t, 0}), stack.push_back({t, 2}), stack.push_back({u, 0}), stack.push_back({u, 1});
    }
    return true;
  }

  struct Ear {
    double crossing;
    int vertex;
    int stamp;
    bool operator<(const Ear &o) const { return crossing > o.crossing; }  // a min-heap
  };

  Kernel &K_;
  const std::vector<HoleVertex> &polygon_;
  const HoleVertex &removed_;
  std::vector<int> prev_, next_;
  std::vector<int> beyond_;  // the triangle across the link edge i -> next(i), or -1
  std::vector<int> stamp_;   // ear version; -1 once off the link
  std::priority_queue<Ear> heap_;
  std::vector<Triangle> triangles_;
  std::vector<predicates::FilteredPoint> certified_;  // by polygon index
};

}  // namespace

HoleVertex lifted_hole_vertex(Kernel &kernel, const TranslatedPoint &p, uint32_t vertex) {
  HoleVertex h{p, vertex, {}, std::numeric_limits<double>::infinity()};
  if (p.site < 0) {
    const predicates::FilteredPoint f =
        p.translation == 0 ? predicates::filtered_point(p.x, p.y)
                           : predicates::filtered_point(p.x, p.y, kernel.surface().table().moebius(p.translation));
    if (f.error < 1e-9 * f.n[0]) {
      h.lift = {f.n[0], f.n[1], f.n[2]};
      h.lift_error = f.error;
      return h;
    }
  }
  bool accurate = false;
  h.lift = kernel.hyperboloid(p, &accurate);
  if (accurate) h.lift_error = 1.01e-9 * h.lift[0];  // and the rounding to double
  return h;
}

bool fill_hole(Kernel &kernel, const std::vector<HoleVertex> &polygon, const HoleVertex &removed,
               std::vector<HoleFace> *faces) {
  return HoleFiller(kernel, polygon, removed).run(faces);
}

template <class Kernel>
void fill_hole_by_wrapping(Kernel &kernel, const std::vector<HoleVertex> &polygon, std::vector<HoleFace> *faces) {
  // The part p[i..j] of the polygon is closed by the edge p[j] -> p[i]; its
  // face on that edge has the third corner c whose circle holds no other
  // vertex of the part on the edge's left: the last one found inside the
  // circle of the one before. It splits the part into p[i..c] and p[c..j].
  faces->clear();
  auto at = [&](int i) { return polygon[std::size_t(i)].point; };
  std::vector<std::pair<int, int>> parts{{0, int(polygon.size()) - 1}};
  while (!parts.empty()) {
    const auto [i, j] = parts.back();
    parts.pop_back();
    int best = -1;
    for (int c = i + 1; c < j; ++c) {
      if (kernel.orientation(at(i), at(c), at(j)) <= 0) continue;
      if (best >= 0 && kernel.in_circle_perturbed({at(i), at(best), at(j), at(c)},
                                                  {polygon[std::size_t(i)].vertex, polygon[std::size_t(best)].vertex,
                                                   polygon[std::size_t(j)].vertex, polygon[std::size_t(c)].vertex}) <= 0)
        continue;
      best = c;
    }
    if (best < 0) throw std::logic_error("vertex removal found no Delaunay triangle on an edge of the hole");
    faces->push_back({i, best, j});
    if (best - i >= 2) parts.push_back({i, best});
    if (j - best >= 2) parts.push_back({best, j});
  }
}

template void fill_hole_by_wrapping(predicates::Kernel &, const std::vector<HoleVertex> &, std::vector<HoleFace> *);
template void fill_hole_by_wrapping(PolygonGeometry::Kernel &, const std::vector<HoleVertex> &, std::vector<HoleFace> *);

}  // namespace hdt::mesh
