#include "predicates/stage_disk_exact.hpp"

#include <gmp.h>

#include <algorithm>
#include <climits>
#include <cmath>

namespace hdt::predicates {

namespace {

// GMP integers kept per thread, so that after the first calls no
// evaluation allocates (these run once per degenerate test, often).
struct Scratch {
  enum { kCoordinates = 8, kTemporaries = 12 };
  mpz_t x[kCoordinates], t[kTemporaries];
  Scratch() {
    for (auto &z : x) mpz_init2(z, 128);
    for (auto &z : t) mpz_init2(z, 512);
  }
  ~Scratch() {
    for (auto &z : x) mpz_clear(z);
    for (auto &z : t) mpz_clear(z);
  }
  Scratch(const Scratch &) = delete;
  Scratch &operator=(const Scratch &) = delete;
};

Scratch &scratch() {
  thread_local Scratch s;
  return s;
}

// Sets x[i] to the integer coordinates[i] 2^-exponent and returns the
// exponent: the least power of two of which every coordinate is an integer
// multiple (a non-zero double is m 2^(e - 53) with an integer |m| < 2^53).
long scale(const double *coordinates, int n, mpz_t *x) {
  long low = LONG_MAX;
  for (int i = 0; i < n; ++i) {
    if (coordinates[i] == 0) continue;
    int e;
    std::frexp(coordinates[i], &e);
    low = std::min(low, long(e) - 53);
  }
  if (low == LONG_MAX) low = 0;
  for (int i = 0; i < n; ++i) {
    int e;
    const double f = std::frexp(coordinates[i], &e);  // 0 for 0
    mpz_set_d(x[i], std::ldexp(f, 53));                // an integer, exactly
    if (coordinates[i] != 0) mpz_mul_2exp(x[i], x[i], mp_bitcnt_t(long(e) - 53 - low));
  }
  return low;
}

// r = a b - c d.
void cross(mpz_t r, const mpz_t a, const mpz_t b, const mpz_t c, const mpz_t d, mpz_t tmp) {
  mpz_mul(r, a, b);
  mpz_mul(tmp, c, d);
  mpz_sub(r, r, tmp);
}

// r = a^2 + b^2.
void lift(mpz_t r, const mpz_t a, const mpz_t b, mpz_t tmp) {
  mpz_mul(r, a, a);
  mpz_mul(tmp, b, b);
  mpz_add(r, r, tmp);
}

}  // namespace

Sign disk_orientation_exact(double ax, double ay, double bx, double by, double cx, double cy) {
  Scratch &s = scratch();
  const double coordinates[6] = {ax, ay, bx, by, cx, cy};
  const long exponent = scale(coordinates, 6, s.x);
  mpz_t *x = s.x, *t = s.t;
  // Differences d = q - a for q = b (t0, t1) and c (t2, t3).
  mpz_sub(t[0], x[2], x[0]), mpz_sub(t[1], x[3], x[1]);
  mpz_sub(t[2], x[4], x[0]), mpz_sub(t[3], x[5], x[1]);
  // disk_orientation's value (1 - |a|^2) P - l_b Q + l_c R is, with
  // S = 2^exponent and the integer minors below, S^2 (P - S^2 T) where
  // T = |a|^2 P + l_b Q - l_c R.
  cross(t[4], t[0], t[3], t[2], t[1], t[11]);  // P
  cross(t[5], x[0], t[3], x[1], t[2], t[11]);  // Q
  cross(t[6], x[0], t[1], x[1], t[0], t[11]);  // R
  lift(t[7], x[0], x[1], t[11]);
  mpz_mul(t[8], t[7], t[4]);  // |a|^2 P
  lift(t[7], t[0], t[1], t[11]);
  mpz_addmul(t[8], t[7], t[5]);  // + l_b Q
  lift(t[7], t[2], t[3], t[11]);
  mpz_submul(t[8], t[7], t[6]);  // - l_c R
  // sign(P - 2^(2 exponent) T), without fractions.
  const long k = -2 * exponent;
  if (k >= 0) {
    mpz_mul_2exp(t[4], t[4], mp_bitcnt_t(k));
  } else {
    mpz_mul_2exp(t[8], t[8], mp_bitcnt_t(-k));
  }
  mpz_sub(t[9], t[4], t[8]);
  return sign_of_int(mpz_sgn(t[9]));
}

Sign disk_in_circle_exact(double ax, double ay, double bx, double by, double cx, double cy, double ex, double ey) {
  Scratch &s = scratch();
  const double coordinates[8] = {ax, ay, bx, by, cx, cy, ex, ey};
  scale(coordinates, 8, s.x);  // homogeneous of degree 4: the scale drops out
  mpz_t *x = s.x, *t = s.t;
  mpz_sub(t[0], x[2], x[0]), mpz_sub(t[1], x[3], x[1]);  // b - a
  mpz_sub(t[2], x[4], x[0]), mpz_sub(t[3], x[5], x[1]);  // c - a
  mpz_sub(t[4], x[6], x[0]), mpz_sub(t[5], x[7], x[1]);  // e - a
  // disk_in_circle's value: l_b (c x e) + l_c (e x b) + l_e (b x c).
  cross(t[6], t[2], t[5], t[4], t[3], t[11]);
  lift(t[7], t[0], t[1], t[11]);
  mpz_mul(t[8], t[7], t[6]);
  cross(t[6], t[4], t[1], t[0], t[5], t[11]);
  lift(t[7], t[2], t[3], t[11]);
  mpz_addmul(t[8], t[7], t[6]);
  cross(t[6], t[0], t[3], t[2], t[1], t[11]);
  lift(t[7], t[4], t[5], t[11]);
  mpz_addmul(t[8], t[7], t[6]);
  return sign_of_int(-mpz_sgn(t[8]));
}

}  // namespace hdt::predicates
