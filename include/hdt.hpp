// libhdt for C++17: a header-only layer over the C ABI of hdt.h.
//
// Nothing of C++ crosses the ABI: every call below is a call of hdt.h, made
// inline in the caller's program, so the library's binary interface stays
// the C one. What this header adds:
//   - hdt::Triangulation, an RAII owner of an hdt_triangulation (movable,
//     not copyable; copy() makes an independent one through hdt_save and
//     hdt_load), and hdt::PolygonSurface, one of an hdt_surface;
//   - results as values and std::vector, the two-call pattern done inside;
//   - a failing status as an hdt::Error exception carrying the status and
//     hdt_last_error_message(). The C API's guarantees carry over: a call
//     that throws changed nothing, except where hdt.h says what it kept.
// Threads: as hdt.h (one thread uses a handle at a time).
#ifndef HDT_HPP
#define HDT_HPP

#include <hdt.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace hdt {

// A failing hdt_status, with the library's message.
class Error : public std::runtime_error {
 public:
  Error(hdt_status status, const char *function)
      : std::runtime_error(std::string(function) + ": " + hdt_status_string(status) + " (" +
                           hdt_last_error_message() + ")"),
        status_(status) {}
  hdt_status status() const noexcept { return status_; }

 private:
  hdt_status status_;
};

namespace detail {
inline void check(hdt_status status, const char *function) {
  if (status != HDT_OK) throw Error(status, function);
}
}  // namespace detail

using Word = std::vector<int32_t>;  // letters 0 .. 4g-1 (hdt.h's convention)

struct Point {
  double x, y;
};

// The SU(1,1) matrix [[a, b], [conj b, conj a]] of a group element, as hdt.h
// lays it out: re a, im a, re b, im b.
using Matrix = std::array<double, 4>;

struct Representative {
  Point point;  // h(x + iy) in the half-open F_g
  Word word;    // the canonical word of h
};

struct Vertex {
  uint32_t id;
  Point point;  // the representative in F_g
  bool dummy;
};

struct Face {
  std::array<uint32_t, 3> vertices;     // counterclockwise
  std::array<int32_t, 3> translations;  // corner c: translations[c] applied to vertices[c]'s representative
};

struct Edge {
  std::array<uint32_t, 2> vertices;
  int32_t translation;  // h: the edge runs from vertices[0] to h(vertices[1]) (representatives; hdt_edges)
  std::array<uint32_t, 2> faces;
  double length;
};

struct Location {
  std::size_t face;
  int32_t translation;  // the copy of the face that holds the point
};

struct Refined {
  std::size_t added, unmet;
};

struct Quality {
  double min_angle;  // radians
  double max_ratio, max_radius, min_edge;
};

// ---- The surface and the group (no triangulation needed) ----

inline double systole(int genus) { return hdt_systole(genus); }

inline Point polygon_vertex(int genus, int k) {
  Point p;
  detail::check(hdt_polygon_vertex(genus, k, &p.x, &p.y), "hdt_polygon_vertex");
  return p;
}

inline Point polygon_side_midpoint(int genus, int k) {
  Point p;
  detail::check(hdt_polygon_side_midpoint(genus, k, &p.x, &p.y), "hdt_polygon_side_midpoint");
  return p;
}

inline Representative point_representative(int genus, double x, double y) {
  Representative r;
  std::size_t length = 0;
  detail::check(hdt_point_representative(genus, x, y, &r.point.x, &r.point.y, nullptr, 0, &length),
                "hdt_point_representative");
  r.word.resize(length);
  if (length > 0)
    detail::check(hdt_point_representative(genus, x, y, &r.point.x, &r.point.y, r.word.data(), length, &length),
                  "hdt_point_representative");
  return r;
}

inline Word reduce_word(int genus, const Word &word) {
  std::size_t length = 0;
  detail::check(hdt_word_reduce(genus, word.data(), word.size(), nullptr, 0, &length), "hdt_word_reduce");
  Word out(length);
  if (length > 0)
    detail::check(hdt_word_reduce(genus, word.data(), word.size(), out.data(), length, &length), "hdt_word_reduce");
  return out;
}

inline Matrix word_matrix(int genus, const Word &word) {
  Matrix m;
  detail::check(hdt_word_matrix(genus, word.data(), word.size(), m.data()), "hdt_word_matrix");
  return m;
}

