// lib/picture: the triangulation drawn in the Poincare disk as SVG text,
// hdt_svg. The one drawing code of triangulations: the command-line tool
// hdt-triangulate and the Python package both call it.
//
// A layer above lib/capi. The picture reads the triangulation only through
// the public functions of include/hdt.h, as any caller could (hdt_vertices,
// hdt_faces, hdt_translation_matrix, hdt_polygon_vertex, ...); it never
// touches the core's types. It is C++ for what capi/guard.hpp gives every
// exported function: guarded(), which turns each exception (std::bad_alloc
// above all) into a status and hdt_last_error_message's text, so that none
// crosses the ABI; and for std::string as the growable buffer the text is
// written to. Everything here but hdt_svg has internal linkage (an anonymous
// namespace), so nothing else is exported and no name clashes with hdt_*.
//
// The drawing came from the tool (its svg_picture.c, since folded into this
// file): at size 800 the text is byte for byte what the tool wrote then (the
// meson test `pictures` compares the committed pictures), which is why the
// arithmetic below keeps the tool's formulas and their order of operations.
#include <algorithm>
#include <array>
#include <complex>
#include <memory>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "capi/guard.hpp"
#include "hdt.h"
#include "picture/disk_frame.hpp"

using hdt::capi::ApiError;
using hdt::capi::guarded;
using namespace hdt::picture;

namespace {

constexpr double kSizeMax = HDT_SVG_SIZE_MAX;
constexpr unsigned kKnownFlags = HDT_SVG_NEIGHBOURS | HDT_SVG_HIDE_DUMMIES | HDT_SVG_VORONOI | HDT_SVG_SIDE_LABELS;

// A failed call of the public API inside hdt_svg: its status, and its message
// (which names the function) after "hdt_svg: ".
void check(hdt_status status) {
  if (status != HDT_OK) throw ApiError(status, hdt_last_error_message());
}

// ---- Moebius maps ----

using Matrix = std::array<double, 4>; // SU(1,1), layout of hdt_word_matrix

// z -> (a z + b) / (conj(b) z + conj(a)) for m = (Re a, Im a, Re b, Im b).
void moebius_apply(const double m[4], double x, double y, double *ox, double *oy) {
  const double ar = m[0], ai = m[1], br = m[2], bi = m[3];
  const double nr = ar * x - ai * y + br, ni = ar * y + ai * x + bi; /* a z + b */
  const double dr = br * x + bi * y + ar, di = br * y - bi * x - ai; /* conj(b) z + conj(a) */
  const double d2 = dr * dr + di * di;
  *ox = (nr * dr + ni * di) / d2;
  *oy = (ni * dr - nr * di) / d2;
}

// ---- What the picture needs of the triangulation, read once ----

struct Snapshot {
  int genus = 0;
  // The live vertices by increasing id: representative, and dummy or not.
  std::vector<double> x, y;
  std::vector<unsigned char> dummy;
  std::size_t vertex_count = 0, dummy_count = 0, vertex_id_bound = 0;
  // The canonical copy of each face, in hdt_faces order: 3 corners each.
  std::size_t face_count = 0;
  std::vector<double> cx, cy;
  // With HDT_SVG_VORONOI: hdt_voronoi_edges, 4 numbers per edge.
  std::vector<double> voronoi;
};

void take_snapshot(const hdt_triangulation *t, Snapshot &s) {
  s.genus = hdt_genus(t);
  s.vertex_id_bound = hdt_vertex_id_bound(t);

  size_t count = 0;
  check(hdt_vertices(t, nullptr, nullptr, nullptr, 0, &count));
  std::vector<uint32_t> ids(count);
  std::vector<double> xy(2 * count);
  s.dummy.resize(count);
  if (count > 0) check(hdt_vertices(t, ids.data(), xy.data(), s.dummy.data(), count, &count));
  s.x.resize(count);
  s.y.resize(count);
  std::unordered_map<uint32_t, std::size_t> index_of;
  index_of.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    s.x[i] = xy[2 * i];
    s.y[i] = xy[2 * i + 1];
    index_of.emplace(ids[i], i);
    if (s.dummy[i]) ++s.dummy_count;
  }
  s.vertex_count = count;

