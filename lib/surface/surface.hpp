// One surface M_g: everything that describes it, in one object that the
// predicates, the triangulation and the C API ask.
//
// It owns the presentation of Gamma_g, the translation table (the ids of the
// group elements met so far; ids 0..|N|-1 are the neighbour set N, and
// among them 1..4g are the letters g_0..g_{4g-1}), the sides of F_g with
// their geometry (for the side predicates), the constants of the genus that
// formulas need, and the registry of exact sites (points of the disk with
// algebraic coordinates, such as F_g's vertex and side midpoints, which are
// dummy points).
//
// The translation table and the site registry grow as a triangulation meets
// new elements and registers sites; everything else is fixed at creation.
// One thread at a time, like the triangulation that owns it.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <memory>
#include <unordered_map>
#include <vector>

#include "exact/cyclotomic.hpp"
#include "exact/field.hpp"
#include "exact/multiprecision.hpp"
#include "group/exact_lorentz.hpp"
#include "group/moebius.hpp"
#include "group/presentation.hpp"
#include "group/translation_table.hpp"
#include "surface/home_image.hpp"
#include "surface/site.hpp"

namespace hdt::surface {

using group::TranslationId;

class Surface {
 public:
  explicit Surface(int genus);
  Surface(const Surface &) = delete;
  Surface &operator=(const Surface &) = delete;

  int genus() const { return presentation_.genus(); }
  const group::Presentation &presentation() const { return presentation_; }
  const exact::Field &field() const { return field_; }
  group::TranslationTable &table() { return table_; }
  const group::TranslationTable &table() const { return table_; }

  // Named translation ids.
  static constexpr TranslationId identity = 0;
  // The id of the generator g_k (k = 0..4g-1).
  static TranslationId letter(group::Letter k) { return TranslationId(1 + k); }

  // ---- The sides of F_g ----
  int side_count() const { return presentation_.letter_count(); }
  // O - g_k(O) rounded to double, with the Minkowski signs folded in: the
  // sign of <N, side_normal(k)> tells on which side of side k's line a
  // point with hyperboloid vector N lies (+1 beyond it).
  const std::array<double, 3> &side_normal(int k) const { return side_normals_.at(std::size_t(k)); }
  // g_k's exact Lorentz matrix, times sin(pi/4g)^2 (group/exact_lorentz.hpp).
  // Built on first use: 4g dense matrices over K_g cost gigabytes at genus
  // 1024, and only the exact stage of a side test needs them.
  const group::ExactLorentz &exact_generator(int k) const;
  // The sides whose line may hold or have beyond it a disk point of
  // argument `angle` (radians, atan2's): every other side has the point
  // strictly on F_g's side. Half the sides at genus 2, one or two at large
  // genus.
  const std::vector<int> &sides_near(double angle) const;

  // ---- Constants of the genus ----
  // A = cot(pi/4g) rounded (group::half_trace).
  double half_trace() const { return half_trace_; }
  // cosh(sys/4) = sqrt(1 + cos(pi/2g)), within a few ulps: the limit of a
  // face's circumradius, for the decisions made in double (which face to
  // refine, whether a removal is refused for certain: the latter with a
  // margin of 1e-14).
  double quarter_systole_cosh_rounded() const { return quarter_systole_cosh_rounded_; }
  // sin(pi/4g)^2, exactly: the positive factor of an exact matrix's rows
  // per letter.
  const exact::Cyclotomic &sin2() const { return sin2_; }
  // 1 + cos(pi/2g) = cosh^2(sys/4), exactly: a circle has diameter < sys/2
  // when cosh^2 of its radius is below it.
  const exact::FieldElement &quarter_systole_cosh2() const { return quarter_systole_cosh2_; }

  // ---- Exact sites ----
  // Registers an exact point; returns its id (0, 1, ... in order). Throws
  // std::domain_error unless Z > 0 and the point lies in the open unit
  // disk. approximation (may be null): the coordinates within 2^-128.
  // rounded (may be null): the coordinates correctly rounded, when the
  // caller knows them (the quotient of rounded X, Y and Z can be an ulp
  // off); checked against that quotient.
  int32_t add_site(const ExactSite &site, const group::Complex<SiteReal> *approximation = nullptr,
                   const group::Complex<double> *rounded = nullptr);
  // Registers a site that a surface of the same genus registered (its checks
  // passed there): a copy of the template's sites for a new triangulation
  // costs a copy, not the exact arithmetic of add_site.
  int32_t adopt_site(const Site &site) {
    sites_.push_back(site);
    return int32_t(sites_.size() - 1);
  }
  const Site &site(int32_t id) const { return sites_.at(std::size_t(id)); }
  std::size_t site_count() const { return sites_.size(); }

  // ---- Home images (home_image.hpp), by the stored point ----
  // The image registered for the stored point (x, y), or null.
  const HomeImage *home_image(double x, double y) const {
    if (images_.empty()) return nullptr;
    const auto it = images_.find(PointKey::of(x, y));
    return it == images_.end() ? nullptr : &it->second;
  }
  bool has_home_images() const { return !images_.empty(); }
  // Registers it unless the point has one; false if it had.
  bool add_home_image(const HomeImage &image) { return images_.emplace(PointKey::of(image.x, image.y), image).second; }
  void remove_home_image(double x, double y) { images_.erase(PointKey::of(x, y)); }

 private:
  group::Presentation presentation_;
  const exact::Field &field_;
  group::TranslationTable table_;
  std::vector<std::array<double, 3>> side_normals_;
  mutable std::vector<std::unique_ptr<group::ExactLorentz>> exact_generators_;  // null until used
  std::vector<std::vector<int>> sides_by_sector_;  // sides_near, by sector of angle
  double half_trace_;
  double quarter_systole_cosh_rounded_;
  exact::Cyclotomic sin2_;
  exact::FieldElement quarter_systole_cosh2_;
  std::vector<Site> sites_;
  // The bits of a stored point's coordinates.
  struct PointKey {
    uint64_t x, y;
    static PointKey of(double x, double y) {
      PointKey k;
      std::memcpy(&k.x, &x, sizeof x);
      std::memcpy(&k.y, &y, sizeof y);
      return k;
    }
    bool operator==(const PointKey &o) const { return x == o.x && y == o.y; }
  };
  struct PointKeyHash {
    std::size_t operator()(const PointKey &k) const { return std::size_t(k.x * 0x9e3779b97f4a7c15ull ^ k.y); }
  };
  std::unordered_map<PointKey, HomeImage, PointKeyHash> images_;
};

}  // namespace hdt::surface
