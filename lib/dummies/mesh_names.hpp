// The names of the mesh (lib/mesh) that the dummy construction works with,
// declared once for lib/dummies.
#pragma once

#include "mesh/triangulation.hpp"

namespace hdt::dummies {

using mesh::Corner;
using mesh::Face;
using mesh::kNone;
using mesh::next;
using mesh::prev;
using mesh::StarFace;
using mesh::TranslationId;
using mesh::Triangulation;
using mesh::Vertex;

}  // namespace hdt::dummies
