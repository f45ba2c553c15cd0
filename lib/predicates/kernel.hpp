// Exact geometric predicates on translated points of the Poincare disk.
//
// A point is given as a stored point (x, y) (doubles, hence exact rationals)
// and a translation id h of the kernel's TranslationTable: it stands for
// h(x + iy), an algebraic point. Every predicate returns the mathematically
// correct sign for every input: a double-precision evaluation with a
// certified error bound decides when it can (static for untranslated points,
// disk_filter.hpp; dynamic otherwise), then exact zeros that follow from
// the rows' structure (structural_zero.cpp: points on an axis of F_g and
// translations along it), then refined stages (double-double, 133-bit
// MPFR); otherwise the value is computed exactly in the field K_g
// (exact/field.hpp).
//
// Formulas, on the hyperboloid (N = the point's hyperboloid vector):
//   orientation(p, q, r) = sign det[N_p; N_q; N_r]        (+1: counterclockwise)
//   in_circle(p, q, r, s) = sign det[N_p 1; N_q 1; N_r 1; N_s 1]
//        for p, q, r counterclockwise: +1 when s is inside their circle;
//   beyond_side(p, k)     = sign(<N, O> - <N, g_k O>)     (+1: beyond the line of
//        side s_k, on the side of g_k(F_g); 0: on it; -1: on the side of F_g);
//   same_point(p, q)      = (N_p == N_q).
// The filter uses differences N_i - N_0, which keeps it sharp for small
// triangles; the exact path uses the unnormalised rows (M_h p^, s^2m w), a
// positive multiple of (N, 1) row by row (see group/exact_lorentz.hpp).
//
// Ties of in_circle (cocircular points) are broken by symbolic perturbation:
// vertex v's rows get the last coordinate 1 + eps_v, with eps of a larger
// vertex id infinitely larger. The first vertex (largest id first) whose
// coefficient is non-zero decides; a newer point cocircular with a face is
// thus inside its circle. This is one global perturbation of the point set on
// the surface (all copies of a vertex move alike), so every decision made
// with it is consistent with every other.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "exact/field.hpp"
#include "exact/multiprecision.hpp"
#include "group/exact_lorentz.hpp"
#include "group/translation_table.hpp"
#include "predicates/disk_filter.hpp"
#include "predicates/double_double.hpp"
#include "predicates/filtered_point.hpp"
#include "surface/surface.hpp"

namespace hdt::predicates {

using group::TranslationId;

using surface::ExactSite;

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
// exact disk stage apply (disk_exact.hpp).
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

// A point of a refined filter stage: the hyperboloid vector in the stage's
// reals and a certified bound on each coordinate's error.
template <class Real>
struct RefinedPoint {
  Real n[3];
  double error;  // on each coordinate
};
// Stage 2a: double-double reals (about 106 bits in plain double operations).
using FastReal = DoubleDouble;
using FastPoint = RefinedPoint<FastReal>;
// Stage 2b: 133-bit MPFR reals.
using MidReal = exact::mp_real<40>;
using MidPoint = RefinedPoint<MidReal>;

// x rounded to double-double (hi = RN(x), lo = RN(x - hi)): within
// u^2 |x| = 2^-106 |x|.
FastReal round_to_fast(const MidReal &x);

// Counts of the filter's successes and failures, for tests and benchmarks.
struct FilterStatistics {
  unsigned long filtered = 0;
  unsigned long exact = 0;
  unsigned long fast = 0;     // decided by the double-double stage (counted in exact too)
  unsigned long refined = 0;  // decided by the 133-bit stage (counted in exact too)
  unsigned long structural = 0;  // exact zeros of structural_zero.cpp (counted in exact too)
};

class Kernel {
 public:
  // The predicates on `surface`, which must outlive the kernel.
  explicit Kernel(surface::Surface &surface);

  surface::Surface &surface() const { return surface_; }

