// The shapes of faces under construction, and the scratch space that the
// triangulation's operations reuse so that the common path allocates
// nothing. Private to lib/mesh: insert.cpp (the cavity), remove.cpp
// (the hole), topology.cpp (replace()), validate.cpp (stars).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "mesh/hole.hpp"
#include "mesh/mesh.hpp"

namespace hdt::mesh {

// A corner of a face under construction: a vertex and its translation in
// the common frame of the operation.
struct Corner {
  uint32_t v;
  TranslationId t;
};

struct NewFace {
  std::array<Corner, 3> c;
};

// An edge a -> b of the region being replaced (the region on its left), and
// the face outside it: outer_frame(canonical copy of outer) is the copy
// across the edge in the common frame.
struct BoundaryEdge {
  Corner a, b;
  uint32_t outer;
  int outer_edge;
  TranslationId outer_frame;
};

// A face around a vertex v (Triangulation::star): v's corner in it, and the
// frame in which it surrounds v next to the star's first face.
struct StarFace {
  uint32_t face;
  int corner;
  TranslationId frame;  // frame(canonical copy) is the copy around v
};

struct Scratch {
  // insert: the conflict region, depth first; a face of it and the edges
  // still to cross.
  struct CavityStep {
    uint32_t face;
    TranslationId frame;
    int8_t edge, left;
  };
  std::vector<CavityStep> cavity_stack;
  std::vector<uint32_t> old_faces, new_ids;
  std::vector<NewFace> new_faces;
  std::vector<BoundaryEdge> boundary;

  std::vector<StarFace> star;  // remove() and validate()

  // remove: the link of the vertex and its new faces.
  std::vector<HoleVertex> hole;
  std::vector<HoleFace> hole_faces;
  std::vector<uint32_t> link_ids;

  // replace(): each new face in its canonical copy (kappa maps the common
  // frame to it), the links to the outer faces, the directed-edge table,
  // and the slots freed for compaction.
  struct Built {
    Face face;
    TranslationId kappa;
  };
  struct OuterLink {
    uint32_t outer;
    int edge;
    uint32_t face;
    TranslationId nt;
  };
  // A directed edge a -> b by its corners' keys.
  struct HalfEdge {
    uint64_t a, b;
    uint32_t face;  // index among the new faces (or the boundary's edges); kNone: an empty slot
    int edge;       // -1: a boundary edge
  };
  static uint64_t key(const Corner &c) { return uint64_t(c.v) << 32 | uint32_t(c.t); }
  std::vector<Built> built;
  std::vector<OuterLink> outer_links;
  std::vector<HalfEdge> half_edges;
  std::vector<uint32_t> holes;
};

}  // namespace hdt::mesh
