#include "domain/element_table.hpp"

namespace hdt::domain {

ElementTable::ElementTable(const Number &like) {
  entries_.push_back({identity_element(like), ball_identity()});
  ids_.emplace(entries_.back().element, kIdentityId);
}

ElementId ElementTable::intern(const Element &g) {
  if (const auto found = ids_.find(g); found != ids_.end()) return found->second;
  const ElementId id = ElementId(entries_.size());
  entries_.push_back({g, ball_isometry(g.matrix())});
  ids_.emplace(g, id);
  return id;
}

ElementId ElementTable::compose(ElementId a, ElementId b) {
  if (a == kIdentityId) return b;
  if (b == kIdentityId) return a;
  const std::uint64_t key = std::uint64_t(a) << 32 | b;
  if (const auto found = products_.find(key); found != products_.end()) return found->second;
  const ElementId id = intern(element(a) * element(b));
  products_.emplace(key, id);
  return id;
}

// Cached both ways: the inverse of the inverse is known at once.
ElementId ElementTable::inverse(ElementId a) {
  if (entries_.at(a).inverse != kNone) return entries_[a].inverse;
  const ElementId id = intern(domain::inverse(element(a)));
  entries_[a].inverse = id;
  entries_[id].inverse = a;
  return id;
}

}  // namespace hdt::domain
