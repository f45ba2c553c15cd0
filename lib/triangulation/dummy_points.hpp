// The dummy point set of a genus and its Delaunay triangulation (paper,
// section 5), built once per process and genus, certified, and copied into
// every new triangulation.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "group/presentation.hpp"
#include "predicates/kernel.hpp"
#include "surface/surface.hpp"
#include "triangulation/mesh.hpp"

namespace hdt::triangulation {

struct DummyTemplate {
  int genus;
  std::vector<Vertex> vertices;  // all dummies; 1 is v_0, 2 + k is m_k (k < 2g): the sites
  std::vector<Face> faces;
  // The canonical words of the translation ids from |N| on, in id order: a
  // fresh table interns them to the same ids.
  std::vector<group::Word> extra_words;
  // The template surface's sites (the Q0 sites, registered and checked by
  // register_q0_sites): later triangulations adopt them.
  std::vector<surface::Site> sites;
};

// Registers the sites of Q0 with a fresh surface: site 0 is v_0, site 1 + k
// is m_k (k < 2g); *x, *y receive their roundings (2g + 1 entries each).
void register_q0_sites(surface::Surface &surface, double *x, double *y);

class Triangulation;

// The largest genus whose dummy points are built (HDT_CREATE_GENUS_MAX in
// hdt.h): the largest that a test builds and certifies. The refinement's
// circumcentres far from O are computed in 133 bits (hyperboloid
// coordinates near cosh(2R), R the circumradius of F_g, cancel every bit of
// a double from genus about 128 on).
constexpr int kDummyGenusMax = 256;

// The certified template of a genus if this process has built it, else null
// (thread-safe).
std::shared_ptr<const DummyTemplate> cached_dummy_template(int genus);
// Builds and certifies the dummy points in t (no vertices yet, a fresh
// kernel), keeps a copy for later triangulations and returns it. Throws
// std::length_error above kDummyGenusMax.
std::shared_ptr<const DummyTemplate> build_dummy_points(Triangulation &t);

}  // namespace hdt::triangulation
