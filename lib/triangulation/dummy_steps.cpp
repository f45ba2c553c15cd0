// The dummy construction's steps (triangulation.hpp): the edits that
// dummy_points.cpp and dummy_thinning.cpp make, through replace() and the
// Bowyer-Watson insertion, without reaching into the triangulation's state.
#include <stdexcept>

#include "triangulation/triangulation.hpp"

namespace hdt::triangulation {

void Triangulation::assign_dummies(std::vector<Vertex> vertices, std::vector<Face> faces) {
  vertices_ = std::move(vertices);
  faces_ = std::move(faces);
  for (uint32_t f = 0; f < faces_.size(); ++f)
    for (int i = 0; i < 3; ++i) vertices_[faces_[f].v[i]].face = f;
  dummy_.assign(vertices_.size(), true);
  live_vertices_ = dummies_ = vertices_.size();
  representatives_.clear();
}

void Triangulation::flip(uint32_t f, int i, std::vector<uint32_t> *ids) {
  group::TranslationTable &T = table();
  const Face F = faces_[f];
  const uint32_t n = F.n[i];
  const int k = twin(f, i);
  if (n == f || k < 0) throw std::logic_error("flip: an edge without twin");
  const Face N = faces_[n];
  const int b = next(i), c = prev(i);
  // N's corners: k = D, next(k) = C, prev(k) = B.
  const Corner A{F.v[i], F.t[i]}, B{F.v[b], F.t[b]}, C{F.v[c], F.t[c]};
  const Corner D{N.v[k], T.compose(F.nt[i], N.t[k])};
  const std::vector<NewFace> created{{{A, B, D}}, {{A, D, C}}};
  const std::vector<BoundaryEdge> boundary{
      {A, B, F.n[c], twin(f, c), F.nt[c]},
      {C, A, F.n[b], twin(f, b), F.nt[b]},
      {B, D, N.n[next(k)], twin(n, next(k)), T.compose(F.nt[i], N.nt[next(k)])},
      {D, C, N.n[prev(k)], twin(n, prev(k)), T.compose(F.nt[i], N.nt[prev(k)])},
  };
  replace({f, n}, created, boundary, ids);
}

uint32_t Triangulation::split(const Walk &w, double x, double y, TranslationId home, std::vector<uint32_t> *ids) {
  const auto id = uint32_t(vertices_.size());
  const Face F = faces_[w.face];
  std::vector<NewFace> created;
  std::vector<BoundaryEdge> boundary;
  for (int i = 0; i < 3; ++i) {
    const Corner a{F.v[next(i)], F.t[next(i)]}, b{F.v[prev(i)], F.t[prev(i)]};
    if (F.n[i] == w.face) throw std::logic_error("split: a face next to itself");
    created.push_back({{a, b, Corner{id, w.query}}});
    boundary.push_back({a, b, F.n[i], twin(w.face, i), F.nt[i]});
  }
  vertices_.push_back({x, y, home, kNone});
  dummy_.push_back(true);
  try {
    replace({w.face}, created, boundary, ids);
  } catch (...) {
    vertices_.pop_back(), dummy_.pop_back();
    throw;
  }
  ++live_vertices_, ++dummies_;
  return id;
}

bool Triangulation::insert_dummy(double x, double y, TranslationId home, uint32_t near) {
  last_vertex_ = near;
  const Walk w = walk_from_hint({x, y, home, -1});
  if (vertex_at(w) != kNone) return false;
  insert_located(x, y, home, true, w);
  return true;
}

void Triangulation::save(Checkpoint *c) const {
  c->vertices = vertices_;
  c->faces = faces_;
  c->dummy = dummy_;
  c->live = live_vertices_, c->dummies = dummies_;
  c->last_face = last_face_, c->last_vertex = last_vertex_;
}

void Triangulation::roll_back(Checkpoint *c) {
  vertices_.swap(c->vertices);
  faces_.swap(c->faces);
  dummy_.swap(c->dummy);
  live_vertices_ = c->live, dummies_ = c->dummies;
  last_face_ = c->last_face, last_vertex_ = c->last_vertex;
  // The cache is by id, and the ids above the restored count will name
  // other points.
  if (representatives_.size() > vertices_.size()) representatives_.resize(vertices_.size());
}

void Triangulation::compact_ids() {
  std::vector<uint32_t> id(vertices_.size(), kNone);
  std::vector<Vertex> vertices;
  for (uint32_t v = 0; v < vertices_.size(); ++v)
    if (vertices_[v].alive()) id[v] = uint32_t(vertices.size()), vertices.push_back(vertices_[v]);
  for (Face &F : faces_)
    for (uint32_t &v : F.v) v = id[v];
  std::vector<bool> dummy(vertices.size());
  for (uint32_t v = 0; v < id.size(); ++v)
    if (id[v] != kNone) dummy[id[v]] = dummy_[v];
  vertices_ = std::move(vertices);
  dummy_ = std::move(dummy);
  representatives_.clear();
  // Where walks start and their random choices, as in a copy of the
  // template (triangulation.cpp): the first triangulation of a genus then
  // behaves as every later one, down to the ids its walks intern.
  last_vertex_ = kNone;
  last_face_ = 0;
  rng_ = kWalkSeed;
}

}  // namespace hdt::triangulation
