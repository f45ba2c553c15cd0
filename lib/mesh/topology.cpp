// Replacing a set of faces by new ones: the one primitive behind insertion,
// removal and the flips of the dummy construction.
#include <algorithm>
#include <stdexcept>

#include "mesh/polygon_triangulation.hpp"
#include "mesh/triangulation.hpp"

namespace hdt::mesh {

template <class Geometry>
int BasicTriangulation<Geometry>::corner_of(const Face &f, uint32_t v) const {
  for (int i = 0; i < 3; ++i)
    if (f.v[i] == v) return i;
  throw std::logic_error("a face does not hold the vertex it should");
}

template <class Geometry>
void BasicTriangulation<Geometry>::ambiguous_twin() {
  throw std::logic_error("twin: two edges of a face's neighbour join the same vertices (not a simplicial complex)");
}

// One call of replace(): its steps, in order.
template <class Geometry>
class BasicTriangulation<Geometry>::Replacement {
  using Built = Scratch::Built;
  using HalfEdge = Scratch::HalfEdge;
  using OuterLink = Scratch::OuterLink;
  static uint64_t key(const Corner &c) { return Scratch::key(c); }

 public:
  Replacement(BasicTriangulation &t, const std::vector<uint32_t> &old, const std::vector<NewFace> &created,
              const std::vector<BoundaryEdge> &boundary)
      : t_(t),
        T_(t.table()),
        old_(old),
        created_(created.data()),
        boundary_(boundary.data()),
        k_(created.size()),
        boundary_count_(boundary.size()),
        base_(t.faces_.size()) {}

  void run(std::vector<uint32_t> *ids) {
    build_canonical_copies();
    t_.scratch_.outer_links.clear();
    if (is_fan()) {
      link_fan();
    } else {
      link_by_edge_table();
    }
    if (t_.scratch_.outer_links.size() != boundary_count_) throw std::logic_error("replace: a boundary edge has no new face");
    write(ids);
    fill_freed_slots(ids);
  }

 private:
  // The id of new face j: the old faces' ids first, then new ones.
  uint32_t slot(std::size_t j) const { return j < old_.size() ? old_[j] : uint32_t(base_ + (j - old_.size())); }
  static bool same(const Corner &p, const Corner &q) { return p.v == q.v && p.t == q.t; }

  // Each new face in its canonical copy: kappa maps the common frame to it.
  void build_canonical_copies() {
    t_.scratch_.built.resize(k_);
    built_ = t_.scratch_.built.data();
    for (std::size_t j = 0; j < k_; ++j) {
      const NewFace &nf = created_[j];
      int m = 0;
      for (int i = 1; i < 3; ++i)
        if (nf.c[i].v < nf.c[m].v) m = i;
      const TranslationId home = t_.vertices_[nf.c[m].v].home;
      const TranslationId kappa = nf.c[m].t == home ? 0 : T_.compose(home, T_.inverse(nf.c[m].t));
      Built &b = built_[j];
      b.kappa = kappa;
      for (int i = 0; i < 3; ++i) {
        b.face.v[i] = nf.c[i].v;
        b.face.t[i] = T_.compose(kappa, nf.c[i].t);
      }
    }
  }

  // Adjacency: edge i of a new face (c[i+1] -> c[i+2]) meets the reversed
  // edge of another new face, or a boundary edge a -> b with the region (the
  // new face) on its left.
  void link_outer(std::size_t j, int i, const BoundaryEdge &edge) {
    Built &b = built_[j];
    const TranslationId nt = T_.compose(b.kappa, edge.outer_frame);
    b.face.n[i] = edge.outer;
    b.face.nt[i] = nt;
    t_.scratch_.outer_links.push_back({edge.outer, edge.outer_edge, slot(j), T_.inverse(nt)});
  }
  void link_new(std::size_t j, int i, std::size_t j2) {
    Built &b = built_[j];
    b.face.n[i] = slot(j2);
    b.face.nt[i] = between(b.kappa, built_[j2].kappa);
  }
  // kappa kappa2^-1: the identity when the two faces' canonical copies
  // share the frame, the common case (at genus 128 with 10^5 points two
  // thirds of these calls went to the product cache).
  TranslationId between(TranslationId kappa, TranslationId kappa2) {
    return kappa == kappa2 ? 0 : T_.compose(kappa, T_.inverse(kappa2));
  }

