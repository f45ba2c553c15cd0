// The dummy point set of a genus and its Delaunay triangulation (paper,
// section 5), built once per process and genus, certified, and copied into
// every new triangulation (mesh::Triangulation(const DummyTemplate &)).
#pragma once

#include "domain/fundamental_polygon.hpp"
#include "mesh/polygon_triangulation.hpp"
#include "mesh/triangulation.hpp"

namespace hdt::dummies {

// The largest genus whose dummy points are built (HDT_CREATE_GENUS_MAX in
// hdt.h): the largest that a test builds and certifies. The refinement's
// circumcentres far from O are computed in 133 bits (hyperboloid
// coordinates near cosh(2R), R the circumradius of F_g, cancel every bit of
// a double from genus about 128 on).
constexpr int kDummyGenusMax = 256;

// A new triangulation of a genus: its certified dummy set. The process's
// first call for a genus builds the set in the triangulation it returns
// (whose surface keeps what the construction computed: its first user's
// insertions find warm caches) and keeps its template; later calls copy
// the template (thread-safe; two threads may both build one, the first
// template stays). Throws exact::Unsupported above kDummyGenusMax.
mesh::Triangulation new_triangulation(int genus);

// A new triangulation of the polygon's surface: the paper's Algorithm 1 on
// it (dummy_points.cpp: a fan of the polygon, Lawson flips, circumcentres
// while a circle has diameter sys/2 or more), certified by validate().
// Built at every call. The caller holds the field lock on a number field.
mesh::PolygonTriangulation new_polygon_triangulation(const domain::FundamentalPolygon &polygon);

}  // namespace hdt::dummies
