// The Delaunay triangulation of a finite point set on a surface: M_g
// (Triangulation, on MgGeometry), or a surface of the geometry G
// (mg_geometry.hpp describes what G provides).
//
// Invariant between public calls: the stored faces form the Delaunay
// triangulation (ties broken by the kernel's symbolic perturbation) of the
// vertices on M_g, a simplicial complex whose faces all have hyperbolic
// circumdiameter < sys/2 (paper, Proposition 2.2). A new triangulation holds
// the dummy points of its genus (made by lib/dummies/), which establish the
// invariant; insertion (Bowyer-Watson) keeps it because an empty circle of a
// superset is empty for the set; removal keeps it by refusing.
//
// Every public operation either completes or throws before changing anything
// (the new faces are computed first, then written without failure points).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "predicates/kernel.hpp"
#include "mesh/dummy_template.hpp"
#include "mesh/mg_geometry.hpp"
#include "mesh/mesh.hpp"
#include "mesh/progress.hpp"
#include "mesh/scratch.hpp"
#include "mesh/snapshot.hpp"

namespace hdt::mesh {

using predicates::TranslatedPoint;

template <class Geometry>
class BasicTriangulation {
 public:
  using Kernel = typename Geometry::Kernel;

  // M_g: the dummy set of the template (dummy_template.hpp) on a surface of
  // its genus of its own.
  explicit BasicTriangulation(const DummyTemplate &dummies);
  // The triangulation given, on the geometry given (faces as assemble.hpp
  // makes them, each vertex's face set; dummy: per vertex). Nothing is
  // checked: the caller runs validate(), the certificate, before use.
  BasicTriangulation(std::unique_ptr<Geometry> geometry, std::vector<Vertex> vertices, std::vector<bool> dummy,
                     std::vector<Face> faces);

  int genus() const { return genus_; }
  // The surface: presentation, translation table, sides, sites. A query may
  // add the ids of elements it meets to the translation table (a cache
  // that only grows; ids stay valid), hence a mutable surface.
  typename Geometry::Surface &surface() const { return geometry_->surface(); }
  typename Geometry::Table &table() const { return geometry_->table(); }
  Kernel &kernel() { return geometry_->kernel(); }
  Geometry &geometry() const { return *geometry_; }
  const std::vector<Vertex> &vertices() const { return vertices_; }
  const std::vector<Face> &faces() const { return faces_; }
  // The corner translations relative to the vertices' representatives
  // (hdt_faces' convention): corner i of face f is t h^-1 applied to the
  // representative of its vertex, for the stored translation t and the
  // vertex's home h. That is t itself where h is the identity; the others
  // go to moved as (3f + i, t h^-1), in face order.
  void corner_translations(std::vector<std::pair<std::size_t, TranslationId>> *moved) const;
  std::size_t vertex_count() const { return live_vertices_; }
  // Moves on with every change of the vertices, their flags or the faces,
  // and only then (a call that changes nothing, a failed one included,
  // leaves it): what is derived from the faces and kept (dual::Outputs)
  // holds while the revision it was made at is current.
  uint64_t revision() const { return revision_; }
  std::size_t dummy_count() const { return dummies_; }

  struct Inserted {
    uint32_t vertex;
    bool existed;  // a user vertex was already there
  };
  // Throws std::domain_error unless (x, y) is a finite point of the open disk.
  Inserted insert(double x, double y);
  // The same for a point given in the frame of face `face`'s canonical copy
  // that lies strictly inside its circle (refinement: the face's rounded
  // circumcentre), decided exactly: then the face is in the point's
  // conflict region and Bowyer-Watson starts there, with no walk, and the
  // ids of the faces created (the new vertex's star) go to *created. A point
  // on the circle or outside it changes nothing: vertex kNone, *created
  // empty. Throws std::invalid_argument for an unknown face.
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
  // validate()) and throws SnapshotError naming the part at fault. It
  // takes the snapshot's vectors (no copy); s is left unspecified.
  Snapshot snapshot() const;
  static BasicTriangulation restore(Snapshot &&s);
  // A polygon surface's (its words in the pairings, letters < sides): the
  // same checks and certificate on a fresh geometry from make(), called
  // again when validate() met new elements and the table must be rebuilt.
  static BasicTriangulation restore(const std::function<std::unique_ptr<Geometry>()> &make, Snapshot &&s);