  int orientation(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r) {
#ifndef HDT_CHECK_PREDICATES
    // Inline, the common case of a walk: untranslated points that the disk
    // filter decides.
    if (untranslated(p) && untranslated(q) && untranslated(r))
      if (const int s = disk_orientation(p.x, p.y, q.x, q.y, r.x, r.y)) return ++statistics_.filtered, s;
#endif
    return orientation_checked(p, q, r);
  }
  int in_circle(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r,
                const TranslatedPoint &s);
  // in_circle with ties broken by the symbolic perturbation; never 0 when
  // p, q, r are not on one geodesic (a triangle: always so for a face) and
  // one vertex occurs once among the four (always so in a simplicial
  // triangulation). Throws std::logic_error when no perturbation coefficient
  // decides (four points on one geodesic). vertex[i] is the vertex id of
  // point i.
  int in_circle_perturbed(const std::array<TranslatedPoint, 4> &points, const std::array<uint32_t, 4> &vertex) {
#ifndef HDT_CHECK_PREDICATES
    // Inline, the common case of an insertion's conflict search: four
    // untranslated points that the disk filter decides.
    const auto &p = points;
    if (untranslated(p[0]) && untranslated(p[1]) && untranslated(p[2]) && untranslated(p[3]))
      if (const int s = disk_in_circle(p[0].x, p[0].y, p[1].x, p[1].y, p[2].x, p[2].y, p[3].x, p[3].y))
        return ++statistics_.filtered, s;
#endif
    return in_circle_perturbed_staged(points, vertex);
  }
  int beyond_side(const TranslatedPoint &p, int side);
  // beyond_side for every side k = 0..4g-1 into signs[k], the point's
  // filtered vector computed once.
  void beyond_sides(const TranslatedPoint &p, int *signs);
  // sign(d(p, a) - d(p, b)) for the hyperbolic distance d: -1 when a is
  // nearer to p, 0 at equal distance.
  int compare_distance(const TranslatedPoint &p, const TranslatedPoint &a, const TranslatedPoint &b);
  // Whether p and q are the same point of the disk, exactly.
  bool same_point(const TranslatedPoint &p, const TranslatedPoint &q);
  // +1 when the circle through p, q, r has hyperbolic diameter >= sys/2 (or
  // is no circle: a horocycle or hypercycle), -1 when it is smaller. The
  // dummy-point condition sys > 2 delta asks for -1 on every face. With
  // (c, c_3) the plane through (N_p 1), (N_q 1), (N_r 1) and m = (c0, -c1, -c2),
  // the radius rho has cosh rho = |c_3| / sqrt<m, m>, and
  // cosh^2(sys/4) = 1 + cos(pi/2g): the test is c_3^2 >= (1 + cos(pi/2g)) <m, m>.
  int large_circumdisk(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r);
  int large_circumdisk_exact(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r);

  // The hyperboloid vector of p in double, for constructions (circumcentres
  // of the dummy refinement), not predicates: accurate to about 1e-9
  // relative, from the 133-bit stage where double precision is not.
  // *accurate (may be null) tells whether that accuracy was reached.
  std::array<double, 3> hyperboloid(const TranslatedPoint &p, bool *accurate = nullptr);

  // The exact evaluations alone (for tests against the filter).
  int orientation_exact(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r);
  int in_circle_exact(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r,
                      const TranslatedPoint &s);
  int beyond_side_exact(const TranslatedPoint &p, int side);
  bool same_point_exact(const TranslatedPoint &p, const TranslatedPoint &q);
  int compare_distance_exact(const TranslatedPoint &p, const TranslatedPoint &a, const TranslatedPoint &b);

  // The surface's site `site` under `translation`.
  TranslatedPoint site_point(int32_t site, TranslationId translation) const;

  const FilterStatistics &statistics() const { return statistics_; }
  void reset_statistics() { statistics_ = {}; }

 private:
  // The exact row (M_h p^, s^2m w) of a point.
  struct ExactRow {
    std::array<exact::FieldElement, 4> v;
  };
  ExactRow exact_row(const TranslatedPoint &p);
  // The refined filter stages (refined_filter.cpp): the double filter's
  // determinants with a certified bound in more precise arithmetic. They
  // decide what double precision cannot near the polygon's corners, where
  // translations of N have entries up to cosh(2R) and cancel against the
  // point. Stage 2a (fast) in double-double, stage 2b (mid) in 133-bit MPFR
  // when 2a cannot decide; each returns 2 when it cannot decide (sites
  // without an approximation go straight to exact).
  //
  // Stage 2a, then 2b, statistics counted. Out of line (refined_filter.cpp)
  // so that the double filters' code stays as tight as without them.
  int orientation_refined(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r);
  int in_circle_refined(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r,
                        const TranslatedPoint &s);
  int large_circumdisk_refined(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r);
  using Mid = MidReal;
  bool mid_point(const TranslatedPoint &p, MidPoint *out);
  const group::Lorentz<Mid> &mid_matrix(TranslationId id);
  int orientation_mid(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r);
  int in_circle_mid(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r,
                    const TranslatedPoint &s);
  int large_circumdisk_mid(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r);
  std::vector<std::unique_ptr<group::Lorentz<Mid>>> mid_matrices_;  // by translation id, lazily
  bool fast_point(const TranslatedPoint &p, FastPoint *out);  // cached
  bool compute_fast_point(const TranslatedPoint &p, FastPoint *out);
  const group::Lorentz<FastReal> &fast_matrix(TranslationId id);
  int orientation_fast(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r);
  int in_circle_fast(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r,
                     const TranslatedPoint &s);
  int large_circumdisk_fast(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r);
  // Each entry within 2^-106 |L_ij| + 2^-121 L_00, by translation id, lazily.
  std::vector<std::unique_ptr<group::Lorentz<FastReal>>> fast_matrices_;
  FastReal fast_circumdisk_k_{0};  // 1 + cos(pi/2g), within (u^2 + 2^-132) relative; 0: not yet

