// Exact geometric predicates on translated points of the Poincare disk
// (translated_point.hpp): the driver of the predicate pipeline.
//
// Every predicate returns the mathematically correct sign for every input.
// It runs the stages in order, each a file implementing the predicates
// that it applies to and returning a Sign (sign.hpp), `undecided` when its
// certified error bound cannot separate the value from zero:
//   disk          untranslated or same-frame points, static bounds (stage_disk.hpp);
//   double        certified double points, dynamic bounds (stage_double.hpp);
//   structural    exact zeros from the rows' structure: points on an axis of
//                 F_g, identical descriptions (stage_structural.hpp);
//   double-double about 106 bits (stage_double_double.hpp);
//   MPFR          133 bits (stage_mpfr.hpp); both with the analysis of
//                 stage_refined.hpp;
//   exact         the field K_g (stage_exact.hpp), or GMP integers for
//                 same-frame points (stage_disk_exact.hpp).
// The driver counts which stage decided (statistics()) and, built with
// -Dcheck_predicates=true, compares every other stage's decision with the
// exact stage's.
//
// Formulas, on the hyperboloid (N = the point's hyperboloid vector):
//   orientation(p, q, r) = sign det[N_p; N_q; N_r]        (+1: counterclockwise)
//   in_circle(p, q, r, s) = sign det[N_p 1; N_q 1; N_r 1; N_s 1]
//        for p, q, r counterclockwise: +1 when s is inside their circle;
//   beyond_side(p, k)     = sign(<N, O> - <N, g_k O>)     (+1: beyond the line of
//        side s_k, on the side of g_k(F_g); 0: on it; -1: on the side of F_g);
//   compare_distance(p, a, b) = sign(<N_p, N_a> - <N_p, N_b>);
//   same_point(p, q)      = (N_p == N_q).
// The floating stages use differences N_i - N_0, which keeps them sharp for
// small triangles; the exact stage uses the unnormalised rows (M_h p^, s^2m w),
// a positive multiple of (N, 1) row by row (see group/exact_lorentz.hpp).
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
#include <cstddef>
#include <cstdint>
#include <optional>

#include "predicates/sign.hpp"
#include "predicates/stage_disk.hpp"
#include "predicates/stage_double.hpp"
#include "predicates/stage_double_double.hpp"
#include "predicates/stage_exact.hpp"
#include "predicates/stage_mpfr.hpp"
#include "predicates/stage_structural.hpp"
#include "predicates/translated_point.hpp"
#include "surface/surface.hpp"

namespace hdt::predicates {

using surface::ExactSite;

// The stages, in the order they run.
enum class Stage : uint8_t { disk, double_filter, structural, double_double, mpfr, exact };
constexpr std::size_t kStageCount = 6;

// The predicates, as the statistics count them.
enum class Predicate : uint8_t {
  orientation,
  in_circle,
  in_circle_perturbed,
  beyond_side,
  compare_distance,
  same_point,
  large_circumdisk
};
constexpr std::size_t kPredicateCount = 7;
const char *predicate_name(Predicate p);

// How many calls of each predicate each stage decided, and how many reached
// the MPFR stage (which stages to keep for a predicate is measured with
// these: docs/design.md), for tests and benchmarks.
struct FilterStatistics {
  std::array<std::array<unsigned long, kStageCount>, kPredicateCount> decided{};
  std::array<unsigned long, kPredicateCount> reached_mpfr{};

  unsigned long decided_by(Predicate p, Stage s) const { return decided[std::size_t(p)][std::size_t(s)]; }
  unsigned long calls(Predicate p) const {
    unsigned long n = 0;
    for (const unsigned long d : decided[std::size_t(p)]) n += d;
    return n;
  }
  // Over all predicates.
  unsigned long operator[](Stage s) const {
    unsigned long n = 0;
    for (const auto &by_stage : decided) n += by_stage[std::size_t(s)];
    return n;
  }
  unsigned long calls() const {
    unsigned long n = 0;
    for (std::size_t p = 0; p < kPredicateCount; ++p) n += calls(Predicate(p));
    return n;
  }
  // Decided in double precision (the disk and double stages).
  unsigned long filtered() const { return (*this)[Stage::disk] + (*this)[Stage::double_filter]; }
  // Left to the later stages by the double-precision ones.
  unsigned long past_filters() const { return calls() - filtered(); }
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
      if (const Sign s = disk_orientation(p.x, p.y, q.x, q.y, r.x, r.y); decided(s))
        return ++statistics_.decided[std::size_t(Predicate::orientation)][std::size_t(Stage::disk)], to_int(s);
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
      if (const Sign s = disk_in_circle(p[0].x, p[0].y, p[1].x, p[1].y, p[2].x, p[2].y, p[3].x, p[3].y);
          decided(s))
        return ++statistics_.decided[std::size_t(Predicate::in_circle_perturbed)][std::size_t(Stage::disk)], to_int(s);
#endif
    return in_circle_perturbed_staged(points, vertex);
  }
  int beyond_side(const TranslatedPoint &p, int side);
  // beyond_side for every side k = 0..4g-1 into signs[k], the point's
  // double point computed once.
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

