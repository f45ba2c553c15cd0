// The Delaunay triangulation of a finite point set on M_g.
//
// Invariant between public calls: the stored faces form the Delaunay
// triangulation (ties broken by the kernel's symbolic perturbation) of the
// vertices on M_g, a simplicial complex whose faces all have hyperbolic
// circumdiameter < sys/2 (paper, Proposition 2.2). A new triangulation holds
// the dummy points of its genus (dummy_points.cpp), which establish the
// invariant; insertion (Bowyer-Watson) keeps it because an empty circle of a
// superset is empty for the set; removal keeps it by refusing.
//
// Every public operation either completes or throws before changing anything
// (the new faces are computed first, then written without failure points).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "predicates/kernel.hpp"
#include "triangulation/hole.hpp"
#include "triangulation/mesh.hpp"
#include "triangulation/progress.hpp"
#include "triangulation/snapshot.hpp"

namespace hdt::triangulation {

using predicates::Kernel;
using predicates::TranslatedPoint;

class Triangulation {
 public:
  explicit Triangulation(int genus);

  int genus() const { return genus_; }
  // The surface: presentation, translation table, sides, sites. A query may
  // add the ids of elements it meets to the translation table (a cache
  // that only grows; ids stay valid), hence a mutable surface.
  surface::Surface &surface() const { return *surface_; }
  group::TranslationTable &table() const { return surface_->table(); }
  Kernel &kernel() { return *kernel_; }
  const std::vector<Vertex> &vertices() const { return vertices_; }
  const std::vector<Face> &faces() const { return faces_; }
  // The corner translations of every face relative to its vertices'
  // representatives (3 per face, face order): corner i of face f is
  // out[3f + i] applied to the representative of its vertex, t h^-1 for the
  // stored translation t and the vertex's home h (hdt_faces' convention).
  void corner_translations(std::vector<TranslationId> *out) const;
  std::size_t vertex_count() const { return live_vertices_; }
  std::size_t dummy_count() const { return dummies_; }

  struct Inserted {
    uint32_t vertex;
    bool existed;  // a user vertex was already there
  };
  // Throws std::domain_error unless (x, y) is a finite point of the open disk.
  Inserted insert(double x, double y);
  // The same for a point given in the frame of face `face`'s canonical copy
  // and meant to lie strictly inside its circle (refinement: the face's
  // circumcentre). Checked exactly; then the face is in the point's conflict
  // region and Bowyer-Watson starts there, with no walk (else a walk from
  // the face). The ids of the faces created (the new vertex's star) go to
  // *created. Throws std::invalid_argument for an unknown face.
  Inserted insert_in_circle(double x, double y, uint32_t face, std::vector<uint32_t> *created);
  // All points are checked before any is inserted; vertices may be null.
  // progress (may be null) can stop it part way: the points not handled
  // get kNone.
  void insert_many(const double *xy, std::size_t n, uint32_t *vertices, const Progress *progress = nullptr);
  // False, with nothing changed, when the result would break the invariant.
  // Throws std::invalid_argument for a dead or unknown vertex.
  bool remove(uint32_t v);
  std::size_t remove_dummies();

  struct Located {
    uint32_t face;
    TranslationId translation;  // (x, y) lies in translation(canonical copy)
  };
  // Queries are const: what they change is the walk's starting point and
  // caches (mutable below), and the kernel's and translation table's caches,
  // which only grow (ids stay valid); one thread at a time, as for changes.
  Located locate(double x, double y) const;
  uint32_t nearest_vertex(double x, double y) const;

  // Checks every invariant with exact predicates; throws std::logic_error
  // naming the first broken one.
  void validate() const;

  // Saving and loading (snapshot.hpp, restore.cpp). restore() checks
  // everything it is given (ranges, the sites, canonical words, then
  // validate()) and throws SnapshotError naming the part at fault.
  Snapshot snapshot() const;
  static Triangulation restore(const Snapshot &s);

  bool is_dummy(uint32_t v) const { return dummy_[v]; }
  // The surface's site of vertex v, or -1: sites 0 .. 2g are vertices 1 .. 2g+1.
  int32_t site_of(uint32_t v) const { return v >= 1 && v <= uint32_t(2 * genus_ + 1) ? int32_t(v - 1) : -1; }
  TranslatedPoint point(uint32_t v, TranslationId t) const {
    const Vertex &u = vertices_[v];
    return {u.x, u.y, t, site_of(v)};
  }
  TranslatedPoint corner(const Face &f, int i) const { return point(f.v[i], f.t[i]); }
  // The representative of v in F_g, rounded. A vertex away from F_g pays
  // a multiprecision image once; later calls read it from a cache.
  void vertex_point(uint32_t v, double *x, double *y) const;

 private:
  friend class DummyBuilder;
  friend class DummyThinning;
  friend std::shared_ptr<const struct DummyTemplate> build_dummy_points(Triangulation &t);
  struct Empty {};
  Triangulation(int genus, Empty);  // no vertices: the dummy construction's start
  // restore() without validate(), after the ranges are checked.
  static Triangulation rebuild(const Snapshot &s);

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

