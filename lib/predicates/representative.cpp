#include "predicates/representative.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "exact/unit_disk.hpp"
#include "group/canonical.hpp"
#include "group/cyclic.hpp"
#include "group/word_matrix.hpp"

namespace hdt::predicates {

using group::Letter;
using group::TranslationId;

namespace {

// The id of g * h, where g is a single letter; products are cached by the
// table.
TranslationId prepend(Kernel &kernel, Letter g, TranslationId h) {
  return kernel.surface().table().compose(surface::Surface::letter(g), h);
}

}  // namespace

RepresentativeImage representative_image(int genus, double x, double y, bool with_image) {
  thread_local std::unique_ptr<surface::Surface> surface;
  thread_local std::unique_ptr<Kernel> kernel;
  if (!surface || surface->genus() != genus) {
    auto new_surface = std::make_unique<surface::Surface>(genus);  // may throw: nothing changed then
    auto new_kernel = std::make_unique<Kernel>(*new_surface);
    kernel = std::move(new_kernel);
    surface = std::move(new_surface);
  }
  const Representative r = representative(*kernel, x, y);
  const group::Word &w = surface->table().word(r.translation);
  if (!with_image || r.translation == 0) return {w, {x, y}};
  return {w, group::accurate_image(surface->presentation(), w, {x, y})};
}

Representative representative(Kernel &kernel, double x, double y) {
  if (!std::isfinite(x) || !std::isfinite(y) || !exact::inside_unit_disk(x, y))
    throw std::domain_error("the point is not a finite point of the open unit disk");
  // Most points of F_g lie in its inscribed circle (about 70% of the area),
  // where no side test is needed. The circle's Euclidean radius r has
  // r^2 = (c - 1) / (c + 1), c = cot(pi / 4g); shrunk by 1e-9 it bounds
  // the few roundings here and in x^2 + y^2 with room to spare.
  const double c = kernel.surface().half_trace();
  if (x * x + y * y < (c - 1) / (c + 1) * (1 - 1e-9)) return {0, Representative::interior, 0};
  // Outside it, only the sides near the point's direction can hold it or
  // have it beyond them (one or two at large genus instead of 4g).
  const TranslatedPoint point{x, y, 0};
  bool inside = true;
  for (int k : kernel.surface().sides_near(std::atan2(y, x)))
    if (kernel.beyond_side(point, k) >= 0) {
      inside = false;
      break;
    }
  if (inside) return {0, Representative::interior, 0};
  return representative(kernel, point);
}

namespace {

// Points this near the circle (1 - |z|^2 below it) first walk most of the
// way with a tracked point (group::walk_into_domain). The exact walk below
// tests every side at each step with the matrices of every prefix of the
// word, whose precision follows the word's length: at genus 256 a point
// 1e-15 from the circle took seconds (words of 300 to 400 letters).
constexpr double kFarFromO = 0x1p-10;

// The element the tracked walk reached (0 when it went nowhere). The walk
// has no step limit: each step crosses a line that separates the point from
// O, so it ends within the length of the point's word.
TranslationId tracked_start(Kernel &kernel, double x, double y) {
  if (!(1 - (x * x + y * y) < kFarFromO)) return 0;
  group::TranslationTable &table = kernel.surface().table();
  const group::Presentation &p = table.presentation();
  group::Word letters;
  group::walk_into_domain(p, x, y, letters, std::numeric_limits<std::size_t>::max());
  if (letters.empty()) return 0;
  // g_{k_n}^-1 ... g_{k_1}^-1, as the exact walk prepends them.
  group::Word h;
  h.reserve(letters.size());
  for (std::size_t i = letters.size(); i-- > 0;) h.push_back(p.inverse(letters[i]));
  return table.intern(h);
}

}  // namespace

Representative representative(Kernel &kernel, const TranslatedPoint &point) {
  const group::Presentation &p = kernel.surface().presentation();
  const int n = p.letter_count(), half = p.half_relator();
  TranslationId h = point.translation;
  if (h == 0) h = tracked_start(kernel, point.x, point.y);
  auto at = [&](TranslationId t) { return TranslatedPoint{point.x, point.y, t, point.site}; };
  std::vector<int> on;  // the sides whose line holds h(z)
  thread_local std::vector<int> signs;  // no allocation per call
  signs.resize(std::size_t(n));
  for (;;) {
    on.clear();
    int beyond = -1;
    kernel.beyond_sides(at(h), signs.data());
    for (int k = 0; k < n && beyond < 0; ++k) {
      if (signs[k] > 0) beyond = k;
      if (signs[k] == 0) on.push_back(k);
    }
    if (beyond < 0) break;
    h = prepend(kernel, p.inverse(beyond), h);
  }
  if (on.empty()) return {h, Representative::interior, 0};
  if (on.size() == 1) {
    const int k = on[0];
    if (k >= half) h = prepend(kernel, static_cast<Letter>(k - half), h);
    return {h, Representative::side, k % half};
  }
  // Two sides: the vertex between s_k and s_{k+1} is v_k.
  if (on.size() != 2) throw std::logic_error("representative: a point on more than two side lines of F_g");
  int k = (on[0] == 0 && on[1] == n - 1) ? n - 1 : on[0];
  while (k != 0) {
    const Letter g = static_cast<Letter>(group::cyclic(k - half, n));
    h = prepend(kernel, g, h);
    k = group::cyclic(k - half - 1, n);
  }
  return {h, Representative::vertex, 0};
}

}  // namespace hdt::predicates
