// The predicates' Sign is the exact layer's (exact/sign.hpp): a stage
// returns `undecided` when its certified error bound cannot separate the
// value from zero, and the driver (kernel.cpp) runs the stages until one
// decides.
#pragma once

#include "exact/sign.hpp"

namespace hdt::predicates {

using exact::decided;
using exact::Sign;
using exact::sign_beyond;
using exact::sign_of_int;
using exact::to_int;
using exact::operator-;

}  // namespace hdt::predicates
