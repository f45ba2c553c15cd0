#include "domain/random_octagon.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <optional>
#include <random>
#include <stdexcept>

#include "domain/turning.hpp"

namespace hdt::domain {

namespace {

using Cd = std::complex<double>;

// Attempts before giving up: far more than any seed has needed.
constexpr int kAttempts = 1000000;

double uniform(std::mt19937_64 &rng) { return double(rng() >> 11) * 0x1p-53; }

// z_1 .. z_{m-1}: points of the upper half disk by argument.
std::vector<Cd> draw_upper(std::mt19937_64 &rng, int count) {
  std::vector<Cd> z;
  while (int(z.size()) < count) {
    const Cd p(2 * uniform(rng) - 1, uniform(rng));
    if (std::norm(p) < 1 && p.imag() > 0) z.push_back(p);
  }
  std::sort(z.begin(), z.end(), [](Cd a, Cd b) { return std::arg(a) < std::arg(b); });
  return z;
}

// z_0 in (0, 1) with Z = B (1 - z_0 conj z_1)(1 + z_0 z_{m-1}) real negative,
// B the product of the middle factors: Im Z = a z_0^2 + b z_0 + c = 0.
std::optional<double> solve_z0(const std::vector<Cd> &z) {
  Cd B = 1;
  for (std::size_t k = 1; k + 1 < z.size(); ++k) B *= 1.0 - z[k] * std::conj(z[k + 1]);
  const Cd z1 = z[1], zl = z.back();
  const double a = -(B * std::conj(z1) * zl).imag(), b = (B * (zl - std::conj(z1))).imag(), c = B.imag();
  const double disc = b * b - 4 * a * c;
  if (disc < 0 || a == 0) return std::nullopt;
  for (const double s : {-1.0, 1.0}) {
    const double x = (-b + s * std::sqrt(disc)) / (2 * a);
    if (x > 0 && x < 1 && (B * (1.0 - x * std::conj(z1)) * (1.0 + x * zl)).real() < 0) return x;
  }
  return std::nullopt;
}

Complex truncated(Cd z) {
  auto q = [](double x) {
    mpq_class r(long(std::trunc(x * 1e4)), 10000);
    r.canonicalize();  // e-antic (FLINT) needs canonical fractions
    return Number(r);
  };
  return {q(z.real()), q(z.imag())};
}

// f(z) = (z_0 + z) / (z_0 z + 1), the translation along the real axis that
// sends -z_0 to 0 (z_0 real), and its inverse.
Complex f(const Number &z0, const Complex &z) { return (Complex(z0) + z) / (z0 * z + complex_one(z0)); }
Complex f_inverse(const Number &z0, const Complex &w) { return (w - Complex(z0)) / (complex_one(z0) - z0 * w); }

// Moves z_{m-1} along the geodesic through -z_0 so that the half polygon
// z_0 .. z_{m-1}, -z_0 has the right angle sum (docs/polygons.md): in the
// picture moved by f, -z_0 is at 0 and the condition is linear in lambda.
bool make_exact(std::vector<Complex> &z) {
  const Number &z0 = z[0].re;
  std::vector<Complex> w;
  for (const Complex &p : z) w.push_back(f(z0, p));
  const std::size_t m = z.size();
  Complex I = complex_one(z0);
  for (std::size_t k = 0; k + 2 < m; ++k) I = I * (complex_one(z0) - w[k] * conj(w[k + 1]));
  const Number P0 = I.im, P1 = (I * (complex_one(z0) - w[m - 2] * conj(w[m - 1]))).im;
  if (P0 == P1) return false;
  const Number lambda = P0 / (P0 - P1);
  z[m - 1] = f_inverse(z0, lambda * w[m - 1]);
  return true;
}

Complex klein(const Complex &z) { return (Number(z.re.parent(), 2) / (1 + norm2(z))) * z; }

// The whole polygon z, -z: inside the disk, counterclockwise by argument,
// strictly convex (Klein edges turn left), and
// Z = prod (1 - z_k conj z_{k+1}) (z_m = -z_0) exactly real.
bool acceptable(const std::vector<Complex> &half) {
  std::vector<Complex> all = half;
  for (const Complex &p : half) all.push_back(-p);
  const std::size_t n = all.size();
  for (std::size_t k = 0; k < n; ++k) {
    if (norm2(all[k]) >= 1 || !turns_left(all[k], all[(k + 1) % n])) return false;
    const Complex a = klein(all[k]), b = klein(all[(k + 1) % n]), c = klein(all[(k + 2) % n]);
    if (!turns_left(b - a, c - b)) return false;
  }
  Complex Z = complex_one(half[0].re);
  for (std::size_t k = 0; k < half.size(); ++k) Z = Z * (complex_one(half[0].re) - all[k] * conj(all[k + 1]));
  return Z.im.is_zero();
}

std::optional<std::vector<Complex>> attempt(std::mt19937_64 &rng, int half) {
  std::vector<Cd> z{0.0};
  for (const Cd p : draw_upper(rng, half - 1)) z.push_back(p);
  const std::optional<double> z0 = solve_z0(z);
  if (!z0) return std::nullopt;
  z[0] = *z0;
  std::vector<Complex> exact;
  for (const Cd p : z) exact.push_back(truncated(p));
  if (exact[0].re.sgn() <= 0 || !make_exact(exact) || !acceptable(exact)) return std::nullopt;
  return exact;
}

}  // namespace

FundamentalPolygon random_symmetric_polygon(int half, std::uint64_t seed) {
  if (half != 4 && half != 5) throw std::invalid_argument("random_symmetric_polygon: half must be 4 or 5");
  std::mt19937_64 rng(seed);
  for (int t = 0; t < kAttempts; ++t) {
    std::optional<std::vector<Complex>> z = attempt(rng, half);
    if (!z) continue;
    std::vector<Complex> vertices = *z;
    std::vector<int> paired;
    for (const Complex &p : *z) vertices.push_back(-p);
    for (int k = 0; k < 2 * half; ++k) paired.push_back((k + half) % (2 * half));
    return FundamentalPolygon(nullptr, paired, vertices);
  }
  throw std::runtime_error("random_symmetric_polygon: no polygon after the attempts");
}

FundamentalPolygon random_octagon(std::uint64_t seed) { return random_symmetric_polygon(4, seed); }

}  // namespace hdt::domain
