// The order in which the symbolic perturbation of in_circle decides a tie,
// shared by the M_g kernel (predicates/kernel.hpp) and the polygon kernel
// (domain/polygon_kernel.hpp).
//
// Vertex v's rows get the last coordinate 1 + eps_v, eps of a larger vertex
// id infinitely larger, so the first non-zero coefficient of eps_v, largest
// id first, gives the sign. The coefficient of eps_v is the sum over v's
// rows r of (-1)^(r+1) R_r3 times the minor of row r and column 3. For a
// vertex in one row only, that is (-1)^(r+1) times a positive multiple of
// the orientation of the other three points (the rows are positive
// multiples of (N, 1)), which the kernel's whole pipeline decides; a vertex
// in several rows needs the exact rows (`several`).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>

namespace hdt::exact {

// orientation(i, j, k): the sign of the orientation of points i < j < k of
// the four; several(v): the sign of eps_v's coefficient for a vertex v in
// more than one row. Throws std::logic_error when every coefficient
// vanishes (four points on one geodesic, or every vertex repeated).
template <class Orientation, class Several>
int perturbed_sign(const std::array<std::uint32_t, 4> &vertex, Orientation orientation, Several several,
                   const char *who) {
  std::array<std::uint32_t, 4> order = vertex;
  std::sort(order.begin(), order.end(), std::greater<std::uint32_t>());
  for (int k = 0; k < 4; ++k) {
    if (k > 0 && order[k] == order[k - 1]) continue;
    int rows_of_vertex = 0, row = -1;
    for (int r = 0; r < 4; ++r)
      if (vertex[r] == order[k]) ++rows_of_vertex, row = r;
    int s;
    if (rows_of_vertex == 1) {
      std::array<int, 3> others{};
      for (int i = 0, j = 0; i < 4; ++i)
        if (i != row) others[j++] = i;
      s = (row % 2 == 1 ? 1 : -1) * orientation(others[0], others[1], others[2]);
    } else {
      s = several(order[k]);
    }
    if (s) return s;
  }
  throw std::logic_error(std::string(who) +
                         ": every perturbation coefficient vanishes (points on one geodesic, or each vertex repeated)");
}

}  // namespace hdt::exact