// ---- A triangulation ----

class Triangulation {
 public:
  // A new triangulation of M_genus with its dummy points (hdt_create).
  explicit Triangulation(int genus) { detail::check(hdt_create(&t_, genus), "hdt_create"); }
  // The triangulation saved in bytes (hdt_load).
  static Triangulation load(const std::vector<unsigned char> &bytes) {
    hdt_triangulation *t = nullptr;
    detail::check(hdt_load(&t, bytes.data(), bytes.size()), "hdt_load");
    return Triangulation(t);
  }
  Triangulation(Triangulation &&other) noexcept : t_(std::exchange(other.t_, nullptr)) {}
  Triangulation &operator=(Triangulation &&other) noexcept {
    if (this != &other) {
      hdt_destroy(t_);
      t_ = std::exchange(other.t_, nullptr);
    }
    return *this;
  }
  Triangulation(const Triangulation &) = delete;
  Triangulation &operator=(const Triangulation &) = delete;
  ~Triangulation() { hdt_destroy(t_); }

  // An independent triangulation equal to this one (save, then load).
  Triangulation copy() const { return load(save()); }
  // The C handle, for the functions of hdt.h this header does not wrap;
  // it stays owned by this object.
  hdt_triangulation *handle() const noexcept { return t_; }

  int genus() const { return hdt_genus(t_); }
  std::size_t vertex_count() const { return hdt_vertex_count(t_); }
  std::size_t dummy_count() const { return hdt_dummy_count(t_); }
  std::size_t face_count() const { return hdt_face_count(t_); }
  std::size_t edge_count() const { return hdt_edge_count(t_); }
  std::size_t vertex_id_bound() const { return hdt_vertex_id_bound(t_); }
  bool is_dummy(uint32_t v) const { return hdt_vertex_is_dummy(t_, v) == 1; }

  // The vertex id of the point (HDT_EEXISTS, an Error, when it already is a user vertex).
  uint32_t insert(double x, double y) {
    uint32_t v;
    detail::check(hdt_insert(t_, x, y, &v), "hdt_insert");
    return v;
  }
  // The vertex of each point, in input order (hdt_insert_many).
  std::vector<uint32_t> insert_many(const std::vector<Point> &points) {
    std::vector<uint32_t> ids(points.size());
    static_assert(sizeof(Point) == 2 * sizeof(double), "Point is two doubles");
    detail::check(hdt_insert_many(t_, points.empty() ? nullptr : &points[0].x, points.size(), ids.data()),
                  "hdt_insert_many");
    return ids;
  }
  void remove(uint32_t v) { detail::check(hdt_remove_vertex(t_, v), "hdt_remove_vertex"); }
  // The dummies the guarantee still needs.
  std::size_t remove_dummies() {
    std::size_t left = 0;
    detail::check(hdt_remove_dummies(t_, &left), "hdt_remove_dummies");
    return left;
  }
  void validate() const { detail::check(hdt_validate(t_), "hdt_validate"); }

