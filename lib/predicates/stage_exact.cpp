#include "predicates/stage_exact.hpp"

namespace hdt::predicates {

using exact::Cyclotomic;
using exact::FieldElement;

ExactStage::ExactStage(surface::Surface &surface) : surface_(surface), field_(surface.field()) {}

const group::ExactLorentz &ExactStage::matrix(TranslationId id) {
  group::TranslationTable &table = surface_.table();
  if (std::size_t(id) >= matrices_.size()) matrices_.resize(table.size());
  auto &slot = matrices_.at(id);
  if (!slot) slot = std::make_unique<group::ExactLorentz>(group::exact_lorentz(field_, table.word(id)));
  return *slot;
}

ExactStage::Row ExactStage::row(const TranslatedPoint &p) {
  // z = (X + iY)/Z: p^ = (Z^2 + X^2 + Y^2, 2XZ, 2YZ) and w = Z^2 - X^2 - Y^2,
  // both Z^2 times the values for z (a positive factor).
  const exact::CyclotomicField &K = field_.cyclotomic();
  const surface::ExactSite site =
      p.site >= 0 ? *surface_.site(p.site).exact
                  : surface::ExactSite{field_.from_double(p.x), field_.from_double(p.y),
                                       field_.from_cyclotomic(K.integer(1))};
  const FieldElement xx = field_.mul(site.X, site.X), yy = field_.mul(site.Y, site.Y);
  const FieldElement zz = field_.mul(site.Z, site.Z), r2 = field_.add(xx, yy);
  const FieldElement two_z = field_.add(site.Z, site.Z);
  const FieldElement hat[3] = {field_.add(zz, r2), field_.mul(site.X, two_z), field_.mul(site.Y, two_z)};
  const group::ExactLorentz &M = matrix(p.translation);
  Row row;
  for (int i = 0; i < 3; ++i) {
    FieldElement sum = field_.zero();
    for (int j = 0; j < 3; ++j) sum = field_.add(sum, field_.mul(M.m[i][j], hat[j]));
    row.v[i] = sum;
  }
  row.v[3] = field_.mul(field_.sub(zz, r2), scale(M.letters));
  return row;
}

const Cyclotomic &ExactStage::scale(int letters) {
  // sin(pi/4g)^(2 letters), by repeated multiplication, kept for reuse.
  const exact::CyclotomicField &K = field_.cyclotomic();
  if (scale_powers_.empty()) scale_powers_.push_back(K.integer(1));
  while (int(scale_powers_.size()) <= letters) scale_powers_.push_back(K.mul(scale_powers_.back(), surface_.sin2()));
  return scale_powers_[letters];
}

FieldElement ExactStage::det3(const std::array<const std::array<FieldElement, 4> *, 3> &rows) const {
  const auto &a = *rows[0], &b = *rows[1], &c = *rows[2];
  auto minor = [&](int i, int j) { return field_.sub(field_.mul(b[i], c[j]), field_.mul(b[j], c[i])); };
  FieldElement r = field_.mul(a[0], minor(1, 2));
  r = field_.sub(r, field_.mul(a[1], minor(0, 2)));
  return field_.add(r, field_.mul(a[2], minor(0, 1)));
}

FieldElement ExactStage::det4(const std::array<Row, 4> &rows) const {
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

Sign ExactStage::orientation(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r) {
  const Row a = row(p), b = row(q), c = row(r);
  return field_sign(det3({&a.v, &b.v, &c.v}));
}

Sign ExactStage::beyond_side(const TranslatedPoint &p, int side) {
  // <M_h p^, s^2 e0 - M_k e0>, a positive multiple of <N, O - g_k(O)>.
  const Row r = row(p);
  const group::ExactLorentz &G = surface_.exact_generator(side);
  const FieldElement n0 = field_.sub(field_.from_cyclotomic(surface_.sin2()), G.m[0][0]);
  FieldElement value = field_.mul(r.v[0], n0);
  value = field_.add(value, field_.mul(r.v[1], G.m[1][0]));
  value = field_.add(value, field_.mul(r.v[2], G.m[2][0]));
  return field_sign(value);
}

Sign ExactStage::compare_distance(const TranslatedPoint &p, const TranslatedPoint &a, const TranslatedPoint &b) {
  // cosh d(p, a) = <N_p, N_a> = <r_p, r_a> / (r_p3 r_a3) for the exact rows r
  // (r_3 > 0), so the sign is that of <r_p, r_a> r_b3 - <r_p, r_b> r_a3.
  const Row rp = row(p), ra = row(a), rb = row(b);
  auto minkowski = [&](const Row &u, const Row &v) {
    return field_.sub(field_.mul(u.v[0], v.v[0]), field_.add(field_.mul(u.v[1], v.v[1]), field_.mul(u.v[2], v.v[2])));
  };
  return field_sign(field_.sub(field_.mul(minkowski(rp, ra), rb.v[3]), field_.mul(minkowski(rp, rb), ra.v[3])));
}

Sign ExactStage::distinct(const TranslatedPoint &p, const TranslatedPoint &q) {
  // The rows are positive multiples of (N, 1): equal points have
  // proportional rows, P_i Q_3 = Q_i P_3.
  const Row a = row(p), b = row(q);
  for (int i = 0; i < 3; ++i)
    if (!field_.is_zero(field_.sub(field_.mul(a.v[i], b.v[3]), field_.mul(b.v[i], a.v[3])))) return Sign::positive;
  return Sign::zero;
}

Sign ExactStage::large_circumdisk(const TranslatedPoint &p, const TranslatedPoint &q, const TranslatedPoint &r) {
  // The plane c . (X, 1) = 0 through the three rows: c_j = (-1)^j times the
  // minor without column j. Rows are positive multiples of (N, 1), so c is a
  // positive multiple of the plane of the normalised points.
  const std::array<Row, 3> rows{row(p), row(q), row(r)};
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
  if (field_.sign(mm) != Sign::positive) return Sign::positive;  // not a circle: unbounded
  const FieldElement &k = surface_.quarter_systole_cosh2();  // 1 + cos(pi/2g)
  return field_.sign(field_.sub(field_.mul(c[3], c[3]), field_.mul(k, mm))) != Sign::negative ? Sign::positive
                                                                                      : Sign::negative;
}

Sign ExactStage::perturbation_coefficient(const std::array<Row, 4> &rows, const std::array<uint32_t, 4> &vertex,
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
  return field_sign(coefficient);
}

}  // namespace hdt::predicates
