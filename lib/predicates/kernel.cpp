#include "predicates/kernel.hpp"

#include <algorithm>
#include <functional>
#include <stdexcept>
#include <string>

#include "exact/perturbation.hpp"
#include "predicates/stage_disk_exact.hpp"

namespace hdt::predicates {

const char *predicate_name(Predicate p) {
  static const char *const names[kPredicateCount] = {
      "orientation", "in_circle", "in_circle_perturbed", "beyond_side", "compare_distance", "same_point",
      "large_circumdisk"};
  return names[std::size_t(p)];
}

Kernel::Kernel(surface::Surface &surface)
    : surface_(surface), double_(surface), mpfr_(surface), double_double_(surface, mpfr_), exact_(surface),
      structural_(surface, exact_) {}

TranslatedPoint Kernel::site_point(int32_t site, TranslationId translation) const {
  const surface::Site &d = surface_.site(site);
  return {d.x, d.y, translation, site};
}

bool Kernel::add_home_image(double x, double y, TranslationId home) {
  if (!surface::far_from_domain(x, y, home) || surface_.home_image(x, y)) return false;
  const std::optional<surface::HomeImage> image =
      surface::make_home_image(surface_.presentation(), surface_.table(), x, y, home);
  if (!image) return false;
  surface_.add_home_image(*image);
  // Points cached before were evaluated without it (the representative
  // walk's last steps): as certified, but far less sharp.
  double_.forget(x, y);
  double_double_.forget(x, y);
  return true;
}

void Kernel::forget_home_image(double x, double y) {
  // Points cached with it stay true: the image is a function of (x, y).
  surface_.remove_home_image(x, y);
}

// Built with -Dcheck_predicates=true (HDT_CHECK_PREDICATES), every decision
// of a stage before the exact one is compared with the exact evaluation: a
// wrong sign then throws (HDT_EINTERNAL at the C API) instead of corrupting
// a triangulation. Slow; for debugging and fuzzing.
template <class Exact>
int Kernel::decide(Predicate predicate, Decision d, [[maybe_unused]] Exact &&exact) {
  ++statistics_.decided[std::size_t(predicate)][std::size_t(d.stage)];
#ifdef HDT_CHECK_PREDICATES
  if (d.stage != Stage::exact)
    if (const Sign e = exact(); e != d.sign)
      throw std::logic_error(std::string("check_predicates: ") + predicate_name(predicate) + " decided " +
                             std::to_string(to_int(d.sign)) + " at stage " + std::to_string(int(d.stage)) +
                             ", the exact evaluation says " + std::to_string(to_int(e)));
#endif
  return to_int(d.sign);
}

// ---- orientation ----

template <bool kThroughExact>
Kernel::Decision Kernel::orientation_stages(const TranslatedPoint &p, const TranslatedPoint &q,
                                            const TranslatedPoint &r) {
  if (same_frame(p, q, r)) {
    // Points in one frame have the signs of their stored points: the disk
    // stage, then double-double (points sampled along one line, rounded to
    // doubles, are rarely exactly on it), then the exact disk stage.
    if (const Sign s = disk_orientation(p.x, p.y, q.x, q.y, r.x, r.y); decided(s)) return {s, Stage::disk};
    if (const Sign s = double_double_.orientation(stored(p), stored(q), stored(r)); decided(s))
      return {s, Stage::double_double};
    return {disk_orientation_exact(p.x, p.y, q.x, q.y, r.x, r.y), Stage::exact};
  }
  const FilteredPoint a = double_.point(p), b = double_.point(q), c = double_.point(r);
  if (const Sign s = DoubleStage::orientation(a, b, c); decided(s)) return {s, Stage::double_filter};
  if (const Sign s = DoubleStage::disk_orientation(a, b, c); decided(s)) return {s, Stage::double_filter};
  // The same description is the same point: a duplicate insertion walks
  // onto its vertex, and these orientations are zero without the exact stage.
  if (identical(p, q) || identical(q, r) || identical(r, p)) return {Sign::zero, Stage::structural};
  const TranslatedPoint *points[3] = {&p, &q, &r};
  const FilteredPoint *certified[3] = {&a, &b, &c};
  if (const Sign s = structural_.determinant(points, certified, 3); decided(s)) return {s, Stage::structural};
  if (const Sign s = double_double_.orientation(p, q, r); decided(s)) return {s, Stage::double_double};
  reach_mpfr(Predicate::orientation);
  if (const Sign s = mpfr_.orientation(p, q, r); decided(s)) return {s, Stage::mpfr};
  if constexpr (kThroughExact) return {exact_.orientation(p, q, r), Stage::exact};
  return {Sign::undecided, Stage::exact};
}

int Kernel::orientation_checked(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r) {
  return decide(Predicate::orientation, orientation_stages<true>(p, q, r), [&] { return exact_.orientation(p, q, r); });
}

std::optional<int> Kernel::orientation_before_exact(const TranslatedPoint &p, const TranslatedPoint &q,
                                                    const TranslatedPoint &r) {
  const Decision d = orientation_stages<false>(p, q, r);
  if (!decided(d.sign)) return std::nullopt;
  return decide(Predicate::orientation, d, [&] { return exact_.orientation(p, q, r); });
}

int Kernel::orientation(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r,
                        const FilteredPoint &a, const FilteredPoint &b, const FilteredPoint &c) {
  if (const Sign s = DoubleStage::orientation(a, b, c); decided(s))
    return decide(Predicate::orientation, {s, Stage::double_filter}, [&] { return exact_.orientation(p, q, r); });
  return orientation(p, q, r);
}

// ---- in_circle ----

Kernel::Decision Kernel::in_circle_stages(Predicate which, const TranslatedPoint &p, const TranslatedPoint &q,
                                          const TranslatedPoint &r, const TranslatedPoint &s) {
  if (same_frame(p, q, r, s)) {
    if (const Sign sg = disk_in_circle(p.x, p.y, q.x, q.y, r.x, r.y, s.x, s.y); decided(sg)) return {sg, Stage::disk};
    if (const Sign sg = double_double_.in_circle(stored(p), stored(q), stored(r), stored(s)); decided(sg))
      return {sg, Stage::double_double};
    return {disk_in_circle_exact(p.x, p.y, q.x, q.y, r.x, r.y, s.x, s.y), Stage::exact};
  }
  const FilteredPoint a = double_.point(p), b = double_.point(q), c = double_.point(r), e = double_.point(s);
  if (const Sign sg = DoubleStage::in_circle(a, b, c, e); decided(sg)) return {sg, Stage::double_filter};
  if (const Sign sg = DoubleStage::disk_in_circle(a, b, c, e); decided(sg)) return {sg, Stage::double_filter};
  const TranslatedPoint *points[4] = {&p, &q, &r, &s};
  const FilteredPoint *certified[4] = {&a, &b, &c, &e};
  if (const Sign sg = structural_.determinant(points, certified, 4); decided(sg)) return {sg, Stage::structural};
  if (const Sign sg = double_double_.in_circle(p, q, r, s); decided(sg)) return {sg, Stage::double_double};
  reach_mpfr(which);
  if (const Sign sg = mpfr_.in_circle(p, q, r, s); decided(sg)) return {sg, Stage::mpfr};
  return {Sign::undecided, Stage::exact};
}

int Kernel::in_circle(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r,
                      const TranslatedPoint &s) {
  auto exact = [&] { return exact_.in_circle(p, q, r, s); };
  Decision d = in_circle_stages(Predicate::in_circle, p, q, r, s);
  if (!decided(d.sign)) d = {exact(), Stage::exact};
  return decide(Predicate::in_circle, d, exact);
}

int Kernel::in_circle_perturbed_staged(const std::array<TranslatedPoint, 4> &pt,
                                       const std::array<uint32_t, 4> &vertex) {
  // The unperturbed sign, as in_circle; a tie goes to the perturbation.
  const Decision d = in_circle_stages(Predicate::in_circle_perturbed, pt[0], pt[1], pt[2], pt[3]);
  if (!decided(d.sign)) return in_circle_perturbed_exact(pt, vertex);
  const int s =
      decide(Predicate::in_circle_perturbed, d, [&] { return exact_.in_circle(pt[0], pt[1], pt[2], pt[3]); });
  if (s != 0) return s;
  return perturbed_tie(pt, vertex, nullptr);
}

int Kernel::in_circle_perturbed_exact(const std::array<TranslatedPoint, 4> &pt,
                                      const std::array<uint32_t, 4> &vertex) {
  // The exact rows, kept for a tie's perturbation coefficients.
  const std::array<ExactStage::Row, 4> rows = exact_.rows(pt[0], pt[1], pt[2], pt[3]);
  const int s =
      decide(Predicate::in_circle_perturbed, {exact_.in_circle(rows), Stage::exact}, [] { return Sign::zero; });
  if (s != 0) return s;
  return perturbed_tie(pt, vertex, &rows);
}

int Kernel::perturbed_tie(const std::array<TranslatedPoint, 4> &pt, const std::array<uint32_t, 4> &vertex,
                          const std::array<ExactStage::Row, 4> *rows) {
  // Cocircular: the coefficients of exact/perturbation.hpp, a vertex in one
  // row through the whole pipeline, not the field.
  std::array<ExactStage::Row, 4> computed;
  return exact::perturbed_sign(
      vertex, [&](int i, int j, int k) { return orientation(pt[i], pt[j], pt[k]); },
      [&](uint32_t v) {
        if (!rows) {
          computed = exact_.rows(pt[0], pt[1], pt[2], pt[3]);
          rows = &computed;
        }
        return to_int(exact_.perturbation_coefficient(*rows, vertex, v));
      },
      "in_circle_perturbed");
}

int Kernel::in_circle_perturbed(const std::array<TranslatedPoint, 4> &pt, const std::array<uint32_t, 4> &vertex,
                                const std::array<const FilteredPoint *, 4> &f) {
  if (const Sign s = DoubleStage::in_circle(*f[0], *f[1], *f[2], *f[3]); decided(s))
    return decide(Predicate::in_circle_perturbed, {s, Stage::double_filter},
                  [&] { return exact_.in_circle(pt[0], pt[1], pt[2], pt[3]); });
  return in_circle_perturbed(pt, vertex);
}

// ---- beyond_side ----

Kernel::Decision Kernel::beyond_side_stages(const FilteredPoint &a, int side, const TranslatedPoint &p) {
  if (const Sign s = double_.beyond_side(a, side); decided(s)) return {s, Stage::double_filter};
  if (const Sign s = double_double_.beyond_side(p, side); decided(s)) return {s, Stage::double_double};
  reach_mpfr(Predicate::beyond_side);
  if (const Sign s = mpfr_.beyond_side(p, side); decided(s)) return {s, Stage::mpfr};
  return {exact_.beyond_side(p, side), Stage::exact};
}

int Kernel::beyond_side(const TranslatedPoint &p, int side) {
  return decide(Predicate::beyond_side, beyond_side_stages(double_.point(p), side, p),
                [&] { return exact_.beyond_side(p, side); });
}

void Kernel::beyond_sides(const TranslatedPoint &p, int *signs) {
  const FilteredPoint a = double_.point(p);
  for (int k = 0; k < surface_.side_count(); ++k)
    signs[k] = decide(Predicate::beyond_side, beyond_side_stages(a, k, p), [&] { return exact_.beyond_side(p, k); });
}

// ---- compare_distance ----

Kernel::Decision Kernel::compare_distance_stages(const TranslatedPoint &p, const TranslatedPoint &a,
                                                 const TranslatedPoint &b) {
  const FilteredPoint fp = double_.point(p), fa = double_.point(a), fb = double_.point(b);
  if (const Sign s = DoubleStage::compare_distance(fp, fa, fb); decided(s)) return {s, Stage::double_filter};
  if (const Sign s = double_double_.compare_distance(p, a, b); decided(s)) return {s, Stage::double_double};
  reach_mpfr(Predicate::compare_distance);
  if (const Sign s = mpfr_.compare_distance(p, a, b); decided(s)) return {s, Stage::mpfr};
  return {exact_.compare_distance(p, a, b), Stage::exact};
}

int Kernel::compare_distance(const TranslatedPoint &p, const TranslatedPoint &a, const TranslatedPoint &b) {
  return decide(Predicate::compare_distance, compare_distance_stages(p, a, b),
                [&] { return exact_.compare_distance(p, a, b); });
}

// ---- same_point: the sign of |N_p - N_q|, zero for the same point ----

Kernel::Decision Kernel::distinct_stages(const TranslatedPoint &p, const TranslatedPoint &q) {
  if (identical(p, q)) return {Sign::zero, Stage::structural};
  if (const Sign s = DoubleStage::distinct(double_.point(p), double_.point(q)); decided(s))
    return {s, Stage::double_filter};
  if (const Sign s = double_double_.distinct(p, q); decided(s)) return {s, Stage::double_double};
  reach_mpfr(Predicate::same_point);
  if (const Sign s = mpfr_.distinct(p, q); decided(s)) return {s, Stage::mpfr};
  return {exact_.distinct(p, q), Stage::exact};
}

bool Kernel::same_point(const TranslatedPoint &p, const TranslatedPoint &q) {
  return decide(Predicate::same_point, distinct_stages(p, q), [&] { return exact_.distinct(p, q); }) == 0;
}

// ---- large_circumdisk ----

Kernel::Decision Kernel::large_circumdisk_stages(const TranslatedPoint &p, const TranslatedPoint &q,
                                                 const TranslatedPoint &r) {
  const FilteredPoint a = double_.point(p), b = double_.point(q), c = double_.point(r);
  if (const Sign s = double_.large_circumdisk(a, b, c); decided(s)) return {s, Stage::double_filter};
  if (const Sign s = double_double_.large_circumdisk(p, q, r); decided(s)) return {s, Stage::double_double};
  reach_mpfr(Predicate::large_circumdisk);
  if (const Sign s = mpfr_.large_circumdisk(p, q, r); decided(s)) return {s, Stage::mpfr};
  return {exact_.large_circumdisk(p, q, r), Stage::exact};
}

int Kernel::large_circumdisk(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r) {
  return decide(Predicate::large_circumdisk, large_circumdisk_stages(p, q, r),
                [&] { return exact_.large_circumdisk(p, q, r); });
}

int Kernel::large_circumdisk(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r,
                             const FilteredPoint &a, const FilteredPoint &b, const FilteredPoint &c) {
  if (const Sign s = double_.large_circumdisk(a, b, c); decided(s))
    return decide(Predicate::large_circumdisk, {s, Stage::double_filter},
                  [&] { return exact_.large_circumdisk(p, q, r); });
  return large_circumdisk(p, q, r);
}

// ---- constructions ----

std::array<double, 3> Kernel::hyperboloid(const TranslatedPoint &p, bool *accurate) {
  const FilteredPoint f = double_.point(p);
  const bool good = f.error < 1e-9 * f.n[0];
  if (!good) {
    DoubleDoublePoint d;
    if (double_double_.point(p, &d) && d.error < 1e-12 * static_cast<double>(d.n[0])) {
      if (accurate) *accurate = true;
      return {static_cast<double>(d.n[0]), static_cast<double>(d.n[1]), static_cast<double>(d.n[2])};
    }
    MpfrPoint m;
    if (mpfr_.point(p, &m) && m.error < 1e-12 * static_cast<double>(m.n[0])) {
      if (accurate) *accurate = true;
      return {static_cast<double>(m.n[0]), static_cast<double>(m.n[1]), static_cast<double>(m.n[2])};
    }
  }
  if (accurate) *accurate = good;
  return {f.n[0], f.n[1], f.n[2]};
}

bool Kernel::hyperboloid_mpfr(const TranslatedPoint &p, std::array<MpfrReal, 3> *n) {
  MpfrPoint m;
  if (!mpfr_.point(p, &m)) return false;
  for (int i = 0; i < 3; ++i) (*n)[i] = m.n[i];
  return true;
}

}  // namespace hdt::predicates
