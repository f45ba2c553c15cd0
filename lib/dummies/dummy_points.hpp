// The dummy point set of a genus and its Delaunay triangulation (paper,
// section 5), built once per process and genus, certified, and copied into
// every new triangulation (mesh::Triangulation(const DummyTemplate &)).
#pragma once

#include <memory>

#include "mesh/dummy_template.hpp"

namespace hdt::dummies {

// The largest genus whose dummy points are built (HDT_CREATE_GENUS_MAX in
// hdt.h): the largest that a test builds and certifies. The refinement's
// circumcentres far from O are computed in 133 bits (hyperboloid
// coordinates near cosh(2R), R the circumradius of F_g, cancel every bit of
// a double from genus about 128 on).
constexpr int kDummyGenusMax = 256;

// The certified template of a genus, built on this process's first call for
// the genus (thread-safe; two threads may both build one, the first stays).
// Throws std::length_error above kDummyGenusMax.
std::shared_ptr<const mesh::DummyTemplate> dummy_template(int genus);

}  // namespace hdt::dummies
