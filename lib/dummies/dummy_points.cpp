// The dummy point construction (paper, Algorithm 1).
//
// Start from Q0 = {0, v_0, m_0 .. m_{2g-1}} (v_0 and the m_k as exact sites)
// and its triangulation by the 8g right triangles (0, v_{k-1}, m_k),
// (0, m_k, v_k) of F_g, which is a triangulation of M_g but not a simplicial
// complex (0 and m_k ~ m_{k+2g} are joined twice). Lawson flips make it
// Delaunay; then, while some face has circumdiameter >= sys/2, its
// circumcentre (rounded to double) is inserted, largest circle first, by a
// split and Lawson flips. Flips, unlike Bowyer-Watson, work on triangulations
// that are not simplicial, which the early stages are.
//
// The result is certified by Triangulation::validate(): every face is
// locally Delaunay, surrounds its vertices once and has circumdiameter
// < sys/2, decided with exact predicates, hence sys(M_g) > 2 delta_Q.
#include "dummies/dummy_points.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <utility>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>

#include "dummies/dummy_thinning.hpp"
#include "dummies/mesh_names.hpp"
#include "exact/unsupported.hpp"
#include "group/cyclic.hpp"
#include "domain/base_point.hpp"
#include "mesh/assemble.hpp"
#include "mesh/editor.hpp"
#include "mesh/polygon_triangulation.hpp"
#include "predicates/representative.hpp"
#include "surface/polygon.hpp"
#include "surface/q0_sites.hpp"

namespace hdt::dummies {

using predicates::TranslatedPoint;

// The construction on a surface of the geometry (M_g, or a polygon surface:
// the same flips, splits and circumcentres; only the start and the
// circumcentres' arithmetic differ).
template <class Geometry>
class DummyBuilder {
 public:
  using Editor = mesh::BasicEditor<Geometry>;
  using Triangulation = mesh::BasicTriangulation<Geometry>;

  // e: a triangulation with no vertices and a fresh kernel; it receives the set.
  explicit DummyBuilder(Editor &e) : e_(e), t_(e.triangulation()), K_(t_.kernel()), T_(t_.table()) {}

  // M_g: the set of the genus, thinned and certified, as its template.
  mesh::DummyTemplate build() {
    triangulate(t_.surface().quarter_systole_cosh_rounded(), 64 * std::size_t(t_.genus()) + 256);
    thin_dummy_points(e_);
    t_.validate();  // the certificate
    return e_.dummy_template();
  }

  // A polygon surface: the refined set, certified (not thinned: that takes
  // removals, which are M_g's only so far).
  static constexpr double kPolygonDummyMax = 1e6;
  void build_polygon() {
    domain::PolygonSurface &S = t_.surface();
    const double sys = S.systole().length.lo;
    // Each inserted circumcentre is at least sys/4 (up to rounding) from
    // every earlier point, the centre of an empty circle that large (paper,
    // section 5), so disks of radius sys/8 about the inserted points are
    // disjoint: at most the area 4 pi (g - 1) over a disk's
    // 2 pi (cosh(sys/8) - 1) of them, the fan's few points besides.
    const double packing = 2 * (t_.genus() - 1) / (std::cosh(sys / 8) - 1);
    // A surface with a tiny systole may need that many, each placed by a
    // walk and flips: refused up front rather than worked at for minutes.
    if (!(packing <= kPolygonDummyMax))
      throw exact::Unsupported("dummy points: the systole " + std::to_string(sys) + " allows up to " +
                               std::to_string(std::llround(packing)) + " dummy points, more than " +
                               std::to_string(std::llround(kPolygonDummyMax)) + " are not built");
    triangulate(std::cosh(sys / 4), std::size_t(2 * packing) + 256);
    e_.compact_ids();
    t_.validate();  // the certificate
  }

 private:
  struct Edge {
    uint32_t face;
    int i;
  };

  // Lawson flips from the first triangulation, then circumcentres while a
  // circle is too large: limit, cosh(sys/4) within 1e-7 or so, orders and
  // decides the clear cases (the exact test the others); more than
  // max_points vertices means the refinement does not end.
  void triangulate(double limit, std::size_t max_points) {
    initial_triangulation(t_.geometry());
    for (uint32_t f = 0; f < t_.faces().size(); ++f)
      for (int i = 0; i < 3; ++i) stack_.push_back({f, i});
    lawson();
    refine(limit, max_points);
  }

