// Replacing a set of faces by new ones: the one primitive behind insertion,
// removal and the flips of the dummy construction.
#include <algorithm>
#include <stdexcept>

#include "triangulation/triangulation.hpp"

namespace hdt::triangulation {

int Triangulation::corner_of(const Face &f, uint32_t v) const {
  for (int i = 0; i < 3; ++i)
    if (f.v[i] == v) return i;
  throw std::logic_error("a face does not hold the vertex it should");
}

int Triangulation::twin_by_translations(uint32_t f, int i) const {
  // Two edges of N join the same vertices to f (a non-simplicial stage of
  // the dummy construction): the translations tell them apart.
  const Face &F = faces_[f];
  const Face &N = faces_.at(F.n[i]);
  const uint32_t a = F.v[next(i)], b = F.v[prev(i)];
  group::TranslationTable &T = table();
  for (int k = 0; k < 3; ++k)
    if (N.n[k] == f && N.v[next(k)] == b && N.v[prev(k)] == a && T.compose(F.nt[i], N.t[prev(k)]) == F.t[next(i)] &&
        T.compose(F.nt[i], N.t[next(k)]) == F.t[prev(i)])
      return k;
  return -1;
}

void Triangulation::replace(const std::vector<uint32_t> &old, const std::vector<NewFace> &created,
                            const std::vector<BoundaryEdge> &boundary, std::vector<uint32_t> *ids) {
  group::TranslationTable &T = table();
  const std::size_t k = created.size();
  const std::size_t base = faces_.size();
  auto slot = [&](std::size_t j) { return j < old.size() ? old[j] : uint32_t(base + (j - old.size())); };
  auto same = [](const Corner &p, const Corner &q) { return p.v == q.v && p.t == q.t; };

  // 1. Each new face in its canonical copy: kappa maps the common frame to it.
  std::vector<Built> &built = built_;
  built.resize(k);
  std::vector<OuterLink> &outer_links = outer_links_;
  outer_links.clear();
  for (std::size_t j = 0; j < k; ++j) {
    const NewFace &nf = created[j];
    int m = 0;
    for (int i = 1; i < 3; ++i)
      if (nf.c[i].v < nf.c[m].v) m = i;
    const TranslationId home = vertices_[nf.c[m].v].home;
    const TranslationId kappa = nf.c[m].t == home ? 0 : T.compose(home, T.inverse(nf.c[m].t));
    Built &b = built[j];
    b.kappa = kappa;
    for (int i = 0; i < 3; ++i) {
      b.face.v[i] = nf.c[i].v;
      b.face.t[i] = T.compose(kappa, nf.c[i].t);
    }
  }
  // 2. Adjacency: edge i of a new face (c[i+1] -> c[i+2]) meets the reversed
  // edge of another new face, or a boundary edge a -> b with the region (the
  // new face) on its left.
  auto link_outer = [&](std::size_t j, int i, const BoundaryEdge &edge) {
    const TranslationId nt = T.compose(built[j].kappa, edge.outer_frame);
    built[j].face.n[i] = edge.outer;
    built[j].face.nt[i] = nt;
    outer_links.push_back({edge.outer, edge.outer_edge, slot(j), T.inverse(nt)});
  };
  auto link_new = [&](std::size_t j, int i, std::size_t j2) {
    built[j].face.n[i] = slot(j2);
    built[j].face.nt[i] = T.compose(built[j].kappa, T.inverse(built[j2].kappa));
  };
  // Bowyer-Watson's fan: face j is (a_j, b_j, apex) on boundary edge
  // a_j -> b_j, and its edge apex -> a_j meets the edge b_j' -> apex of the
  // face j' with b_j' = a_j. One corner comparison per pair, where the
  // general search below compares edges with edges.
  bool fan = k == boundary.size();
  for (std::size_t j = 0; j < k && fan; ++j)
    fan = same(created[j].c[0], boundary[j].a) && same(created[j].c[1], boundary[j].b) &&
          same(created[j].c[2], created[0].c[2]);
  if (fan) {
    for (std::size_t j = 0; j < k; ++j) built[j].face.n[0] = kNone;
    for (std::size_t j = 0; j < k; ++j) {
      link_outer(j, 2, boundary[j]);
      // Insertion lists the boundary counterclockwise: then j2 is j - 1.
      std::size_t j2 = j == 0 ? k - 1 : j - 1;
      if (j2 == j || !same(created[j2].c[1], created[j].c[0]))
        for (j2 = 0; j2 < k && (j2 == j || !same(created[j2].c[1], created[j].c[0]));) ++j2;
      if (j2 == k || built[j2].face.n[0] != kNone) throw std::logic_error("replace: the new faces do not close a fan");
      link_new(j, 1, j2);
      link_new(j2, 0, j);
    }
  } else {
    // Any other shape (a removal's hole): each edge found by binary search
    // among the new faces' edges and then the boundary's, O(k log k).
    std::vector<HalfEdge> &edges = half_edges_, &outer = boundary_edges_;
    edges.clear(), outer.clear();
    for (std::size_t j = 0; j < k; ++j)
      for (int i = 0; i < 3; ++i)
        edges.push_back({key(created[j].c[next(i)]), key(created[j].c[prev(i)]), uint32_t(j), i});
    for (std::size_t e = 0; e < boundary.size(); ++e)
      outer.push_back({key(boundary[e].a), key(boundary[e].b), uint32_t(e), 0});
    std::sort(edges.begin(), edges.end());
    std::sort(outer.begin(), outer.end());
    for (const HalfEdge &h : edges) {
      const HalfEdge reversed{h.b, h.a, 0, 0};
      if (const auto it = std::lower_bound(edges.begin(), edges.end(), reversed);
          it != edges.end() && it->a == h.b && it->b == h.a) {
        link_new(h.face, h.edge, it->face);
      } else if (const auto o = std::lower_bound(outer.begin(), outer.end(), HalfEdge{h.a, h.b, 0, 0});
                 o != outer.end() && o->a == h.a && o->b == h.b) {
        link_outer(h.face, h.edge, boundary[o->face]);
      } else {
        throw std::logic_error("replace: a new edge has no partner");
      }
    }
  }
  if (outer_links.size() != boundary.size()) throw std::logic_error("replace: a boundary edge has no new face");

  // 3. Write: nothing below throws (capacity is reserved first).
  const std::size_t new_size = faces_.size() + (k > old.size() ? k - old.size() : 0);
  if (faces_.capacity() < new_size) faces_.reserve(std::max(new_size, 2 * faces_.capacity()));
  if (ids) ids->reserve(k);
  std::vector<uint32_t> &holes = holes_;
  holes.assign(old.begin() + long(std::min(old.size(), k)), old.end());
  if (ids) ids->clear();
  for (std::size_t j = 0; j < k; ++j) {
    const uint32_t s = slot(j);
    if (s == faces_.size()) {
      faces_.push_back(built[j].face);
    } else {
      faces_[s] = built[j].face;
    }
    if (ids) ids->push_back(s);
    for (int i = 0; i < 3; ++i) vertices_[built[j].face.v[i]].face = s;
  }
  for (const OuterLink &l : outer_links) {
    faces_[l.outer].n[l.edge] = l.face;
    faces_[l.outer].nt[l.edge] = l.nt;
  }
  if (k > 0) last_face_ = slot(0);
  // 4. Fill the holes with the last faces, so ids stay dense.
  std::sort(holes.begin(), holes.end());
  while (!holes.empty()) {
    const uint32_t last = uint32_t(faces_.size() - 1);
    if (holes.back() == last) {
      holes.pop_back();
      faces_.pop_back();
      continue;
    }
    const uint32_t hole = holes.front();
    holes.erase(holes.begin());
    const Face moved = faces_[last];
    for (int i = 0; i < 3; ++i) {
      Face &N = faces_[moved.n[i]];
      const uint32_t a = moved.v[next(i)], b = moved.v[prev(i)];
      for (int e = 0; e < 3; ++e)
        if (N.n[e] == last && N.v[next(e)] == b && N.v[prev(e)] == a) N.n[e] = hole;
      if (vertices_[moved.v[i]].face == last) vertices_[moved.v[i]].face = hole;
    }
    faces_[hole] = moved;
    for (uint32_t &n : faces_[hole].n)
      if (n == last) n = hole;  // a face next to itself (dummy construction only)
    faces_.pop_back();
    if (ids)
      for (uint32_t &id : *ids)
        if (id == last) id = hole;
    if (last_face_ == last) last_face_ = hole;
  }
  if (last_face_ >= faces_.size()) last_face_ = 0;
}

}  // namespace hdt::triangulation
