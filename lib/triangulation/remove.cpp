// Vertex removal: the hole left by the star of v is filled with the Delaunay
// triangulation of its boundary polygon, clipping Delaunay ears; the removal
// is refused when a new face would break the circumdiameter guarantee.
#include <stdexcept>
#include <string>

#include "triangulation/triangulation.hpp"

namespace hdt::triangulation {

bool Triangulation::remove(uint32_t v) {
  if (v >= vertices_.size() || !vertices_[v].alive())
    throw std::invalid_argument("vertex " + std::to_string(v) + " is not a live vertex");
  group::TranslationTable &T = kernel_->table();
  star(v, &star_);
  old_faces_.clear();
  boundary_.clear();
  new_faces_.clear();
  std::vector<Corner> polygon;  // the link of v, counterclockwise, in the first star face's frame
  polygon.reserve(star_.size());
  for (const StarFace &s : star_) {
    const Face &F = faces_[s.face];
    const int a = next(s.corner), b = prev(s.corner);
    old_faces_.push_back(s.face);
    polygon.push_back({F.v[a], T.compose(s.frame, F.t[a])});
    boundary_.push_back({{F.v[a], T.compose(s.frame, F.t[a])},
                         {F.v[b], T.compose(s.frame, F.t[b])},
                         F.n[s.corner],
                         twin(s.face, s.corner),
                         T.compose(s.frame, F.nt[s.corner])});
  }
  for (std::size_t i = 0; i < polygon.size(); ++i)
    for (std::size_t j = i + 1; j < polygon.size(); ++j)
      if (polygon[i].v == polygon[j].v) throw std::logic_error("the link of a vertex repeats a vertex");
  auto at = [&](const Corner &c) { return point(c.v, c.t); };

  // An ear (a, b, c) convex at b whose circle holds no other link vertex is
  // a face of the Delaunay triangulation of the link, inside the hole.
  while (polygon.size() > 3) {
    const std::size_t n = polygon.size();
    bool clipped = false;
    for (std::size_t i = 0; i < n && !clipped; ++i) {
      const Corner &a = polygon[(i + n - 1) % n], &b = polygon[i], &c = polygon[(i + 1) % n];
      if (kernel_->orientation(at(a), at(b), at(c)) <= 0) continue;
      bool empty = true;
      for (std::size_t j = 0; j < n && empty; ++j) {
        if (j == i || j == (i + 1) % n || j == (i + n - 1) % n) continue;
        const Corner &d = polygon[j];
        empty = kernel_->in_circle_perturbed({at(a), at(b), at(c), at(d)}, {a.v, b.v, c.v, d.v}) < 0;
      }
      if (!empty) continue;
      new_faces_.push_back({{a, b, c}});
      polygon.erase(polygon.begin() + long(i));
      clipped = true;
    }
    if (!clipped) throw std::logic_error("vertex removal found no Delaunay ear");
  }
  if (kernel_->orientation(at(polygon[0]), at(polygon[1]), at(polygon[2])) <= 0)
    throw std::logic_error("vertex removal left a flat last triangle");
  new_faces_.push_back({{polygon[0], polygon[1], polygon[2]}});

  for (const NewFace &f : new_faces_)
    if (kernel_->large_circumdisk(at(f.c[0]), at(f.c[1]), at(f.c[2])) > 0) return false;
  replace(old_faces_, new_faces_, boundary_, &new_ids_);
  if (dummy_[v]) --dummies_;
  vertices_[v].face = kNone;
  --live_vertices_;
  return true;
}

std::size_t Triangulation::remove_dummies() {
  // A removal can make room for another, so sweep until nothing changes.
  for (bool progress = true; progress && dummies_ > 0;) {
    progress = false;
    for (uint32_t v = 0; v < vertices_.size(); ++v)
      if (vertices_[v].alive() && dummy_[v] && remove(v)) progress = true;
  }
  return dummies_;
}

}  // namespace hdt::triangulation