  // Q0 and its triangulation by right triangles of F_g (above).
  void initial_triangulation(mesh::MgGeometry &) {
    const group::Presentation &p = t_.surface().presentation();
    const int g = p.genus(), n = p.letter_count();
    std::vector<double> sx(2 * g + 1), sy(2 * g + 1);
    surface::register_q0_sites(t_.surface(), sx.data(), sy.data());
    std::vector<Vertex> vertices{{0, 0, 0, kNone}};  // 0: the centre of F_g
    for (int s = 0; s <= 2 * g; ++s) vertices.push_back({sx[s], sy[s], 0, kNone});  // 1: v_0; 2 + k: m_k
    // vertex_copy[k] maps v_0 to v_k: g_{k-2g} maps v_k to v_{k-2g-1}, and
    // the steps -(2g+1) visit every vertex.
    // The 4g letters of the cycle multiply to 1, so after m steps the
    // element is the run [l_m .. l_1] or, equally, the inverse of the rest
    // of the cycle; the shorter (the shortlex-least at m = 2g) is its
    // canonical word, an element of N: found in the table without arithmetic.
    std::vector<group::Letter> cycle;  // l_1, l_2, ...
    std::vector<int> vertex_of_step{0};
    for (int k = 0, step = 0; step < n; ++step) {
      cycle.push_back(static_cast<group::Letter>((k + 2 * g) % n));
      k = group::cyclic(k - 2 * g - 1, n);
      vertex_of_step.push_back(k);
    }
    std::vector<TranslationId> vertex_copy(n, 0);
    for (int m = 1; m < n; ++m) {
      const group::Word run(cycle.rend() - m, cycle.rend());  // l_m .. l_1
      group::Word rest;                                     // l_{m+1}^-1 .. l_{4g}^-1
      for (int i = m; i < n; ++i) rest.push_back(p.inverse(cycle[i]));
      TranslationId id = -1;
      if (run.size() < rest.size() || (run.size() == rest.size() && run < rest)) id = T_.find_canonical(run);
      else id = T_.find_canonical(rest);
      if (id < 0) id = T_.intern(run);  // not expected: the cycle stays in N
      vertex_copy[vertex_of_step[m]] = id;
    }
    for (int k = 0; k < n; ++k) {  // a cheap guard against a wrong cycle
      const auto z = T_.moebius(vertex_copy[k]).apply({vertices[1].x, vertices[1].y});
      const auto v = surface::vertex(p, k);
      if (std::abs(z.re - v.re) + std::abs(z.im - v.im) > 1e-6) throw std::logic_error("dummy points: vertex cycle");
    }
    // m_k for k >= 2g is g_k(m_{k-2g}).
    auto midpoint = [&](int k) {
      return k < 2 * g ? Corner{uint32_t(2 + k), 0} : Corner{uint32_t(2 + k - 2 * g), T_.intern({static_cast<group::Letter>(k)})};
    };
    // Faces A_k = (0, v_{k-1}, m_k) and B_k = (0, m_k, v_k) at 2k and 2k+1.
    // Across side s_k, g_k(B_{k+2g}) = (g_k 0, m_k, v_{k-1}) meets A_k and
    // g_k(A_{k+2g}) = (g_k 0, v_k, m_k) meets B_k.
    std::vector<Face> built(2 * std::size_t(n));
    auto A = [&](int k) { return uint32_t(2 * group::cyclic(k, n)); };
    auto B = [&](int k) { return A(k) + 1; };
    for (int k = 0; k < n; ++k) {
      const Corner o{0, 0}, a{1, vertex_copy[(k + n - 1) % n]}, b{1, vertex_copy[k]}, m = midpoint(k);
      const TranslationId across = T_.intern({static_cast<group::Letter>(k)});
      built[A(k)] = Face{{o.v, a.v, m.v}, {o.t, a.t, m.t}, {B(k + 2 * g), B(k), B(k - 1)}, {across, 0, 0}};
      built[B(k)] = Face{{o.v, m.v, b.v}, {o.t, m.t, b.t}, {A(k + 2 * g), A(k + 1), A(k)}, {across, 0, 0}};
    }
    e_.assign_dummies(std::move(vertices), std::move(built));
  }