  // Replaces the faces `old` by `created` (given in one common frame),
  // linking them to each other and to the outer faces of `boundary`. The ids
  // of the new faces go to *ids in order. Throws before changing anything.
  void replace(const std::vector<uint32_t> &old, const std::vector<NewFace> &created,
               const std::vector<BoundaryEdge> &boundary, std::vector<uint32_t> *ids);
  // The edge of f.n[i] that is edge i of f seen from the other side.
  // Inline: insertion asks it for every edge of the hole's boundary.
  int twin(uint32_t f, int i) const {
    const Face &F = faces_[f];
    const Face &N = faces_[F.n[i]];
    const uint32_t a = F.v[next(i)], b = F.v[prev(i)];
    int found = -1, matches = 0;
    for (int k = 0; k < 3; ++k)
      if (N.n[k] == f && N.v[next(k)] == b && N.v[prev(k)] == a) found = k, ++matches;
    return matches <= 1 ? found : twin_by_translations(f, i);
  }
  int twin_by_translations(uint32_t f, int i) const;
  int corner_of(const Face &f, uint32_t v) const;

  // Walks from `start` (its canonical copy) to a face whose copy contains q.
  // q_in_face is q's translation in that face's canonical frame; zero_edges
  // has bit i set when q lies on the line of edge i.
  struct Walk {
    uint32_t face;
    TranslationId query;
    int zero_edges;
  };
  // The walk starts in the copy start_frame(canonical copy of start); the
  // argument is the inverse of that frame.
  Walk walk(const TranslatedPoint &q, uint32_t start, TranslationId start_frame_inverse) const;
  // Where the next walk starts: the copy of a face around the last vertex
  // touched, the one in which that vertex sits at its representative (so
  // near the next point of a spatially sorted sequence).
  struct Hint {
    uint32_t face;
    TranslationId frame_inverse;
  };
  Hint hint() const;
  // Before a walk to a point in no particular order: makes last_vertex_ the
  // nearest of it and a few random vertices to (x, y), whose representative
  // is home(x + iy).
  void jump_near(double x, double y, TranslationId home) const;
  Walk walk_from_hint(const TranslatedPoint &q) const {
    const Hint h = hint();
    return walk(q, h.face, h.frame_inverse);
  }

  // Bowyer-Watson insertion of the point (x, y) with home `home`, located in
  // `at`. Returns the new vertex id.
  uint32_t insert_located(double x, double y, TranslationId home, bool dummy, const Walk &at);
  // insert()'s end, once the point is located: an existing vertex, or a new one.
  Inserted insert_walked(double x, double y, TranslationId home, const Walk &at);
  // The vertex of `at`'s face at the walked-to point, if it is one of its
  // corners (kNone otherwise).
  uint32_t vertex_at(const Walk &at) const;

  // The faces around v, counterclockwise, with their frames relative to the
  // first (the canonical copy of vertices_[v].face).
  struct StarFace {
    uint32_t face;
    int corner;             // v's corner in the face
    TranslationId frame;    // frame(canonical copy) is the copy around v
  };
  void star(uint32_t v, std::vector<StarFace> *out) const;

  int genus_;
  std::unique_ptr<surface::Surface> surface_;
  std::unique_ptr<Kernel> kernel_;  // on *surface_
  std::vector<Vertex> vertices_;
  // vertex_point's results for vertices with home != 0, by id, filled on
  // first query (NaN: not computed yet). A vertex's point and home never
  // change and ids are not reused, so entries stay true; it grows with the
  // ids lazily.
  mutable std::vector<group::Complex<double>> representatives_;
  std::vector<bool> dummy_;  // per vertex
  std::vector<Face> faces_;
  std::size_t live_vertices_ = 0, dummies_ = 0;
  // Where the next walk starts, and the walk's random choices: queries
  // move them too (mutable), which changes no answer.
  uint32_t last_face_ = 0;                // where the last operation ended
  mutable uint32_t last_vertex_ = kNone;  // the vertex last inserted or found
  mutable uint64_t rng_ = 0x9E3779B97F4A7C15ull;

  // Scratch space reused by every operation (no allocation on the common path).
  struct CavityStep {  // a face of the conflict region and the edges still to cross
    uint32_t face;
    TranslationId frame;
    int8_t edge, left;
  };
  std::vector<CavityStep> cavity_stack_;
  std::vector<uint32_t> old_faces_, new_ids_;
  std::vector<NewFace> new_faces_;
  std::vector<BoundaryEdge> boundary_;
  mutable std::vector<StarFace> star_;  // also validate()'s
  std::vector<HoleVertex> hole_;  // remove(): the link of the vertex
  std::vector<HoleFace> hole_faces_;
  std::vector<uint32_t> link_ids_;
  struct Built {  // a new face in its canonical copy; kappa maps the common frame to it
    Face face;
    TranslationId kappa;
  };
  struct OuterLink {
    uint32_t outer;
    int edge;
    uint32_t face;
    TranslationId nt;
  };
  std::vector<Built> built_;
  // replace()'s edge table: directed edges a -> b by their corners.
  static uint64_t key(const Corner &c) { return uint64_t(c.v) << 32 | uint32_t(c.t); }
  struct HalfEdge {
    uint64_t a, b;
    uint32_t face;  // index among the new faces (or the boundary's edges); kNone: an empty slot
    int edge;       // -1: a boundary edge
  };
  std::vector<HalfEdge> half_edges_;
  class Replacement;  // replace()'s steps (topology.cpp)
  std::vector<OuterLink> outer_links_;
  std::vector<uint32_t> holes_;
};

}  // namespace hdt::triangulation
