// Whole turns counted exactly, with no angle ever computed.
//
// Let D_0, ..., D_m be nonzero complex numbers, each a counterclockwise turn
// of less than a half turn from the one before: Im(D_t conj(D_{t-1})) > 0.
// Lift their arguments continuously, phi_0 <= phi_1 <= ... (each step in
// (0, pi)). Then floor(phi_t / pi) rises by 0 or 1 per step, and its parity
// is read off D_t's half plane: even when Im D_t > 0 or D_t is real positive,
// odd when Im D_t < 0 or D_t is real negative. So the count of parity changes
// is exactly floor(phi_m / pi) - floor(phi_0 / pi), decided by signs alone.
#pragma once

#include <vector>

#include "domain/complex.hpp"

namespace hdt::domain {

// Im(w conj(v)) > 0: w is v turned counterclockwise by an angle in (0, pi).
bool turns_left(const Complex &v, const Complex &w);

// floor(phi_m / pi) - floor(phi_0 / pi) for directions as above. Throws
// std::invalid_argument when a step does not turn left by less than pi.
long half_turns(const std::vector<Complex> &directions);

// The positive real numbers: D has argument 0 mod 2 pi.
bool is_positive_real(const Complex &d);

}  // namespace hdt::domain