  // A polygon P: the same fan from the base point c (rounded) to the
  // vertices and side midpoints, 2n triangles (c, v_k, m_k), (c, m_k,
  // v_{k+1}); with one double point per vertex cycle, a little inside P
  // from the cycle's smallest vertex, and one per pair of sides, its
  // rounded midpoint. The cycle's point stands at v_k as h_k(w), h_{k0} the
  // identity and h_{p(v)+1} = g_{p(v)} h_v (g_{p(v)} sends v_v to
  // v_{p(v)+1}); the midpoint m of side k < p(k) stands on side j = p(k) as
  // g_j(m). So the fan closes up across every side as on the surface, and
  // moving each cycle's point off the vertex moves all its copies alike.
  // Each triangle is checked counterclockwise, exactly; the offset is
  // halved until they are.
  void initial_triangulation(mesh::PolygonGeometry &G) {
    const domain::FundamentalPolygon &P = G.surface().polygon();
    const int n = P.side_count();
    const domain::Complex base = domain::base_point(P);
    const std::complex<double> c(static_cast<double>(base.re), static_cast<double>(base.im));
    std::vector<int> cycle_of(std::size_t(n), -1), first(P.cycles().size());
    std::vector<TranslationId> h(static_cast<std::size_t>(n), 0);
    for (std::size_t k = 0; k < P.cycles().size(); ++k) {
      const std::vector<int> &cycle = P.cycles()[k];
      first[k] = cycle[0];
      for (std::size_t i = 0; i < cycle.size(); ++i) {
        const int v = cycle[i], next_v = cycle[(i + 1) % cycle.size()];
        cycle_of[std::size_t(v)] = int(k);
        const TranslationId step = T_.compose(TranslationId(G.surface().pairing(P.paired(v))), h[std::size_t(v)]);
        if (i + 1 < cycle.size()) h[std::size_t(next_v)] = step;
        else if (step != 0) throw std::logic_error("dummy points: a vertex cycle's transformation is not the identity");
      }
    }
    auto hyperboloid = [](std::complex<double> z) {
      const double w = 1 - std::norm(z);
      return std::array<double, 3>{(1 + std::norm(z)) / w, 2 * z.real() / w, 2 * z.imag() / w};
    };
    auto disk = [](const std::array<double, 3> &N) { return std::complex<double>(N[1], N[2]) / (1 + N[0]); };
    for (double offset = 0x1p-5; offset > 0x1p-40; offset /= 2) {
      std::vector<Vertex> vertices{{c.real(), c.imag(), 0, kNone}};
      for (std::size_t k = 0; k < first.size(); ++k) {
        const std::complex<double> v = P.vertex_double(first[k]), w = v + offset * (c - v);
        vertices.push_back({w.real(), w.imag(), 0, kNone});
      }
      std::vector<uint32_t> midpoint(static_cast<std::size_t>(n));
      for (int k = 0; k < n; ++k) {
        if (k > P.paired(k)) continue;
        const std::array<double, 3> a = hyperboloid(P.vertex_double(k)), b = hyperboloid(P.vertex_double(k + 1));
        const std::complex<double> m = disk({a[0] + b[0], a[1] + b[1], a[2] + b[2]});
        midpoint[std::size_t(k)] = midpoint[std::size_t(P.paired(k))] = uint32_t(vertices.size());
        vertices.push_back({m.real(), m.imag(), 0, kNone});
      }
      for (Vertex &u : vertices) u.home = G.home(u.x, u.y);
      auto at_vertex = [&](int k) {
        const std::size_t v = std::size_t((k % n + n) % n);
        return std::pair<uint32_t, TranslationId>{uint32_t(1 + cycle_of[v]), h[v]};
      };
      std::vector<mesh::CornerFace> fan;
      for (int k = 0; k < n; ++k) {
        const uint32_t m = midpoint[std::size_t(k)];
        const TranslationId on_side = k < P.paired(k) ? 0 : TranslationId(G.surface().pairing(k));
        const auto a = at_vertex(k), b = at_vertex(k + 1);
        fan.push_back({{0, a.first, m}, {0, a.second, on_side}});
        fan.push_back({{0, m, b.first}, {0, on_side, b.second}});
      }
      bool counterclockwise = true;
      for (const mesh::CornerFace &f : fan) {
        std::array<TranslatedPoint, 3> p;
        for (int i = 0; i < 3; ++i) p[i] = {vertices[f.v[i]].x, vertices[f.v[i]].y, f.t[i], -1};
        counterclockwise = counterclockwise && K_.orientation(p[0], p[1], p[2]) > 0;
      }
      if (!counterclockwise) continue;
      std::vector<Face> faces = mesh::assemble_faces(&vertices, fan, T_);
      e_.assign_dummies(std::move(vertices), std::move(faces));
      return;
    }
    throw std::logic_error("dummy points: no counterclockwise fan of the polygon");
  }