  size_t faces = 0;
  check(hdt_faces(t, nullptr, nullptr, 0, &faces));
  std::vector<uint32_t> vertices(3 * faces);
  std::vector<int32_t> translations(3 * faces);
  if (faces > 0) check(hdt_faces(t, vertices.data(), translations.data(), faces, &faces));
  s.face_count = faces;
  s.cx.resize(3 * faces);
  s.cy.resize(3 * faces);
  std::unordered_map<int32_t, Matrix> matrices;
  for (std::size_t i = 0; i < 3 * faces; ++i) {
    const auto v = index_of.find(vertices[i]);
    if (v == index_of.end())
      throw std::logic_error("hdt_svg: face " + std::to_string(i / 3) + " names vertex " +
                             std::to_string(vertices[i]) + ", which is not live");
    const double px = s.x[v->second], py = s.y[v->second];
    const int32_t id = translations[i];
    if (id == 0) {
      s.cx[i] = px;
      s.cy[i] = py;
      continue;
    }
    auto m = matrices.find(id);
    if (m == matrices.end()) {
      Matrix matrix;
      check(hdt_translation_matrix(t, id, matrix.data()));
      m = matrices.emplace(id, matrix).first;
    }
    moebius_apply(m->second.data(), px, py, &s.cx[i], &s.cy[i]);
  }
}

void take_voronoi(const hdt_triangulation *t, Snapshot &s) {
  size_t edges = 0;
  check(hdt_voronoi_edges(t, nullptr, 0, &edges));
  s.voronoi.resize(4 * edges);
  if (edges > 0) check(hdt_voronoi_edges(t, s.voronoi.data(), edges, &edges));
}

// ---- The polygon F_g and the neighbour set N ----

struct Geometry {
  int n = 0;                            // 4g sides (n for a polygon surface)
  std::vector<double> vx, vy;           // F_g's vertices v_0 .. v_{n-1}
  std::vector<double> mx, my;           // the sides' midpoints m_0 .. m_{n-1}
  std::vector<double> cx, cy;           // centres of the sides' circles (orthogonal to the unit circle)
  // A polygon surface's sides: sign +1 or -1 makes the power positive on
  // the polygon's side; a side on a diameter has no circle and line set
  // (its power then the sign times the cross product with the side).
  std::vector<double> sign;
  std::vector<unsigned char> line;
  std::vector<Matrix> generator;        // g_0 .. g_{n-1} (a polygon's pairings)
  std::vector<Matrix> neighbour;        // the elements of N, by translation id
  bool polygon = false;                 // a surface given by a polygon, not F_g
};

double side_power(const Geometry &g, int k, double x, double y);

Matrix product(const Matrix &p, const Matrix &q) {  // p after q, SU(1,1) parts (Re a, Im a, Re b, Im b)
  const std::complex<double> a(p[0], p[1]), b(p[2], p[3]), c(q[0], q[1]), d(q[2], q[3]);
  const std::complex<double> e = a * c + b * std::conj(d), f = a * d + b * std::conj(c);
  return {e.real(), e.imag(), f.real(), f.imag()};
}

// The polygon of a surface given by one: its vertices, its sides' circles
// (through v_k and v_{k+1}, orthogonal to the unit circle: centre c with
// c.v = (1 + |v|^2) / 2 at both), their hyperbolic midpoints, the pairings
// and the elements of N as products of them, all in double: for drawing.
void take_polygon_geometry(const hdt_surface *surface, Geometry &g) {
  const int n = hdt_surface_side_count(surface);
  g.n = n;
  g.polygon = true;
  for (auto *v : {&g.vx, &g.vy, &g.mx, &g.my, &g.cx, &g.cy, &g.sign}) v->assign(std::size_t(n), 0);
  g.line.assign(std::size_t(n), 0);
  g.generator.resize(std::size_t(n));
  for (int k = 0; k < n; ++k) {
    check(hdt_surface_vertex(surface, k, &g.vx[std::size_t(k)], &g.vy[std::size_t(k)]));
    check(hdt_surface_pairing(surface, k, nullptr, g.generator[std::size_t(k)].data()));
  }
  double ix = 0, iy = 0;  // a point inside: the vertices' mean in the Klein model, back in the disk
  for (int k = 0; k < n; ++k) {
    const double x = g.vx[std::size_t(k)], y = g.vy[std::size_t(k)], d = 1 + x * x + y * y;
    ix += 2 * x / d / n, iy += 2 * y / d / n;
  }
  const double kr = 1 + std::sqrt(std::max(0.0, 1 - ix * ix - iy * iy));
  ix /= kr, iy /= kr;
  for (int k = 0; k < n; ++k) {
    const std::size_t a = std::size_t(k), b = std::size_t((k + 1) % n);
    const double px = g.vx[a], py = g.vy[a], qx = g.vx[b], qy = g.vy[b];
    const double det = px * qy - py * qx, rp = (1 + px * px + py * py) / 2, rq = (1 + qx * qx + qy * qy) / 2;
    if (std::fabs(det) < 1e-12 * (std::hypot(px, py) + std::hypot(qx, qy))) {
      g.line[a] = 1;  // a diameter: the power is the cross product with the side's direction
      g.cx[a] = -(qy - py), g.cy[a] = qx - px;
    } else {
      g.cx[a] = (rp * qy - rq * py) / det, g.cy[a] = (px * rq - qx * rp) / det;
    }
    g.sign[a] = 1;
    // The hyperbolic midpoint: q seen from p at the origin, halfway out, and back.
    const std::complex<double> p(px, py), q(qx, qy), w = (q - p) / (1.0 - std::conj(p) * q);
    const std::complex<double> half = w / std::abs(w) * std::tanh(std::atanh(std::abs(w)) / 2);
    const std::complex<double> m = (half + p) / (1.0 + std::conj(p) * half);
    g.mx[a] = m.real(), g.my[a] = m.imag();
  }
  for (int k = 0; k < n; ++k)  // positive powers on the polygon's side
    if (side_power(g, k, ix, iy) < 0) g.sign[std::size_t(k)] = -1;
  size_t count = 0;
  check(hdt_surface_neighbour_count(surface, &count));
  g.neighbour.resize(count);
  std::vector<int32_t> word;
  for (std::size_t id = 0; id < count; ++id) {
    size_t length = 0;
    check(hdt_surface_neighbour_word(surface, id, nullptr, 0, &length));
    word.resize(length + 1);
    check(hdt_surface_neighbour_word(surface, id, word.data(), word.size(), &length));
    Matrix m{1, 0, 0, 0};
    for (std::size_t i = 0; i < length; ++i) m = product(m, g.generator[std::size_t(word[i])]);
    g.neighbour[id] = m;
  }
}

