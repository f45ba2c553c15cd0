// The input of every predicate: a stored point and a translation.
//
// A point is given as a stored point (x, y) (doubles, hence exact rationals)
// and a translation id h of the surface's TranslationTable: it stands for
// h(x + iy), an algebraic point; or as a registered site (surface.hpp) under
// h, (x, y) then its rounding.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

#include "group/translation_table.hpp"

namespace hdt::predicates {

using group::TranslationId;

struct TranslatedPoint {
  double x, y;  // the stored point, |x + iy| < 1: exact, or a site's rounding
  TranslationId translation;
  int32_t site = -1;  // >= 0: the point is the surface's site `site`, (x, y) its rounding
};

// The point is (x, y) itself, exactly: the disk filters apply.
inline bool untranslated(const TranslatedPoint &p) { return p.translation == 0 && p.site < 0; }
// Points given by their stored coordinates and one common translation (no
// site): h acts on the hyperboloid with determinant 1, so orientation and
// in_circle are those of the stored points, where the disk filters and the
// exact disk stage apply (stage_disk_exact.hpp).
inline bool same_frame(const TranslatedPoint &a, const TranslatedPoint &b, const TranslatedPoint &c) {
  return a.site < 0 && b.site < 0 && c.site < 0 && a.translation == b.translation && a.translation == c.translation;
}
inline bool same_frame(const TranslatedPoint &a, const TranslatedPoint &b, const TranslatedPoint &c,
                       const TranslatedPoint &d) {
  return same_frame(a, b, c) && d.site < 0 && d.translation == a.translation;
}
// The same description (hence the same point).
inline bool identical(const TranslatedPoint &a, const TranslatedPoint &b) {
  return a.x == b.x && a.y == b.y && a.translation == b.translation && a.site == b.site;
}
// The stored point of p, untranslated: points in one frame have the signs of
// their stored points.
inline TranslatedPoint stored(const TranslatedPoint &p) { return {p.x, p.y, 0, -1}; }

// A small direct-mapped cache of a stage's points, 2^Bits slots: a walk or
// a conflict search asks for the same few corners and query again and
// again. Points along a curve that crosses the sides of F_g make conflict
// searches of a few dozen translated points, which a cache of a few dozen
// slots misses often; the double stage, which sees them all, has 1024
// (the size chosen on curves_bench --shape geodesic).
template <class Point, int Bits = 8>
class PointCache {
 public:
  // The cached value of p, or compute(p) stored (a throw leaves the slot as
  // it was).
  template <class Compute>
  const Point &get(const TranslatedPoint &p, Compute &&compute) {
    Slot &c = slots_[slot(p)];
    if (!identical(c.key, p)) {
      c.point = compute(p);
      c.key = p;
    }
    return c.point;
  }
  // Forgets every entry of the stored point (x, y), under any translation:
  // how that point is evaluated has changed (it got a home image).
  void forget(double x, double y) {
    for (Slot &c : slots_)
      if (c.key.x == x && c.key.y == y) c.key = Slot{}.key;
  }

 private:
  static constexpr int kBits = Bits;
  static std::size_t slot(const TranslatedPoint &p) {
    uint64_t bits;
    std::memcpy(&bits, &p.x, sizeof bits);
    uint64_t h = bits * 0x9E3779B97F4A7C15ull;
    std::memcpy(&bits, &p.y, sizeof bits);
    h ^= (bits + uint64_t(uint32_t(p.translation)) * 0xC2B2AE3D27D4EB4Full) * 0x165667B19E3779F9ull;
    return h >> (64 - kBits);
  }
  struct Slot {
    TranslatedPoint key{NAN, NAN, -1, -1};  // NaN: identical to no point
    Point point;
  };
  Slot slots_[std::size_t(1) << kBits]{};
};

}  // namespace hdt::predicates
