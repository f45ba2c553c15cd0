// hdt_surface_svg: a surface given by a fundamental polygon, drawn in the
// Poincare disk as SVG text: the polygon filled, its sides as geodesic arcs,
// each pair of glued sides in one colour with both indices written at their
// midpoints, and each vertex as a dot in the colour of its vertex cycle.
// Like hdt_svg it reads the surface through include/hdt.h only.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "capi/guard.hpp"
#include "hdt.h"
#include "picture/disk_frame.hpp"

using hdt::capi::ApiError;
using hdt::capi::guarded;
using namespace hdt::picture;

namespace {

// Twelve colours far apart, for the pairs of sides and the vertex cycles.
const char *const kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf",
                                "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#393b79", "#637939"};
constexpr int kColours = sizeof kPalette / sizeof *kPalette;

void check(hdt_status status) {
  if (status != HDT_OK) throw ApiError(status, hdt_last_error_message());
}

struct Polygon {
  int n = 0, genus = 0;
  std::vector<double> x, y;
  std::vector<int> paired, cycle;
  std::size_t cycles = 0;
};

Polygon read_polygon(const hdt_surface *s) {
  Polygon p;
  p.n = hdt_surface_side_count(s), p.genus = hdt_surface_genus(s);
  p.x.resize(std::size_t(p.n)), p.y.resize(std::size_t(p.n));
  p.paired.resize(std::size_t(p.n)), p.cycle.resize(std::size_t(p.n));
  for (int k = 0; k < p.n; ++k) {
    check(hdt_surface_vertex(s, k, &p.x[std::size_t(k)], &p.y[std::size_t(k)]));
    check(hdt_surface_pairing(s, k, &p.paired[std::size_t(k)], nullptr));
  }
  check(hdt_surface_vertex_cycles(s, p.cycle.data(), p.cycle.size(), &p.cycles));
  return p;
}

// The midpoint of the geodesic from a to b: in the Klein model (k = 2z /
// (1 + |z|^2)) the geodesic is the chord, whose midpoint maps back to the
// disk by z = k / (1 + sqrt(1 - |k|^2)); a point on the geodesic, near its
// hyperbolic midpoint, where the label goes.
void midpoint(double ax, double ay, double bx, double by, double *x, double *y) {
  const double ka = 2 / (1 + ax * ax + ay * ay), kb = 2 / (1 + bx * bx + by * by);
  const double kx = (ka * ax + kb * bx) / 2, ky = (ka * ay + kb * by) / 2;
  const double back = 1 / (1 + std::sqrt(1 - kx * kx - ky * ky));
  *x = kx * back, *y = ky * back;
}

// The colour of side k's pair: by the rank of the pair's smaller side.
int pair_colour(const Polygon &p, int k) {
  const int first = std::min(k, p.paired[std::size_t(k)]);
  int rank = 0;
  for (int j = 0; j < first; ++j) rank += j < p.paired[std::size_t(j)];
  return rank % kColours;
}

void draw(Text &f, const Polygon &p, double size) {
  const DiskFrame d(size, kTitleHeight);
  const double scale = size / kReferenceSize, height = size + d.title_height(), r = size / 2 * kDiskScale;
  f.put("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.10g\" height=\"%.10g\" viewBox=\"0 0 %.10g %.10g\">\n",
        size, height, size, height);
  f.puts("<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n");
  f.put("<text x=\"%.2f\" y=\"%.2f\" font-family=\"sans-serif\" font-size=\"%.2f\">A surface of genus %d from a "
        "fundamental %d-gon</text>\n",
        12 * scale, 24 * scale, 16 * scale, p.genus, p.n);
  f.put("<text x=\"%.2f\" y=\"%.2f\" font-family=\"sans-serif\" font-size=\"%.2f\" fill=\"#555\">%zu vertex "
        "cycle%s (dots by cycle); glued sides share a colour and both carry their indices; Poincare disk</text>\n",
        12 * scale, 44 * scale, 13 * scale, p.cycles, p.cycles == 1 ? "" : "s");
  f.put("<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\" fill=\"#f4f6fb\" stroke=\"#333\" stroke-width=\"1.5\"/>\n", d.sx(0),
        d.sy(0), r);
  f.puts("<path fill=\"#ffd98a\" fill-opacity=\"0.35\" stroke=\"none\" d=\"");
  d.geodesic_polygon(f, p.x.data(), p.y.data(), p.n);
  f.puts("\"/>\n");
  for (int k = 0; k < p.n; ++k) {
    const std::size_t a = std::size_t(k), b = std::size_t((k + 1) % p.n);
    f.put("<path fill=\"none\" stroke=\"%s\" stroke-width=\"%.2f\" d=\"M%.2f %.2f", kPalette[pair_colour(p, k)],
          2.5 * scale, d.sx(p.x[a]), d.sy(p.y[a]));
    d.geodesic_to(f, p.x[a], p.y[a], p.x[b], p.y[b]);
    f.puts("\"/>\n");
    double mx, my;
    midpoint(p.x[a], p.y[a], p.x[b], p.y[b], &mx, &my);
    f.put("<text x=\"%.2f\" y=\"%.2f\" font-family=\"sans-serif\" font-size=\"%.2f\" text-anchor=\"middle\" "
          "fill=\"%s\">%d~%d</text>\n",
          d.sx(mx * 0.9), d.sy(my * 0.9), 12 * scale, kPalette[pair_colour(p, k)], k, p.paired[a]);
  }
  for (int k = 0; k < p.n; ++k)
    f.put("<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\" fill=\"%s\"/>\n", d.sx(p.x[std::size_t(k)]),
          d.sy(p.y[std::size_t(k)]), 3.5 * scale, kPalette[p.cycle[std::size_t(k)] % kColours]);
  f.puts("</svg>\n");
}

}  // namespace

extern "C" {

HDT_API hdt_status hdt_surface_svg(const hdt_surface *s, double size, char *text, size_t capacity,
                                   size_t *length) HDT_NOEXCEPT {
  return guarded("hdt_surface_svg", [&] {
    if (!s) throw ApiError(HDT_EINVAL, "the surface handle is NULL");
    if (!length) throw ApiError(HDT_EINVAL, "length must not be NULL");
    if (!(size > 0 && size <= HDT_SVG_SIZE_MAX))
      throw ApiError(HDT_EINVAL, "size must be a number of pixels in (0, " + std::to_string(long(HDT_SVG_SIZE_MAX)) + "]");
    if (capacity > 0 && !text) throw ApiError(HDT_EINVAL, "text is NULL but capacity is " + std::to_string(capacity));
    Text f;
    draw(f, read_polygon(s), size);
    return hdt::capi::copy_text(f.str(), "the picture", text, capacity, length);
  });
}

}  // extern "C"