void take_geometry(int genus, Geometry &g) {
  const int n = 4 * genus;
  g.n = n;
  g.vx.resize(std::size_t(n));
  g.vy.resize(std::size_t(n));
  g.mx.resize(std::size_t(n));
  g.my.resize(std::size_t(n));
  g.cx.resize(std::size_t(n));
  g.cy.resize(std::size_t(n));
  g.generator.resize(std::size_t(n));
  for (int k = 0; k < n; ++k) {
    const int32_t letter = k;
    double mx, my;
    check(hdt_polygon_vertex(genus, k, &g.vx[std::size_t(k)], &g.vy[std::size_t(k)]));
    check(hdt_polygon_side_midpoint(genus, k, &mx, &my));
    check(hdt_word_matrix(genus, &letter, 1, g.generator[std::size_t(k)].data()));
    // The circle through m_k orthogonal to the unit circle has its centre on
    // the ray through m_k, at |c| = (|m| + 1/|m|) / 2.
    g.mx[std::size_t(k)] = mx;
    g.my[std::size_t(k)] = my;
    const double m2 = mx * mx + my * my, scale = (1 + m2) / (2 * m2);
    g.cx[std::size_t(k)] = mx * scale;
    g.cy[std::size_t(k)] = my * scale;
  }
  size_t count = 0;
  check(hdt_neighbour_count(genus, &count));
  g.neighbour.resize(count);
  std::vector<int32_t> word(2 * std::size_t(genus) + 1); // the words of N have at most 2g letters
  for (std::size_t id = 0; id < count; ++id) {
    size_t length = 0;
    check(hdt_neighbour_word(genus, id, word.data(), word.size(), &length));
    check(hdt_word_matrix(genus, word.data(), length, g.neighbour[id].data()));
  }
}

// The power of the disk point (x, y) with respect to the circle of side k:
// negative beyond the side's geodesic (outside F_g's half-plane), zero on it.
double side_power(const Geometry &g, int k, double x, double y) {
  const std::size_t i = std::size_t(k);
  if (!g.polygon) return 1 + x * x + y * y - 2 * (g.cx[i] * x + g.cy[i] * y);
  if (g.line[i]) return g.sign[i] * (g.cx[i] * (x - g.vx[i]) + g.cy[i] * (y - g.vy[i]));
  return g.sign[i] * (1 + x * x + y * y - 2 * (g.cx[i] * x + g.cy[i] * y));
}

bool beyond(const Geometry &g, int k, double x, double y) { return side_power(g, k, x, y) < 0; }

// Whether the triangle with corners x, y can meet F_g.
bool may_meet_polygon(const Geometry &g, const double x[3], const double y[3]) {
  for (int k = 0; k < g.n; ++k)
    if (beyond(g, k, x[0], y[0]) && beyond(g, k, x[1], y[1]) && beyond(g, k, x[2], y[2])) return false;
  return true;
}

// ---- Drawing ----

class Picture : public DiskFrame {
 public:
  // band: the caption band's height at size 800 (kTitleHeight for a
  // caption of two lines).
  Picture(const Snapshot &s, const Geometry &g, double size, double band) : DiskFrame(size, band), s_(s), g_(g) {}

