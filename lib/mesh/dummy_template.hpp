// What every new triangulation of a genus starts from: a certified dummy
// point set and its Delaunay triangulation (lib/dummies/ makes one per
// process and genus), with what a fresh surface needs to give translations
// and sites the same ids as the surface it was made on.
#pragma once

#include <vector>

#include "group/presentation.hpp"
#include "mesh/mesh.hpp"
#include "surface/site.hpp"

namespace hdt::mesh {

struct DummyTemplate {
  int genus;
  std::vector<Vertex> vertices;  // all dummies; 1 is v_0, 2 + k is m_k (k < 2g): the sites
  std::vector<Face> faces;
  // The canonical words of the translation ids from |N| on, in id order: a
  // fresh table interns them to the same ids.
  std::vector<group::Word> extra_words;
  // The sites of the surface it was made on (surface/q0_sites.hpp), which
  // later surfaces adopt.
  std::vector<surface::Site> sites;
};

}  // namespace hdt::mesh