  bool is_dummy(uint32_t v) const { return dummy_[v]; }
  // Whether v is the id of a vertex not removed.
  bool is_live(uint32_t v) const { return v < vertices_.size() && vertices_[v].alive(); }
  // Throws std::invalid_argument ("vertex v is not a live vertex") unless
  // is_live(v): the one check of every call that takes a vertex id.
  void check_live(uint32_t v) const;
  // The surface's site of vertex v, or -1 (M_g: sites 0 .. 2g are vertices 1 .. 2g+1).
  int32_t site_of(uint32_t v) const { return geometry_->site_of(v); }
  TranslatedPoint point(uint32_t v, TranslationId t) const {
    const Vertex &u = vertices_[v];
    return {u.x, u.y, t, site_of(v)};
  }
  TranslatedPoint corner(const Face &f, int i) const { return point(f.v[i], f.t[i]); }
  // The representative of v in F_g, rounded. A vertex away from F_g pays
  // a multiprecision image once; later calls read it from a cache.
  void vertex_point(uint32_t v, double *x, double *y) const;

  // The live vertices in id order (vertex_count() of them): their ids, their
  // representatives (vertex_point) as x, y pairs, and 1 for a dummy, 0 for
  // a user's vertex; each output may be null. What may fail (the
  // representatives not yet cached: memory, multiprecision images) comes
  // before anything is written.
  void write_vertices(uint32_t *ids, double *xy, uint8_t *dummy) const;

  // The faces around v, counterclockwise, the first the canonical copy of
  // vertices()[v].face, each with its frame relative to that one.
  void star(uint32_t v, std::vector<StarFace> *out) const;
  // The edge of f.n[i] that is edge i of f seen from the other side.
  // Inline: insertion asks it for every edge of the hole's boundary. Two
  // candidates (f.n[i] meeting f along two edges with the same ends) occur
  // in no simplicial complex, nor in the dummy construction's early stages
  // at any genus up to HDT_CREATE_GENUS_MAX (each genus was run to check).
  int twin(uint32_t f, int i) const {
    const Face &F = faces_[f];
    const Face &N = faces_[F.n[i]];
    const uint32_t a = F.v[next(i)], b = F.v[prev(i)];
    int found = -1, matches = 0;
    for (int k = 0; k < 3; ++k)
      if (N.n[k] == f && N.v[next(k)] == b && N.v[prev(k)] == a) found = k, ++matches;
    if (matches > 1) [[unlikely]] ambiguous_twin();
    return found;
  }

  // Walks from face `start` (its canonical copy) to a face whose copy
  // contains q. query is q's translation in that face's canonical frame;
  // zero_edges has bit i set when q lies on the line of edge i.
  struct Walk {
    uint32_t face;
    TranslationId query;
    int zero_edges;
  };
  Walk walk_from(const TranslatedPoint &q, uint32_t start) const { return walk(q, start, 0); }

 private:
  template <class>
  friend class BasicEditor;  // the dummy construction's edits (editor.hpp)
  struct Empty {};
  // No vertices: the dummy construction's start (M_g: of the genus).
  BasicTriangulation(int genus, Empty);
  BasicTriangulation(std::unique_ptr<Geometry> geometry, Empty);
  // restore() without validate(), after the ranges are checked; moves the
  // vertices, flags and faces out of s.
  static BasicTriangulation rebuild(Snapshot &s);
  static BasicTriangulation rebuild(std::unique_ptr<Geometry> geometry, Snapshot &s);
  // rebuild()'s last step: the snapshot's records moved in.
  void take(Snapshot &s, std::size_t live, std::size_t dummies);
  // restore()'s certificate: validate(), true when it gave no new ids, else
  // the records moved back into s for a rebuild.
  static bool certify(BasicTriangulation &t, Snapshot &s);

