#include "surface/q0_sites.hpp"

#include <stdexcept>
#include <vector>

#include "surface/exact_polygon.hpp"
#include "surface/polygon.hpp"

namespace hdt::surface {

void register_q0_sites(Surface &surface, double *x, double *y) {
  const int g = surface.genus();
  // The doubles are v_0 and m_k correctly rounded, as hdt_polygon_vertex
  // and hdt_polygon_side_midpoint give them.
  const group::Complex<SiteReal> v = polygon_vertex<SiteReal>(g, 0);
  const group::Complex<double> v_rounded = vertex(surface.presentation(), 0);
  if (surface.add_site(exact_vertex(surface.field(), 0), &v, &v_rounded) != 0)
    throw std::logic_error("Q0 sites: the surface has sites already");
  x[0] = v_rounded.re, y[0] = v_rounded.im;
  const std::vector<ExactSite> midpoints = exact_side_midpoints(surface.field(), 2 * g);
  for (int k = 0; k < 2 * g; ++k) {
    const group::Complex<SiteReal> m = polygon_side_midpoint<SiteReal>(g, k);
    const group::Complex<double> m_rounded = side_midpoint(surface.presentation(), k);
    surface.add_site(midpoints[std::size_t(k)], &m, &m_rounded);
    x[1 + k] = m_rounded.re, y[1 + k] = m_rounded.im;
  }
}

}  // namespace hdt::surface
