#include "domain/fundamental_polygon.hpp"

#include <stdexcept>

#include "domain/distance.hpp"
#include "domain/klein.hpp"
#include "domain/turning.hpp"

namespace hdt::domain {

namespace {

std::string cycle_text(const std::vector<int> &cycle) {
  std::string s = "(";
  for (std::size_t t = 0; t < cycle.size(); ++t) s += (t ? " " : "") + std::to_string(cycle[t]);
  return s + ")";
}

}  // namespace

FundamentalPolygon::FundamentalPolygon(FieldPtr field, std::vector<int> paired, std::vector<Complex> vertices)
    : field_(std::move(field)), paired_(std::move(paired)), vertices_(std::move(vertices)) {
  const std::size_t n = vertices_.size();
  if (n < 4 || n % 2 != 0)
    throw InvalidPolygon("the polygon has " + std::to_string(n) +
                         " vertices: a fundamental polygon needs an even number, at least 4");
  if (paired_.size() != n)
    throw InvalidPolygon("the pairing names " + std::to_string(paired_.size()) + " sides for " + std::to_string(n) +
                         " vertices");
  check_numbers();
  check_pairing();
  check_disk();
  check_convex();
  check_lengths();
  make_pairings();
  make_cycles();
  for (const std::vector<int> &cycle : cycles_) check_cycle(cycle);
  find_genus();
}

FundamentalPolygon::FundamentalPolygon(const PolygonText &text)
    : FundamentalPolygon(text.field, text.paired, text.vertices) {}

std::size_t FundamentalPolygon::index(int k) const {
  const int n = side_count();
  return std::size_t(((k % n) + n) % n);
}

Complex FundamentalPolygon::exact_point(double x, double y) const {
  mpq_class qx(x), qy(y);  // exact: a double is a dyadic rational
  qx.canonicalize(), qy.canonicalize();
  const auto &parent = vertices_.front().re.parent();
  return {Number(parent, qx), Number(parent, qy)};
}

std::complex<double> FundamentalPolygon::vertex_double(int k) const {
  const Complex &z = vertex(k);
  return {static_cast<double>(z.re), static_cast<double>(z.im)};
}

// Every coordinate rational or in the one field; rationals are moved into the
// field, so that all arithmetic below has one parent.
void FundamentalPolygon::check_numbers() {
  for (std::size_t k = 0; k < vertices_.size(); ++k)
    for (Number *x : {&vertices_[k].re, &vertices_[k].im}) {
      if (x->is_rational()) {
        if (field_) *x = Number(*field_, static_cast<mpq_class>(*x));
      } else if (!field_ || x->parent() != *field_) {
        throw InvalidPolygon("a coordinate of vertex " + std::to_string(k) + " is not in the polygon's field");
      }
    }
}

void FundamentalPolygon::check_pairing() const {
  const int n = side_count();
  for (int k = 0; k < n; ++k) {
    const int j = paired_[std::size_t(k)];
    if (j < 0 || j >= n)
      throw InvalidPolygon("the pairing is not a perfect matching: side " + std::to_string(k) +
                           " is paired with " + std::to_string(j) + ", which is not a side");
    if (j == k)
      throw InvalidPolygon("the pairing is not a perfect matching: side " + std::to_string(k) +
                           " is paired with itself");
    if (paired_[std::size_t(j)] != k)
      throw InvalidPolygon("the pairing is not a perfect matching: side " + std::to_string(k) + " is paired with " +
                           std::to_string(j) + ", which is paired with " + std::to_string(paired_[std::size_t(j)]));
  }
}

void FundamentalPolygon::check_disk() const {
  for (int k = 0; k < side_count(); ++k)
    if (norm2(vertex(k)) >= 1)
      throw InvalidPolygon("vertex " + std::to_string(k) + " is not in the open unit disk (|z|^2 >= 1)");
}

// Counterclockwise and strictly convex: every Klein edge turns left from the
// one before (an exact orientation sign). A polygon with only left turns is
// simple exactly when its edge directions make one whole turn, two half
// turns, counted exactly (turning.hpp).
void FundamentalPolygon::check_convex() const {
  const int n = side_count();
  std::vector<Complex> edges;
  for (int k = 0; k <= n; ++k) edges.push_back(klein(vertex(k + 1)) - klein(vertex(k)));
  for (int k = 0; k < n; ++k)
    if (!turns_left(edges[std::size_t(k)], edges[std::size_t(k + 1)]))
      throw InvalidPolygon("the polygon is not strictly convex and counterclockwise at vertex " +
                           std::to_string((k + 1) % n));
  const long turns = half_turns(edges);
  if (turns != 2)
    throw InvalidPolygon("the polygon is convex at each vertex but winds " + std::to_string(turns / 2) +
                         " times around: it is not simple");
}

void FundamentalPolygon::check_lengths() const {
  for (int k = 0; k < side_count(); ++k) {
    const int j = paired(k);
    if (j < k) continue;
    if (cosh_distance(vertex(k), vertex(k + 1)) != cosh_distance(vertex(j), vertex(j + 1)))
      throw InvalidPolygon("sides " + std::to_string(k) + " and " + std::to_string(j) +
                           " are paired but have different hyperbolic lengths");
  }
}

void FundamentalPolygon::make_pairings() {
  for (int k = 0; k < side_count(); ++k) {
    const int j = paired(k);
    pairings_.push_back(segment_map(vertex(j + 1), vertex(j), vertex(k), vertex(k + 1)));
  }
}

// Side v is paired with j = paired(v); the pairing of side j sends side v,
// from v_{v+1} to v_v, onto side j from v_j to v_{j+1}: so v_v goes to
// v_{j+1}, the next vertex of the cycle.
void FundamentalPolygon::make_cycles() {
  std::vector<bool> seen(vertices_.size(), false);
  for (int start = 0; start < side_count(); ++start) {
    if (seen[std::size_t(start)]) continue;
    std::vector<int> cycle;
    for (int v = start; !seen[std::size_t(v)]; v = int(index(paired(v) + 1))) {
      seen[std::size_t(v)] = true;
      cycle.push_back(v);
    }
    cycles_.push_back(std::move(cycle));
  }
}

// The angle at v, between the geodesics to v_{v+1} and to v_{v-1}, is the
// argument of rho = T_v(v_{v-1}) conj(T_v(v_{v+1})) (T_v is conformal with
// positive derivative at v), in (0, pi) by convexity. The cycle's angles sum
// to the argument of the product of its rhos, and the turns are counted
// exactly: the sum is 2 pi when the product is positive real after exactly
// two half turns. The composition of the pairings around the cycle fixes v;
// it is the identity, exactly, when the sum is a multiple of 2 pi, which
// this checks again independently.
void FundamentalPolygon::check_cycle(const std::vector<int> &cycle) const {
  std::vector<Complex> product{complex_one(vertex(0).re)};
  Moebius around = identity(vertex(0).re);
  for (const int v : cycle) {
    const Moebius T = to_origin(vertex(v));
    const Complex rho = T.apply(vertex(v - 1)) * conj(T.apply(vertex(v + 1)));
    if (rho.im.sgn() <= 0) throw std::logic_error("FundamentalPolygon: an angle outside (0, pi) past check_convex");
    product.push_back(product.back() * rho);
    around = pairing(paired(v)) * around;
  }
  const long halves = half_turns(product);
  if (!product.back().im.is_zero())
    throw InvalidPolygon("the angles at the vertex cycle " + cycle_text(cycle) + " sum to between " +
                         std::to_string(halves) + " pi and " + std::to_string(halves + 1) +
                         " pi: the angle sum must be 2 pi");
  if (halves != 2 || !is_positive_real(product.back()))
    throw InvalidPolygon("the angles at the vertex cycle " + cycle_text(cycle) + " sum to " + std::to_string(halves) +
                         " pi: the angle sum must be 2 pi");
  if (!around.is_identity())
    throw InvalidPolygon("the pairings around the vertex cycle " + cycle_text(cycle) +
                         " compose to a map that is not the identity");
}

// Euler: V - E + F = cycles - n/2 + 1 = 2 - 2g.
void FundamentalPolygon::find_genus() {
  const long chi = long(cycles_.size()) - side_count() / 2 + 1;
  if (chi % 2 != 0 || chi > -2)
    throw InvalidPolygon("the surface has Euler characteristic " + std::to_string(chi) +
                         ": its genus must be a whole number, at least 2");
  genus_ = int((2 - chi) / 2);
}

}  // namespace hdt::domain
