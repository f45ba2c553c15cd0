// The disk-filter stage: double filters for untranslated points: points given as themselves
// (translation 0, no site), whose coordinates are exact doubles. Their
// hyperboloid determinants reduce to small determinants of disk coordinates,
// with no division and no matrix. This is the common case inside F_g (nine
// in-circle tests of ten at genus 2), so the filters are inline and their
// error bounds static: a constant times a permanent, as in Shewchuk's
// predicates, derived below for these determinants.
#pragma once

#include <cmath>

#include "predicates/filtered_point.hpp"
#include "predicates/sign.hpp"

namespace hdt::predicates {

// The error bounds assume no underflow. Where a bound is relative only (the
// filters below, built from the exact inputs), a square or product that
// underflows errs by up to 2^-1075 absolutely instead; with entries below 8
// the few dozen such errors of a determinant stay far below
// kUnderflowAllowance, which every decision also requires. (Points with
// subnormal coordinates near the origin decided in_circle wrongly without
// it; found by fuzzing.) Elsewhere the bounds are above 2^-150 and the
// allowance changes nothing.
constexpr double kUnderflowAllowance = 0x1p-1000;

// +1 or -1 when |value| exceeds the bound, else undecided.
inline Sign sign_of(double value, double bound) { return sign_beyond(value, bound + kUnderflowAllowance); }

// Rounding analysis shared by both filters: every difference, product and
// sum is one rounding (a factor 1 + d, |d| <= u). Expanded into monomials of
// the exact inputs, the computed determinant is the sum of the monomials each
// times at most k such factors, k the longest chain of roundings, so it errs
// by at most ((1 + u)^k - 1) times the sum of the monomials' magnitudes; the
// computed permanent (that sum, evaluated in double) is within (1 + u)^k of
// it. For k <= 11 and u = 2^-53, 12u of the computed permanent bounds the
// error.

// Sign of the hyperbolic orientation of untranslated a, b, c, or undecided.
//
// det[N_a; N_b; N_c] is a positive multiple of det of the rows (1 + s, x, y)
// (s = x^2 + y^2); subtracting row a and then 2x and 2y times the last two
// columns from the first gives the rows (1 - s_a, a_x, a_y) and (l, dx, dy)
// for b and c, with d = q - a and l = |d|^2. Expanded along the first
// column: w_a (Euclidean orientation) minus curvature terms of order |d|^3.
// Chains: w_a = 1 - s_a errs by at most 3.01u absolutely (s_a < 1); the
// monomials w_a dx dy take at most 7 more roundings, so err by at most
// (3.01u + 7.01u w_a) |dx dy| <= 10.1u |dx dy| (w_a <= 1); the monomials
// l a_x dy take 10.
// The determinant and the permanent that bounds its rounding, shared with
// the double stage's disk determinants of inexact points.
struct DiskDeterminant {
  double value, permanent;
};
// Always inlined: a call here cost the insertion at genus 2 0.13% more
// instructions (callgrind).
[[gnu::always_inline]] inline DiskDeterminant disk_orientation_determinant(double ax, double ay, double bx, double by,
                                                                           double cx, double cy) {
  const double bdx = bx - ax, bdy = by - ay, cdx = cx - ax, cdy = cy - ay;
  const double wa = 1 - (ax * ax + ay * ay);
  const double lb = bdx * bdx + bdy * bdy, lc = cdx * cdx + cdy * cdy;
  const double p1 = bdx * cdy, p2 = cdx * bdy;  // w_a's minor
  const double q1 = ax * cdy, q2 = ay * cdx;    // l_b's minor
  const double r1 = ax * bdy, r2 = ay * bdx;    // l_c's minor
  return {(wa * (p1 - p2) - lb * (q1 - q2)) + lc * (r1 - r2),
          (std::abs(p1) + std::abs(p2)) + lb * (std::abs(q1) + std::abs(q2)) + lc * (std::abs(r1) + std::abs(r2))};
}
inline Sign disk_orientation(double ax, double ay, double bx, double by, double cx, double cy) {
  const DiskDeterminant d = disk_orientation_determinant(ax, ay, bx, by, cx, cy);
  return sign_of(d.value, 12 * kUnit * d.permanent);
}

// Sign of det[N 1] (in_circle: +1 when e is inside the circle through a, b,
// c counterclockwise) of untranslated points, or undecided.
//
// det[N 1] is a negative multiple of det of the rows (dx, dy, s_q - s_a) for
// q = b, c, e and d = q - a, and s_q - s_a = |d|^2 + 2 a.d differs from the
// lift l = |d|^2 by a combination of the other two columns: the Euclidean
// in-circle determinant (hyperbolic circles of the disk are Euclidean
// circles). Chains: the lifts take 4 roundings, the minors 4, their product
// 1, the two sums 2: k = 11.
[[gnu::always_inline]] inline DiskDeterminant disk_in_circle_determinant(double ax, double ay, double bx, double by,
                                                                         double cx, double cy, double ex, double ey) {
  const double bdx = bx - ax, bdy = by - ay, cdx = cx - ax, cdy = cy - ay, edx = ex - ax, edy = ey - ay;
  const double lb = bdx * bdx + bdy * bdy, lc = cdx * cdx + cdy * cdy, le = edx * edx + edy * edy;
  const double ce1 = cdx * edy, ce2 = edx * cdy;
  const double eb1 = edx * bdy, eb2 = bdx * edy;
  const double bc1 = bdx * cdy, bc2 = cdx * bdy;
  return {(lb * (ce1 - ce2) + lc * (eb1 - eb2)) + le * (bc1 - bc2),
          (lb * (std::abs(ce1) + std::abs(ce2)) + lc * (std::abs(eb1) + std::abs(eb2))) +
              le * (std::abs(bc1) + std::abs(bc2))};
}
inline Sign disk_in_circle(double ax, double ay, double bx, double by, double cx, double cy, double ex,
                          double ey) {
  const DiskDeterminant d = disk_in_circle_determinant(ax, ay, bx, by, cx, cy, ex, ey);
  return sign_of(-d.value, 12 * kUnit * d.permanent);  // -value: exact, and undecided stays undecided
}

}  // namespace hdt::predicates
