// A new triangulation: its genus's certified dummy points, built in the
// first triangulation of the genus, copied into the later ones.
#include "triangulation/triangulation.hpp"

#include <stdexcept>

#include "triangulation/dummy_points.hpp"

namespace hdt::triangulation {

Triangulation::Triangulation(int genus, Empty)
    : genus_(genus), surface_(std::make_unique<surface::Surface>(genus)), kernel_(std::make_unique<Kernel>(*surface_)) {}

Triangulation::Triangulation(int genus) : Triangulation(genus, Empty{}) {
  const std::shared_ptr<const DummyTemplate> q = cached_dummy_template(genus);
  if (!q) {  // the first of its genus in this process: built here, in place
    build_dummy_points(*this);
    return;
  }
  // The same sites and translation ids as the template's surface had.
  for (const surface::Site &site : q->sites) surface_->adopt_site(site);
  group::TranslationTable &T = surface_->table();
  for (const group::Word &w : q->extra_words)
    if (std::size_t(T.intern_canonical(w)) + 1 != T.size()) throw std::logic_error("dummy template: translation ids");
  vertices_ = q->vertices;
  faces_ = q->faces;
  dummy_.assign(vertices_.size(), true);
  live_vertices_ = dummies_ = vertices_.size();
}

}  // namespace hdt::triangulation