  // A triangle whose corners are all within a pixel of each other.
  bool too_small(const double x[3], const double y[3]) const {
    const double pixel = 2.0 / (size_ * kDiskScale);
    for (int a = 0; a < 3; ++a)
      if (std::hypot(x[a] - x[(a + 1) % 3], y[a] - y[(a + 1) % 3]) > pixel) return false;
    return true;
  }

  // ---- The surface's pieces in F_g ----
  //
  // The picture shows M_g as F_g with its sides paired: every copy h(T) of a
  // face T that meets F_g, cut at F_g's sides by a clip path, so that F_g is
  // tiled exactly and an edge leaving through side s_k comes back through
  // s_{k+2g}. The canonical copy T of a face has its smallest vertex in F_g
  // and lies in D_N, the union of the tiles n(F_g), n in N; so a tile
  // h^{-1}(F_g) meeting T is one of those, and the copies to look at are
  // h(T), h in N (N = N^{-1}). A copy is dropped when its three corners lie
  // beyond one side of F_g (then all of it does: half-planes are convex); the
  // few others that miss F_g are cut away by the clip path.

  // Path data for the copies h(T) meeting F_g, each then mapped by `then`
  // (nullptr: the identity); with `skip_small`, copies below a pixel are left
  // out.
  void pieces(Text &f, const double *then, bool skip_small) const {
    std::size_t drawn = 0;
    for (std::size_t i = 0; i < s_.face_count; ++i) {
      const double *tx = &s_.cx[3 * i], *ty = &s_.cy[3 * i];
      for (std::size_t h = 0; h < g_.neighbour.size(); ++h) {
        double x[3], y[3];
        for (int c = 0; c < 3; ++c) {
          x[c] = tx[c];
          y[c] = ty[c];
          if (h != 0) moebius_apply(g_.neighbour[h].data(), tx[c], ty[c], &x[c], &y[c]);
        }
        if (!may_meet_polygon(g_, x, y)) continue;
        if (then)
          for (int c = 0; c < 3; ++c) moebius_apply(then, x[c], y[c], &x[c], &y[c]);
        if (skip_small && too_small(x, y)) continue;
        geodesic_polygon(f, x, y, 3);
        if (++drawn % 8 == 0) f.putc('\n');
      }
    }
  }

  // The Voronoi edges' copies h(e), h in N, that may meet F_g (both ends
  // beyond one side: all of the geodesic segment is), as in pieces(): the
  // edge is placed in its left face's canonical frame, within the circumdisks
  // of that copy and of the neighbour's copy beside it. Segments shorter
  // than a pixel (cocircular faces give length 0) are left out, and with
  // `then` (nullptr: the identity) each copy is mapped by it, and left out
  // when it is then below a pixel.
  void voronoi_pieces(Text &f, const double *then) const {
    const double pixel = 2.0 / (size_ * kDiskScale);
    std::size_t drawn = 0;
    for (std::size_t e = 0; 4 * e < s_.voronoi.size(); ++e) {
      const double *p = &s_.voronoi[4 * e];
      if (std::hypot(p[2] - p[0], p[3] - p[1]) <= pixel) continue;
      for (std::size_t h = 0; h < g_.neighbour.size(); ++h) {
        double x[2] = {p[0], p[2]}, y[2] = {p[1], p[3]};
        if (h != 0)
          for (int c = 0; c < 2; ++c) moebius_apply(g_.neighbour[h].data(), p[2 * c], p[2 * c + 1], &x[c], &y[c]);
        bool away = false;
        for (int k = 0; k < g_.n && !away; ++k) away = beyond(g_, k, x[0], y[0]) && beyond(g_, k, x[1], y[1]);
        if (away) continue;
        if (then) {
          for (int c = 0; c < 2; ++c) moebius_apply(then, x[c], y[c], &x[c], &y[c]);
          if (std::hypot(x[1] - x[0], y[1] - y[0]) <= pixel) continue;
        }
        f.put("M%.2f %.2f", sx(x[0]), sy(y[0]));
        geodesic_to(f, x[0], y[0], x[1], y[1]);
        if (++drawn % 8 == 0) f.putc('\n');
      }
    }
  }

  // The polygon F_g, or its image under m (nullptr: the identity).
  void polygon_copy(Text &f, const double *m) const {
    std::vector<double> x(g_.vx), y(g_.vy);
    if (m)
      for (std::size_t k = 0; k < x.size(); ++k) moebius_apply(m, g_.vx[k], g_.vy[k], &x[k], &y[k]);
    geodesic_polygon(f, x.data(), y.data(), g_.n);
  }

