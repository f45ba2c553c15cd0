#include "domain/base_point.hpp"

#include <cmath>
#include <complex>
#include <stdexcept>

#include "domain/klein.hpp"
#include "domain/klein_polygon.hpp"

namespace hdt::domain {

namespace {

std::complex<double> klein_centroid(const KleinPolygon &K) {
  std::complex<double> sum = 0;
  for (int k = 0; k < K.side_count(); ++k)
    sum += std::complex<double>(static_cast<double>(K.vertex(k).re), static_cast<double>(K.vertex(k).im));
  return sum / double(K.side_count());
}

Number exact(const Number &like, double x) {
  mpq_class q(x);
  q.canonicalize();
  return Number(like.parent(), q);
}

}  // namespace

Complex base_point(const FundamentalPolygon &P) {
  const KleinPolygon K(P);
  const Number &like = P.vertex(0).re;
  const Complex origin = Complex(Number(like.parent(), 0));
  if (K.contains_strictly(origin)) return origin;
  const std::complex<double> m = klein_centroid(K);
  const std::complex<double> z = m / (1 + std::sqrt(1 - std::norm(m)));
  const Complex c{exact(like, z.real()), exact(like, z.imag())};
  if (!K.contains_strictly(klein(c)))
    throw std::runtime_error("domain::base_point: the polygon is too narrow for a double to find its centre");
  return c;
}

}  // namespace hdt::domain
