// A new triangulation: a copy of its genus's certified dummy points.
#include "mesh/triangulation.hpp"

#include <stdexcept>
#include <utility>

#include "mesh/polygon_triangulation.hpp"

namespace hdt::mesh {

template <class Geometry>
BasicTriangulation<Geometry>::BasicTriangulation(int genus, Empty)
    : genus_(genus), geometry_(std::make_unique<Geometry>(genus)), kernel_(&geometry_->kernel()) {}

template <class Geometry>
BasicTriangulation<Geometry>::BasicTriangulation(std::unique_ptr<Geometry> geometry, Empty)
    : genus_(geometry->genus()), geometry_(std::move(geometry)), kernel_(&geometry_->kernel()) {}

template <class Geometry>
BasicTriangulation<Geometry>::BasicTriangulation(const DummyTemplate &q) : BasicTriangulation(q.genus, Empty{}) {
  // The same sites and translation ids as the template's surface had.
  for (const surface::Site &site : q.sites) geometry_->surface().adopt_site(site);
  group::TranslationTable &T = geometry_->table();
  for (const group::Word &w : q.extra_words)
    if (std::size_t(T.intern_canonical(w)) + 1 != T.size()) throw std::logic_error("dummy template: translation ids");
  vertices_ = q.vertices;
  faces_ = q.faces;
  dummy_.assign(vertices_.size(), true);
  live_vertices_ = dummies_ = vertices_.size();
}


template <class Geometry>
BasicTriangulation<Geometry>::BasicTriangulation(std::unique_ptr<Geometry> geometry, std::vector<Vertex> vertices,
                                                 std::vector<bool> dummy, std::vector<Face> faces)
    : genus_(geometry->genus()),
      geometry_(std::move(geometry)),
      kernel_(&geometry_->kernel()),
      vertices_(std::move(vertices)),
      dummy_(std::move(dummy)),
      faces_(std::move(faces)) {
  if (dummy_.size() != vertices_.size()) throw std::invalid_argument("BasicTriangulation: a dummy flag per vertex");
  for (std::size_t v = 0; v < vertices_.size(); ++v)
    if (vertices_[v].alive()) ++live_vertices_, dummies_ += dummy_[v];
}

// M_g's (the only geometry with a dummy template so far).
template Triangulation::BasicTriangulation(int, Triangulation::Empty);
template Triangulation::BasicTriangulation(std::unique_ptr<MgGeometry>, Triangulation::Empty);
template Triangulation::BasicTriangulation(const DummyTemplate &);

// Polygon surfaces': what their triangulations support so far (insertion,
// removal, location, stars, validation), each file instantiating its part.
template PolygonTriangulation::BasicTriangulation(std::unique_ptr<PolygonGeometry>, std::vector<Vertex>, std::vector<bool>,
                                                  std::vector<Face>);
template PolygonTriangulation::BasicTriangulation(std::unique_ptr<PolygonGeometry>, PolygonTriangulation::Empty);

}  // namespace hdt::mesh
