// k modulo n in [0, n), for any integer k: the index of a letter, a side, a
// vertex or a sector of F_g read cyclically (C++'s % keeps the sign of k).
#pragma once

namespace hdt::group {

template <class Int>
constexpr Int cyclic(Int k, Int n) {
  return (k % n + n) % n;
}

}  // namespace hdt::group
