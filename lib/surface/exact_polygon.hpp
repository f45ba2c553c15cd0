// The vertices and side midpoints of F_g as exact points of K_g, in
// homogeneous disk coordinates z = (X + iY)/Z (Z > 0). With c = cos(pi/4g),
// s = sin(pi/4g), sigma = sqrt(cos(pi/2g)):
//   v_k = sigma e^{i (2k+1) pi/4g}              (Z = 1)
//   m_k = (c - s) e^{i k pi/2g} / sigma          (Z = sigma), radius tanh(d/2)
// since tanh(d/2)^2 = (A-1)/(A+1) = (c-s)^2 / cos(pi/2g).
#pragma once

#include <vector>

#include "surface/surface.hpp"

namespace hdt::surface {

ExactSite exact_vertex(const exact::Field &field, int k);
ExactSite exact_side_midpoint(const exact::Field &field, int k);
// m_0 .. m_{count-1} (count <= 4g), each equal to exact_side_midpoint's,
// from one rotation sequence instead of two products per midpoint (a
// visible part of the first hdt_create at large genus, where the products
// are dense).
std::vector<ExactSite> exact_side_midpoints(const exact::Field &field, int count);

}  // namespace hdt::surface
