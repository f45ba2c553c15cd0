#include "predicates/kernel.hpp"

#include <algorithm>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>

#include "group/word_matrix.hpp"
#include "predicates/disk_exact.hpp"
#include "predicates/filtered_point.hpp"
#include "surface/systole.hpp"

namespace hdt::predicates {

using exact::Cyclotomic;
using exact::FieldElement;

namespace {

// A filter's decision, compared with the exact evaluation when the library
// is built with -Dcheck_predicates=true (HDT_CHECK_PREDICATES): a wrong sign
// then throws (HDT_EINTERNAL at the C API) instead of corrupting a
// triangulation. Slow; for debugging and fuzzing.
template <class Exact>
int checked([[maybe_unused]] const char *predicate, int decided, [[maybe_unused]] Exact &&exact) {
#ifdef HDT_CHECK_PREDICATES
  if (const int e = int(exact()); e != decided)
    throw std::logic_error(std::string("check_predicates: ") + predicate + " decided " + std::to_string(decided) +
                           ", the exact evaluation says " + std::to_string(e));
#endif
  return decided;
}

// The difference a - b of filtered points and its error bound.
struct Difference {
  double d[3];
  double error;
};

// The stored point of p, untranslated. Points in one frame (same_frame) have
// the signs of their stored points; after the disk filter, the double-double
// stage decides those near a tie (points sampled along one line or circle,
// rounded to doubles, are rarely exactly on it) at a few hundred
// instructions, and only exact ties go on to the integer stage
// (disk_exact.hpp).
TranslatedPoint stored(const TranslatedPoint &p) { return {p.x, p.y, 0, -1}; }

Difference difference(const FilteredPoint &a, const FilteredPoint &b) {
  Difference r;
  for (int i = 0; i < 3; ++i) r.d[i] = a.n[i] - b.n[i];
  r.error = (a.error + b.error) * (1 + kUnit) + kUnit * max_abs3(r.d) * 1.01;
  return r;
}

}  // namespace

Kernel::Kernel(surface::Surface &surface)
    : surface_(surface), table_(surface.table()), field_(surface.field()) {}

const Kernel::SiteStages &Kernel::site_stages(int32_t site) {
  while (site_stages_.size() <= std::size_t(site)) {
    const surface::Site &d = surface_.site(int32_t(site_stages_.size()));
    const ExactSite &e = d.exact;
    // N = (Z^2 + X^2 + Y^2, 2XZ, 2YZ) / w, w = Z^2 - X^2 - Y^2, each part
    // exact before rounding.
    const FieldElement zz = field_.mul(e.Z, e.Z);
    const FieldElement r2 = field_.add(field_.mul(e.X, e.X), field_.mul(e.Y, e.Y));
    const FieldElement two_z = field_.add(e.Z, e.Z);
    const double den = field_.approximate(field_.sub(zz, r2));
    SiteStages stages;
    stages.n[0] = field_.approximate(field_.add(zz, r2)) / den;
    stages.n[1] = field_.approximate(field_.mul(e.X, two_z)) / den;
    stages.n[2] = field_.approximate(field_.mul(e.Y, two_z)) / den;
    if (d.has_approximation) {
      stages.has_mid = true, stages.mid = d.approximation;
      stages.fast = {round_to_fast(stages.mid.re), round_to_fast(stages.mid.im)};
    }
    site_stages_.push_back(stages);
  }
  return site_stages_[std::size_t(site)];
}

const group::ExactLorentz &Kernel::exact_matrix(TranslationId id) {
  if (std::size_t(id) >= exact_matrices_.size()) exact_matrices_.resize(table_.size());
  auto &slot = exact_matrices_.at(id);
  if (!slot) slot = std::make_unique<group::ExactLorentz>(group::exact_lorentz(field_, table_.word(id)));
  return *slot;
}

Kernel::ExactRow Kernel::exact_row(const TranslatedPoint &p) {
  // z = (X + iY)/Z: p^ = (Z^2 + X^2 + Y^2, 2XZ, 2YZ) and w = Z^2 - X^2 - Y^2,
  // both Z^2 times the values for z (a positive factor).
  const exact::CyclotomicField &K = field_.cyclotomic();
  const ExactSite site = p.site >= 0 ? surface_.site(p.site).exact
                                     : ExactSite{field_.from_double(p.x), field_.from_double(p.y),
                                                 field_.from_cyclotomic(K.integer(1))};
  const FieldElement xx = field_.mul(site.X, site.X), yy = field_.mul(site.Y, site.Y);
  const FieldElement zz = field_.mul(site.Z, site.Z), r2 = field_.add(xx, yy);
  const FieldElement two_z = field_.add(site.Z, site.Z);
  const FieldElement hat[3] = {field_.add(zz, r2), field_.mul(site.X, two_z), field_.mul(site.Y, two_z)};
  const group::ExactLorentz &M = exact_matrix(p.translation);
  ExactRow row;
  for (int i = 0; i < 3; ++i) {
    FieldElement sum = field_.zero();
    for (int j = 0; j < 3; ++j) sum = field_.add(sum, field_.mul(M.m[i][j], hat[j]));
    row.v[i] = sum;
  }
  row.v[3] = field_.mul(field_.sub(zz, r2), scale(M.letters));
  return row;
}

const Cyclotomic &Kernel::scale(int letters) {
  // sin(pi/4g)^(2 letters), by repeated multiplication, kept for reuse.
  const exact::CyclotomicField &K = field_.cyclotomic();
  if (scale_powers_.empty()) scale_powers_.push_back(K.integer(1));
  while (int(scale_powers_.size()) <= letters) scale_powers_.push_back(K.mul(scale_powers_.back(), surface_.sin2()));
  return scale_powers_[letters];
}

TranslatedPoint Kernel::site_point(int32_t site, TranslationId translation) const {
  const surface::Site &d = surface_.site(site);
  return {d.x, d.y, translation, site};
}

std::size_t Kernel::cache_slot(const TranslatedPoint &p) {
  uint64_t bits;
  std::memcpy(&bits, &p.x, sizeof bits);
  uint64_t h = bits * 0x9E3779B97F4A7C15ull;
  std::memcpy(&bits, &p.y, sizeof bits);
  h ^= (bits + uint64_t(uint32_t(p.translation)) * 0xC2B2AE3D27D4EB4Full) * 0x165667B19E3779F9ull;
  return h >> (64 - kCacheBits);
}

FilteredPoint Kernel::filtered(const TranslatedPoint &p) {
  auto &c = filtered_cache_[cache_slot(p)];
  if (identical(c.key, p)) return c.point;
  c.point = compute_filtered(p);
  c.key = p;
  return c.point;
}

FilteredPoint Kernel::compute_filtered(const TranslatedPoint &p) {
  if (p.site < 0 && p.translation == 0) return filtered_point(p.x, p.y);
  const group::Lorentz<double> &L = table_.lorentz(p.translation);
  if (p.site < 0) return filtered_point(p.x, p.y, L);
  // A site's hyperboloid vector is stored rounded (4u per entry): apply L
  // (u per entry) with three more roundings.
  const double *n = site_stages(p.site).n;
  FilteredPoint r;
  double worst = 0;
  for (int i = 0; i < 3; ++i) {
    r.n[i] = L.m[i][0] * n[0] + L.m[i][1] * n[1] + L.m[i][2] * n[2];
    worst = std::max(worst, std::abs(L.m[i][0] * n[0]) + std::abs(L.m[i][1] * n[1]) + std::abs(L.m[i][2] * n[2]));
  }
  r.error = 10 * kUnit * worst * 1.01;
  return r;
}

FieldElement Kernel::det3(const std::array<const std::array<FieldElement, 4> *, 3> &rows) const {
  const auto &a = *rows[0], &b = *rows[1], &c = *rows[2];
  auto minor = [&](int i, int j) { return field_.sub(field_.mul(b[i], c[j]), field_.mul(b[j], c[i])); };
  FieldElement r = field_.mul(a[0], minor(1, 2));
  r = field_.sub(r, field_.mul(a[1], minor(0, 2)));
  return field_.add(r, field_.mul(a[2], minor(0, 1)));
}

FieldElement Kernel::det4(const std::array<ExactRow, 4> &rows) const {
  // Laplace expansion along rows 0 and 1: sum over column pairs j < k of
  // (-1)^(j+k+1) minor01(j, k) minor23(the other two columns); 30 products
  // where the expansion along a column takes 40.
  auto minor = [&](int r, int j, int k) {
    return field_.sub(field_.mul(rows[r].v[j], rows[r + 1].v[k]), field_.mul(rows[r].v[k], rows[r + 1].v[j]));
  };
  static constexpr int pairs[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2}, {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  FieldElement r = field_.zero();
  for (const auto &q : pairs) {
    const FieldElement term = field_.mul(minor(0, q[0], q[1]), minor(2, q[2], q[3]));
    r = ((q[0] + q[1]) % 2 == 1) ? field_.add(r, term) : field_.sub(r, term);
  }
  return r;
}

int Kernel::orientation_exact(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r) {
  const ExactRow a = exact_row(p), b = exact_row(q), c = exact_row(r);
  return field_.sign(det3({&a.v, &b.v, &c.v}));
}

int Kernel::in_circle_exact(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r,
                            const TranslatedPoint &s) {
  return field_.sign(det4({exact_row(p), exact_row(q), exact_row(r), exact_row(s)}));
}

int Kernel::beyond_side_exact(const TranslatedPoint &p, int side) {
  // <M_h p^, s^2 e0 - M_k e0>, a positive multiple of <N, O - g_k(O)>.
  const ExactRow row = exact_row(p);
  const group::ExactLorentz &G = surface_.exact_generator(side);
  const FieldElement n0 = field_.sub(field_.from_cyclotomic(surface_.sin2()), G.m[0][0]);
  FieldElement value = field_.mul(row.v[0], n0);
  value = field_.add(value, field_.mul(row.v[1], G.m[1][0]));
  value = field_.add(value, field_.mul(row.v[2], G.m[2][0]));
  return field_.sign(value);
}

int Kernel::orientation_checked(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r) {
  return checked("orientation", orientation_staged(p, q, r), [&] { return orientation_exact(p, q, r); });
}

int Kernel::orientation_staged(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r) {
  if (same_frame(p, q, r)) {
    if (const int s = disk_orientation(p.x, p.y, q.x, q.y, r.x, r.y)) return ++statistics_.filtered, s;
    ++statistics_.exact;
    if (const int s = orientation_fast(stored(p), stored(q), stored(r)); s != 2) return ++statistics_.fast, s;
    return disk_orientation_exact(p.x, p.y, q.x, q.y, r.x, r.y);
  }
  const FilteredPoint a = filtered(p);
  const FilteredPoint b = filtered(q);
  const FilteredPoint c = filtered(r);
  const Difference db = difference(b, a), dc = difference(c, a);
  const Det3 d = det3_filtered(a.n, a.error, db.d, db.error, dc.d, dc.error);
  if (const int s = sign_of(d.value, d.bound)) return ++statistics_.filtered, s;
  // The same description is the same point: a duplicate insertion walks
  // onto its vertex, and these orientations are zero without the exact stage.
  if (identical(p, q) || identical(q, r) || identical(r, p)) return ++statistics_.filtered, 0;
  ++statistics_.exact;
  const TranslatedPoint *points[3] = {&p, &q, &r};
  const FilteredPoint *certified[3] = {&a, &b, &c};
  if (common_zero_coordinate(points, certified, 3)) return ++statistics_.structural, 0;
  if (const int s = orientation_refined(p, q, r); s != 2) return s;
  return orientation_exact(p, q, r);
}

int Kernel::in_circle_filter(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r,
                             const TranslatedPoint &s) {
  if (same_frame(p, q, r, s))
    if (const int sg = disk_in_circle(p.x, p.y, q.x, q.y, r.x, r.y, s.x, s.y))
      return ++statistics_.filtered, sg;
  const FilteredPoint a = filtered(p);
  const FilteredPoint b = filtered(q);
  const FilteredPoint c = filtered(r);
  const FilteredPoint e = filtered(s);
  const Difference db = difference(b, a), dc = difference(c, a), de = difference(e, a);
  // det[N 1] = -det[N_q - N_p; N_r - N_p; N_s - N_p].
  const Det3 d = det3_filtered(db.d, db.error, dc.d, dc.error, de.d, de.error);
  if (const int sg = sign_of(d.value, d.bound)) return ++statistics_.filtered, -sg;
  ++statistics_.exact;
  const TranslatedPoint *points[4] = {&p, &q, &r, &s};
  const FilteredPoint *certified[4] = {&a, &b, &c, &e};
  if (common_zero_coordinate(points, certified, 4)) return ++statistics_.structural, 0;
  return in_circle_refined(p, q, r, s);
}

int Kernel::in_circle(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r,
                      const TranslatedPoint &s) {
  const int sg = in_circle_filter(p, q, r, s);
  if (sg == 2 && same_frame(p, q, r, s)) return disk_in_circle_exact(p.x, p.y, q.x, q.y, r.x, r.y, s.x, s.y);
  if (sg == 2) return in_circle_exact(p, q, r, s);
  return checked("in_circle", sg, [&] { return in_circle_exact(p, q, r, s); });
}

int Kernel::in_circle_perturbed_staged(const std::array<TranslatedPoint, 4> &pt,
                                       const std::array<uint32_t, 4> &vertex) {
  if (same_frame(pt[0], pt[1], pt[2], pt[3])) {
    // Points in one frame: the disk filter, then the exact disk stage.
    if (const int s = disk_in_circle(pt[0].x, pt[0].y, pt[1].x, pt[1].y, pt[2].x, pt[2].y, pt[3].x, pt[3].y))
      return ++statistics_.filtered,
             checked("in_circle_perturbed", s, [&] { return in_circle_exact(pt[0], pt[1], pt[2], pt[3]); });
    ++statistics_.exact;
    if (const int s = in_circle_fast(stored(pt[0]), stored(pt[1]), stored(pt[2]), stored(pt[3])); s != 2)
      return ++statistics_.fast,
             checked("in_circle_perturbed", s, [&] { return in_circle_exact(pt[0], pt[1], pt[2], pt[3]); });
    const int s = disk_in_circle_exact(pt[0].x, pt[0].y, pt[1].x, pt[1].y, pt[2].x, pt[2].y, pt[3].x, pt[3].y);
    if (s != 0) return checked("in_circle_perturbed", s, [&] { return in_circle_exact(pt[0], pt[1], pt[2], pt[3]); });
    return perturbed_tie(pt, vertex, nullptr);
  }
  if (const int s = in_circle_filter(pt[0], pt[1], pt[2], pt[3]); s != 2) {
    checked("in_circle_perturbed", s, [&] { return in_circle_exact(pt[0], pt[1], pt[2], pt[3]); });
    if (s != 0) return s;
    return perturbed_tie(pt, vertex, nullptr);  // a structural zero (structural_zero.cpp)
  }
  const std::array<ExactRow, 4> rows{exact_row(pt[0]), exact_row(pt[1]), exact_row(pt[2]), exact_row(pt[3])};
  if (const int s = field_.sign(det4(rows))) return s;
  return perturbed_tie(pt, vertex, &rows);
}

int Kernel::perturbed_tie(const std::array<TranslatedPoint, 4> &pt, const std::array<uint32_t, 4> &vertex,
                          const std::array<ExactRow, 4> *rows) {
  // Cocircular: the coefficient of eps_v is the sum over v's rows r of
  // (-1)^(r+1) v_r3 cofactor(r, 3) of the exact matrix. For a vertex in one
  // row that is (-1)^(r+1) times a positive multiple of the orientation of
  // the other three points (the rows are positive multiples of (N, 1)): a
  // filtered predicate, no field arithmetic.
  std::array<uint32_t, 4> order = vertex;
  std::sort(order.begin(), order.end(), std::greater<uint32_t>());
  for (int k = 0; k < 4; ++k) {
    if (k > 0 && order[k] == order[k - 1]) continue;
    int rows_of_vertex = 0, row = -1;
    for (int r = 0; r < 4; ++r)
      if (vertex[r] == order[k]) ++rows_of_vertex, row = r;
    int s;
    if (rows_of_vertex == 1) {
      std::array<TranslatedPoint, 3> others;
      for (int i = 0, j = 0; i < 4; ++i)
        if (i != row) others[j++] = pt[i];
      s = (row % 2 == 1 ? 1 : -1) * orientation(others[0], others[1], others[2]);
    } else {
      std::array<ExactRow, 4> computed;
      if (!rows) {
        computed = {exact_row(pt[0]), exact_row(pt[1]), exact_row(pt[2]), exact_row(pt[3])};
        rows = &computed;
      }
      s = field_.sign(perturbation_coefficient(*rows, vertex, order[k]));
    }
    if (s) return s;
  }
  throw std::logic_error(
      "in_circle_perturbed: every perturbation coefficient vanishes (points on one geodesic, or each vertex "
      "repeated)");
}

FieldElement Kernel::perturbation_coefficient(const std::array<ExactRow, 4> &rows, const std::array<uint32_t, 4> &vertex,
                                              uint32_t v) const {
  FieldElement coefficient = field_.zero();
  for (int r = 0; r < 4; ++r) {
    if (vertex[r] != v) continue;
    std::array<const std::array<FieldElement, 4> *, 3> others;
    for (int i = 0, j = 0; i < 4; ++i)
      if (i != r) others[j++] = &rows[i].v;
    const FieldElement term = field_.mul(rows[r].v[3], det3(others));
    coefficient = (r % 2 == 1) ? field_.add(coefficient, term) : field_.sub(coefficient, term);
  }
  return coefficient;
}

void Kernel::beyond_sides(const TranslatedPoint &p, int *signs) {
  const FilteredPoint a = filtered(p);
  for (int k = 0; k < surface_.side_count(); ++k) signs[k] = beyond_side_filtered(a, k, p);
}

int Kernel::beyond_side(const TranslatedPoint &p, int side) { return beyond_side_filtered(filtered(p), side, p); }

int Kernel::beyond_side_filtered(const FilteredPoint &a, int side, const TranslatedPoint &p) {
  const auto &n = surface_.side_normal(side);
  // <N, n> with the Minkowski signs folded into n (n = (1 - Q0, Q1, Q2)).
  const double value = a.n[0] * n[0] + a.n[1] * n[1] + a.n[2] * n[2];
  const double size = std::abs(a.n[0] * n[0]) + std::abs(a.n[1] * n[1]) + std::abs(a.n[2] * n[2]);
  const double norm = std::abs(n[0]) + std::abs(n[1]) + std::abs(n[2]);
  // n is rounded (u per entry, 1 - Q0 one more), the sum rounds 3u.
  const double bound = (8 * kUnit * size + a.error * norm * (1 + 4 * kUnit)) * 1.01;
  if (const int s = sign_of(value, bound))
    return ++statistics_.filtered, checked("beyond_side", s, [&] { return beyond_side_exact(p, side); });
  ++statistics_.exact;
  return beyond_side_exact(p, side);
}

int Kernel::compare_distance_exact(const TranslatedPoint &p, const TranslatedPoint &a, const TranslatedPoint &b) {
  // cosh d(p, a) = <N_p, N_a> = <r_p, r_a> / (r_p3 r_a3) for the exact rows r
  // (r_3 > 0), so the sign is that of <r_p, r_a> r_b3 - <r_p, r_b> r_a3.
  const ExactRow rp = exact_row(p), ra = exact_row(a), rb = exact_row(b);
  auto minkowski = [&](const ExactRow &u, const ExactRow &v) {
    return field_.sub(field_.mul(u.v[0], v.v[0]), field_.add(field_.mul(u.v[1], v.v[1]), field_.mul(u.v[2], v.v[2])));
  };
  return field_.sign(field_.sub(field_.mul(minkowski(rp, ra), rb.v[3]), field_.mul(minkowski(rp, rb), ra.v[3])));
}

int Kernel::compare_distance(const TranslatedPoint &p, const TranslatedPoint &a, const TranslatedPoint &b) {
  const FilteredPoint fp = filtered(p), fa = filtered(a), fb = filtered(b);
  const Difference d = difference(fa, fb);
  // <N_p, N_a - N_b>; cosh is increasing, so its sign is the answer.
  const double value = fp.n[0] * d.d[0] - fp.n[1] * d.d[1] - fp.n[2] * d.d[2];
  const double size = std::abs(fp.n[0] * d.d[0]) + std::abs(fp.n[1] * d.d[1]) + std::abs(fp.n[2] * d.d[2]);
  const double bound = (3 * (fp.error * (max_abs3(d.d) + d.error) + (max_abs3(fp.n) + fp.error) * d.error) +
                        4 * kUnit * size) * 1.01;
  if (const int s = sign_of(value, bound))
    return ++statistics_.filtered, checked("compare_distance", s, [&] { return compare_distance_exact(p, a, b); });
  ++statistics_.exact;
  return compare_distance_exact(p, a, b);
}

bool Kernel::same_point_exact(const TranslatedPoint &p, const TranslatedPoint &q) {
  // The rows are positive multiples of (N, 1): equal points have
  // proportional rows, P_i Q_3 = Q_i P_3.
  const ExactRow a = exact_row(p), b = exact_row(q);
  for (int i = 0; i < 3; ++i)
    if (!field_.is_zero(field_.sub(field_.mul(a.v[i], b.v[3]), field_.mul(b.v[i], a.v[3])))) return false;
  return true;
}

bool Kernel::same_point(const TranslatedPoint &p, const TranslatedPoint &q) {
  if (p.site == q.site && p.translation == q.translation && p.x == q.x && p.y == q.y) return true;
  const FilteredPoint a = filtered(p), b = filtered(q);
  for (int i = 0; i < 3; ++i)
    if (std::abs(a.n[i] - b.n[i]) > (a.error + b.error) * (1 + 4 * kUnit) + kUnit * std::abs(a.n[i] - b.n[i]))
      return ++statistics_.filtered, checked("same_point", false, [&] { return same_point_exact(p, q); });
  ++statistics_.exact;
  return same_point_exact(p, q);
}

int Kernel::large_circumdisk_exact(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r) {
  // The plane c . (X, 1) = 0 through the three rows: c_j = (-1)^j times the
  // minor without column j. Rows are positive multiples of (N, 1), so c is a
  // positive multiple of the plane of the normalised points.
  const std::array<ExactRow, 3> rows{exact_row(p), exact_row(q), exact_row(r)};
  std::array<FieldElement, 4> c;
  for (int skip = 0; skip < 4; ++skip) {
    std::array<std::array<FieldElement, 4>, 3> minor;  // the 3 columns other than skip, padded
    for (int i = 0; i < 3; ++i)
      for (int j = 0, k = 0; j < 4; ++j)
        if (j != skip) minor[i][k++] = rows[i].v[j];
    const FieldElement d = det3({&minor[0], &minor[1], &minor[2]});
    c[skip] = skip % 2 == 0 ? d : field_.neg(d);
  }
  const FieldElement mm =
      field_.sub(field_.mul(c[0], c[0]), field_.add(field_.mul(c[1], c[1]), field_.mul(c[2], c[2])));
  if (field_.sign(mm) <= 0) return 1;  // not a circle: unbounded
  const FieldElement &k = surface_.quarter_systole_cosh2();  // 1 + cos(pi/2g)
  return field_.sign(field_.sub(field_.mul(c[3], c[3]), field_.mul(k, mm))) >= 0 ? 1 : -1;
}

int Kernel::large_circumdisk(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r) {
  return checked("large_circumdisk", large_circumdisk_staged(p, q, r),
                 [&] { return large_circumdisk_exact(p, q, r); });
}

int Kernel::large_circumdisk_staged(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r) {
  const FilteredPoint a = filtered(p), b = filtered(q), e = filtered(r);
  const Difference d2 = difference(b, a), d3 = difference(e, a);
  const double m2 = max_abs3(d2.d) + d2.error, m3 = max_abs3(d3.d) + d3.error;
  // c = d2 x d3 (Euclidean cross product): each entry is two products.
  const double c[3] = {d2.d[1] * d3.d[2] - d2.d[2] * d3.d[1], d2.d[2] * d3.d[0] - d2.d[0] * d3.d[2],
                       d2.d[0] * d3.d[1] - d2.d[1] * d3.d[0]};
  const double ec = 2 * (d2.error * m3 + m2 * d3.error) + 4 * kUnit * m2 * m3;
  const double cmax = max_abs3(c) + ec;
  // c_3 = -c . N_a.
  const double c3 = -(c[0] * a.n[0] + c[1] * a.n[1] + c[2] * a.n[2]);
  const double amax = max_abs3(a.n) + a.error;
  const double e3 = 3 * (ec * amax + cmax * a.error) + 4 * kUnit * 3 * cmax * amax;
  const double c3max = std::abs(c3) + e3;
  // <m, m> = c0^2 - c1^2 - c2^2 and Q = c3^2 - k <m, m>, k = 1 + cos(pi/2g) in [1, 2].
  const double mm = c[0] * c[0] - c[1] * c[1] - c[2] * c[2];
  const double emm = 3 * (2 * cmax * ec) + 6 * kUnit * 3 * cmax * cmax;
  const double k = surface::quarter_systole_cosh2<double>(surface_.genus());  // within 4u of the exact value
  const double Q = c3 * c3 - k * mm;
  const double eQ = 2 * c3max * e3 + 2 * emm + 8 * kUnit * k * 3 * cmax * cmax + 4 * kUnit * c3max * c3max;
  const double bound_mm = emm * 1.01, bound_Q = eQ * 1.01;
  if (mm < -bound_mm) return ++statistics_.filtered, 1;
  if (mm > bound_mm && std::abs(Q) > bound_Q) return ++statistics_.filtered, Q > 0 ? 1 : -1;
  ++statistics_.exact;
  if (const int s = large_circumdisk_refined(p, q, r); s != 2) return s;
  return large_circumdisk_exact(p, q, r);
}

}  // namespace hdt::predicates