  // Insertion's star: face j is (a_j, b_j, apex) on boundary edge a_j -> b_j,
  // the boundary listed counterclockwise (b_j-1 = a_j).
  bool is_fan() const {
    if (k_ != boundary_count_ || k_ < 2) return false;
    for (std::size_t j = 0; j < k_; ++j) {
      const NewFace &f = created_[j];
      if (!same(f.c[0], boundary_[j].a) || !same(f.c[1], boundary_[j].b) || !same(f.c[2], created_[0].c[2]) ||
          !same(created_[j == 0 ? k_ - 1 : j - 1].c[1], f.c[0]))
        return false;
    }
    return true;
  }
  // Then face j's edge apex -> a_j meets face j-1's edge b_j-1 -> apex.
  // The two translations across that edge are inverses: one product.
  void link_fan() {
    for (std::size_t j = 0; j < k_; ++j) {
      const std::size_t before = j == 0 ? k_ - 1 : j - 1;
      link_outer(j, 2, boundary_[j]);
      Built &b = built_[j], &a = built_[before];
      const TranslationId nt = between(b.kappa, a.kappa);
      b.face.n[1] = slot(before), b.face.nt[1] = nt;
      a.face.n[0] = slot(j), a.face.nt[0] = T_.inverse(nt);
    }
  }

  // Any other shape (a removal's hole, a flip): the partner of each new
  // edge a -> b is the new edge b -> a or the boundary edge a -> b, found in
  // a hash table of directed edges, O(k). The boundary edges go in as the
  // outside sees them, b -> a, so that one lookup finds either.
  void link_by_edge_table() {
    const std::size_t n = 3 * k_ + boundary_count_;
    bits_ = 4;
    while ((std::size_t(1) << bits_) < 2 * n) ++bits_;
    t_.scratch_.half_edges.assign(std::size_t(1) << bits_, HalfEdge{0, 0, kNone, 0});
    for (std::size_t e = 0; e < boundary_count_; ++e) enter(key(boundary_[e].b), key(boundary_[e].a), uint32_t(e), -1);
    for (std::size_t j = 0; j < k_; ++j)
      for (int i = 0; i < 3; ++i) enter(key(created_[j].c[next(i)]), key(created_[j].c[prev(i)]), uint32_t(j), i);
    for (std::size_t j = 0; j < k_; ++j)
      for (int i = 0; i < 3; ++i) {
        const HalfEdge &h = slot_of(key(created_[j].c[prev(i)]), key(created_[j].c[next(i)]));
        if (h.face == kNone) throw std::logic_error("replace: a new edge has no partner");
        if (h.edge < 0) {
          link_outer(j, i, boundary_[h.face]);
        } else {
          link_new(j, i, h.face);
        }
      }
  }
  // The slot of a -> b in the table (linear probing): its entry, or the
  // empty slot where it would go.
  HalfEdge &slot_of(uint64_t a, uint64_t b) {
    std::vector<HalfEdge> &table = t_.scratch_.half_edges;
    const std::size_t mask = table.size() - 1;
    std::size_t s = ((a ^ (b * 0x9E3779B97F4A7C15ull)) * 0xBF58476D1CE4E5B9ull) >> (64 - bits_);
    while (table[s].face != kNone && (table[s].a != a || table[s].b != b)) s = (s + 1) & mask;
    return table[s];
  }
  void enter(uint64_t a, uint64_t b, uint32_t face, int edge) {
    HalfEdge &h = slot_of(a, b);
    if (h.face != kNone) throw std::logic_error("replace: two edges of the region coincide");
    h = {a, b, face, edge};
  }

