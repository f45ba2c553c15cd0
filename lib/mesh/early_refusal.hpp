// A removal that must be refused, recognised before its hole is filled.
//
// Lemma: a triangle inscribed in a circle of radius R has a corner within R
// of each of its points. (The points of the circle farther than R from a
// point x at distance d from the centre lie beyond the chord perpendicular
// to the diameter through x at distance d/2 from the centre, on the side
// away from x; a triangle with its corners there does not hold x.) So if
// some point x of the hole is at distance >= sys/4 from every vertex of
// the link, the face of the hole's triangulation that holds x (whatever
// the triangulation) has circumdiameter >= sys/2, and the removal is
// refused (a circumcircle that is no circle is refused anyway).
//
// Points sampled along a curve that passes near a dummy make holes of
// thousands of vertices whose removal is refused this way: the proof costs
// a few scans of the link instead of the filling.
#pragma once

#include <vector>

#include "predicates/kernel.hpp"
#include "mesh/hole.hpp"

namespace hdt::mesh {

// True when the lemma proves, with certified error bounds, that every
// triangulation of the polygon (the link of `removed`, as for fill_hole)
// has a face of circumdiameter >= sys/2 on the kernel's surface.
// False when it cannot tell.
bool refusal_is_certain(predicates::Kernel &kernel, const std::vector<HoleVertex> &polygon,
                        const HoleVertex &removed);

}  // namespace hdt::mesh
