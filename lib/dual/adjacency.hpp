// Read-only queries of the mesh's combinatorics for users: the faces around
// a vertex and the edge list, with translation ids in hdt_faces' convention
// (relative to the vertices' representatives, not to their stored points).
// They read the public accessors of Triangulation only.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/triangulation.hpp"

namespace hdt::dual {

// Corner i of face f as hdt_faces gives it: the element c with c(rep) at
// that corner of the canonical copy, rep the vertex's representative.
// Inline: the edge list and the stars ask it of every corner, and most
// vertices are at home in F_g.
template <class Tri>
inline mesh::TranslationId public_corner(const Tri &tri, const mesh::Face &f, int i) {
  const mesh::TranslationId home = tri.vertices()[f.v[i]].home;
  if (home == 0) return f.t[i];
  auto &T = tri.table();
  return T.compose(f.t[i], T.inverse(home));
}

struct StarEntry {
  uint32_t face;
  int corner;                 // the vertex's corner in the face
  mesh::TranslationId translation;  // translation(canonical copy) has the vertex at its representative
};
// The faces around the live vertex v, counterclockwise, from the face the
// vertex stores. Throws std::invalid_argument for a dead or unknown vertex.
template <class Tri>
void vertex_star(const Tri &tri, uint32_t v, std::vector<StarEntry> *out);

// The edges, each once: edge i of face f (opposite corner i, from corner
// i+1 to corner i+2, f on its left) is listed with f when f is the smaller
// of its two faces (a face of a simplicial complex is never its own
// neighbour), by increasing f, then i.
inline bool edge_listed_with(const mesh::Face &F, uint32_t f, int i) { return F.n[i] > f; }
// The translation h of that edge: it runs from rep(a) to h(rep(b)), a and
// b the vertices of corners i+1 and i+2 (c_a^-1 c_b for their corner
// translations). May add ids to the table.
template <class Tri>
mesh::TranslationId edge_translation(const Tri &tri, const mesh::Face &F, int i);

}  // namespace hdt::dual
