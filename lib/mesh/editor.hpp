// The dummy construction's hold on a triangulation (lib/dummies/): a
// triangulation of a genus that starts with no vertices, and the edits that
// build its dummy set, which no other caller has. Between edits the
// invariant of triangulation.hpp need not hold: the construction ends with
// validate(), its certificate.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "mesh/dummy_template.hpp"
#include "mesh/triangulation.hpp"

namespace hdt::mesh {

template <class Geometry>
class BasicEditor {
 public:
  using Triangulation = BasicTriangulation<Geometry>;
  // M_g: an empty triangulation of the genus.
  explicit BasicEditor(int genus);
  // An empty triangulation on the geometry given.
  explicit BasicEditor(std::unique_ptr<Geometry> geometry);

  // The triangulation being built, for its queries, remove() and validate().
  Triangulation &triangulation() { return t_; }
  const Triangulation &triangulation() const { return t_; }

  // Replaces everything by these vertices, all dummies, and faces.
  void assign_dummies(std::vector<Vertex> vertices, std::vector<Face> faces);
  // Flips edge i of face f, shared with edge twin(f, i) of f.n[i], to the
  // other diagonal of the quadrilateral; the two faces' new ids to *ids.
  void flip(uint32_t f, int i, std::vector<uint32_t> *ids);
  // Splits face w.face at a new dummy (x, y) with home `home` (walked to by
  // walk_from, on no edge's line): three faces, their ids to *ids. Returns
  // the new vertex.
  uint32_t split(const typename Triangulation::Walk &w, double x, double y, TranslationId home, std::vector<uint32_t> *ids);
  // Bowyer-Watson insertion of a new dummy at (x, y) with home `home`, the
  // walk starting around vertex `near`. False, with nothing changed, when a
  // vertex is there already.
  bool insert_dummy(double x, double y, TranslationId home, uint32_t near);

  // What a thinning move changes, to undo a move that a removal refused.
  struct Checkpoint {
    std::vector<Vertex> vertices;
    std::vector<Face> faces;
    std::vector<bool> dummy;
    std::size_t live = 0, dummies = 0;
    uint32_t last_face = 0, last_vertex = kNone;
  };
  void save(Checkpoint *c) const;
  void roll_back(Checkpoint *c);  // *c is left unspecified
  // Dense vertex ids in the old order, and the walk's starting point and
  // random state as a triangulation made from a template has them.
  void compact_ids();

  // The finished set, from which Triangulation(const DummyTemplate &) makes
  // every later triangulation of the genus.
  DummyTemplate dummy_template() const;
  // The finished triangulation itself, for its first user.
  Triangulation take() && { return std::move(t_); }

 private:
  Triangulation t_;
};

using Editor = BasicEditor<MgGeometry>;

}  // namespace hdt::mesh