  // A dot at each place a vertex appears in the closed F_g: its
  // representative, and for a vertex on F_g's boundary its other copies
  // there (on the paired side; at every corner for a vertex at v_0). With
  // `tiles`, those places mapped by each of the matrices instead (the dots
  // of the tiles across F_g's sides).
  void vertex_dots(Text &f, bool dummies, const char *colour, double radius,
                   const std::vector<Matrix> *tiles = nullptr) const {
    f.put("<g fill=\"%s\">\n", colour);
    if (!tiles) {
      for (std::size_t v = 0; v < s_.vertex_count; ++v)
        if (bool(s_.dummy[v]) == dummies) vertex_places(f, v, radius, nullptr);
    } else {
      for (const Matrix &m : *tiles)
        for (std::size_t v = 0; v < s_.vertex_count; ++v)
          if (bool(s_.dummy[v]) == dummies) vertex_places(f, v, radius, m.data());
    }
    f.puts("</g>\n");
  }

 private:
  // A dot of vertex_dots at (x, y), mapped by then (nullptr: the identity).
  void dot(Text &f, double x, double y, double radius, const double *then) const {
    if (then) moebius_apply(then, x, y, &x, &y);
    f.put("<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%g\"/>\n", sx(x), sy(y), radius);
  }

  // The dots of vertex v at its places in the closed F_g, mapped by then.
  void vertex_places(Text &f, std::size_t v, double radius, const double *then) const {
    const double eps = 1e-9;
    {
      const double px = s_.x[v], py = s_.y[v];
      dot(f, px, py, radius, then);
      bool on_boundary = false;
      for (int k = 0; k < g_.n && !on_boundary; ++k) on_boundary = std::fabs(side_power(g_, k, px, py)) < eps;
      for (std::size_t h = 1; on_boundary && h < g_.neighbour.size(); ++h) {
        double x, y;
        moebius_apply(g_.neighbour[h].data(), px, py, &x, &y);
        bool inside = true;
        for (int k = 0; k < g_.n && inside; ++k) inside = side_power(g_, k, x, y) > -eps;
        if (inside) dot(f, x, y, radius, then);
      }
    }
  }

  const Snapshot &s_;
  const Geometry &g_;
};

// The length of the valid UTF-8 sequence at p (1 to 4 bytes), or 0.
int utf8_sequence(const unsigned char *p) {
  int n;
  unsigned int min;
  if (p[0] < 0x80) return 1;
  if ((p[0] & 0xe0) == 0xc0) n = 2, min = 0x80;
  else if ((p[0] & 0xf0) == 0xe0) n = 3, min = 0x800;
  else if ((p[0] & 0xf8) == 0xf0) n = 4, min = 0x10000;
  else return 0;
  unsigned int code = p[0] & (0x7fu >> n);
  for (int i = 1; i < n; ++i) {
    if ((p[i] & 0xc0) != 0x80) return 0; // also stops at the terminating NUL
    code = (code << 6) | (p[i] & 0x3f);
  }
  if (code < min || code > 0x10ffff || (code >= 0xd800 && code <= 0xdfff)) return 0;
  return n;
}

// Plain text as SVG character data: markup and quotes escaped, and what XML
// 1.0 does not allow (control characters, bytes that are not UTF-8, as in a
// file name) shown as '?'.
void put_escaped(Text &f, const char *text) {
  const unsigned char *p = reinterpret_cast<const unsigned char *>(text);
  while (*p) {
    const int n = utf8_sequence(p);
    if (n == 0 || (*p < 0x20 && *p != '\t')) {
      f.putc('?');
      ++p;
    } else if (*p == '&') {
      f.puts("&amp;"), ++p;
    } else if (*p == '<') {
      f.puts("&lt;"), ++p;
    } else if (*p == '>') {
      f.puts("&gt;"), ++p;
    } else if (*p == '"') {
      f.puts("&quot;"), ++p;
    } else {
      f.write(reinterpret_cast<const char *>(p), std::size_t(n));
      p += n;
    }
  }
}

// The caption's first line when the caller gives none.
// polygon: the surface is given by a polygon, not the built-in M_g.
std::string default_title(const Snapshot &s, bool polygon) {
  char text[160], surface[64];
  if (polygon) std::snprintf(surface, sizeof surface, "a surface of genus %d", s.genus);
  else std::snprintf(surface, sizeof surface, "M_%d", s.genus);
  const std::size_t user = s.vertex_count - s.dummy_count;
  if (user == 0)
    std::snprintf(text, sizeof text, "The dummy point set of %s%s and its Delaunay triangulation", surface,
                  s.vertex_count == s.vertex_id_bound ? ", before any insertion," : "");
  else
    std::snprintf(text, sizeof text, "Delaunay triangulation of %zu point%s on %s", user, user == 1 ? "" : "s",
                  surface);
  return text;
}

