// The surface M_g as the mesh sees it: what BasicTriangulation
// (triangulation.hpp) asks of the geometry it triangulates, for the
// built-in surfaces. The mesh's algorithms (walk, Bowyer-Watson, removal,
// stars, validation) are written once against this interface, whose every
// function here is an inline call into the surface and kernel of M_g: the
// path keeps its code and its cost. A polygon surface provides the same
// interface (polygon_geometry.hpp).
//
// The interface: Surface, Kernel and Table types and accessors; the genus;
// a point's home (the translation taking it into the half-open fundamental
// domain); the point's image at home in double; whether a vertex is an
// exact site; and a scope for the home images of points far from the
// domain, which only M_g keeps.
#pragma once

#include <cstdint>

#include "group/translation_table.hpp"
#include "group/word_matrix.hpp"
#include "predicates/kernel.hpp"
#include "predicates/representative.hpp"
#include "surface/home_image.hpp"
#include "surface/surface.hpp"

namespace hdt::mesh {

class MgGeometry {
 public:
  using Surface = surface::Surface;
  using Kernel = predicates::Kernel;
  using Table = group::TranslationTable;

  explicit MgGeometry(int genus) : surface_(genus), kernel_(surface_) {}
  MgGeometry(const MgGeometry &) = delete;
  MgGeometry &operator=(const MgGeometry &) = delete;

  int genus() const { return surface_.genus(); }
  Surface &surface() { return surface_; }
  Kernel &kernel() { return kernel_; }
  Table &table() { return surface_.table(); }

  // The surface's site of vertex v, or -1: the Q0 dummies v_0 and m_k
  // (sites 0 .. 2g) are vertices 1 .. 2g+1 of every triangulation.
  int32_t site_of(uint32_t v) const {
    return v >= 1 && v <= uint32_t(2 * genus() + 1) ? int32_t(v - 1) : -1;
  }
  // The translation h with h(x + iy) in the half-open F_g; throws
  // std::domain_error unless (x, y) is a finite point of the open disk.
  TranslationId home(double x, double y) { return predicates::representative(kernel_, x, y).translation; }
  // Whether home(x + iy) is `home`, decided exactly (validate()).
  bool is_home(double x, double y, TranslationId home) {
    return home == 0 ? predicates::representative(kernel_, x, y).translation == 0
                     : predicates::representative(kernel_, {x, y, home, -1}).translation == home;
  }
  // home(x + iy) in double (from its home image when it has one: far from
  // F_g the double map loses the point's digits).
  group::Complex<double> image(double x, double y, TranslationId home) {
    if (home == 0) return {x, y};
    if (const surface::HomeImage *image = surface_.home_image(x, y)) return image->rounded;
    return table().moebius(home).apply({x, y});
  }
  // h(x + iy) by the double map alone, for a sort key (h not the identity).
  group::Complex<double> quick_image(double x, double y, TranslationId home) {
    return table().moebius(home).apply({x, y});
  }
  // The same, correctly rounded from a multiprecision image.
  group::Complex<double> accurate_image(double x, double y, TranslationId home) {
    return group::accurate_image(surface_.presentation(), table().word(home), {x, y});
  }

  // A query's home image (Kernel::add_home_image) for the query's length:
  // kept when the point became a vertex, else given back.
  class HomeImageScope {
   public:
    HomeImageScope(MgGeometry &g, double x, double y, TranslationId home)
        : kernel_(g.kernel_), x_(x), y_(y), added_(surface::far_from_domain(x, y, home) && kernel_.add_home_image(x, y, home)) {}
    HomeImageScope(const HomeImageScope &) = delete;
    ~HomeImageScope() {
      if (added_ && !kept_) kernel_.forget_home_image(x_, y_);
    }
    void keep() { kept_ = true; }

   private:
    Kernel &kernel_;
    double x_, y_;
    bool added_, kept_ = false;
  };

 private:
  Surface surface_;
  Kernel kernel_;  // on surface_
};

}  // namespace hdt::mesh
