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
  RecentProduct &recent = recent_[std::size_t((key * 0x9E3779B97F4A7C15ull) >> (64 - kRecentBits))];
  if (recent.key == key) return recent.id;
  ElementId id;
  if (const auto found = products_.find(key); found != products_.end()) {
    id = found->second;
  } else {
    id = intern(element(a) * element(b));
    products_.emplace(key, id);
  }
  recent = {key, id};
  return id;
}

// Cached both ways: the inverse of the inverse is known at once.
ElementId ElementTable::inverse(ElementId a) {
  if (a < inverses_.size() && inverses_[a] != kNone) return inverses_[a];
  const ElementId id = intern(domain::inverse(element(a)));
  inverses_.resize(entries_.size(), kNone);
  inverses_[a] = id, inverses_[id] = a;
  return id;
}

}  // namespace hdt::domain