// ---- The caption's lines ----
//
// SVG cannot wrap text, so the caption is wrapped here, at spaces, from an
// estimate of its width: the advance widths of DejaVu Sans (the widest of
// the usual sans-serif fonts, matplotlib's default), in thousandths of an
// em and rounded up, plus 5%; 1 em for a character beyond ASCII. The numbers
// are bindings/python/hdt/picture.py's too.
constexpr unsigned short kAsciiWidth[95] = {
    // ' ' to '/'
    318, 401, 460, 838, 637, 950, 780, 276, 391, 391, 500, 838, 318, 361, 318, 337,
    // '0' to '?'
    637, 637, 637, 637, 637, 637, 637, 637, 637, 637, 337, 337, 838, 838, 838, 531,
    // '@' to 'O'
    1000, 685, 687, 699, 771, 632, 576, 775, 752, 295, 295, 656, 558, 863, 749, 788,
    // 'P' to '_'
    604, 788, 695, 635, 611, 732, 685, 989, 686, 611, 686, 391, 337, 391, 838, 500,
    // '`' to 'o'
    500, 613, 635, 550, 635, 616, 353, 635, 634, 278, 278, 580, 278, 975, 634, 613,
    // 'p' to '~'
    635, 635, 412, 521, 393, 634, 592, 819, 592, 592, 525, 637, 337, 637, 838};

// The estimated width of n bytes of caption text, in thousandths of an em,
// character by character as put_escaped writes it ('?' for what it replaces).
double text_width(const char *text, std::size_t n) {
  const unsigned char *p = reinterpret_cast<const unsigned char *>(text), *end = p + n;
  double width = 0;
  while (p < end) {
    const int k = utf8_sequence(p);
    if (k == 0 || (*p < 0x20 && *p != '\t')) width += kAsciiWidth['?' - ' '], ++p;
    else if (*p == '\t') width += kAsciiWidth[0], ++p;
    else if (k == 1) width += kAsciiWidth[*p - ' '], ++p;
    else width += 1000, p += k;
  }
  return width;
}

// The text cut into lines at spaces, each (but a single word) estimated to
// fit `width` pixels at font size `font`: at the line's last space after a
// ',' or ';' if it has one, else at its last space. Each piece but the last
// keeps its space at its end, so that the pieces joined are the text.
std::vector<std::string> wrap(const std::string &text, double width, double font) {
  const double limit = width * 1000 / (font * 1.05);
  std::vector<std::string> lines;
  // The current line, where it can end, and its last space after ',' or ';'.
  std::size_t start = 0, end = 0, clause = 0;
  while (end < text.size()) {
    std::size_t next = text.find(' ', end + 1);
    if (next == std::string::npos) next = text.size();
    if (end > start && text_width(text.data() + start, next - start) > limit) {
      const std::size_t cut = clause > start ? clause : end;
      lines.push_back(text.substr(start, cut + 1 - start)); // with its space
      start = cut + 1;
      end = start;
      continue;
    }
    end = next;
    if (end < text.size() && (text[end - 1] == ',' || text[end - 1] == ';')) clause = end;
  }
  if (start < text.size() || lines.empty()) lines.push_back(text.substr(start));
  return lines;
}

// One part of the caption as a <text> element: the lines after the first in
// tspans, step apart.
void put_lines(Text &f, const std::vector<std::string> &lines, double x, double y, double font, double step,
               const char *fill) {
  f.put("<text x=\"%.10g\" y=\"%.10g\" font-family=\"sans-serif\" font-size=\"%.10g\"%s%s%s>", x, y, font,
        fill ? " fill=\"" : "", fill ? fill : "", fill ? "\"" : "");
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (i > 0) f.put("<tspan x=\"%.10g\" dy=\"%.10g\">", x, step);
    put_escaped(f, lines[i].c_str());
    if (i > 0) f.puts("</tspan>");
  }
  f.puts("</text>\n");
}