  Point vertex_point(uint32_t v) const {
    Point p;
    detail::check(hdt_vertex_point(t_, v, &p.x, &p.y), "hdt_vertex_point");
    return p;
  }
  std::vector<Vertex> vertices() const {
    const std::size_t n = vertex_count();
    std::vector<uint32_t> ids(n);
    std::vector<double> xy(2 * n);
    std::vector<uint8_t> dummy(n);
    std::size_t count = 0;
    detail::check(hdt_vertices(t_, ids.data(), xy.data(), dummy.data(), n, &count), "hdt_vertices");
    std::vector<Vertex> out(count);
    for (std::size_t i = 0; i < count; ++i) out[i] = {ids[i], {xy[2 * i], xy[2 * i + 1]}, dummy[i] != 0};
    return out;
  }
  std::vector<Face> faces() const {
    const std::size_t n = face_count();
    std::vector<Face> out(n);
    std::vector<uint32_t> v(3 * n);
    std::vector<int32_t> t(3 * n);
    std::size_t count = 0;
    detail::check(hdt_faces(t_, v.data(), t.data(), n, &count), "hdt_faces");
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) out[i].vertices[c] = v[3 * i + c], out[i].translations[c] = t[3 * i + c];
    return out;
  }
  // Each face's three corners in its canonical copy, in faces() order.
  std::vector<std::array<Point, 3>> face_points() const {
    const std::size_t n = face_count();
    std::vector<double> xy(6 * n);
    std::size_t count = 0;
    detail::check(hdt_face_points(t_, xy.data(), n, &count), "hdt_face_points");
    std::vector<std::array<Point, 3>> out(n);
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) out[i][c] = {xy[6 * i + 2 * c], xy[6 * i + 2 * c + 1]};
    return out;
  }
  std::vector<Edge> edges() const {
    const std::size_t n = edge_count();
    std::vector<uint32_t> v(2 * n), f(2 * n);
    std::vector<int32_t> t(n);
    std::vector<double> lengths(n);
    std::size_t count = 0;
    detail::check(hdt_edges(t_, v.data(), t.data(), f.data(), lengths.data(), n, &count), "hdt_edges");
    std::vector<Edge> out(count);
    for (std::size_t i = 0; i < count; ++i) out[i] = {{v[2 * i], v[2 * i + 1]}, t[i], {f[2 * i], f[2 * i + 1]}, lengths[i]};
    return out;
  }
  Word translation_word(int32_t id) const {
    std::size_t length = 0;
    detail::check(hdt_translation_word(t_, id, nullptr, 0, &length), "hdt_translation_word");
    Word w(length);
    if (length > 0) detail::check(hdt_translation_word(t_, id, w.data(), length, &length), "hdt_translation_word");
    return w;
  }
  Matrix translation_matrix(int32_t id) const {
    Matrix m;
    detail::check(hdt_translation_matrix(t_, id, m.data()), "hdt_translation_matrix");
    return m;
  }
  Location locate(double x, double y) const {
    Location l;
    detail::check(hdt_locate(t_, x, y, &l.face, &l.translation), "hdt_locate");
    return l;
  }
  uint32_t nearest_vertex(double x, double y) const {
    uint32_t v;
    detail::check(hdt_nearest_vertex(t_, x, y, &v), "hdt_nearest_vertex");
    return v;
  }

  Refined refine(double max_radius, double max_ratio, std::size_t max_points = SIZE_MAX) {
    Refined r{0, 0};
    detail::check(hdt_refine(t_, max_radius, max_ratio, max_points, &r.added, &r.unmet), "hdt_refine");
    return r;
  }
  Refined epsilon_net(double epsilon, std::size_t max_points = SIZE_MAX) {
    Refined r{0, 0};
    detail::check(hdt_epsilon_net(t_, epsilon, max_points, &r.added, &r.unmet), "hdt_epsilon_net");
    return r;
  }
  Quality quality() const {
    Quality q;
    detail::check(hdt_quality(t_, &q.min_angle, &q.max_ratio, &q.max_radius, &q.min_edge), "hdt_quality");
    return q;
  }

  std::vector<unsigned char> save() const {
    std::size_t size = 0;
    detail::check(hdt_save(t_, nullptr, 0, &size), "hdt_save");
    std::vector<unsigned char> bytes(size);
    detail::check(hdt_save(t_, bytes.data(), size, &size), "hdt_save");
    return bytes;
  }
  // The picture (hdt_svg; flags HDT_SVG_*), title may be empty.
  std::string svg(double size = 800, const std::string &title = "", unsigned flags = 0) const {
    std::size_t length = 0;
    const char *caption = title.empty() ? nullptr : title.c_str();
    detail::check(hdt_svg(t_, size, caption, flags, nullptr, 0, &length), "hdt_svg");
    std::string text(length + 1, '\0');
    detail::check(hdt_svg(t_, size, caption, flags, &text[0], text.size(), &length), "hdt_svg");
    text.resize(length);
    return text;
  }

 private:
  explicit Triangulation(hdt_triangulation *t) noexcept : t_(t) {}
  hdt_triangulation *t_ = nullptr;
};

// ---- A surface given by a fundamental polygon (HDT_0.7) ----

// The pairing of a side: the side glued to it and the isometry
// z -> (a z + b) / (conj(b) z + conj(a)) as hdt_surface_pairing gives it.
struct Pairing {
  int paired_side;
  Matrix matrix;
};

