// Interned group elements: each distinct Element once, named by a small id,
// with its products and inverses cached, for the polygon kernel's points
// (polygon_kernel.hpp) and later the triangulation of polygon surfaces.
//
// Ids are dense from 0, 0 being the identity. Equal elements get equal ids
// (the table finds them by Element's exact equality), so comparing ids
// compares maps. Each entry keeps its SU(1,1) ball matrix (ball_isometry.hpp),
// computed once from the exact entries, for the floating stages.
//
// Entries are never removed; references returned stay valid while the
// table lives (a deque).
#pragma once

#include <cstdint>
#include <deque>
#include <unordered_map>
#include <vector>

#include "domain/ball_isometry.hpp"
#include "domain/element.hpp"

namespace hdt::domain {

using ElementId = std::uint32_t;
constexpr ElementId kIdentityId = 0;

class ElementTable {
 public:
  // The identity in the field of `like` (a polygon's coordinate).
  explicit ElementTable(const Number &like);

  ElementId intern(const Element &g);
  const Element &element(ElementId id) const { return entries_.at(id).element; }
  const BallIsometry &ball(ElementId id) const { return entries_.at(id).ball; }
  ElementId compose(ElementId a, ElementId b);  // a after b
  ElementId inverse(ElementId a);
  std::size_t size() const { return entries_.size(); }

 private:
  static constexpr ElementId kNone = ~ElementId(0);
  struct Entry {
    Element element;
    BallIsometry ball;
  };

  std::deque<Entry> entries_;
  std::unordered_map<Element, ElementId, ElementHash> ids_;
  std::unordered_map<std::uint64_t, ElementId> products_;  // key a << 32 | b
  // The triangulation's hot path asks the same few products and inverses
  // again and again: a direct-mapped cache of recent products in front of
  // the map; the inverses by id (kNone: not yet), each pair set both ways.
  struct RecentProduct {
    std::uint64_t key = ~std::uint64_t(0);
    ElementId id = 0;
  };
  static constexpr int kRecentBits = 10;
  std::vector<RecentProduct> recent_ = std::vector<RecentProduct>(std::size_t(1) << kRecentBits);
  std::vector<ElementId> inverses_;
};

}  // namespace hdt::domain
