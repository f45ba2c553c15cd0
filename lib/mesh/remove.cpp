// Vertex removal: the hole left by the star of v is filled with the Delaunay
// triangulation of its boundary polygon (hole.hpp); the removal is refused
// when a new face would break the circumdiameter guarantee, before the
// filling when that can be proved from distances (early_refusal.hpp).
#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "mesh/early_refusal.hpp"
#include "mesh/hole.hpp"
#include "mesh/polygon_triangulation.hpp"
#include "mesh/triangulation.hpp"

namespace hdt::mesh {

namespace {

// Whether a vertex occurs twice in the polygon: a hash set of the ids
// (linear probing, kNone: an empty slot) in *slots, O(k).
bool repeats_a_vertex(const std::vector<HoleVertex> &polygon, std::vector<uint32_t> *slots) {
  int bits = 4;
  while ((std::size_t(1) << bits) < 2 * polygon.size()) ++bits;
  slots->assign(std::size_t(1) << bits, kNone);
  const std::size_t mask = slots->size() - 1;
  for (const HoleVertex &h : polygon) {
    std::size_t s = (uint64_t(h.vertex) * 0x9E3779B97F4A7C15ull) >> (64 - bits);
    for (; (*slots)[s] != kNone; s = (s + 1) & mask)
      if ((*slots)[s] == h.vertex) return true;
    (*slots)[s] = h.vertex;
  }
  return false;
}

}  // namespace

template <class Geometry>
bool BasicTriangulation<Geometry>::remove(uint32_t v) {
  check_live(v);
  auto &T = table();
  star(v, &scratch_.star);
  scratch_.old_faces.clear();
  scratch_.boundary.clear();
  scratch_.new_faces.clear();
  // M_g's kernel takes certified double lifts of the hole's points (the
  // ears' order, the early refusal, the circumdiameter tests); a polygon
  // surface's decides from the points alone.
  constexpr bool lifts = std::is_same_v<Geometry, MgGeometry>;
  // The link of v, counterclockwise, in the first star face's frame.
  auto hole_vertex = [&](uint32_t u, TranslationId t) {
    if constexpr (lifts) return lifted_hole_vertex(*kernel_, point(u, t), u);
    else return HoleVertex{point(u, t), u, {}, std::numeric_limits<double>::infinity()};
  };
  std::vector<HoleVertex> &polygon = scratch_.hole;
  polygon.clear();
  polygon.reserve(scratch_.star.size());
  for (const StarFace &s : scratch_.star) {
    const Face &F = faces_[s.face];
    const int a = next(s.corner), b = prev(s.corner);
    scratch_.old_faces.push_back(s.face);
    polygon.push_back(hole_vertex(F.v[a], T.compose(s.frame, F.t[a])));
    scratch_.boundary.push_back({{F.v[a], T.compose(s.frame, F.t[a])},
                         {F.v[b], T.compose(s.frame, F.t[b])},
                         F.n[s.corner],
                         twin(s.face, s.corner),
                         T.compose(s.frame, F.nt[s.corner])});
  }
  // The link never repeats a vertex in a simplicial complex.
  if (repeats_a_vertex(polygon, &scratch_.link_ids)) throw std::logic_error("the link of a vertex repeats a vertex");

  const Face &first = faces_[scratch_.star[0].face];
  const HoleVertex removed = hole_vertex(v, T.compose(scratch_.star[0].frame, first.t[scratch_.star[0].corner]));
  if constexpr (lifts) {
    if (refusal_is_certain(*kernel_, polygon, removed)) {
#ifdef HDT_CHECK_PREDICATES
      // The debugging build checks the proof against the filled hole.
      fill_hole_by_wrapping(*kernel_, polygon, &scratch_.hole_faces);
      bool large = false;
      for (const HoleFace &f : scratch_.hole_faces)
        large = large || kernel_->large_circumdisk(polygon[std::size_t(f[0])].point, polygon[std::size_t(f[1])].point,
                                                   polygon[std::size_t(f[2])].point) > 0;
      if (!large) throw std::logic_error("check_predicates: a removal refused early has no large face");
#endif
      return false;
    }
    if (!fill_hole(*kernel_, polygon, removed, &scratch_.hole_faces)) fill_hole_by_wrapping(*kernel_, polygon, &scratch_.hole_faces);
#ifdef HDT_CHECK_PREDICATES
    // The debugging build checks the fast method against the simple one.
    std::vector<HoleFace> wrapped;
    fill_hole_by_wrapping(*kernel_, polygon, &wrapped);
    auto canonical = [](std::vector<HoleFace> faces) {
      for (HoleFace &f : faces) std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
      std::sort(faces.begin(), faces.end());
      return faces;
    };
    if (canonical(wrapped) != canonical(scratch_.hole_faces))
      throw std::logic_error("check_predicates: the two hole-filling methods disagree");
#endif
  } else {
    fill_hole_by_wrapping(*kernel_, polygon, &scratch_.hole_faces);
  }
  for (const HoleFace &f : scratch_.hole_faces) {
    const TranslatedPoint &a = polygon[std::size_t(f[0])].point, &b = polygon[std::size_t(f[1])].point,
                          &c = polygon[std::size_t(f[2])].point;
    // The lifts, certified, skip the point cache (one test per new face).
    if constexpr (lifts) {
      if (kernel_->large_circumdisk(a, b, c, polygon[std::size_t(f[0])].certified(),
                                    polygon[std::size_t(f[1])].certified(), polygon[std::size_t(f[2])].certified()) > 0)
        return false;
    } else if (kernel_->large_circumdisk(a, b, c) > 0) {
      return false;
    }
    scratch_.new_faces.push_back({{Corner{polygon[std::size_t(f[0])].vertex, a.translation},
                           Corner{polygon[std::size_t(f[1])].vertex, b.translation},
                           Corner{polygon[std::size_t(f[2])].vertex, c.translation}}});
  }
  replace(scratch_.old_faces, scratch_.new_faces, scratch_.boundary, &scratch_.new_ids);
  if (dummy_[v]) --dummies_;
  vertices_[v].face = kNone;
  --live_vertices_;
  return true;
}

template <class Geometry>
std::size_t BasicTriangulation<Geometry>::remove_dummies() {
  // Sweeps in id order until nothing changes. A removal can make room for
  // another only on the link of the removed vertex (whose stars changed), so
  // a dummy refused once is tried again only after that.
  std::vector<bool> changed(vertices_.size(), true);
  for (bool progress = true; progress && dummies_ > 0;) {
    progress = false;
    for (uint32_t v = 0; v < vertices_.size(); ++v) {
      if (!vertices_[v].alive() || !dummy_[v] || !changed[v]) continue;
      changed[v] = false;
      if (!remove(v)) continue;
      progress = true;
      for (const HoleVertex &h : scratch_.hole) changed[h.vertex] = true;
    }
  }
  return dummies_;
}


template bool Triangulation::remove(uint32_t);
template std::size_t Triangulation::remove_dummies();
template bool PolygonTriangulation::remove(uint32_t);
template std::size_t PolygonTriangulation::remove_dummies();

}  // namespace hdt::mesh