class PolygonSurface {
 public:
  // From the polygon's text (hdt_surface_from_polygon; docs/polygons.md).
  static PolygonSurface from_polygon(const std::string &text) {
    hdt_surface *s = nullptr;
    detail::check(hdt_surface_from_polygon(&s, text.data(), text.size()), "hdt_surface_from_polygon");
    return PolygonSurface(s);
  }
  // A random genus-2 polygon with 8 or 10 sides (hdt_surface_random_symmetric).
  static PolygonSurface random_symmetric(int sides, uint64_t seed) {
    hdt_surface *s = nullptr;
    detail::check(hdt_surface_random_symmetric(&s, sides, seed), "hdt_surface_random_symmetric");
    return PolygonSurface(s);
  }
  PolygonSurface(PolygonSurface &&other) noexcept : s_(std::exchange(other.s_, nullptr)) {}
  PolygonSurface &operator=(PolygonSurface &&other) noexcept {
    if (this != &other) {
      hdt_surface_destroy(s_);
      s_ = std::exchange(other.s_, nullptr);
    }
    return *this;
  }
  PolygonSurface(const PolygonSurface &) = delete;
  PolygonSurface &operator=(const PolygonSurface &) = delete;
  ~PolygonSurface() { hdt_surface_destroy(s_); }
  // The C handle, owned by this object.
  hdt_surface *handle() const noexcept { return s_; }

  int genus() const { return hdt_surface_genus(s_); }
  int side_count() const { return hdt_surface_side_count(s_); }
  Point vertex(int k) const {
    Point p;
    detail::check(hdt_surface_vertex(s_, k, &p.x, &p.y), "hdt_surface_vertex");
    return p;
  }
  Pairing pairing(int k) const {
    Pairing p;
    detail::check(hdt_surface_pairing(s_, k, &p.paired_side, p.matrix.data()), "hdt_surface_pairing");
    return p;
  }
  // The cycle index of each vertex (cycles numbered by their smallest vertex).
  std::vector<int> vertex_cycles() const {
    std::vector<int> cycle(static_cast<std::size_t>(side_count()));
    std::size_t count = 0;
    detail::check(hdt_surface_vertex_cycles(s_, cycle.data(), cycle.size(), &count), "hdt_surface_vertex_cycles");
    return cycle;
  }
  // The certified systole: lo <= sys <= hi (hdt_surface_systole).
  std::array<double, 2> systole() const {
    std::array<double, 2> b;
    detail::check(hdt_surface_systole(s_, &b[0], &b[1]), "hdt_surface_systole");
    return b;
  }
  std::size_t neighbour_count() const {
    std::size_t count = 0;
    detail::check(hdt_surface_neighbour_count(s_, &count), "hdt_surface_neighbour_count");
    return count;
  }
  // The point in the fundamental set and the word in the pairings taking
  // (x, y) there (hdt_surface_representative).
  Representative representative(double x, double y) const {
    Representative r;
    std::size_t length = 0;
    detail::check(hdt_surface_representative(s_, x, y, &r.point.x, &r.point.y, nullptr, 0, &length),
                  "hdt_surface_representative");
    r.word.resize(length);
    if (length > 0)
      detail::check(hdt_surface_representative(s_, x, y, &r.point.x, &r.point.y, r.word.data(), length, &length),
                    "hdt_surface_representative");
    return r;
  }
  // The polygon drawn as SVG (hdt_surface_svg).
  std::string svg(double size = 800) const {
    std::size_t length = 0;
    detail::check(hdt_surface_svg(s_, size, nullptr, 0, &length), "hdt_surface_svg");
    std::string text(length + 1, '\0');
    detail::check(hdt_surface_svg(s_, size, &text[0], text.size(), &length), "hdt_surface_svg");
    text.resize(length);
    return text;
  }
  // The exact text, which from_polygon reads back as the same surface.
  std::string polygon_text() const {
    std::size_t length = 0;
    detail::check(hdt_surface_polygon_text(s_, nullptr, 0, &length), "hdt_surface_polygon_text");
    std::string text(length + 1, '\0');
    detail::check(hdt_surface_polygon_text(s_, &text[0], text.size(), &length), "hdt_surface_polygon_text");
    text.resize(length);
    return text;
  }

 private:
  explicit PolygonSurface(hdt_surface *s) noexcept : s_(s) {}
  hdt_surface *s_ = nullptr;
};

}  // namespace hdt

#endif  // HDT_HPP
