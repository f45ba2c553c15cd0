// A surface given by a fundamental polygon as the mesh sees it: the
// interface of mg_geometry.hpp over domain::PolygonSurface, so that
// BasicTriangulation<PolygonGeometry> runs the same walk, Bowyer-Watson
// insertion, stars and validation as M_g's triangulations.
//
// Translation ids are the surface's element ids (ElementTable: 0 is the
// identity, equal elements have equal ids), so the mesh's comparisons of
// ids compare elements exactly. No vertex is an exact site (the points are
// the user's doubles) and no home image is kept: the polygon kernel reads
// every point through its element's SU(1,1) ball, as accurate far from P as
// near it.
//
// The caller holds the field lock (domain/field_lock.hpp) on a polygon over
// a number field, as for every use of the surface.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <utility>

#include "domain/polygon_surface.hpp"
#include "group/moebius.hpp"
#include "predicates/sign.hpp"
#include "predicates/stage_disk.hpp"
#include "predicates/translated_point.hpp"

namespace hdt::mesh {

using group::TranslationId;
using predicates::TranslatedPoint;

class PolygonGeometry {
 public:
  using Surface = domain::PolygonSurface;

  // The mesh's predicates on translated points, by the polygon kernel; the
  // circumdiameter test against sys/2 with the surface's certified
  // threshold (a lower bound: a face it passes is certainly below sys/2).
  // Points that share one element first meet M_g's static disk filters
  // (predicates/stage_disk.hpp) on their stored coordinates: the predicates
  // are invariant under a common isometry, and the two kernels compute the
  // same determinants (polygon_kernel.hpp); the common case of a walk and
  // of a conflict search, decided without the kernel's rows.
  class Kernel {
   public:
    explicit Kernel(Surface &s) : s_(s), k_(s.kernel()) {}
    int orientation(const TranslatedPoint &a, const TranslatedPoint &b, const TranslatedPoint &c) {
      if (a.translation == b.translation && a.translation == c.translation)
        if (const predicates::Sign s = predicates::disk_orientation(a.x, a.y, b.x, b.y, c.x, c.y);
            predicates::decided(s))
          return predicates::to_int(s);
      return k_.orientation(p(a), p(b), p(c));
    }
    int in_circle(const TranslatedPoint &a, const TranslatedPoint &b, const TranslatedPoint &c,
                  const TranslatedPoint &d) {
      if (const int s = disk_in_circle({a, b, c, d})) return s;
      return k_.in_circle(p(a), p(b), p(c), p(d));
    }
    int in_circle_perturbed(const std::array<TranslatedPoint, 4> &q, const std::array<uint32_t, 4> &vertex) {
      if (const int s = disk_in_circle(q)) return s;  // not 0: the perturbation decides only ties
      return k_.in_circle_perturbed({p(q[0]), p(q[1]), p(q[2]), p(q[3])}, vertex);
    }
    int compare_distance(const TranslatedPoint &q, const TranslatedPoint &a, const TranslatedPoint &b) {
      return k_.compare_distance(p(q), p(a), p(b));
    }
    int large_circumdisk(const TranslatedPoint &a, const TranslatedPoint &b, const TranslatedPoint &c) {
      return k_.large_circumdisk(p(a), p(b), p(c), s_.quarter_systole_cosh2_below());
    }

   private:
    static domain::PolygonPoint p(const TranslatedPoint &q) { return {q.x, q.y, domain::ElementId(q.translation)}; }
    // The disk filter's sign for four points of one element, else 0.
    static int disk_in_circle(const std::array<TranslatedPoint, 4> &q) {
      const TranslationId t = q[0].translation;
      if (q[1].translation != t || q[2].translation != t || q[3].translation != t) return 0;
      const predicates::Sign s =
          predicates::disk_in_circle(q[0].x, q[0].y, q[1].x, q[1].y, q[2].x, q[2].y, q[3].x, q[3].y);
      return predicates::decided(s) ? predicates::to_int(s) : 0;
    }
    Surface &s_;
    domain::PolygonKernel &k_;
  };

  // The element table under the mesh's id type, with the double matrices
  // the dual's constructions read (as group::TranslationTable gives M_g's):
  // the midpoints of the elements' certified balls, and their double-double
  // parts with an error bound. Kept per id, in a deque: a reference stays
  // valid while later ids are added.
  class Table {
   public:
    explicit Table(Surface &s) : s_(s), t_(s.table()) {}
    TranslationId compose(TranslationId a, TranslationId b) {
      return TranslationId(t_.compose(domain::ElementId(a), domain::ElementId(b)));
    }
    TranslationId inverse(TranslationId a) { return TranslationId(t_.inverse(domain::ElementId(a))); }
    std::size_t size() const { return t_.size(); }
    const group::Moebius<double> &moebius(TranslationId h) { return matrices(h).hi; }
    const group::Moebius<double> &moebius_low(TranslationId h) { return matrices(h).lo; }
    double moebius_error(TranslationId h) { return matrices(h).error; }

   private:
    struct Matrices {
      group::Moebius<double> hi, lo;
      double error;
    };
    const Matrices &matrices(TranslationId h) {
      while (matrices_.size() <= std::size_t(h)) {
        const domain::PolygonSurface::SplitMatrix m = s_.split(domain::ElementId(matrices_.size()));
        matrices_.push_back({{{m.a_hi.real(), m.a_hi.imag()}, {m.b_hi.real(), m.b_hi.imag()}},
                             {{m.a_lo.real(), m.a_lo.imag()}, {m.b_lo.real(), m.b_lo.imag()}},
                             m.error});
      }
      return matrices_[std::size_t(h)];
    }
    Surface &s_;
    domain::ElementTable &t_;
    std::deque<Matrices> matrices_;
  };

  explicit PolygonGeometry(domain::FundamentalPolygon polygon)
      : surface_(std::move(polygon)), kernel_(surface_), table_(surface_) {}
  PolygonGeometry(const PolygonGeometry &) = delete;
  PolygonGeometry &operator=(const PolygonGeometry &) = delete;

  int genus() const { return surface_.genus(); }
  Surface &surface() { return surface_; }
  Kernel &kernel() { return kernel_; }
  Table &table() { return table_; }

  int32_t site_of(uint32_t) const { return -1; }
  TranslationId home(double x, double y) { return TranslationId(surface_.home(x, y)); }
  bool is_home(double x, double y, TranslationId h) { return home(x, y) == h; }
  group::Complex<double> image(double x, double y, TranslationId h) {
    if (h == 0) return {x, y};
    const std::complex<double> w = surface_.image(domain::ElementId(h), x, y);
    return {w.real(), w.imag()};
  }
  group::Complex<double> quick_image(double x, double y, TranslationId h) { return image(x, y, h); }
  // For now the same double image: its rounded matrix loses a few digits
  // for elements far from the identity, which only the values reported
  // (vertex_point) would show, never a decision.
  group::Complex<double> accurate_image(double x, double y, TranslationId h) { return image(x, y, h); }

  struct HomeImageScope {
    HomeImageScope(PolygonGeometry &, double, double, TranslationId) {}
    void keep() {}
  };

 private:
  Surface surface_;
  Kernel kernel_;
  Table table_;
};

}  // namespace hdt::mesh