  // Writes the new faces and the outer faces' links: nothing here throws
  // (capacity is reserved first).
  void write(std::vector<uint32_t> *ids) {
    std::vector<Face> &faces = t_.faces_;
    const std::size_t new_size = faces.size() + (k_ > old_.size() ? k_ - old_.size() : 0);
    if (faces.capacity() < new_size) faces.reserve(std::max(new_size, 2 * faces.capacity()));
    if (ids) ids->reserve(k_);
    t_.scratch_.holes.assign(old_.begin() + long(std::min(old_.size(), k_)), old_.end());
    if (ids) ids->clear();
    for (std::size_t j = 0; j < k_; ++j) {
      const uint32_t s = slot(j);
      const Face &f = built_[j].face;
      if (s == faces.size()) {
        faces.push_back(f);
      } else {
        faces[s] = f;
      }
      if (ids) ids->push_back(s);
      for (int i = 0; i < 3; ++i) t_.vertices_[f.v[i]].face = s;
    }
    for (const OuterLink &l : t_.scratch_.outer_links) {
      faces[l.outer].n[l.edge] = l.face;
      faces[l.outer].nt[l.edge] = l.nt;
    }
    if (k_ > 0) t_.last_face_ = slot(0);
  }

  // The old faces left over (when fewer faces replace them) are filled with
  // the last faces, so that ids stay dense.
  void fill_freed_slots(std::vector<uint32_t> *ids) {
    std::vector<Face> &faces = t_.faces_;
    std::vector<uint32_t> &holes = t_.scratch_.holes;
    std::sort(holes.begin(), holes.end());
    while (!holes.empty()) {
      const uint32_t last = uint32_t(faces.size() - 1);
      if (holes.back() == last) {
        holes.pop_back();
        faces.pop_back();
        continue;
      }
      const uint32_t hole = holes.front();
      holes.erase(holes.begin());
      const Face moved = faces[last];
      for (int i = 0; i < 3; ++i) {
        Face &N = faces[moved.n[i]];
        const uint32_t a = moved.v[next(i)], b = moved.v[prev(i)];
        for (int e = 0; e < 3; ++e)
          if (N.n[e] == last && N.v[next(e)] == b && N.v[prev(e)] == a) N.n[e] = hole;
        if (t_.vertices_[moved.v[i]].face == last) t_.vertices_[moved.v[i]].face = hole;
      }
      faces[hole] = moved;
      for (uint32_t &n : faces[hole].n)
        if (n == last) n = hole;  // a face next to itself (dummy construction only)
      faces.pop_back();
      if (ids)
        for (uint32_t &id : *ids)
          if (id == last) id = hole;
      if (t_.last_face_ == last) t_.last_face_ = hole;
    }
    if (t_.last_face_ >= faces.size()) t_.last_face_ = 0;
  }

  BasicTriangulation &t_;
  typename Geometry::Table &T_;
  const std::vector<uint32_t> &old_;
  const NewFace *created_;
  const BoundaryEdge *boundary_;
  const std::size_t k_, boundary_count_;  // the numbers of new faces and boundary edges
  const std::size_t base_;                // the number of faces before
  Built *built_ = nullptr;                // t_.scratch_.built's k_ faces
  int bits_ = 0;            // the edge table has 2^bits_ slots
};

template <class Geometry>
void BasicTriangulation<Geometry>::replace(const std::vector<uint32_t> &old, const std::vector<NewFace> &created,
                            const std::vector<BoundaryEdge> &boundary, std::vector<uint32_t> *ids) {
  Replacement(*this, old, created, boundary).run(ids);
  ++revision_;
}


template int Triangulation::corner_of(const Face &, uint32_t) const;
template void Triangulation::ambiguous_twin();
template void Triangulation::replace(const std::vector<uint32_t> &, const std::vector<NewFace> &,
                                     const std::vector<BoundaryEdge> &, std::vector<uint32_t> *);

template int PolygonTriangulation::corner_of(const Face &, uint32_t) const;
template void PolygonTriangulation::ambiguous_twin();
template void PolygonTriangulation::replace(const std::vector<uint32_t> &, const std::vector<NewFace> &,
                                            const std::vector<BoundaryEdge> &, std::vector<uint32_t> *);

}  // namespace hdt::mesh
