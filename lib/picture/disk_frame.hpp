// What the pictures of lib/picture share: the growable SVG text and the
// Poincare disk drawn in a square below a caption band, with its geodesics
// as SVG arcs. hdt_svg (svg.cpp) and hdt_surface_svg (polygon_svg.cpp) use
// it; nothing here is exported (the library's symbols are hidden).
#pragma once

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace hdt::picture {

constexpr double kReferenceSize = 800.0; // the tool's width: the caption's layout is given for it
constexpr double kTitleHeight = 56.0;    // a band above the disk for the caption, at size 800
constexpr double kTitleStep = 20.0;      // the band grows by this for each further title line, at size 800
constexpr double kInfoStep = 17.0;       // and by this for each further line of the second part
constexpr double kDiskScale = 0.97;      // the unit circle's radius, in half picture widths

// The SVG text, written with printf formats.
class Text {
 public:
  void put(const char *format, ...)
#if defined(__GNUC__)
      __attribute__((format(printf, 2, 3)))
#endif
  {
    char small[160];
    std::va_list args;
    va_start(args, format);
    const int n = std::vsnprintf(small, sizeof small, format, args);
    va_end(args);
    if (n < 0) throw std::logic_error("hdt_svg: a number could not be formatted");
    if (std::size_t(n) < sizeof small) {
      out_.append(small, std::size_t(n));
      return;
    }
    std::vector<char> large(std::size_t(n) + 1);
    va_start(args, format);
    std::vsnprintf(large.data(), large.size(), format, args);
    va_end(args);
    out_.append(large.data(), std::size_t(n));
  }
  void puts(const char *text) { out_.append(text); }
  void putc(char c) { out_.push_back(c); }
  void write(const char *p, std::size_t n) { out_.append(p, n); }
  const std::string &str() const { return out_; }

 private:
  std::string out_;
};

// The disk in a picture `size` pixels wide, below a caption band `band`
// pixels high at size 800.
class DiskFrame {
 public:
  DiskFrame(double size, double band) : size_(size), band_(band) {}

  // Disk coordinates to SVG coordinates (y points down in SVG), rounded to
  // 0.01 px when printed (about 3e-5 in the disk at size 800): enough for
  // the eye and for zooming in, and it keeps the files small.
  double sx(double x) const { return size_ / 2 * (1 + kDiskScale * x); }
  double sy(double y) const { return title_height() + size_ / 2 * (1 - kDiskScale * y); }
  double title_height() const { return band_ * size_ / kReferenceSize; }

  // Path data for the geodesic from p to q: an arc of the circle orthogonal
  // to the unit circle through both, or a segment when p, q and 0 are
  // collinear (within a rounding-size margin, where the arc's radius would
  // exceed any visible curvature). Inside the disk that arc is less than a
  // half circle (large-arc flag 0). The sweep flag follows the turn from p
  // to q about the circle's centre c: counterclockwise in the disk (y up) is
  // flag 0 in SVG's y-down coordinates.
  void geodesic_to(Text &f, double px, double py, double qx, double qy) const {
    const double cross = px * qy - py * qx;
    const double bp = (1 + px * px + py * py) / 2, bq = (1 + qx * qx + qy * qy) / 2;
    if (std::fabs(cross) <= 1e-9 * bp * bq) {
      f.put("L%.2f %.2f", sx(qx), sy(qy));
      return;
    }
    // c solves c.p = (1 + |p|^2)/2 and c.q = (1 + |q|^2)/2.
    const double cx = (bp * qy - bq * py) / cross, cy = (px * bq - qx * bp) / cross;
    const double r = std::sqrt(std::fmax(cx * cx + cy * cy - 1, 0)) * size_ / 2 * kDiskScale;
    const bool counterclockwise = (px - cx) * (qy - cy) - (py - cy) * (qx - cx) > 0;
    f.put("A%.2f %.2f 0 0 %d %.2f %.2f", r, r, counterclockwise ? 0 : 1, sx(qx), sy(qy));
  }

  // A closed geodesic polygon through n disk points, as path data.
  void geodesic_polygon(Text &f, const double *x, const double *y, int n) const {
    f.put("M%.2f %.2f", sx(x[0]), sy(y[0]));
    for (int k = 0; k < n; ++k) geodesic_to(f, x[k], y[k], x[(k + 1) % n], y[(k + 1) % n]);
    f.putc('Z');
  }

 protected:
  double size_, band_;
};

}  // namespace hdt::picture
