// Saving and loading at the core's level: a triangulation as plain data
// (snapshot.hpp) and back. The data may come from a hostile file, so
// restore() checks every index before anything uses it, then runs the full
// exact validate() on the result.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <new>
#include <string>
#include <type_traits>
#include <utility>

#include "exact/unit_disk.hpp"
#include "group/canonical.hpp"
#include "surface/q0_sites.hpp"
#include "domain/word.hpp"
#include "mesh/polygon_triangulation.hpp"
#include "mesh/triangulation.hpp"

namespace hdt::mesh {

namespace {

std::string vertex_name(std::size_t v) { return "vertex " + std::to_string(v); }
std::string face_name(std::size_t f) { return "face " + std::to_string(f); }

using E = SnapshotError;

// The checks that need no surface, for both kinds: Euler's formula, the
// words' lengths and letters (0 .. letters - 1), every vertex and face
// record against the counts and the ids to be (0 .. ids - 1), the walk's
// state. *live and *dummies receive the counts.
void check_records(const Snapshot &s, const std::string &surface, std::size_t letters, std::size_t ids,
                   std::size_t *live, std::size_t *dummies) {
  const int g = s.genus;
  const std::size_t V = s.vertices.size(), F = s.faces.size();
  if (s.dummy.size() != V) throw std::logic_error("restore: dummy flags and vertices differ in number");
  if (V >= kNone) throw E(E::kCounts, 0, "too many vertices");
  *live = 0;
  for (const Vertex &u : s.vertices) *live += u.alive();
  if (F != 2 * (*live + 2 * std::size_t(g) - 2))
    throw E(E::kCounts, 0,
            std::to_string(F) + " faces for " + std::to_string(*live) + " live vertices on " + surface +
                ": Euler's formula wants " + std::to_string(2 * (*live + 2 * std::size_t(g) - 2)));
  if (ids > std::size_t(INT32_MAX)) throw E(E::kCounts, 0, "too many translation words");
  auto bad_id = [&](TranslationId id) { return id < 0 || std::size_t(id) >= ids; };
  for (std::size_t i = 0; i < s.extra_words.size(); ++i) {
    const group::Word &w = s.extra_words[i];
    if (w.size() > max_saved_word_length(g))
      throw E(E::kWord, i, "word " + std::to_string(i) + " has " + std::to_string(w.size()) + " letters (at most " +
                               std::to_string(max_saved_word_length(g)) + ")");
    for (group::Letter l : w)
      if (l < 0 || std::size_t(l) >= letters)
        throw E(E::kWord, i, "word " + std::to_string(i) + " has the bad letter " + std::to_string(l));
  }
  *dummies = 0;
  for (std::size_t v = 0; v < V; ++v) {
    const Vertex &u = s.vertices[v];
    if (!u.alive()) {
      if (u.x != 0 || std::signbit(u.x) || u.y != 0 || std::signbit(u.y) || u.home != 0 || s.dummy[v])
        throw E(E::kVertex, v, vertex_name(v) + " is removed but its record is not blank");
      continue;
    }
    *dummies += s.dummy[v];
    if (u.face >= F) throw E(E::kVertex, v, vertex_name(v) + " names face " + std::to_string(u.face) + " of " + std::to_string(F));
    if (bad_id(u.home)) throw E(E::kVertex, v, vertex_name(v) + " has an unknown home translation");
    if (!std::isfinite(u.x) || !std::isfinite(u.y) || !exact::inside_unit_disk(u.x, u.y))
      throw E(E::kVertex, v, vertex_name(v) + " is not a point of the open unit disk");
  }
  for (std::size_t f = 0; f < F; ++f) {
    const Face &A = s.faces[f];
    for (int i = 0; i < 3; ++i) {
      if (A.v[i] >= V) throw E(E::kFace, f, face_name(f) + " names vertex " + std::to_string(A.v[i]) + " of " + std::to_string(V));
      if (A.n[i] >= F) throw E(E::kFace, f, face_name(f) + " names neighbour " + std::to_string(A.n[i]) + " of " + std::to_string(F));
      if (bad_id(A.t[i]) || bad_id(A.nt[i])) throw E(E::kFace, f, face_name(f) + " has an unknown translation id");
    }
  }
  if (s.last_face >= F) throw E(E::kState, 0, "the last face " + std::to_string(s.last_face) + " is not a face");
  if (s.last_vertex != kNone && s.last_vertex >= V)
    throw E(E::kState, 0, "the last vertex " + std::to_string(s.last_vertex) + " is not a vertex id");
}

}  // namespace

template <class Geometry>
Snapshot BasicTriangulation<Geometry>::snapshot() const {
  Snapshot s;
  s.genus = genus_;
  if constexpr (std::is_same_v<Geometry, MgGeometry>) {
    const auto &T = table();
    for (std::size_t id = T.neighbour_count(); id < T.size(); ++id) s.extra_words.push_back(T.word(TranslationId(id)));
  } else {
    // Every element but the identity, as its word in the pairings.
    for (std::size_t id = 1; id < table().size(); ++id) {
      const std::vector<int> w = surface().word(domain::ElementId(id));
      s.extra_words.emplace_back(w.begin(), w.end());
    }
  }
  s.vertices = vertices_;
  s.dummy = dummy_;
  // A removed id keeps nothing: its record is the same in every file.
  for (std::size_t v = 0; v < s.vertices.size(); ++v)
    if (!s.vertices[v].alive()) s.vertices[v] = {0, 0, 0, kNone}, s.dummy[v] = false;
  s.faces = faces_;
  s.last_face = last_face_;
  s.last_vertex = last_vertex_;
  s.rng = rng_;
  return s;
}

template <class Geometry>
void BasicTriangulation<Geometry>::take(Snapshot &s, std::size_t live, std::size_t dummies) {
  vertices_ = std::move(s.vertices);
  dummy_ = std::move(s.dummy);
  faces_ = std::move(s.faces);
  live_vertices_ = live;
  dummies_ = dummies;
  last_face_ = s.last_face;
  last_vertex_ = s.last_vertex;
  rng_ = s.rng;
}

template <class Geometry>
bool BasicTriangulation<Geometry>::certify(BasicTriangulation &t, Snapshot &s) {
  const std::size_t ids = t.table().size();
  try {
    t.validate();
  } catch (const std::logic_error &e) {
    throw SnapshotError(SnapshotError::kStructure, 0, e.what());
  }
  // validate() may give new translation ids to products it meets; the
  // result's table must be exactly the saved one (saving it again gives the
  // same bytes), so then it is built once more. Otherwise validate() changed
  // only caches that hold for the same ids.
  if (t.table().size() == ids) return true;
  s.vertices = std::move(t.vertices_);
  s.dummy = std::move(t.dummy_);
  s.faces = std::move(t.faces_);
  return false;
}

template <class Geometry>
BasicTriangulation<Geometry> BasicTriangulation<Geometry>::rebuild(Snapshot &s) {
  const int g = s.genus;
  if (g < 2) throw E(E::kGenus, 0, "genus " + std::to_string(g) + " is not >= 2");
  const std::size_t V = s.vertices.size();
  // First every check that needs no surface: setting up a surface of large
  // genus (its tables and dummy set) is the dearest step of a load, which
  // a damaged file must not cost. The ids to be: N, |N| = (4g-1)^2, then
  // one per word.
  const std::size_t letters = 4 * std::size_t(g), ids = (letters - 1) * (letters - 1) + s.extra_words.size();
  std::size_t live, dummies;
  check_records(s, "M_" + std::to_string(g), letters, ids, &live, &dummies);

  // Then the surface: the sites and the words.
  BasicTriangulation t(g, Empty{});
  std::vector<double> sx(2 * g + 1), sy(2 * g + 1);
  surface::register_q0_sites(t.geometry_->surface(), sx.data(), sy.data());
  // Vertices 1 .. 2g+1 are the kernel's exact sites v_0 and m_k: their
  // doubles must be the sites' roundings, at home in F_g.
  for (std::size_t v = 1; v < V && v <= std::size_t(2 * g + 1); ++v) {
    const Vertex &u = s.vertices[v];
    if (u.alive() && (std::memcmp(&u.x, &sx[v - 1], sizeof(double)) != 0 ||
                      std::memcmp(&u.y, &sy[v - 1], sizeof(double)) != 0 || u.home != 0))
      throw E(E::kVertex, v, vertex_name(v) + " is not the site it must be (v_0 or a side midpoint m_k)");
  }
  group::TranslationTable &T = t.table();
  if (T.size() != T.neighbour_count() || T.size() != (letters - 1) * (letters - 1))
    throw std::logic_error("restore: a fresh table does not hold exactly N");
  // Each word is checked to be canonical, not canonicalised: the check
  // costs a product a letter at a fixed precision and stops at the first
  // wrong letter, where canonical_word's precision grows with the length (a
  // crafted file of long words cost minutes). Letters were checked above.
  for (std::size_t i = 0; i < s.extra_words.size(); ++i) {
    const group::Word &w = s.extra_words[i];
    const group::CanonicalCheck c = group::check_canonical(T.presentation(), w.data(), w.size());
    if (c == group::CanonicalCheck::kOpen)
      throw E(E::kWord, i, "word " + std::to_string(i) + "'s element lies too far from O for the format to certify its word");
    if (c == group::CanonicalCheck::kNotCanonical || T.find_canonical(w) >= 0)
      throw E(E::kWord, i,
              "word " + std::to_string(i) + " is not the canonical word of a new element (an element of N, a repeat, or not reduced)");
    T.intern_canonical(w);
  }

  // Moved, not copied: at 10^6 vertices a copy was 120 MB written to fresh
  // pages. restore() gives them back when it must rebuild.
  t.take(s, live, dummies);
  // The home images of the vertices far from F_g, as their insertion made
  // them: validate() and every later call read them.
  for (const Vertex &u : t.vertices_)
    if (u.alive()) t.kernel_->add_home_image(u.x, u.y, u.home);
  return t;
}

template <class Geometry>
BasicTriangulation<Geometry> BasicTriangulation<Geometry>::rebuild(std::unique_ptr<Geometry> geometry, Snapshot &s) {
  const int g = geometry->genus();
  if (s.genus != g)
    throw E(E::kGenus, 0, "genus " + std::to_string(s.genus) + ", but the polygon's surface has genus " + std::to_string(g));
  const domain::FundamentalPolygon &P = geometry->surface().polygon();
  const std::size_t letters = std::size_t(P.side_count()), ids = 1 + s.extra_words.size();
  std::size_t live, dummies;
  check_records(s, "a surface of genus " + std::to_string(g), letters, ids, &live, &dummies);
  // The ids in order: 0 the identity, 1 .. n the pairings (interned as the
  // surface is made), then each word's element, exactly, which must be new.
  domain::ElementTable &T = geometry->surface().table();
  for (std::size_t i = 0; i < s.extra_words.size(); ++i) {
    const group::Word &w = s.extra_words[i];
    const domain::ElementId id = T.intern(domain::word_element(P, std::vector<int>(w.begin(), w.end())));
    if (id != i + 1)
      throw E(E::kWord, i,
              "word " + std::to_string(i) + " is not the word of translation id " + std::to_string(i + 1) +
                  " (it gives id " + std::to_string(id) + ": a repeat, or a pairing out of its place)");
    // The word snapshot() writes for it (the reduction's), so that saving
    // again gives the same bytes, as for M_g's canonical words.
    const std::vector<int> written = geometry->surface().word(id);
    if (!std::equal(written.begin(), written.end(), w.begin(), w.end()))
      throw E(E::kWord, i, "word " + std::to_string(i) + " is not the word hdt_save writes for its element");
  }
  if (T.size() != ids) throw E(E::kCounts, 0, "the words do not list every pairing");
  BasicTriangulation t(std::move(geometry), Empty{});
  t.take(s, live, dummies);
  return t;
}

template <class Geometry>
BasicTriangulation<Geometry> BasicTriangulation<Geometry>::restore(
    const std::function<std::unique_ptr<Geometry>()> &make, Snapshot &&s) {
  BasicTriangulation t = rebuild(make(), s);
  if (certify(t, s)) return t;
  return rebuild(make(), s);
}

template <class Geometry>
BasicTriangulation<Geometry> BasicTriangulation<Geometry>::restore(Snapshot &&s) {
  BasicTriangulation t = rebuild(s);
  if (certify(t, s)) return t;
  return rebuild(s);
}


template Snapshot Triangulation::snapshot() const;
template Triangulation Triangulation::rebuild(Snapshot &);
template Triangulation Triangulation::restore(Snapshot &&);
template Snapshot PolygonTriangulation::snapshot() const;
template PolygonTriangulation PolygonTriangulation::rebuild(std::unique_ptr<PolygonGeometry>, Snapshot &);
template PolygonTriangulation PolygonTriangulation::restore(const std::function<std::unique_ptr<PolygonGeometry>()> &,
                                                            Snapshot &&);

}  // namespace hdt::mesh
