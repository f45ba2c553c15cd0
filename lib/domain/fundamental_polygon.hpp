// A closed hyperbolic surface given by a fundamental polygon in the Poincare
// disk and a pairing of its sides, as CGAL's Triangulation_on_hyperbolic_surface_2
// takes it. Everything is checked exactly on entry (docs/polygons.md has each
// argument); a polygon that fails a check is refused with InvalidPolygon,
// whose message names the side, the vertex or the cycle.
//
// Conventions (CGAL's): vertices v_0 .. v_{n-1} counterclockwise; side k runs
// from v_k to v_{k+1} (indices mod n); the pairing of side k is the isometry
// that sends side j = paired(k), taken from v_{j+1} to v_j, onto side k from
// v_k to v_{k+1}.
#pragma once

#include <complex>
#include <stdexcept>
#include <string>
#include <vector>

#include "domain/complex.hpp"
#include "domain/field_text.hpp"
#include "domain/pairing.hpp"
#include "domain/polygon_text.hpp"

namespace hdt::domain {

struct InvalidPolygon : std::invalid_argument {
  explicit InvalidPolygon(const std::string &what) : std::invalid_argument(what) {}
};

class FundamentalPolygon {
 public:
  // field: null when every coordinate is rational; otherwise the field of
  // every coordinate that is not rational.
  FundamentalPolygon(FieldPtr field, std::vector<int> paired, std::vector<Complex> vertices);
  explicit FundamentalPolygon(const PolygonText &text);

  int side_count() const { return int(vertices_.size()); }
  int paired(int k) const { return paired_[index(k)]; }
  const Complex &vertex(int k) const { return vertices_[index(k)]; }
  std::complex<double> vertex_double(int k) const;
  // The point x + iy of two doubles, exactly, in the polygon's field.
  Complex exact_point(double x, double y) const;
  // The isometry that sends side paired(k) onto side k (see above).
  const Moebius &pairing(int k) const { return pairings_[index(k)]; }
  // The vertex cycles, each from its smallest vertex in the order
  // v -> paired(v) + 1 (the pairing of side paired(v) sends v there).
  const std::vector<std::vector<int>> &cycles() const { return cycles_; }
  int genus() const { return genus_; }
  const FieldPtr &field() const { return field_; }  // null for Q
  PolygonText text() const { return {field_, paired_, vertices_}; }

 private:
  FieldPtr field_;
  std::vector<int> paired_;
  std::vector<Complex> vertices_;
  std::vector<Moebius> pairings_;
  std::vector<std::vector<int>> cycles_;
  int genus_ = 0;

  std::size_t index(int k) const;  // k mod n
  void check_numbers();
  void check_pairing() const;
  void check_disk() const;
  void check_convex() const;
  void check_lengths() const;
  void make_pairings();
  void make_cycles();
  void check_cycle(const std::vector<int> &cycle) const;
  void find_genus();
};

}  // namespace hdt::domain
