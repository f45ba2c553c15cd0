// The star of a vertex and the edge list, read off the faces' neighbours.
#include "dual/adjacency.hpp"

#include <stdexcept>
#include <string>

namespace hdt::dual {

void vertex_star(const mesh::Triangulation &tri, uint32_t v, std::vector<StarEntry> *out) {
  tri.check_live(v);
  group::TranslationTable &T = tri.table();
  const auto &faces = tri.faces();
  const uint32_t first = tri.vertices()[v].face;
  // public_corner of v's corner in each face, with v's home read once.
  const mesh::TranslationId home = tri.vertices()[v].home, home_inverse = T.inverse(home);
  out->clear();
  std::size_t left = faces.size();  // a star that does not close is a broken invariant
  uint32_t f = first;
  do {
    const mesh::Face &F = faces[f];
    const int c = F.v[0] == v ? 0 : F.v[1] == v ? 1 : 2;
    if (F.v[c] != v)
      throw std::logic_error("vertex_star: face " + std::to_string(f) + " does not hold vertex " + std::to_string(v));
    // (t h^-1)^-1 for the corner's t and v's home h; most corners, and
    // most homes, are the identity.
    const mesh::TranslationId t = F.t[c] == 0 ? home : T.inverse(T.compose(F.t[c], home_inverse));
    out->push_back({f, c, t});
    // Counterclockwise about v: the next face holds the edge from v to the corner after it.
    f = F.n[c == 2 ? 0 : c + 1];
    if (--left == 0 && f != first) throw std::logic_error("vertex_star: the star does not close");
  } while (f != first);
}

mesh::TranslationId edge_translation(const mesh::Triangulation &tri, const mesh::Face &F, int i) {
  group::TranslationTable &T = tri.table();
  return T.compose(T.inverse(public_corner(tri, F, mesh::next(i))), public_corner(tri, F, mesh::prev(i)));
}

}  // namespace hdt::dual
