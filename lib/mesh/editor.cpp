// The dummy construction's edits (editor.hpp), through replace() and the
// Bowyer-Watson insertion of the triangulation they build.
#include "mesh/editor.hpp"

#include <stdexcept>
#include <utility>

#include "mesh/polygon_triangulation.hpp"

namespace hdt::mesh {

template <class Geometry>
BasicEditor<Geometry>::BasicEditor(int genus) : t_(genus, typename Triangulation::Empty{}) {}

template <class Geometry>
BasicEditor<Geometry>::BasicEditor(std::unique_ptr<Geometry> geometry)
    : t_(std::move(geometry), typename Triangulation::Empty{}) {}

template <class Geometry>
DummyTemplate BasicEditor<Geometry>::dummy_template() const {
  DummyTemplate q;
  q.genus = t_.genus();
  q.vertices = t_.vertices();
  q.faces = t_.faces();
  const auto &T = t_.table();
  for (std::size_t id = T.neighbour_count(); id < T.size(); ++id) q.extra_words.push_back(T.word(TranslationId(id)));
  const surface::Surface &S = t_.surface();
  for (std::size_t id = 0; id < S.site_count(); ++id) q.sites.push_back(S.site(int32_t(id)));
  return q;
}

template <class Geometry>
void BasicEditor<Geometry>::assign_dummies(std::vector<Vertex> vertices, std::vector<Face> faces) {
  t_.vertices_ = std::move(vertices);
  t_.faces_ = std::move(faces);
  for (uint32_t f = 0; f < t_.faces_.size(); ++f)
    for (int i = 0; i < 3; ++i) t_.vertices_[t_.faces_[f].v[i]].face = f;
  t_.dummy_.assign(t_.vertices_.size(), true);
  t_.live_vertices_ = t_.dummies_ = t_.vertices_.size();
  t_.representatives_.clear();
  ++t_.revision_;
}

template <class Geometry>
void BasicEditor<Geometry>::flip(uint32_t f, int i, std::vector<uint32_t> *ids) {
  auto &T = t_.table();
  const Face F = t_.faces_[f];
  const uint32_t n = F.n[i];
  const int k = t_.twin(f, i);
  if (n == f || k < 0) throw std::logic_error("flip: an edge without twin");
  const Face N = t_.faces_[n];
  const int b = next(i), c = prev(i);
  // N's corners: k = D, next(k) = C, prev(k) = B.
  const Corner A{F.v[i], F.t[i]}, B{F.v[b], F.t[b]}, C{F.v[c], F.t[c]};
  const Corner D{N.v[k], T.compose(F.nt[i], N.t[k])};
  const std::vector<NewFace> created{{{A, B, D}}, {{A, D, C}}};
  const std::vector<BoundaryEdge> boundary{
      {A, B, F.n[c], t_.twin(f, c), F.nt[c]},
      {C, A, F.n[b], t_.twin(f, b), F.nt[b]},
      {B, D, N.n[next(k)], t_.twin(n, next(k)), T.compose(F.nt[i], N.nt[next(k)])},
      {D, C, N.n[prev(k)], t_.twin(n, prev(k)), T.compose(F.nt[i], N.nt[prev(k)])},
  };
  t_.replace({f, n}, created, boundary, ids);
}

template <class Geometry>
uint32_t BasicEditor<Geometry>::split(const typename Triangulation::Walk &w, double x, double y, TranslationId home, std::vector<uint32_t> *ids) {
  const auto id = uint32_t(t_.vertices_.size());
  const Face F = t_.faces_[w.face];
  std::vector<NewFace> created;
  std::vector<BoundaryEdge> boundary;
  for (int i = 0; i < 3; ++i) {
    const Corner a{F.v[next(i)], F.t[next(i)]}, b{F.v[prev(i)], F.t[prev(i)]};
    if (F.n[i] == w.face) throw std::logic_error("split: a face next to itself");
    created.push_back({{a, b, Corner{id, w.query}}});
    boundary.push_back({a, b, F.n[i], t_.twin(w.face, i), F.nt[i]});
  }
  t_.vertices_.push_back({x, y, home, kNone});
  t_.dummy_.push_back(true);
  try {
    t_.replace({w.face}, created, boundary, ids);
  } catch (...) {
    t_.vertices_.pop_back(), t_.dummy_.pop_back();
    throw;
  }
  ++t_.live_vertices_, ++t_.dummies_;
  return id;
}

template <class Geometry>
bool BasicEditor<Geometry>::insert_dummy(double x, double y, TranslationId home, uint32_t near) {
  t_.last_vertex_ = near;
  const typename Triangulation::Walk w = t_.walk_from_hint({x, y, home, -1});
  if (t_.vertex_at(w) != kNone) return false;
  t_.insert_located(x, y, home, true, w);
  return true;
}

template <class Geometry>
void BasicEditor<Geometry>::save(Checkpoint *c) const {
  c->vertices = t_.vertices_;
  c->faces = t_.faces_;
  c->dummy = t_.dummy_;
  c->live = t_.live_vertices_, c->dummies = t_.dummies_;
  c->last_face = t_.last_face_, c->last_vertex = t_.last_vertex_;
}

template <class Geometry>
void BasicEditor<Geometry>::roll_back(Checkpoint *c) {
  t_.vertices_.swap(c->vertices);
  t_.faces_.swap(c->faces);
  t_.dummy_.swap(c->dummy);
  t_.live_vertices_ = c->live, t_.dummies_ = c->dummies;
  t_.last_face_ = c->last_face, t_.last_vertex_ = c->last_vertex;
  // The cache is by id, and the ids above the restored count will name
  // other points.
  if (t_.representatives_.size() > t_.vertices_.size()) t_.representatives_.resize(t_.vertices_.size());
  ++t_.revision_;
}

template <class Geometry>
void BasicEditor<Geometry>::compact_ids() {
  std::vector<uint32_t> id(t_.vertices_.size(), kNone);
  std::vector<Vertex> vertices;
  for (uint32_t v = 0; v < t_.vertices_.size(); ++v)
    if (t_.vertices_[v].alive()) id[v] = uint32_t(vertices.size()), vertices.push_back(t_.vertices_[v]);
  for (Face &F : t_.faces_)
    for (uint32_t &v : F.v) v = id[v];
  std::vector<bool> dummy(vertices.size());
  for (uint32_t v = 0; v < id.size(); ++v)
    if (id[v] != kNone) dummy[id[v]] = t_.dummy_[v];
  t_.vertices_ = std::move(vertices);
  t_.dummy_ = std::move(dummy);
  t_.representatives_.clear();
  // Where walks start and their random choices, as in a copy of the
  // template (triangulation.cpp): the first triangulation of a genus then
  // behaves as every later one, down to the ids its walks intern.
  t_.last_vertex_ = kNone;
  t_.last_face_ = 0;
  t_.rng_ = Triangulation::kWalkSeed;
  ++t_.revision_;
}

template class BasicEditor<MgGeometry>;

// A polygon surface's dummy construction uses these.
template BasicEditor<PolygonGeometry>::BasicEditor(std::unique_ptr<PolygonGeometry>);
template void BasicEditor<PolygonGeometry>::assign_dummies(std::vector<Vertex>, std::vector<Face>);
template void BasicEditor<PolygonGeometry>::flip(uint32_t, int, std::vector<uint32_t> *);
template uint32_t BasicEditor<PolygonGeometry>::split(const PolygonTriangulation::Walk &, double, double, TranslationId,
                                                      std::vector<uint32_t> *);
template void BasicEditor<PolygonGeometry>::compact_ids();

}  // namespace hdt::mesh
