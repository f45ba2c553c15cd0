// The opaque handle behind hdt_triangulation: a core triangulation, made
// by hdt_create (a genus) or hdt_load (a restored triangulation).
#pragma once

#include <utility>

#include "triangulation/triangulation.hpp"

struct hdt_triangulation {
  explicit hdt_triangulation(int genus) : tri(genus) {}
  explicit hdt_triangulation(hdt::triangulation::Triangulation &&t) : tri(std::move(t)) {}
  hdt::triangulation::Triangulation tri;
};