  // The out-of-line paths of the inline predicates above: every filter,
  // then exact, each decision checked under -Dcheck_predicates.
  int orientation_checked(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r);
  int in_circle_perturbed_staged(const std::array<TranslatedPoint, 4> &points, const std::array<uint32_t, 4> &vertex);
  // The perturbed sign of four exactly cocircular points; rows (may be null)
  // are their exact rows when already computed.
  int perturbed_tie(const std::array<TranslatedPoint, 4> &points, const std::array<uint32_t, 4> &vertex,
                    const std::array<ExactRow, 4> *rows);
  // The coefficient of eps_v in the perturbed determinant.
  exact::FieldElement perturbation_coefficient(const std::array<ExactRow, 4> &rows,
                                               const std::array<uint32_t, 4> &vertex, uint32_t v) const;
  // The public predicates' stages (filters, then exact), before the check of
  // -Dcheck_predicates.
  int orientation_staged(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r);
  int large_circumdisk_staged(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r);
  int beyond_side_filtered(const FilteredPoint &a, int side, const TranslatedPoint &p);
  // The in-circle sign of the stages before exact (double filter,
  // structural zero, refined): +1 or -1, 0 only for a structural zero, or 2
  // when none decides.
  int in_circle_filter(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r,
                       const TranslatedPoint &s);
  const group::ExactLorentz &exact_matrix(TranslationId id);
  // The structural-zero stage (structural_zero.cpp): true when one of
  // coordinates 1, 2 is exactly zero in the exact rows of all n points (a
  // sufficient condition for the orientation and in-circle determinants to
  // vanish). filtered[k] is points[k]'s certified double point.
  bool common_zero_coordinate(const TranslatedPoint *const *points, const FilteredPoint *const *filtered, int n);
  unsigned row_zeros(const TranslatedPoint &p);  // bit i: coordinate i (1, 2) of p's exact row is 0
  unsigned matrix_zeros(TranslationId id);       // bit 3i + j: entry (i, j) of the exact matrix is 0
  std::vector<uint16_t> matrix_zeros_;           // by translation id, lazily (bit 15: computed)
  std::vector<uint16_t> site_zeros_;             // by site: bit 1 X = 0, bit 2 Y = 0 (bit 15: computed)
  exact::FieldElement det3(const std::array<const std::array<exact::FieldElement, 4> *, 3> &rows) const;
  exact::FieldElement det4(const std::array<ExactRow, 4> &rows) const;

  // The double point of p for the filter; a site's rounding error is
  // folded into the error bound.
  FilteredPoint filtered(const TranslatedPoint &p);
  FilteredPoint compute_filtered(const TranslatedPoint &p);
  // A small direct-mapped cache of filtered points: a walk or a conflict
  // search asks for the same few corners and query again and again. 256
  // slots: points along a curve that crosses the sides of F_g make conflict
  // searches of a few dozen translated points, and 64 slots missed a
  // quarter of their lookups (to 5% more instructions per insertion).
  template <class Point>
  struct CachedPoint {
    TranslatedPoint key{NAN, NAN, -1, -1};  // NaN: identical to no point
    Point point;
  };
  static constexpr int kCacheBits = 8;
  static std::size_t cache_slot(const TranslatedPoint &p);  // 0 .. 2^kCacheBits - 1
  std::array<CachedPoint<FilteredPoint>, std::size_t(1) << kCacheBits> filtered_cache_{};
  // The same for the double-double stage, which runs for most faces near
  // the corners of F_g at large genus (where the hyperboloid is nearly flat
  // in the coordinates and the double filter cannot decide in-circle tests).
  struct FastEntry {
    bool ok;  // fast_point's answer
    FastPoint point;
  };
  std::array<CachedPoint<FastEntry>, std::size_t(1) << kCacheBits> fast_cache_{};

  surface::Surface &surface_;
  group::TranslationTable &table_;  // surface_'s
  const exact::Field &field_;       // surface_'s
  // What the stages need of a site, derived from the surface's site once.
  struct SiteStages {
    double n[3];           // the hyperboloid vector, each entry within 4u relative
    bool has_mid = false;  // mid: the coordinates within 2^-128
    group::Complex<MidReal> mid;
    group::Complex<FastReal> fast;  // mid rounded: within 2^-128 + 2^-106 (has_mid only)
  };
  const SiteStages &site_stages(int32_t site);
  std::vector<SiteStages> site_stages_;  // by site id, filled up to the last one asked for
  std::vector<std::unique_ptr<group::ExactLorentz>> exact_matrices_;  // by translation id, lazily
  // sin(pi/4g)^(2 letters): the positive factor of an exact matrix's rows.
  const exact::Cyclotomic &scale(int letters);
  std::vector<exact::Cyclotomic> scale_powers_;
  FilterStatistics statistics_;
};

}  // namespace hdt::predicates
