#include "domain/turning.hpp"

#include <stdexcept>

namespace hdt::domain {

namespace {

// floor(arg / pi) mod 2, for any lift of the argument of d != 0.
int half_plane(const Complex &d) {
  const int s = d.im.sgn();
  if (s != 0) return s > 0 ? 0 : 1;
  return d.re.sgn() > 0 ? 0 : 1;
}

}  // namespace

bool turns_left(const Complex &v, const Complex &w) { return (w * conj(v)).im.sgn() > 0; }

long half_turns(const std::vector<Complex> &directions) {
  long count = 0;
  for (std::size_t t = 1; t < directions.size(); ++t) {
    if (!turns_left(directions[t - 1], directions[t]))
      throw std::invalid_argument("half_turns: a step that is not a left turn of less than pi");
    count += half_plane(directions[t]) != half_plane(directions[t - 1]) ? 1 : 0;
  }
  return count;
}

bool is_positive_real(const Complex &d) { return d.im.is_zero() && d.re.sgn() > 0; }

}  // namespace hdt::domain
