// Constructions in double on the faces of a triangulation: corner points of
// the canonical copies, circumcentres and circumradii (the Voronoi
// vertices), hyperbolic distances. Unlike the predicates these are not
// exact: each result is a rounded value (its accuracy is stated in hdt.h and
// measured by tests/test_dual.c against a 256-bit MPFR recomputation).
#pragma once

#include "group/moebius.hpp"
#include "triangulation/triangulation.hpp"

namespace hdt::triangulation {

using Point = group::Complex<double>;

// Corner i of face f's canonical copy: the stored point under the corner's
// translation t (which includes the vertex's home h), one Moebius map with
// the table's last-bit-accurate matrix; for a vertex with a home, its
// representative under t h^-1 (which may add ids to the table).
Point face_corner(const Triangulation &tri, const Face &f, int i);

struct Circle {
  Point centre;
  double radius;  // hyperbolic
};
// The hyperbolic circle through three points of the disk, in double, or
// false when double cannot resolve it (the conditions are in the .cpp);
// rounded: some point is not exact (a translated or algebraic corner).
bool try_circumcircle(const Point &p0, const Point &p1, const Point &p2, bool rounded, Circle *circle);

// Face f's circumcircle, p its corners (face_corner): in double, or in
// multiprecision from the exact data for the rare faces double cannot
// resolve (precise_circumcircle.hpp). Every face has one.
Circle circumcircle(const Triangulation &tri, const Face &f, const Point p[3]);

// Hyperbolic distance in the Poincare disk (curvature -1).
double distance(const Point &p, const Point &q);

// h(p) for a translation id h.
Point translate(const Triangulation &tri, group::TranslationId h, const Point &p);

}  // namespace hdt::triangulation
