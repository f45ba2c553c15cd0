// The star of a vertex and the edge list, read off the faces' neighbours.
#include "dual/adjacency.hpp"

#include <stdexcept>
#include <string>
#include "mesh/polygon_triangulation.hpp"

namespace hdt::dual {

template <class Tri>
void vertex_star(const Tri &tri, uint32_t v, std::vector<StarEntry> *out) {
  tri.check_live(v);
  auto &T = tri.table();
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

template <class Tri>
mesh::TranslationId edge_translation(const Tri &tri, const mesh::Face &F, int i) {
  auto &T = tri.table();
  return T.compose(T.inverse(public_corner(tri, F, mesh::next(i))), public_corner(tri, F, mesh::prev(i)));
}

// Both kinds of triangulation: M_g's and a polygon surface's.
#define HDT_DUAL_INSTANTIATE(Tri) \
  template void vertex_star(const Tri &, uint32_t, std::vector<StarEntry> *); \
  template mesh::TranslationId edge_translation(const Tri &, const mesh::Face &, int);
HDT_DUAL_INSTANTIATE(mesh::Triangulation)
HDT_DUAL_INSTANTIATE(mesh::PolygonTriangulation)
#undef HDT_DUAL_INSTANTIATE

}  // namespace hdt::dual
