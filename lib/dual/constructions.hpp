// Constructions in double on the faces of a triangulation: corner points of
// the canonical copies, circumcentres and circumradii (the Voronoi
// vertices), hyperbolic distances. Unlike the predicates these are not
// exact: each result is a rounded value (its accuracy is stated in hdt.h and
// measured by tests/test_dual.c against a 256-bit MPFR recomputation).
#pragma once

#include <array>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "dual/circle.hpp"
#include "group/moebius.hpp"
#include "mesh/triangulation.hpp"

namespace hdt::dual {

// Whether the triangulation is M_g's (exact sites, Dehn words) rather than
// a polygon surface's (mesh/polygon_triangulation.hpp): the few steps that
// differ choose by it.
template <class Tri>
constexpr bool kMg = std::is_same_v<Tri, mesh::Triangulation>;

// Corner i of face f's canonical copy: the stored point under the corner's
// translation t (which includes the vertex's home h), one Moebius map with
// the table's last-bit-accurate matrix; for a vertex with a home, its
// representative under t h^-1 (which may add ids to the table).
template <class Tri>
Point face_corner(const Tri &tri, const mesh::Face &f, int i);

// A face's corners with its sides as differences: side[i] = p[i+2] - p[i+1],
// the side opposite corner i. The constructions read a short side from
// side[], never from two corners: for corners that are exact doubles the
// difference in double is within an ulp of itself, and where rounded
// corners (translated, dummy sites: a few ulps each, tens at genus 5) could
// put a side off by more than 2^-46 of the face's smallest altitude (an
// a-priori bound, face_frame), corners and sides come from the exact data
// instead, in double-double, or at 200 bits where that is not enough; the
// corners are then their exact values rounded once, and rounded is false.
struct FaceFrame {
  Point p[3];
  Point side[3];
  bool rounded;  // some corner is a rounded value with a rounded side
};
// Face f's frame, p its corners (face_corner).
template <class Tri>
FaceFrame face_frame(const Tri &tri, const mesh::Face &f, const Point p[3]);

// Face f's circumcircle, p its corners (face_corner): in double from its
// frame, or in multiprecision from the exact data for the rare faces
// double cannot resolve (precise_circumcircle.hpp). Every face has one. The
// quality measures and the dual outputs all use it, so their centres agree
// to the bit.
template <class Tri>
Circle circumcircle(const Tri &tri, const mesh::Face &f, const Point p[3]);

// The same circle from the corners as they are, without the frame: as
// accurate as the corners (docs/refinement.md's error analysis), not
// relatively accurate on thin or tiny faces, which refinement leaves
// anyway (refine.hpp's resolution); refinement's choice, for speed.
template <class Tri>
Circle coarse_circumcircle(const Tri &tri, const mesh::Face &f, const Point p[3]);
// Face f's circumcircle from its frame (the same bits as circumcircle()).
template <class Tri>
Circle circumcircle(const Tri &tri, const mesh::Face &f, const FaceFrame &frame);

// Hyperbolic distance in the Poincare disk (curvature -1).
double distance(const Point &p, const Point &q);
// The hyperbolic length of a side d = q - p of points p, q with
// 1 - |p|^2 = wp and 1 - |q|^2 = wq, relatively accurate to a few ulps of
// d's own accuracy, down to sides of 1e-300.
double side_length(const Point &d, double wp, double wq);
// The hyperbolic angle at corner i of the frame's triangle, in radians,
// read with the corner moved to the origin (thin angles from the sides).
double corner_angle(const FaceFrame &frame, int i);

// h(p) for a translation id h.
template <class Tri>
Point translate(const Tri &tri, group::TranslationId h, const Point &p);

// The circumcentres (and radii) of the faces' canonical copies, each
// computed on first request and kept: a Voronoi cell needs the centres of
// its vertex's star, and every face is in three stars. hdt_voronoi_cell
// makes it; the Voronoi vertices and edges read it (and add to it) when it
// exists. An entry
// holds the face's vertices and corner translations beside the centre and
// is used only while the face at that index still has them: vertex ids are
// never reused and a vertex's point never changes, so they determine the
// centre, and every change of the triangulation leaves stale entries that
// no longer match (no hook in the core). 48 bytes per face once used. Not
// thread-safe: it belongs to a handle, which one thread uses at a time
// (hdt.h).
class CentreCache {
 public:
  // Room for every face (may throw std::bad_alloc); nothing else allocates.
  template <class Tri>
  void reserve(const Tri &tri);
  // Whether reserve() has made room for every face (a caller that does
  // without the cache rather than allocate it).
  template <class Tri>
  bool ready(const Tri &tri) const { return keys_.size() >= tri.faces().size(); }
  // The circumcentre of face f's canonical copy and its radius when radius
  // is not null (the same bits as circumcircle()'s of its corners).
  // reserve() first; the face's corner matrices may be computed (as
  // face_corner does).
  template <class Tri>
  Point centre(const Tri &tri, uint32_t f, double *radius = nullptr) {
    if (holds(tri, f)) return centre_held(f, radius);
    return compute(tri, f, radius);
  }
  // Whether face f's entry holds its centre (reserve() first); its radius
  // then comes with it.
  template <class Tri>
  bool holds(const Tri &tri, uint32_t f) const {
    const mesh::Face &F = tri.faces()[f];
    const Key &e = keys_[f];
    // Compared one by one: std::array's == calls memcmp.
    return e.v[0] == F.v[0] && e.v[1] == F.v[1] && e.v[2] == F.v[2] && e.t[0] == F.t[0] && e.t[1] == F.t[1] &&
           e.t[2] == F.t[2];
  }
  Point centre_held(uint32_t f, double *radius) {
    if (radius) *radius = radius_held(f);
    return centres_[f];
  }
  // Every face's centre, indexed by face: valid where holds() (a caller
  // that has made every entry hold reads them here, 16 bytes a face,
  // without a copy).
  const Point *centres() const { return centres_.data(); }
  // Face f's centre and what its radius needs (kept, as radii_),
  // computed by the caller (the same bits).
  template <class Tri>
  void store(const Tri &tri, uint32_t f, const Point &centre, double kept) {
    const mesh::Face &F = tri.faces()[f];
    keys_[f] = Key{F.v, F.t};
    centres_[f] = centre;
    radii_[f] = kept;
  }

