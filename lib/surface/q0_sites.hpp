// The sites of F_g that every triangulation of M_g starts from: its vertex
// v_0 and its side midpoints m_0 .. m_{2g-1} (with the centre 0, the set Q0
// of the dummy construction), registered with exact coordinates.
#pragma once

#include "surface/surface.hpp"

namespace hdt::surface {

// Registers the sites of Q0 with a surface that has none yet: site 0 is
// v_0, site 1 + k is m_k (k < 2g); *x, *y receive their coordinates
// correctly rounded (2g + 1 entries each). Throws std::logic_error when the
// surface has sites already.
void register_q0_sites(Surface &surface, double *x, double *y);

}  // namespace hdt::surface
