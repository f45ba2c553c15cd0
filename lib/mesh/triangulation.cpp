// A new triangulation: a copy of its genus's certified dummy points.
#include "mesh/triangulation.hpp"

#include <stdexcept>

namespace hdt::mesh {

Triangulation::Triangulation(int genus, Empty)
    : genus_(genus), surface_(std::make_unique<surface::Surface>(genus)), kernel_(std::make_unique<Kernel>(*surface_)) {}

Triangulation::Triangulation(const DummyTemplate &q) : Triangulation(q.genus, Empty{}) {
  // The same sites and translation ids as the template's surface had.
  for (const surface::Site &site : q.sites) surface_->adopt_site(site);
  group::TranslationTable &T = surface_->table();
  for (const group::Word &w : q.extra_words)
    if (std::size_t(T.intern_canonical(w)) + 1 != T.size()) throw std::logic_error("dummy template: translation ids");
  vertices_ = q.vertices;
  faces_ = q.faces;
  dummy_.assign(vertices_.size(), true);
  live_vertices_ = dummies_ = vertices_.size();
}

}  // namespace hdt::mesh
