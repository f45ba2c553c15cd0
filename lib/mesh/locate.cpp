// Point location (a visibility walk through translated neighbours), the star
// of a vertex, and the nearest vertex.
#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <stdexcept>

#include "mesh/polygon_triangulation.hpp"
#include "mesh/triangulation.hpp"

namespace hdt::mesh {

template <class Geometry>
typename BasicTriangulation<Geometry>::Hint BasicTriangulation<Geometry>::hint() const {
  if (last_vertex_ < vertices_.size() && vertices_[last_vertex_].alive()) {
    const Vertex &u = vertices_[last_vertex_];
    const Face &F = faces_[u.face];
    auto &T = table();
    const TranslationId t = F.t[corner_of(F, last_vertex_)];
    return {u.face, u.home == 0 ? t : T.compose(t, T.inverse(u.home))};
  }
  return {last_face_ < faces_.size() ? last_face_ : 0, 0};
}

namespace {


// The grid cell of q: the square [-half, half]^2 cut into side^2 cells,
// points outside it (or not finite) in the nearest border cell.
std::size_t grid_cell(const group::Complex<double> &q, uint32_t side, double half) {
  const double scale = side / (2 * half), top = side - 1;
  double i = (q.re + half) * scale, j = (q.im + half) * scale;
  i = i >= 0 ? std::min(i, top) : 0;  // (NaN goes to 0)
  j = j >= 0 ? std::min(j, top) : 0;
  return std::size_t(j) * side + std::size_t(i);
}

}  // namespace

template <class Geometry>
group::Complex<double> BasicTriangulation<Geometry>::at_home(double x, double y, TranslationId home) const {
  return geometry_->image(x, y, home);
}

template <class Geometry>
void BasicTriangulation<Geometry>::build_grid() const {
  // Built aside and then swapped in: the grid is a cache, and a query must
  // not fail for it. Without memory for it, the jumps sample at random
  // until the vertices double again.
  grid_built_ = vertices_.size();
  grid_.clear(), grid_side_ = 0;
  double half = 0;
  for (const Vertex &u : vertices_)
    if (u.alive()) {
      const group::Complex<double> z = at_home(u.x, u.y, u.home);
      if (std::isfinite(z.re) && std::isfinite(z.im)) half = std::max({half, std::abs(z.re), std::abs(z.im)});
    }
  const auto side = uint32_t(std::max(1.0, std::sqrt(double(live_vertices_) / 2)));
  half = half > 0 ? half * (1 + 0x1p-20) : 1;
  std::vector<uint32_t> grid;
  try {
    grid.assign(std::size_t(side) * side, kNone);
  } catch (const std::bad_alloc &) {
    return;
  }
  for (uint32_t v = 0; v < vertices_.size(); ++v) {
    const Vertex &u = vertices_[v];
    if (u.alive()) grid[grid_cell(at_home(u.x, u.y, u.home), side, half)] = v;
  }
  grid_.swap(grid), grid_side_ = side, grid_half_ = half;
}

template <class Geometry>
uint32_t BasicTriangulation<Geometry>::grid_vertex(const group::Complex<double> &q) const {
  if (vertices_.size() >= 2 * grid_built_) build_grid();
  return grid_side_ == 0 ? kNone : grid_[grid_cell(q, grid_side_, grid_half_)];
}

template <class Geometry>
void BasicTriangulation<Geometry>::jump_near(double x, double y, TranslationId home, bool grid) const {
  // Jump and walk (Devroye, Mucke, Zhu): of the last vertex and about n^(1/3)
  // random ones, the walk starts at the one nearest to the query, so that
  // queries in no particular order walk about n^(1/4) faces instead of
  // n^(1/2); with the grid, of the last vertex and the grid cell's, about a
  // cell away. Nearness is only a heuristic here (rounded disk points, the
  // representatives in F_g, no side pairing): it picks a start, the walk's
  // exact predicates decide.
  const std::size_t n = vertices_.size();
  if (n < 64) return;
  const group::Complex<double> q = at_home(x, y, home);
  const double wq = 1 - (q.re * q.re + q.im * q.im);
  // A monotone function of the hyperbolic distance: |z - q|^2 / (w_z w_q).
  auto farness = [&](uint32_t v) {
    const Vertex &u = vertices_[v];
    const group::Complex<double> z = at_home(u.x, u.y, u.home);
    const double dx = z.re - q.re, dy = z.im - q.im;
    return (dx * dx + dy * dy) / ((1 - (z.re * z.re + z.im * z.im)) * wq);
  };
  uint32_t best = last_vertex_ < n && vertices_[last_vertex_].alive() ? last_vertex_ : kNone;
  double best_farness = best != kNone ? farness(best) : HUGE_VAL;
  const uint32_t cell = grid ? grid_vertex(q) : kNone;
  if (cell != kNone && vertices_[cell].alive()) {
    if (farness(cell) < best_farness) best = cell;
    last_vertex_ = best;
    return;
  }
  const int samples = int(std::cbrt(double(live_vertices_)));
  for (int k = 0; k < samples; ++k) {
    const auto v = uint32_t(next_random() % n);
    if (!vertices_[v].alive()) continue;
    const double f = farness(v);
    if (f < best_farness) best = v, best_farness = f;
  }
  if (best != kNone) last_vertex_ = best;
}

template <class Geometry>
typename BasicTriangulation<Geometry>::Walk BasicTriangulation<Geometry>::walk(const TranslatedPoint &q, uint32_t start, TranslationId start_frame_inverse) const {
  auto &T = table();
  uint32_t f = start;
  TranslationId qt = T.compose(start_frame_inverse, q.translation);  // q in the canonical frame of f
  int entry = -1;  // the edge we came in by: q is on its inner side
  // The walk visits each copy of a face at most once on a Delaunay
  // triangulation; the bound only turns a broken invariant into an error.
  const std::size_t limit = 16 * faces_.size() + 1024;
  for (std::size_t step = 0; step < limit; ++step) {
    const Face &F = faces_[f];
    const TranslatedPoint x{q.x, q.y, qt, q.site};
    const int first = int(next_random() % 3);  // a random first edge: no cycles
    int zero = 0;
    bool moved = false;
    for (int k = 0; k < 3 && !moved; ++k) {
      const int i = (first + k) % 3;
      if (i == entry) continue;
      const int o = kernel_->orientation(corner(F, next(i)), corner(F, prev(i)), x);
      if (o < 0) {
        qt = T.compose(T.inverse(F.nt[i]), qt);
        entry = twin(f, i);
        f = F.n[i];
        moved = true;
      } else if (o == 0) {
        zero |= 1 << i;
      }
    }
    if (!moved) return {f, qt, zero};  // q is strictly inside the entry edge
  }
  throw std::logic_error("point location does not end: the triangulation is broken");
}

template <class Geometry>
typename BasicTriangulation<Geometry>::Located BasicTriangulation<Geometry>::locate(double x, double y) const {
  const TranslationId home = geometry_->home(x, y);
  const HomeImageScope image(*geometry_, x, y, home);
  jump_near(x, y, home);
  const Walk w = walk_from_hint({x, y, home, -1});
  return {w.face, table().inverse(w.query)};
}

template <class Geometry>
void BasicTriangulation<Geometry>::check_live(uint32_t v) const {
  if (!is_live(v)) throw std::invalid_argument("vertex " + std::to_string(v) + " is not a live vertex");
}

template <class Geometry>
void BasicTriangulation<Geometry>::star(uint32_t v, std::vector<StarFace> *out) const {
  check_live(v);
  const Vertex &u = vertices_[v];
  auto &T = table();
  out->clear();
  uint32_t f = u.face;
  TranslationId frame = 0;
  for (;;) {
    const Face &F = faces_[f];
    const int c = corner_of(F, v);
    out->push_back({f, c, frame});
    // Counterclockwise around v: the next face holds the edge v -> F's last corner.
    const int e = next(c);
    frame = T.compose(frame, F.nt[e]);
    f = F.n[e];
    if (f == u.face) break;
    if (out->size() > faces_.size()) throw std::logic_error("the star of a vertex does not close");
  }
  if (frame != 0) throw std::logic_error("the star of vertex " + std::to_string(v) + " winds onto another copy");
}

template <class Geometry>
void BasicTriangulation<Geometry>::vertex_point(uint32_t v, double *x, double *y) const {
  check_live(v);
  const Vertex &u = vertices_[v];
  if (u.home == 0) {
    *x = u.x, *y = u.y;
    return;
  }
  if (representatives_.size() <= v)
    representatives_.resize(vertices_.size(), {std::numeric_limits<double>::quiet_NaN(), 0.0});
  group::Complex<double> &z = representatives_[v];
  // In multiprecision: near the unit circle a double Moebius map loses digits.
  if (std::isnan(z.re)) z = geometry_->accurate_image(u.x, u.y, u.home);
  *x = z.re, *y = z.im;
}

template <class Geometry>
void BasicTriangulation<Geometry>::write_vertices(uint32_t *ids, double *xy, uint8_t *dummy) const {
  double x, y;
  if (xy)  // fills the cache of every representative away from F_g
    for (uint32_t v = 0; v < vertices_.size(); ++v)
      if (vertices_[v].alive() && vertices_[v].home != 0) vertex_point(v, &x, &y);
  std::size_t i = 0;
  for (uint32_t v = 0; v < vertices_.size(); ++v) {
    const Vertex &u = vertices_[v];
    if (!u.alive()) continue;
    if (i == live_vertices_) throw std::logic_error("write_vertices: the live vertex count is out of date");
    if (ids) ids[i] = v;
    if (dummy) dummy[i] = dummy_[v] ? 1 : 0;
    if (xy) {
      const group::Complex<double> z = u.home == 0 ? group::Complex<double>{u.x, u.y} : representatives_[v];
      xy[2 * i] = z.re, xy[2 * i + 1] = z.im;
    }
    ++i;
  }
}

template <class Geometry>
void BasicTriangulation<Geometry>::corner_translations(std::vector<std::pair<std::size_t, TranslationId>> *moved) const {
  auto &T = table();
  moved->clear();
  // Points given in F_g have the identity for home: then no corner moves,
  // which one pass over the vertices in order tells (where asking each
  // corner's vertex reads them in no order).
  bool homes = false;
  for (const Vertex &u : vertices_) homes |= u.alive() && u.home != 0;
  if (!homes) return;
  for (std::size_t f = 0; f < faces_.size(); ++f)
    for (int i = 0; i < 3; ++i) {
      const TranslationId home = vertices_[faces_[f].v[i]].home;
      if (home != 0) moved->push_back({3 * f + i, T.compose(faces_[f].t[i], T.inverse(home))});
    }
}

template <class Geometry>
uint32_t BasicTriangulation<Geometry>::nearest_vertex(double x, double y) const {
  auto &T = table();
  const TranslationId home = geometry_->home(x, y);
  const HomeImageScope image(*geometry_, x, y, home);
  jump_near(x, y, home);
  const Walk w = walk_from_hint({x, y, home, -1});
  const TranslatedPoint q{x, y, w.query, -1};  // the frame: w.face's canonical copy
  // Start at the nearest corner, then move to a nearer Delaunay neighbour
  // while there is one: a vertex none of whose neighbours is nearer has q
  // in its Voronoi cell.
  const Face &F = faces_[w.face];
  int best = 0;
  for (int i = 1; i < 3; ++i) {
    const int s = kernel_->compare_distance(q, corner(F, i), corner(F, best));
    if (s < 0 || (s == 0 && F.v[i] < F.v[best])) best = i;
  }
  uint32_t face = w.face;
  int c = best;
  TranslationId frame = 0;  // the copy frame(canonical copy of face) holds the current vertex
  for (std::size_t steps = 0; steps <= vertices_.size(); ++steps) {
    const Face &G = faces_[face];
    const uint32_t u = G.v[c];
    const TranslatedPoint pu = point(u, T.compose(frame, G.t[c]));
    bool moved = false;
    uint32_t f = face;
    int cf = c;
    TranslationId fr = frame;
    do {
      const Face &H = faces_[f];
      const int a = next(cf);
      const TranslatedPoint pa = point(H.v[a], T.compose(fr, H.t[a]));
      const int s = kernel_->compare_distance(q, pa, pu);
      if (s < 0 || (s == 0 && H.v[a] < u)) {
        face = f, c = a, frame = fr;
        moved = true;
        break;
      }
      const int e = next(cf);
      fr = T.compose(fr, H.nt[e]);
      const uint32_t nf = H.n[e];
      cf = corner_of(faces_[nf], u);
      f = nf;
    } while (f != face || cf != c);
    if (!moved) return u;
  }
  throw std::logic_error("nearest_vertex: the descent does not end");
}


template Triangulation::Hint Triangulation::hint() const;
template group::Complex<double> Triangulation::at_home(double, double, TranslationId) const;
template void Triangulation::build_grid() const;
template uint32_t Triangulation::grid_vertex(const group::Complex<double> &) const;
template void Triangulation::jump_near(double, double, TranslationId, bool) const;
template Triangulation::Walk Triangulation::walk(const TranslatedPoint &, uint32_t, TranslationId) const;
template Triangulation::Located Triangulation::locate(double, double) const;
template void Triangulation::check_live(uint32_t) const;
template void Triangulation::star(uint32_t, std::vector<StarFace> *) const;
template void Triangulation::vertex_point(uint32_t, double *, double *) const;
template void Triangulation::write_vertices(uint32_t *, double *, uint8_t *) const;
template void Triangulation::corner_translations(std::vector<std::pair<std::size_t, TranslationId>> *) const;
template uint32_t Triangulation::nearest_vertex(double, double) const;

template PolygonTriangulation::Hint PolygonTriangulation::hint() const;
template group::Complex<double> PolygonTriangulation::at_home(double, double, TranslationId) const;
template void PolygonTriangulation::build_grid() const;
template uint32_t PolygonTriangulation::grid_vertex(const group::Complex<double> &) const;
template void PolygonTriangulation::jump_near(double, double, TranslationId, bool) const;
template PolygonTriangulation::Walk PolygonTriangulation::walk(const TranslatedPoint &, uint32_t, TranslationId) const;
template PolygonTriangulation::Located PolygonTriangulation::locate(double, double) const;
template void PolygonTriangulation::check_live(uint32_t) const;
template void PolygonTriangulation::star(uint32_t, std::vector<StarFace> *) const;
template void PolygonTriangulation::vertex_point(uint32_t, double *, double *) const;
template void PolygonTriangulation::write_vertices(uint32_t *, double *, uint8_t *) const;
template void PolygonTriangulation::corner_translations(std::vector<std::pair<std::size_t, TranslationId>> *) const;
template uint32_t PolygonTriangulation::nearest_vertex(double, double) const;

}  // namespace hdt::mesh
