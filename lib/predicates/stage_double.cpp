#include "predicates/stage_double.hpp"

#include "group/lorentz.hpp"
#include "predicates/stage_refined.hpp"
#include "surface/systole.hpp"

namespace hdt::predicates {

FilteredPoint DoubleStage::compute_point(const TranslatedPoint &p) {
  if (p.site < 0 && p.translation == 0) return filtered_point(p.x, p.y);
  if (p.site < 0) {
    if (const surface::HomeImage *image = surface_.home_image(p.x, p.y)) return image_point(p, *image);
    return filtered_point(p.x, p.y, surface_.table().moebius(p.translation));
  }
  const group::Lorentz<double> &L = surface_.table().lorentz(p.translation);
  // A site's hyperboloid vector is stored rounded (4u per entry): apply L
  // (u per entry) with three more roundings.
  const std::array<double, 3> &n = surface_.site(p.site).vector;
  FilteredPoint r;
  double worst = 0;
  for (int i = 0; i < 3; ++i) {
    r.n[i] = L.m[i][0] * n[0] + L.m[i][1] * n[1] + L.m[i][2] * n[2];
    worst = std::max(worst, std::abs(L.m[i][0] * n[0]) + std::abs(L.m[i][1] * n[1]) + std::abs(L.m[i][2] * n[2]));
  }
  r.error = 10 * kUnit * worst * 1.01;
  return r;
}

FilteredPoint DoubleStage::image_point(const TranslatedPoint &p, const surface::HomeImage &image) {
  // p's point is s(h(z)), s = t h^-1, from h(z)'s vector (each entry within
  // vector_error): L_s moves those errors by at most its row sums; its own
  // error and the three roundings stay within the sites' 10u (above).
  group::TranslationTable &table = surface_.table();
  const group::Lorentz<double> &L = table.lorentz(table.compose(p.translation, image.home_inverse));
  const std::array<double, 3> &n = image.vector;
  FilteredPoint r;
  double worst = 0, row = 0;
  for (int i = 0; i < 3; ++i) {
    r.n[i] = L.m[i][0] * n[0] + L.m[i][1] * n[1] + L.m[i][2] * n[2];
    worst = std::max(worst, std::abs(L.m[i][0] * n[0]) + std::abs(L.m[i][1] * n[1]) + std::abs(L.m[i][2] * n[2]));
    row = std::max(row, std::abs(L.m[i][0]) + std::abs(L.m[i][1]) + std::abs(L.m[i][2]));
  }
  r.error = (10 * kUnit * worst + row * image.vector_error) * 1.01;
  return r;
}

namespace {

// The point in the disk, z = (N1, N2) / (1 + N0), and the error of each
// coordinate: N within e moves the quotient by at most 2e / (1 + N0)
// (|N_i| <= N0), and its two roundings by 2u |z| < 2u. About the relative
// error of N (e / N0), whatever N's size: near the circle the disk's
// determinants keep what the hyperboloid's lose (stage_double.hpp).
struct DiskPoint {
  double x, y, error;
};
DiskPoint disk_point(const FilteredPoint &p) {
  const double d = 1 + p.n[0];
  return {p.n[1] / d, p.n[2] / d, 2.02 * p.error / d + 2.01 * kUnit};
}

}  // namespace

// Both: the disk stage's value and its rounding bound (12u of the
// permanent, for the exact determinant at the computed coordinates), plus
// how far the exact determinant moves when the coordinates move by their
// errors: each difference q - a by eta <= e_q + e_a, so each |d|^2 by
// 2 (X + Y) eta, with X, Y bounds on the differences' x and y parts.
Sign DoubleStage::disk_in_circle(const FilteredPoint &fa, const FilteredPoint &fb, const FilteredPoint &fc,
                                 const FilteredPoint &fe) {
  const DiskPoint a = disk_point(fa), b = disk_point(fb), c = disk_point(fc), e = disk_point(fe);
  const double eta = (std::max(std::max(b.error, c.error), e.error) + a.error) * (1 + kUnit);
  if (!(eta < 1e-3)) return Sign::undecided;  // also NaN
  const DiskDeterminant d = disk_in_circle_determinant(a.x, a.y, b.x, b.y, c.x, c.y, e.x, e.y);
  // The differences again, for the bound.
  const double bdx = b.x - a.x, bdy = b.y - a.y, cdx = c.x - a.x, cdy = c.y - a.y;
  const double edx = e.x - a.x, edy = e.y - a.y;
  const double lb = bdx * bdx + bdy * bdy, lc = cdx * cdx + cdy * cdy, le = edx * edx + edy * edy;
  // Rows (dx, dy, |d|^2): each of the 6 products of the expansion takes one
  // entry of each column and moves by at most eta Y L + X eta L +
  // X Y 2 (X + Y) eta.
  const double X = std::max(std::max(std::abs(bdx), std::abs(cdx)), std::abs(edx)) * 1.01 + eta;
  const double Y = std::max(std::max(std::abs(bdy), std::abs(cdy)), std::abs(edy)) * 1.01 + eta;
  const double L = std::max(std::max(lb, lc), le) * 1.01 + 2 * (X + Y) * eta;
  const double input = 6 * eta * (X + Y) * (L + 2 * X * Y);
  return sign_of(-d.value, (12 * kUnit * d.permanent + input) * 1.02);
}

Sign DoubleStage::disk_orientation(const FilteredPoint &fa, const FilteredPoint &fb, const FilteredPoint &fc) {
  const DiskPoint a = disk_point(fa), b = disk_point(fb), c = disk_point(fc);
  const double ea = a.error, eta = (std::max(b.error, c.error) + ea) * (1 + kUnit);
  if (!(eta < 1e-3)) return Sign::undecided;  // also NaN
  const DiskDeterminant d = disk_orientation_determinant(a.x, a.y, b.x, b.y, c.x, c.y);
  const double ax = a.x, ay = a.y;
  const double bdx = b.x - ax, bdy = b.y - ay, cdx = c.x - ax, cdy = c.y - ay;
  const double wa = 1 - (ax * ax + ay * ay);
  const double lb = bdx * bdx + bdy * bdy, lc = cdx * cdx + cdy * cdy;
  // Rows (w_a, a_x, a_y), (|d|^2, dx, dy) for b and c. a moves by ea: w_a
  // by at most 3 ea (|a| <= 1 + ea), |a_x| + |a_y| stays below A. The
  // term w_a (bdx cdy - cdx bdy) moves by 3 ea 2 X Y + W 2 eta (X + Y); each
  // of the two curvature terms |d|^2 (a_x dy - a_y dx) by
  // 2 (X + Y) eta A (X + Y) + Lm (ea (X + Y) + 2 A eta).
  const double X = std::max(std::abs(bdx), std::abs(cdx)) * 1.01 + eta;
  const double Y = std::max(std::abs(bdy), std::abs(cdy)) * 1.01 + eta;
  const double Lm = std::max(lb, lc) * 1.01 + 2 * (X + Y) * eta;
  const double A = (std::abs(ax) + std::abs(ay)) * 1.01 + 2 * ea;
  const double W = std::abs(wa) + 3.01 * kUnit + 3 * ea;
  const double input = 6 * ea * X * Y + 2 * W * eta * (X + Y) +
                       2 * (2 * (X + Y) * eta * A * (X + Y) + Lm * (ea * (X + Y) + 2 * A * eta));
  return sign_of(d.value, (12 * kUnit * d.permanent + input) * 1.02);
}

Sign DoubleStage::large_circumdisk(const FilteredPoint &a, const FilteredPoint &b, const FilteredPoint &c) const {
  auto as_refined = [](const FilteredPoint &f) { return RefinedPoint<double>{{f.n[0], f.n[1], f.n[2]}, f.error}; };
  // k within 4u of the exact value, computed once, not a cos per face: a
  // load tests every face.
  return refined::large_circumdisk_sign(as_refined(a), as_refined(b), as_refined(c), quarter_systole_cosh2_, kUnit);
}

}  // namespace hdt::predicates
