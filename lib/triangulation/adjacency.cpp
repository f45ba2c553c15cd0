// The star of a vertex and the edge list, read off the faces' neighbours.
#include "triangulation/adjacency.hpp"

#include <stdexcept>
#include <string>

namespace hdt::triangulation {

TranslationId public_corner(const Triangulation &tri, const Face &f, int i) {
  const TranslationId home = tri.vertices()[f.v[i]].home;
  if (home == 0) return f.t[i];
  group::TranslationTable &T = tri.table();
  return T.compose(f.t[i], T.inverse(home));
}

void vertex_star(const Triangulation &tri, uint32_t v, std::vector<StarEntry> *out) {
  if (v >= tri.vertices().size() || !tri.vertices()[v].alive())
    throw std::invalid_argument("vertex " + std::to_string(v) + " is not a live vertex");
  group::TranslationTable &T = tri.table();
  const auto &faces = tri.faces();
  const uint32_t first = tri.vertices()[v].face;
  out->clear();
  uint32_t f = first;
  do {
    const Face &F = faces[f];
    int c = 0;
    while (c < 3 && F.v[c] != v) ++c;
    if (c == 3) throw std::logic_error("vertex_star: face " + std::to_string(f) + " does not hold vertex " +
                                       std::to_string(v));
    out->push_back({f, c, T.inverse(public_corner(tri, F, c))});
    // Counterclockwise about v: the next face holds the edge from v to the corner after it.
    f = F.n[next(c)];
    if (out->size() > faces.size()) throw std::logic_error("vertex_star: the star does not close");
  } while (f != first);
}

TranslationId edge_translation(const Triangulation &tri, const Face &F, int i) {
  group::TranslationTable &T = tri.table();
  return T.compose(T.inverse(public_corner(tri, F, next(i))), public_corner(tri, F, prev(i)));
}

}  // namespace hdt::triangulation
