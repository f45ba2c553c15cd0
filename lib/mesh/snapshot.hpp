// Everything that makes a triangulation behave as it does, as plain data:
// what hdt_save writes and hdt_load reads back (lib/capi/save_format.cpp).
//
// A restored triangulation answers every query as the saved one did, with
// the same vertex ids, the same faces in the same slots and the same
// translation ids, and later operations on both give the same results: the
// translation table's ids beyond the neighbour set, the walk's starting
// point and its random state are part of the snapshot.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "group/presentation.hpp"
#include "mesh/mesh.hpp"

namespace hdt::mesh {

struct Snapshot {
  int genus = 0;
  // The canonical words of the translation ids from |N| on, in id order.
  std::vector<group::Word> extra_words;
  std::vector<Vertex> vertices;  // by id; face == kNone for a removed id
  std::vector<bool> dummy;       // per vertex
  std::vector<Face> faces;       // by slot
  uint32_t last_face = 0, last_vertex = kNone;
  uint64_t rng = 0;
};

// The longest translation word a snapshot may hold. The canonical words a
// triangulation meets are short: homes of points within 2^-53 of the unit
// circle, and their products with elements of N, took at most 28 letters at
// genus 2, 30 at genus 3 and 46 at genus 5 (300 such points each). The
// bound keeps a hostile word from costing long multiprecision
// canonicalisation (its precision grows with the word's length).
inline std::size_t max_saved_word_length(int genus) { return 64 + 32 * std::size_t(genus); }

// Why a snapshot is refused, with the part at fault (the genus, the counts,
// a word, a vertex, a face, the walk's state, or the structure as a whole) and the item's index, so that
// a reader can name the bytes that hold it.
struct SnapshotError : std::invalid_argument {
  enum Part { kGenus, kCounts, kWord, kVertex, kFace, kState, kStructure };
  SnapshotError(Part p, std::size_t i, const std::string &what) : std::invalid_argument(what), part(p), index(i) {}
  Part part;
  std::size_t index;
};

}  // namespace hdt::mesh
