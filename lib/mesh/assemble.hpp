// Faces given by their corners, each face in a frame of its own, assembled
// into the mesh's records (mesh.hpp): each face moved to its canonical copy,
// its neighbours found across its edges with their translations. For a
// triangulation computed elsewhere (an independent brute force, the dummy
// construction of a polygon surface) that BasicTriangulation then takes
// and validates.
//
// An edge from corner a to corner b is named, whatever the frame, by
// (v_a, v_b, t_a^-1 t_b): a change of frame k multiplies both translations
// by k on the left, which cancels. The face across it holds the reversed
// edge (v_b, v_a, (t_a^-1 t_b)^-1), and the translation between the two
// canonical copies is t_a s_a^-1 for the neighbour's corner s_a at v_a.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "mesh/mesh.hpp"

namespace hdt::mesh {

struct CornerFace {
  std::array<uint32_t, 3> v;        // counterclockwise
  std::array<TranslationId, 3> t;   // corner i is t[i] applied to vertex v[i]'s stored point
};

// vertices: with their homes set (faces are written; their .face is set
// here). Throws std::invalid_argument when an edge has no reversed twin
// or more than one: the faces do not close up into a surface.
template <class Table>
std::vector<Face> assemble_faces(std::vector<Vertex> *vertices, const std::vector<CornerFace> &given, Table &T) {
  std::vector<Face> faces(given.size());
  using Key = std::tuple<uint32_t, uint32_t, TranslationId>;
  std::map<Key, std::pair<uint32_t, int>> edges;  // edge i of face f, i opposite corner i
  for (uint32_t f = 0; f < given.size(); ++f) {
    const CornerFace &c = given[f];
    int m = 0;
    for (int i = 1; i < 3; ++i)
      if (c.v[i] < c.v[m]) m = i;
    // The canonical copy: the smallest vertex at its home.
    const TranslationId kappa = T.compose((*vertices).at(c.v[m]).home, T.inverse(c.t[m]));
    Face &F = faces[f];
    for (int i = 0; i < 3; ++i) F.v[i] = c.v[i], F.t[i] = T.compose(kappa, c.t[i]);
    for (int i = 0; i < 3; ++i) {
      const int a = next(i), b = prev(i);
      const Key key{F.v[a], F.v[b], T.compose(T.inverse(F.t[a]), F.t[b])};
      if (!edges.emplace(key, std::make_pair(f, i)).second)
        throw std::invalid_argument("assemble_faces: an edge occurs twice in one direction");
    }
    (*vertices)[F.v[0]].face = (*vertices)[F.v[1]].face = (*vertices)[F.v[2]].face = f;
  }
  for (uint32_t f = 0; f < faces.size(); ++f) {
    Face &F = faces[f];
    for (int i = 0; i < 3; ++i) {
      const int a = next(i), b = prev(i);
      const auto twin = edges.find(Key{F.v[b], F.v[a], T.compose(T.inverse(F.t[b]), F.t[a])});
      if (twin == edges.end())
        throw std::invalid_argument("assemble_faces: edge " + std::to_string(i) + " of face " + std::to_string(f) +
                                    " has no twin");
      const Face &N = faces[twin->second.first];
      const int k = twin->second.second;  // N's edge from its corner at v_b to its corner at v_a
      F.n[i] = twin->second.first;
      F.nt[i] = T.compose(F.t[a], T.inverse(N.t[prev(k)]));
    }
  }
  return faces;
}

}  // namespace hdt::mesh