void draw(Text &f, const Snapshot &s, const Geometry &g, double size, const char *title, unsigned flags) {
  const bool neighbours = flags & HDT_SVG_NEIGHBOURS, hide_dummies = flags & HDT_SVG_HIDE_DUMMIES;
  const bool voronoi = flags & HDT_SVG_VORONOI, side_labels = flags & HDT_SVG_SIDE_LABELS;
  const double scale = size / kReferenceSize; // the caption's layout

  // The caption: the title, and what the picture shows, each wrapped to the
  // width less the margins.
  std::string info;
  {
    Text t;
    t.put("%zu vertices", s.vertex_count);
    if (s.dummy_count)
      t.put(" (%zu dumm%s, %s)", s.dummy_count, s.dummy_count == 1 ? "y" : "ies", hide_dummies ? "not marked" : "red");
    if (g.polygon) t.put(", %zu faces, drawn in the surface's %d-sided polygon and cut at its sides", s.face_count, g.n);
    else t.put(", %zu faces, drawn in F_%d and cut at its sides", s.face_count, s.genus);
    if (neighbours) t.put(", and in the %d tiles across them", g.n);
    if (voronoi) t.puts("; Voronoi diagram green");
    if (side_labels && g.polygon) t.puts("; side k labelled g_k, the pairing that maps its paired side onto it");
    else if (side_labels) t.puts("; side s_k labelled g_k: g_k maps s_(k+2g), labelled g_k^-1, onto it");
    t.puts("; Poincare disk");
    info = t.str();
  }
  const double text_width_px = size - 24 * scale;
  const std::vector<std::string> title_lines =
      wrap(title ? title : default_title(s, g.polygon), text_width_px, 16 * scale);
  const std::vector<std::string> info_lines = wrap(info, text_width_px, 13 * scale);
  const double more_title = kTitleStep * double(title_lines.size() - 1);
  const double band = kTitleHeight + more_title + kInfoStep * double(info_lines.size() - 1);
  const Picture p(s, g, size, band);
  // Sizes are printed with 10 digits (%g's 6 would round a width such as
  // 1234.567); at size 800 they are the integers the tool always wrote.
  const double height = size + p.title_height(), r = size / 2 * kDiskScale;
  // Thinner lines and smaller dots for large triangulations.
  const double line = s.face_count > 6000 ? 0.3 : 0.6;
  const double dot = s.vertex_count > 3000 ? 0.9 : 1.6;

  f.put("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.10g\" height=\"%.10g\" viewBox=\"0 0 %.10g %.10g\">\n",
        size, height, size, height);
  f.puts("<defs><clipPath id=\"hdt-polygon\"><path d=\"");
  p.polygon_copy(f, nullptr);
  f.puts("\"/></clipPath></defs>\n");
  f.puts("<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n");
  f.put("<circle cx=\"%.10g\" cy=\"%.10g\" r=\"%.10g\" fill=\"#f4f6fb\" stroke=\"#333\" stroke-width=\"1.5\"/>\n", p.sx(0),
        p.sy(0), r);

  // F_g, lightly filled under everything.
  f.puts("<path fill=\"#ffd98a\" fill-opacity=\"0.35\" stroke=\"none\" d=\"");
  p.polygon_copy(f, nullptr);
  f.puts("\"/>\n");

  // Across the sides, lighter: the tiles g_k(F_g), each with the
  // triangulation drawn in it (F_g's pieces mapped by g_k, cut at the tile).
  if (neighbours) {
    f.puts("<defs>\n");
    for (int k = 0; k < g.n; ++k) {
      f.put("<clipPath id=\"hdt-tile-%d\"><path d=\"", k);
      p.polygon_copy(f, g.generator[std::size_t(k)].data());
      f.puts("\"/></clipPath>\n");
    }
    f.puts("</defs>\n<g fill=\"none\" stroke-linejoin=\"round\">\n");
    for (int k = 0; k < g.n; ++k) {
      f.put("<path clip-path=\"url(#hdt-tile-%d)\" stroke=\"#8a9ac0\" stroke-width=\"%g\" d=\"", k, line * 2 / 3);
      p.pieces(f, g.generator[std::size_t(k)].data(), true);
      f.puts("\"/>\n");
    }
    // Their Voronoi diagrams, lighter green, cut at each tile.
    for (int k = 0; voronoi && k < g.n; ++k) {
      f.put("<path clip-path=\"url(#hdt-tile-%d)\" stroke=\"#8cc498\" stroke-width=\"%g\" stroke-linecap=\"round\" "
            "d=\"",
            k, line);
      p.voronoi_pieces(f, g.generator[std::size_t(k)].data());
      f.puts("\"/>\n");
    }
    f.puts("<path stroke=\"#e0b070\" stroke-width=\"1\" d=\"");
    for (int k = 0; k < g.n; ++k) p.polygon_copy(f, g.generator[std::size_t(k)].data());
    f.puts("\"/>\n</g>\n");
    // And their vertices, lighter and smaller.
    p.vertex_dots(f, false, "#7585b0", dot * 0.85, &g.generator);
    if (!hide_dummies) p.vertex_dots(f, true, "#e89a9b", (dot + 1.0) * 0.85, &g.generator);
  }

  // The triangulation in F_g, cut at its sides.
  f.put("<path clip-path=\"url(#hdt-polygon)\" fill=\"none\" stroke=\"#1f2a44\" stroke-width=\"%g\" "
        "stroke-linejoin=\"round\" d=\"",
        line);
  p.pieces(f, nullptr, false);
  f.puts("\"/>\n");

  // The Voronoi diagram over it, cut the same way.
  if (voronoi) {
    f.put("<path clip-path=\"url(#hdt-polygon)\" fill=\"none\" stroke=\"#2a8a3a\" stroke-width=\"%g\" "
          "stroke-linecap=\"round\" d=\"",
          line * 1.5);
    p.voronoi_pieces(f, nullptr);
    f.puts("\"/>\n");
  }

  // F_g's boundary on top.
  f.puts("<path fill=\"none\" stroke=\"#c05a00\" stroke-width=\"1.8\" stroke-opacity=\"0.85\" d=\"");
  p.polygon_copy(f, nullptr);
  f.puts("\"/>\n");

  // The vertices: user points dark, dummies red.
  p.vertex_dots(f, false, "#1f2a44", dot);
  if (!hide_dummies) p.vertex_dots(f, true, "#d62728", dot + 1.0);

  // The sides' labels, outside F_g beside their midpoints, over a white halo.
  if (side_labels) {
    const double font = 12 * scale;
    f.put("<g font-family=\"sans-serif\" font-size=\"%.10g\" text-anchor=\"middle\" fill=\"#c05a00\" "
          "stroke=\"white\" stroke-width=\"%.10g\" stroke-linejoin=\"round\" paint-order=\"stroke\">\n",
          font, 3 * scale);
    for (int k = 0; k < g.n; ++k) {
      char label[32];
      if (g.polygon) std::snprintf(label, sizeof label, "g_%d", k);
      else if (k < g.n / 2) std::snprintf(label, sizeof label, "g_%d", k);
      else std::snprintf(label, sizeof label, "g_%d^-1", k - g.n / 2);
      // The outward unit vector at m_k in SVG's coordinates (y down), and the
      // distance from m_k to the label's centre: a gap and half the label's
      // extent in that direction.
      const double mx = g.mx[std::size_t(k)], my = g.my[std::size_t(k)], m = std::hypot(mx, my);
      const double ux = mx / m, uy = -my / m;
      const double w = text_width(label, std::strlen(label)) * font * 1.05 / 1000;
      const double gap = 4 * scale + std::fabs(ux) * w / 2 + std::fabs(uy) * font / 2;
      f.put("<text x=\"%.2f\" y=\"%.2f\">", p.sx(mx) + ux * gap, p.sy(my) + uy * gap + 0.35 * font);
      put_escaped(f, label);
      f.puts("</text>\n");
    }
    f.puts("</g>\n");
  }

  put_lines(f, title_lines, 12 * scale, 22 * scale, 16 * scale, kTitleStep * scale, nullptr);
  put_lines(f, info_lines, 12 * scale, (42 + more_title) * scale, 13 * scale, kInfoStep * scale, "#555");
  f.puts("</svg>\n");
}

} // namespace