  // Replaces the faces `old` by `created` (given in one common frame),
  // linking them to each other and to the outer faces of `boundary`. The ids
  // of the new faces go to *ids in order. Throws before changing anything.
  void replace(const std::vector<uint32_t> &old, const std::vector<NewFace> &created,
               const std::vector<BoundaryEdge> &boundary, std::vector<uint32_t> *ids);
  [[noreturn]] static void ambiguous_twin();
  int corner_of(const Face &f, uint32_t v) const;

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
  // nearest to (x, y), whose representative is home(x + iy), of itself and
  // the vertex the grid holds for that place (with grid; see grid_), or of
  // itself and a few random vertices.
  void jump_near(double x, double y, TranslationId home, bool grid = true) const;
  // The representative of the stored point (x, y) with home `home`, in
  // double (from its home image when it has one: far from F_g the double
  // map loses the point's digits).
  group::Complex<double> at_home(double x, double y, TranslationId home) const;
  // A query's home image for the query's length (mg_geometry.hpp).
  using HomeImageScope = typename Geometry::HomeImageScope;
  // The grid's vertex for the representative q (kNone if none), the grid
  // built first when the vertices have doubled since it was.
  uint32_t grid_vertex(const group::Complex<double> &q) const;
  void build_grid() const;
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
  // A user's point found at vertex v: a dummy there becomes the user's
  // vertex (true), a user vertex stays as it was (false).
  bool met_vertex(uint32_t v);
  // The walk's next random number (xorshift64).
  uint64_t next_random() const {
    rng_ ^= rng_ << 13, rng_ ^= rng_ >> 7, rng_ ^= rng_ << 17;
    return rng_;
  }

  int genus_;
  // The surface, its kernel and its translations, on the heap: the kernel
  // refers to the surface, and a triangulation moves.
  std::unique_ptr<Geometry> geometry_;
  Kernel *kernel_;  // &geometry_->kernel(), the predicates' hot path
  std::vector<Vertex> vertices_;
  // vertex_point's results for vertices with home != 0, by id, filled on
  // first query (NaN: not computed yet). A vertex's point and home never
  // change and ids are not reused, so entries stay true; it grows with the
  // ids lazily.
  mutable std::vector<group::Complex<double>> representatives_;
  std::vector<bool> dummy_;  // per vertex
  std::vector<Face> faces_;
  std::size_t live_vertices_ = 0, dummies_ = 0;
  uint64_t revision_ = 0;
  // Where the next walk starts, and the walk's random choices: queries
  // move them too (mutable), which changes no answer.
  uint32_t last_face_ = 0;                // where the last operation ended
  mutable uint32_t last_vertex_ = kNone;  // the vertex last inserted or found
  static constexpr uint64_t kWalkSeed = 0x9E3779B97F4A7C15ull;
  mutable uint64_t rng_ = kWalkSeed;
  // A square grid of about V / 2 cells over the representatives, each cell
  // holding a vertex whose representative lay in it when the grid was built
  // (kNone: none), so that a query in no particular order starts its walk
  // a cell away. Rebuilt once the vertex ids have doubled; a removed
  // vertex's cell falls back to random samples until then.
  mutable std::vector<uint32_t> grid_;
  mutable uint32_t grid_side_ = 0;
  mutable double grid_half_ = 1;        // it covers [-grid_half_, grid_half_]^2
  mutable std::size_t grid_built_ = 0;  // vertices_.size() when built

  // Scratch space reused by every operation (scratch.hpp); star is also
  // validate()'s, hence mutable.
  mutable Scratch scratch_;
  class Replacement;  // replace()'s steps (topology.cpp)
};

// The triangulations of M_g.
using Triangulation = BasicTriangulation<MgGeometry>;

}  // namespace hdt::mesh
