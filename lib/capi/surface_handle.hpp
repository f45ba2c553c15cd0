// The opaque handle behind hdt_surface: a closed hyperbolic surface given by
// a fundamental polygon, checked on entry (lib/domain). Not changed after it
// is made; one thread at a time (e-antic refines a field's embedding, shared
// by its elements, as it compares them).
#pragma once

#include <utility>

#include "domain/fundamental_polygon.hpp"

struct hdt_surface {
  explicit hdt_surface(hdt::domain::FundamentalPolygon p) : polygon(std::move(p)) {}
  const hdt::domain::FundamentalPolygon polygon;
};
