// The stored triangulation: vertices and faces with per-corner translations.
//
// As in CGAL's periodic triangulations, a face is three vertices and, per
// corner, the group element that places that vertex in the face's canonical
// copy in the disk; neighbours are faces, with the translation between the two
// canonical copies. Translations are ids of the kernel's TranslationTable.
//
// Conventions:
//   - corner i of face f stands for the disk point f.t[i](x + iy) of vertex
//     f.v[i]'s stored point (x, y); the translation includes the vertex's
//     home, so the predicates take (x, y, f.t[i]) as they are;
//   - corners are counterclockwise; edge i is the edge opposite corner i,
//     from corner i+1 to corner i+2;
//   - f.nt[i](canonical copy of f.n[i]) is the copy adjacent to f's canonical
//     copy across edge i;
//   - the canonical copy of a face is the one in which its smallest vertex id
//     sits at its representative: t == home for that corner;
//   - faces are dense: ids 0..F-1, no holes (a removal moves the last faces
//     into the freed slots).
#pragma once

#include <array>
#include <cstdint>

#include "group/translation_table.hpp"

namespace hdt::mesh {

using group::TranslationId;

constexpr uint32_t kNone = UINT32_MAX;

// 24 bytes: whether a vertex is a dummy is kept in a bit vector beside, and
// the only exact algebraic points (kernel sites) are the Q0 dummies v_0 and
// m_k, vertices 1 .. 2g+1, whose (x, y) are their roundings.
struct Vertex {
  double x, y;         // the point as stored: the user's input, exactly
  TranslationId home;  // home(x + iy) lies in the half-open F_g
  uint32_t face;       // an incident face; kNone once the vertex is removed
  bool alive() const { return face != kNone; }
};

struct Face {
  std::array<uint32_t, 3> v;
  std::array<TranslationId, 3> t;
  std::array<uint32_t, 3> n;
  std::array<TranslationId, 3> nt;
};

inline int next(int i) { return i == 2 ? 0 : i + 1; }
inline int prev(int i) { return i == 0 ? 2 : i - 1; }

}  // namespace hdt::mesh