  // The in-circle test of the flips: perturbed when the four vertices are
  // distinct, plain (a tie keeps the edge) otherwise.
  int in_circle(const std::array<TranslatedPoint, 4> &p, const std::array<uint32_t, 4> &v) {
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        if (v[i] == v[j]) return K_.in_circle(p[0], p[1], p[2], p[3]);
    return K_.in_circle_perturbed(p, v);
  }

  void lawson() {
    while (!stack_.empty()) {
      const Edge e = stack_.back();
      stack_.pop_back();
      if (e.face < t_.faces().size()) flip_if_illegal(e.face, e.i);
    }
  }

  void flip_if_illegal(uint32_t f, int i) {
    const Face F = t_.faces()[f];
    const uint32_t n = F.n[i];
    if (n == f) return;
    const int k = t_.twin(f, i);
    if (k < 0) throw std::logic_error("dummy points: an edge without twin");
    const Face N = t_.faces()[n];
    const int b = next(i), c = prev(i);
    for (int j : {b, c})
      if (F.n[j] == f || F.n[j] == n) return;
    for (int j : {next(k), prev(k)})
      if (N.n[j] == f || N.n[j] == n) return;
    // The quadrilateral A B D C; the flip replaces B-C by A-D.
    const TranslatedPoint A = t_.corner(F, i), B = t_.corner(F, b), C = t_.corner(F, c);
    const TranslatedPoint D = t_.point(N.v[k], T_.compose(F.nt[i], N.t[k]));
    if (in_circle({A, B, C, D}, {F.v[i], F.v[b], F.v[c], N.v[k]}) <= 0) return;
    if (K_.orientation(A, B, D) <= 0 || K_.orientation(A, D, C) <= 0) return;
    e_.flip(f, i, &ids_);
    for (uint32_t id : ids_)
      for (int j = 0; j < 3; ++j) stack_.push_back({id, j});
  }

  // Inserts the point (x, y), given in the canonical frame of face `from`.
  void insert(double x, double y, uint32_t from) {
    if (!std::isfinite(x) || !std::isfinite(y) || x * x + y * y >= 1)
      throw std::logic_error("dummy points: at genus " + std::to_string(t_.genus()) +
                             " the circumcentre of a refinement face is not a point of the disk");
    typename Triangulation::Walk w{};
    for (int attempt = 0;; ++attempt) {
      if (attempt > 64) throw std::logic_error("dummy points: cannot place a refinement point");
      w = t_.walk_from({x, y, 0, -1}, from);
      if (w.zero_edges == 0) break;
      // On an edge line: move off it (the dummy points are ours to choose).
      x = std::nextafter(x, 0.0) * (1 - 0x1p-30);
      y = std::nextafter(y, 0.0) * (1 - 0x1p-29);
    }
    e_.split(w, x, y, t_.geometry().home(x, y), &ids_);
    for (uint32_t f : ids_) stack_.push_back({f, 2});
    lawson();
  }

  // A face's circle as the refinement sees it: cosh of the radius (INFINITY
  // when rounding made nonsense) and the centre in the disk, in the face's
  // canonical frame; or the centroid (circle(F, true)) for a face whose
  // large circle only the exact test saw.
  struct Circle {
    double cosh_r, cx, cy;
  };

