// Precision: 200 bits against inputs that are doubles (exact) or sites
// known within 2^-128. With the origin at a corner of the shortest edge,
// the moved corners keep their relative precision whatever their scale
// (mp_real's exponent range has no underflow), and the circle's centre
// loses about log2(1 / sin) bits to the angle there: a face would have to
// be flat to within 2^-140 to exhaust the margin. A translation's product
// of up to 2g letters loses a few bits per letter to the growth of its
// entries.
#include "dual/precise_circumcircle.hpp"

#include <stdexcept>

#include "exact/multiprecision.hpp"
#include "group/generators.hpp"
#include "dual/constructions.hpp"
#include "dual/disk_isometry.hpp"
#include "mesh/polygon_triangulation.hpp"

namespace hdt::dual {

namespace {

using Real = exact::mp_real<60>;
using PrecisePoint = group::Complex<Real>;

// The point vertex v stands for, under translation h.
template <class Tri>
PrecisePoint corner(const Tri &tri, uint32_t v, group::TranslationId h) {
  const mesh::Vertex &u = tri.vertices()[v];
  PrecisePoint z{Real(u.x), Real(u.y)};
  if constexpr (kMg<Tri>) {
    const int32_t site = tri.site_of(v);
    if (site >= 0) {
      const surface::Site &s = tri.surface().site(site);
      if (s.has_approximation) z = {Real(s.approximation.re), Real(s.approximation.im)};
    }
    if (h == 0) return z;
    const auto &generators = group::shared_generators<Real>(tri.surface().presentation());
    return generators.moebius(tri.table().word(h)).apply(z);
  } else {
    // The element's exact image of the double point, rounded once.
    if (h == 0) return z;
    tri.surface().precise_image(domain::ElementId(h), u.x, u.y, z.re.backend().data(), z.im.backend().data());
    return z;
  }
}

}  // namespace

template <class Tri>
Circle precise_circumcircle(const Tri &tri, const mesh::Face &f) {
  PrecisePoint p[3];
  for (int i = 0; i < 3; ++i) p[i] = corner(tri, f.v[i], f.t[i]);
  // Moved to the origin: the corner opposite the longest edge, whose angle
  // has the largest sine (about). Another choice could lose the difference
  // of two close corners next to a far one (0 and 1e-238 seen from 0.3).
  Real longest = -1;
  int o = 0;
  for (int i = 0; i < 3; ++i) {
    const PrecisePoint &a = p[mesh::next(i)], &b = p[mesh::prev(i)];
    const Real d = (a.re - b.re) * (a.re - b.re) + (a.im - b.im) * (a.im - b.im);
    if (d > longest) longest = d, o = i;
  }
  const PrecisePoint &p0 = p[o];
  const PrecisePoint w1 = to_origin(p0, p[mesh::next(o)]), w2 = to_origin(p0, p[mesh::prev(o)]);
  // The Euclidean circle through 0, w1, w2 (centre c, 2 c.w = |w|^2); its
  // diameter from 0 has Euclidean length s and hyperbolic length 2 atanh(s),
  // and the hyperbolic centre is that diameter's midpoint.
  const Real n1 = w1.re * w1.re + w1.im * w1.im, n2 = w2.re * w2.re + w2.im * w2.im;
  const Real cross = 2 * (w1.re * w2.im - w1.im * w2.re);
  if (cross == 0) throw std::logic_error("circumcircle: the three corners are collinear at 200 bits");
  const PrecisePoint c{(n1 * w2.im - n2 * w1.im) / cross, (n2 * w1.re - n1 * w2.re) / cross};
  const Real s = 2 * sqrt(c.re * c.re + c.im * c.im);
  if (!(s < 1)) throw std::logic_error("circumcircle: no proper circle at 200 bits");
  const Real k = 2 / (1 + sqrt((1 - s) * (1 + s)));
  const PrecisePoint centre = from_origin(p0, PrecisePoint{k * c.re, k * c.im});
  return {Point{static_cast<double>(centre.re), static_cast<double>(centre.im)}, static_cast<double>(atanh(s))};
}

template <class Tri>
void precise_frame(const Tri &tri, const mesh::Face &f, Point p[3], Point side[3]) {
  PrecisePoint z[3];
  for (int i = 0; i < 3; ++i) z[i] = corner(tri, f.v[i], f.t[i]);
  for (int i = 0; i < 3; ++i) {
    p[i] = {static_cast<double>(z[i].re), static_cast<double>(z[i].im)};
    const PrecisePoint &a = z[mesh::next(i)], &b = z[mesh::prev(i)];
    side[i] = {static_cast<double>(b.re - a.re), static_cast<double>(b.im - a.im)};
  }
}

#define HDT_DUAL_INSTANTIATE(Tri)                                    \
  template Circle precise_circumcircle(const Tri &, const mesh::Face &); \
  template void precise_frame(const Tri &, const mesh::Face &, Point[3], Point[3]);
HDT_DUAL_INSTANTIATE(mesh::Triangulation)
HDT_DUAL_INSTANTIATE(mesh::PolygonTriangulation)
#undef HDT_DUAL_INSTANTIATE

}  // namespace hdt::dual
