// A new triangulation: a copy of its genus's certified dummy template.
#include "triangulation/triangulation.hpp"

#include <stdexcept>

#include "surface/exact_polygon.hpp"
#include "triangulation/dummy_points.hpp"

namespace hdt::triangulation {

Triangulation::Triangulation(int genus, Empty)
    : genus_(genus), kernel_(std::make_unique<Kernel>(group::Presentation(genus))) {}

Triangulation::Triangulation(int genus) : Triangulation(genus, Empty{}) {
  const std::shared_ptr<const DummyTemplate> q = dummy_template(genus);
  // The same sites and translation ids as the template's kernel had.
  double x, y;
  if (kernel_->add_site(surface::exact_vertex(kernel_->field(), 0), &x, &y) != 0)
    throw std::logic_error("dummy template: site ids");
  for (int k = 0; k < 2 * genus; ++k) kernel_->add_site(surface::exact_side_midpoint(kernel_->field(), k), &x, &y);
  group::TranslationTable &T = kernel_->table();
  for (const group::Word &w : q->extra_words)
    if (std::size_t(T.intern(w)) + 1 != T.size()) throw std::logic_error("dummy template: translation ids");
  vertices_ = q->vertices;
  faces_ = q->faces;
  stamp_.assign(faces_.size(), 0);
  live_vertices_ = dummies_ = vertices_.size();
}

}  // namespace hdt::triangulation
