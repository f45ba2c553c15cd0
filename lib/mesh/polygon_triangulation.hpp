// Triangulations of a surface given by a fundamental polygon: the mesh's
// algorithms on PolygonGeometry (polygon_geometry.hpp). What they support so
// far: building from given faces (assemble.hpp), insertion, removal,
// location, the nearest vertex, stars, vertices and validate(), and
// lib/dual's outputs and refinement on top; saving is M_g's only.
#pragma once

#include "mesh/polygon_geometry.hpp"
#include "mesh/triangulation.hpp"

namespace hdt::mesh {

using PolygonTriangulation = BasicTriangulation<PolygonGeometry>;

}  // namespace hdt::mesh
