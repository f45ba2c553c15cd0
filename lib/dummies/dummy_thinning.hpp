// Thinning of the dummy point set: fewer dummies, the same certificate.
// Genus 3 .. 128 use the relaxation of dummy_relaxation.hpp; genus 2 the
// local moves below.
//
// The refinement of dummy_points.cpp inserts circumcentres of the largest
// circles, which leaves about twice the area lower bound, and no single dummy
// can then go (each one is the only point of some circle of diameter near
// sys/2). Two close dummies can often be replaced by one between them: the
// pass inserts the hyperbolic midpoint of an edge, then removes both ends,
// each removal refused by Triangulation::remove when a face of its hole would
// have circumdiameter >= sys/2 (exact predicates, local to the hole); a
// refused merge is undone. Shortest edges first: the closest pairs are the
// most redundant.
#pragma once

namespace hdt::mesh {
template <class Geometry>
class BasicEditor;
class MgGeometry;
using Editor = BasicEditor<MgGeometry>;
}

namespace hdt::dummies {

// e: a triangulation whose vertices are all dummies and that meets the
// invariant (mesh/triangulation.hpp). Removes dummies, never Q0's (vertex 0, the
// sites 1 .. 2g+1), keeps the invariant, then renumbers the live vertices
// densely in their order (the order the symbolic perturbation reads).
void thin_dummy_points(mesh::Editor &e);

}  // namespace hdt::dummies