  // From the corners' hyperboloid vectors P (in double or MpfrReal): the
  // plane's Euclidean normal, whose Minkowski dual is the centre.
  template <class Real>
  static Circle circle_of(const Real (&P)[3][3]) {
    using std::sqrt;
    const Real u[3] = {P[1][0] - P[0][0], P[1][1] - P[0][1], P[1][2] - P[0][2]};
    const Real v[3] = {P[2][0] - P[0][0], P[2][1] - P[0][1], P[2][2] - P[0][2]};
    const Real m[3] = {u[1] * v[2] - u[2] * v[1], -(u[2] * v[0] - u[0] * v[2]), -(u[0] * v[1] - u[1] * v[0])};
    const Real mm = m[0] * m[0] - m[1] * m[1] - m[2] * m[2];
    // Three points on a horocycle or hypercycle have no circle: a face so
    // large occurs in the construction at no genus up to kDummyGenusMax
    // (each genus was run to check).
    if (!(mm > 0)) throw std::logic_error("dummy points: a face without a circumcircle");
    const Real s = Real(m[0] > 0 ? 1 : -1) / sqrt(mm);
    Real centre[3];
    for (int j = 0; j < 3; ++j) centre[j] = m[j] * s;
    double cosh_r = static_cast<double>(centre[0] * P[0][0] - centre[1] * P[0][1] - centre[2] * P[0][2]);
    if (!(cosh_r >= 1)) cosh_r = INFINITY;  // rounding made nonsense: still a candidate
    return {cosh_r, static_cast<double>(centre[1] / (1 + centre[0])), static_cast<double>(centre[2] / (1 + centre[0]))};
  }
  template <class Real>
  static Circle centroid_of(const Real (&P)[3][3]) {
    using std::sqrt;
    Real c[3], centre[3];
    for (int j = 0; j < 3; ++j) c[j] = P[0][j] + P[1][j] + P[2][j];
    const Real cc = sqrt(c[0] * c[0] - c[1] * c[1] - c[2] * c[2]);
    for (int j = 0; j < 3; ++j) centre[j] = c[j] / cc;
    return {INFINITY, static_cast<double>(centre[1] / (1 + centre[0])), static_cast<double>(centre[2] / (1 + centre[0]))};
  }

  // The normal's Minkowski norm cancels about 2 log2(n_0) bits, n_0 the
  // corners' largest coordinate. Below n_0 = 2^16 in double, as the
  // construction always did (the sets of genus 2..96 were certified so and
  // stay as they were); beyond, far from O at large genus, in the MPFR
  // stage's 133 bits, which keep about 65 bits at n_0 ~ cosh(2R) ~ 1e10
  // (genus 256).
  Circle circle(const Face &F, bool centroid = false) { return circle_on(t_.geometry(), F, centroid); }
  // A polygon surface: from the corners' images in double.
  Circle circle_on(mesh::PolygonGeometry &G, const Face &F, bool centroid) {
    double P[3][3];
    for (int i = 0; i < 3; ++i) {
      const Vertex &u = t_.vertices()[F.v[i]];
      const group::Complex<double> z = G.image(u.x, u.y, F.t[i]);
      const double r2 = z.re * z.re + z.im * z.im, w = 1 - r2;
      P[i][0] = (1 + r2) / w, P[i][1] = 2 * z.re / w, P[i][2] = 2 * z.im / w;
    }
    return centroid ? centroid_of(P) : circle_of(P);
  }
  Circle circle_on(mesh::MgGeometry &, const Face &F, bool centroid) {
    double P[3][3];
    bool far = false;
    for (int i = 0; i < 3; ++i) {
      const std::array<double, 3> n = K_.hyperboloid(t_.corner(F, i));
      for (int j = 0; j < 3; ++j) P[i][j] = n[j];
      far = far || !(n[0] < 0x1p16);
    }
    if (far) {
      predicates::MpfrReal M[3][3];
      bool mid = true;
      for (int i = 0; i < 3 && mid; ++i) {
        std::array<predicates::MpfrReal, 3> n;
        mid = K_.hyperboloid_mpfr(t_.corner(F, i), &n);
        for (int j = 0; j < 3; ++j) M[i][j] = n[j];
      }
      if (mid) return centroid ? centroid_of(M) : circle_of(M);
    }
    return centroid ? centroid_of(P) : circle_of(P);  // near O, or no approximation: in double
  }

  // The circle of face f, computed once per face content (a face keeps its
  // id while its corners change under flips and splits).
  struct CachedCircle {
    std::array<uint32_t, 3> v{kNone, kNone, kNone};
    std::array<TranslationId, 3> t{};
    Circle c{};
    int large = 0;  // K_.large_circumdisk when asked, 0 before
  };
  CachedCircle &cached_circle(uint32_t f) {
    if (circles_.size() <= f) circles_.resize(t_.faces().size());
    CachedCircle &e = circles_[f];
    const Face &F = t_.faces()[f];
    if (e.v != F.v || e.t != F.t) e = {F.v, F.t, circle(F), 0};
    return e;
  }

