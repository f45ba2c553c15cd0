// A surface given by a fundamental polygon, as a triangulation of it sees
// the surface: the polygon, its group elements interned as ids, the exact
// predicates on points (x, y, id), the reduction of a point into the polygon
// as an id, and the systole's threshold for the faces. One object, so that
// the mesh and the dummy construction share one table of ids (an id means
// the same element to both) and one kernel (its caches are warm for both).
//
// The role of surface::Surface for M_g: ids play the part of TranslationIds
// (0 is the identity, compose and inverse are cached), a point's home is
// the id h with h(x + iy) in P's fundamental set (representative.hpp).
//
// One thread at a time; the caller holds the field lock (field_lock.hpp) on
// a surface over a number field.
#pragma once

#include <mpfr.h>

#include <array>
#include <complex>
#include <cstddef>
#include <optional>
#include <vector>

#include "domain/element_table.hpp"
#include "domain/fundamental_polygon.hpp"
#include "domain/homology.hpp"
#include "domain/polygon_kernel.hpp"
#include "domain/representative.hpp"
#include "domain/systole.hpp"

namespace hdt::domain {

class PolygonSurface {
 public:
  explicit PolygonSurface(FundamentalPolygon polygon);
  PolygonSurface(const PolygonSurface &) = delete;
  PolygonSurface &operator=(const PolygonSurface &) = delete;

  const FundamentalPolygon &polygon() const { return polygon_; }
  int genus() const { return polygon_.genus(); }
  ElementTable &table() { return table_; }
  PolygonKernel &kernel() { return kernel_; }

  // The id of the pairing g_k of side k.
  ElementId pairing(int k) const { return pairings_.at(std::size_t(k)); }

  // The home of the point x + iy of the open disk: the id of the element h
  // that Reduction finds, h(x + iy) in the fundamental set. The walk's
  // pairings composed as ids (cached products), so a point the floating
  // walk decides costs no exact multiplication. Throws std::domain_error
  // outside the open disk.
  ElementId home(double x, double y);

  // h(x + iy) in double, from h's SU(1,1) ball rounded (about 1e-15
  // relative: for the walk's starting points and pictures, never for a
  // decision); the rounded matrix is kept per element.
  std::complex<double> image(ElementId h, double x, double y) const;
  // h's SU(1,1) form (a, b), z -> (a z + b) / (conj(b) z + conj(a)), each
  // part the midpoint of its certified ball: the matrix image() uses.
  std::array<std::complex<double>, 2> rounded(ElementId h) const;
  // h's (a, b) as double-double parts, for the dual's accurate stage:
  // each exact part within error (|a| + |b|) of hi + lo, plus 2^-106 of
  // itself (the 128-bit ball's midpoint rounded twice, its radius bounded).
  struct SplitMatrix {
    std::complex<double> a_hi, b_hi, a_lo, b_lo;
    double error;
  };
  SplitMatrix split(ElementId h) const;
  // h(x + iy) exactly (in K), rounded to the precision of re and im (MPFR
  // variables the caller initialised): for the dual's last resort, faces
  // that double-double cannot resolve.
  void precise_image(ElementId h, double x, double y, mpfr_ptr re, mpfr_ptr im) const;

  // h as a word in the pairings (letter k: the pairing of side k, the word
  // w_0 w_1 ... the product g_{w_0} g_{w_1} ...). Exact: the reduction of
  // h(b), b the interior base point, gives t with t h (b) = b, so t h = 1 as
  // the group acts freely; h's word is t's inverted. Checked by the exact
  // product of the word (no id is made for its prefixes).
  std::vector<int> word(ElementId h) const;

  // H_1 as Z^{2g} (homology.hpp), made on first use.
  const Homology &homology() const;

  // The systole, certified (systole.hpp), computed on first use.
  const Systole &systole();
  // A rational k with 1 <= k <= cosh^2(sys / 4), for large_circumdisk: a
  // face of which it answers -1 has circumdiameter below sys / 2, the
  // paper's condition on the dummy points (a lower bound of the threshold
  // only ever calls a small face large, never the converse).
  const Number &quarter_systole_cosh2_below();

 private:
  FundamentalPolygon polygon_;
  ElementTable table_;
  PolygonKernel kernel_;
  Reduction reduction_;
  std::vector<ElementId> pairings_;
  Complex base_;  // interior: word()'s witness point
  mutable std::vector<std::array<std::complex<double>, 2>> rounded_;  // (a, b) by element id, as far as asked
  std::optional<Systole> systole_;
  mutable std::optional<Homology> homology_;
  std::optional<Number> threshold_;
};

}  // namespace hdt::domain
