// A new triangulation of a genus, made as hdt_create makes it: from the
// genus's certified dummy set.
#pragma once

#include "dummies/dummy_points.hpp"
#include "mesh/triangulation.hpp"

inline hdt::mesh::Triangulation new_triangulation(int genus) {
  return hdt::mesh::Triangulation(*hdt::dummies::dummy_template(genus));
}