  // Largest circles first: the circumcentre of the face whose circle is
  // largest among those of hyperbolic diameter >= sys/2.
  void refine(double limit, std::size_t max_points) {
    for (;;) {
      uint32_t best = kNone;
      double best_cosh = 0, cx = 0, cy = 0;
      for (uint32_t f = 0; f < t_.faces().size(); ++f) {
        CachedCircle &e = cached_circle(f);
        const double cosh_r = e.c.cosh_r;
        // The rounded radius orders the faces and decides the clear cases;
        // the exact test decides near the limit (and the final check
        // decides them all).
        if (cosh_r <= best_cosh || cosh_r < limit * (1 - 1e-6)) continue;
        if (cosh_r < limit * (1 + 1e-6)) {
          const Face &F = t_.faces()[f];
          if (e.large == 0) e.large = K_.large_circumdisk(t_.corner(F, 0), t_.corner(F, 1), t_.corner(F, 2));
          if (e.large < 0) continue;
        }
        best = f, best_cosh = cosh_r;
        cx = e.c.cx, cy = e.c.cy;
      }
      if (best == kNone) {
        // Rounding may have hidden a large circle: look again, exactly.
        for (uint32_t f = 0; f < t_.faces().size() && best == kNone; ++f) {
          const Face &F = t_.faces()[f];
          if (K_.large_circumdisk(t_.corner(F, 0), t_.corner(F, 1), t_.corner(F, 2)) > 0) best = f;
        }
        if (best == kNone) return;
        const Circle c = circle(t_.faces()[best], true);  // its centroid serves
        cx = c.cx, cy = c.cy;
      }
      if (t_.vertices().size() > max_points) throw std::logic_error("dummy points: the refinement does not end");
      // Congruent faces have symmetric circumcentres, and symmetric points
      // are cocircular: a relative nudge of about 2^-20 keeps the set in
      // general position, so the filters decide every test. Near the circle
      // (large genus) it is scaled by 1 - |c|^2 to stay hyperbolically small.
      rng_ = rng_ * 6364136223846793005ull + 1442695040888963407ull;
      double dx = double(int64_t(rng_ >> 44) - (1 << 19)) * 0x1p-39;
      double dy = double(int64_t((rng_ >> 24) & 0xFFFFF) - (1 << 19)) * 0x1p-39;
      const double w = 1 - (cx * cx + cy * cy);
      if (w < 0x1p-10) dx *= w * 0x1p10, dy *= w * 0x1p10;
      insert(cx * (1 + dx), cy * (1 + dy), best);
    }
  }

  Editor &e_;
  Triangulation &t_;
  typename Triangulation::Kernel &K_;
  typename Geometry::Table &T_;
  std::vector<Edge> stack_;
  std::vector<uint32_t> ids_;
  std::vector<CachedCircle> circles_;  // by face id
  uint64_t rng_ = 0x2545F4914F6CDD1Dull;
};

namespace {

std::mutex cache_mutex;
std::map<int, std::shared_ptr<const mesh::DummyTemplate>> cache;

}  // namespace

mesh::Triangulation new_triangulation(int genus) {
  {
    std::lock_guard<std::mutex> lock(cache_mutex);
    auto it = cache.find(genus);
    if (it != cache.end()) return mesh::Triangulation(*it->second);
  }
  if (genus > kDummyGenusMax)
    throw exact::Unsupported("dummy points are built up to genus " + std::to_string(kDummyGenusMax) +
                            " (HDT_CREATE_GENUS_MAX), not " + std::to_string(genus) +
                            ": beyond it their double-precision construction loses every bit");
  // Built outside the lock.
  mesh::Editor e(genus);
  auto built = std::make_shared<const mesh::DummyTemplate>(DummyBuilder<mesh::MgGeometry>(e).build());
  {
    std::lock_guard<std::mutex> lock(cache_mutex);
    cache.emplace(genus, built);
  }
  return std::move(e).take();
}

mesh::PolygonTriangulation new_polygon_triangulation(const domain::FundamentalPolygon &polygon) {
  mesh::BasicEditor<mesh::PolygonGeometry> e(std::make_unique<mesh::PolygonGeometry>(polygon));
  DummyBuilder<mesh::PolygonGeometry>(e).build_polygon();
  return std::move(e).take();
}

}  // namespace hdt::dummies
