// Read-only queries of the mesh's combinatorics for users: the faces around
// a vertex and the edge list, with translation ids in hdt_faces' convention
// (relative to the vertices' representatives, not to their stored points).
// They read the public accessors of Triangulation only.
#pragma once

#include <cstdint>
#include <vector>

#include "triangulation/triangulation.hpp"

namespace hdt::triangulation {

// Corner i of face f as hdt_faces gives it: the element c with c(rep) at
// that corner of the canonical copy, rep the vertex's representative.
TranslationId public_corner(const Triangulation &tri, const Face &f, int i);

struct StarEntry {
  uint32_t face;
  int corner;                 // the vertex's corner in the face
  TranslationId translation;  // translation(canonical copy) has the vertex at its representative
};
// The faces around the live vertex v, counterclockwise, from the face the
// vertex stores. Throws std::invalid_argument for a dead or unknown vertex.
void vertex_star(const Triangulation &tri, uint32_t v, std::vector<StarEntry> *out);

struct Edge {
  uint32_t a, b;              // the edge runs from rep(a) to translation(rep(b))
  TranslationId translation;
  uint32_t left, right;       // left: the face on the left of a -> b (the smaller face index)
  int left_edge;              // the edge's index in `left` (opposite that corner)
};
// Every edge once, by its left face and edge index: the edge i of face f is
// listed with f when f < f.n[i] (a face of a simplicial complex is never its
// own neighbour).
void edge_list(const Triangulation &tri, std::vector<Edge> *out);

}  // namespace hdt::triangulation
