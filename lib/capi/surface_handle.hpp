// The opaque handle behind hdt_surface: a closed hyperbolic surface given by
// a fundamental polygon, checked on entry (lib/domain). Not changed after it
// is made; one thread at a time, and every call on a surface over a number
// field holds the field lock (domain/field_lock.hpp).
#pragma once

#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "domain/fundamental_polygon.hpp"
#include "domain/neighbours.hpp"
#include "domain/representative.hpp"
#include "domain/systole.hpp"

struct hdt_surface {
  explicit hdt_surface(hdt::domain::FundamentalPolygon p) : polygon(std::move(p)) {}
  const hdt::domain::FundamentalPolygon polygon;
  // Computed on first use and kept (the queries are const; one thread at a
  // time uses a surface): the certified systole, the size of N, and the
  // reduction into the polygon with its Klein form.
  mutable std::optional<hdt::domain::Systole> systole;
  mutable std::optional<std::vector<hdt::domain::Word>> neighbours;  // N, by id (0: the identity)
  mutable std::unique_ptr<hdt::domain::Reduction> reduction;
};