  // orientation, in_circle_perturbed and large_circumdisk with each point's
  // double point given (a, b, c, e: certified as the double stage's, any
  // error, an infinite one never decides): a vertex removal computes them
  // once per hole and tests each many times, which then skips the point
  // cache. The double stage runs on them; the later stages as above.
  int orientation(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r,
                  const FilteredPoint &a, const FilteredPoint &b, const FilteredPoint &c);
  int in_circle_perturbed(const std::array<TranslatedPoint, 4> &points, const std::array<uint32_t, 4> &vertex,
                          const std::array<const FilteredPoint *, 4> &certified);
  int large_circumdisk(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r,
                       const FilteredPoint &a, const FilteredPoint &b, const FilteredPoint &c);

  // The hyperboloid vector of p in double, for constructions (circumcentres
  // of the dummy refinement), not predicates: accurate to about 1e-9
  // relative, from the refined stages where double precision is not.
  // *accurate (may be null) tells whether that accuracy was reached.
  std::array<double, 3> hyperboloid(const TranslatedPoint &p, bool *accurate = nullptr);
  // The same vector to 133 bits (the MPFR stage's point), for constructions
  // whose double formulas cancel: far from O at large genus the coordinates
  // reach cosh(2R) ~ 1e10 and a circumcentre loses twice their bits. False
  // when that stage has no approximation of p.
  bool hyperboloid_mpfr(const TranslatedPoint &p, std::array<MpfrReal, 3> *n);

  // orientation(p, q, r) when a stage before the field K_g's decides it,
  // else nothing: for callers that may answer "cannot tell" (the early
  // refusal of a removal), where the exact stage's matrices over K_g would
  // cost more than the answer saves (seconds at genus 256: a point placed
  // on a line through a vertex is near-degenerate by construction).
  std::optional<int> orientation_before_exact(const TranslatedPoint &p, const TranslatedPoint &q,
                                              const TranslatedPoint &r);

  // Registers the home image of the stored point (x, y) with home `home`
  // when it lies far from F_g (home_image.hpp) and has none yet; true when
  // one was added (remove it with forget_home_image). The floating stages
  // read it from then on.
  bool add_home_image(double x, double y, TranslationId home);
  void forget_home_image(double x, double y);

  // The surface's site `site` under `translation`.
  TranslatedPoint site_point(int32_t site, TranslationId translation) const;

  const FilterStatistics &statistics() const { return statistics_; }
  void reset_statistics() { statistics_ = {}; }

 private:
  // A stage's decision and the stage.
  struct Decision {
    Sign sign;
    Stage stage;
  };
  // d counted, and checked against the exact stage under -Dcheck_predicates.
  template <class Exact>
  int decide(Predicate predicate, Decision d, Exact &&exact);

  // Each predicate's stages in order, through the exact one (orientation:
  // without kThroughExact, the stages before the field K_g's, undecided
  // when none decides; a template so that the common path keeps its code).
  template <bool kThroughExact>
  Decision orientation_stages(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r);
  // The in-circle stages before the field K_g's (same-frame points: through
  // the exact disk stage); undecided when none decides.
  Decision in_circle_stages(Predicate which, const TranslatedPoint &p, const TranslatedPoint &q,
                            const TranslatedPoint &r, const TranslatedPoint &s);
  // Counts a call of `which` that reaches the MPFR stage.
  void reach_mpfr(Predicate which) { ++statistics_.reached_mpfr[std::size_t(which)]; }
  Decision beyond_side_stages(const FilteredPoint &a, int side, const TranslatedPoint &p);
  Decision compare_distance_stages(const TranslatedPoint &p, const TranslatedPoint &a, const TranslatedPoint &b);
  Decision distinct_stages(const TranslatedPoint &p, const TranslatedPoint &q);
  Decision large_circumdisk_stages(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r);

  // The out-of-line paths of the inline predicates above.
  int orientation_checked(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r);
  int in_circle_perturbed_staged(const std::array<TranslatedPoint, 4> &points, const std::array<uint32_t, 4> &vertex);
  // The exact stage of in_circle_perturbed: out of line, so that the hot
  // path does not construct (and destroy) four rows of field elements.
  [[gnu::noinline]] int in_circle_perturbed_exact(const std::array<TranslatedPoint, 4> &points,
                                                  const std::array<uint32_t, 4> &vertex);
  // The perturbed sign of four exactly cocircular points; rows (may be null)
  // are their exact rows when already computed.
  int perturbed_tie(const std::array<TranslatedPoint, 4> &points, const std::array<uint32_t, 4> &vertex,
                    const std::array<ExactStage::Row, 4> *rows);

  surface::Surface &surface_;
  DoubleStage double_;
  MpfrStage mpfr_;
  DoubleDoubleStage double_double_;  // uses mpfr_
  ExactStage exact_;
  StructuralStage structural_;  // uses exact_
  FilterStatistics statistics_;
};

}  // namespace hdt::predicates