extern "C" {

HDT_API hdt_status hdt_svg(const hdt_triangulation *t, double size, const char *title, unsigned flags, char *text,
                           size_t capacity, size_t *length) HDT_NOEXCEPT {
  return guarded("hdt_svg", [&] {
    if (!t) throw ApiError(HDT_EINVAL, "the triangulation handle is NULL");
    if (!length) throw ApiError(HDT_EINVAL, "length must not be NULL");
    if (!(size > 0 && size <= kSizeMax)) {
      char message[128];
      std::snprintf(message, sizeof message, "size must be a number of pixels in (0, %g], got %g", kSizeMax, size);
      throw ApiError(HDT_EINVAL, message);
    }
    if (flags & ~kKnownFlags)
      throw ApiError(HDT_EINVAL, "unknown flags " + std::to_string(flags & ~kKnownFlags) +
                                     " (HDT_SVG_NEIGHBOURS = 1, HDT_SVG_HIDE_DUMMIES = 2, HDT_SVG_VORONOI = 4 and "
                                     "HDT_SVG_SIDE_LABELS = 8 are known)");
    if (capacity > 0 && !text)  // before the drawing, which copy_text would check after
      throw ApiError(HDT_EINVAL, "text is NULL but capacity is " + std::to_string(capacity));

    // A polygon surface is drawn in its polygon, with its pairings and N.
    hdt_surface *surface = nullptr;
    check(hdt_triangulation_surface(t, &surface));
    const std::unique_ptr<hdt_surface, void (*)(hdt_surface *)> owned(surface, hdt_surface_destroy);
    Snapshot s;
    take_snapshot(t, s);
    if (flags & HDT_SVG_VORONOI) take_voronoi(t, s);
    Geometry g;
    if (surface) {
      take_polygon_geometry(surface, g);
    } else {
      take_geometry(s.genus, g);
    }
    Text f;
    draw(f, s, g, size, title, flags);

    return hdt::capi::copy_text(f.str(), "the picture", text, capacity, length);
  });
}

} // extern "C"