 private:
  template <class Tri>
  Point compute(const Tri &tri, uint32_t f, double *radius);
  double radius_held(uint32_t f);
  // What an entry was computed for: the face's vertices and corner
  // translations.
  struct Key {
    std::array<uint32_t, 3> v;
    std::array<mesh::TranslationId, 3> t;
  };
  // Three arrays, not one of entries: the cells read only the centres, in
  // the rows' order, scattered (16 bytes a face, where a whole entry's 48
  // cost a copy into a compact array first).
  std::vector<Key> keys_;
  std::vector<Point> centres_;
  // The radius, or, until one is asked, -s2 with s2 > 0 the squared
  // diameter it is computed from (a logarithm, where the centre costs
  // an isometry's worth): a cell's centres need no radius, and a later
  // hdt_voronoi_vertices then need not recompute the centre.
  std::vector<double> radii_;
};

// Whole outputs, in hdt_faces' face order and hdt_edges' edge order. They
// need the matrices of the corner translations (and of the neighbour
// translations for hdt_voronoi_edges): warm_corner_matrices() computes
// those first, which may fail (memory); after it these allocate nothing,
// so a caller can write into its user's buffers.
template <class Tri>
void warm_corner_matrices(const Tri &tri, bool across);
template <class Tri>
void face_points(const Tri &tri, double *xy);  // 6 per face
// 2 and 1 per face, either null; through the cache when one is given (ready()).
template <class Tri>
void voronoi_vertices(const Tri &tri, double *xy, double *radii, CentreCache *cache);
// 1 per face, the same; may make the corners' matrices, and with across
// those of the neighbour translations too (warm_corner_matrices(tri, true)
// in the same pass). With a cache, out may be null (the cache filled only).
template <class Tri>
void face_centres(const Tri &tri, Point *out, CentreCache *cache, bool across = false);
// The same for the faces begin .. end - 1 only (out still indexed by face).
template <class Tri>
void face_centres(const Tri &tri, Point *out, CentreCache *cache, bool across, std::size_t begin,
                  std::size_t end);
// hdt_edges' vertices, faces and lengths (each may be null), count = 3F/2.
template <class Tri>
void write_edges(const Tri &tri, std::size_t count, uint32_t *vertices, uint32_t *faces, double *lengths);

}  // namespace hdt::dual
