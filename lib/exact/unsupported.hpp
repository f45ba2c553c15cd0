// The one exception for work beyond what this build computes: a word too
// long for the top rung of a precision ladder, a genus past the dummy
// construction's, more vertices or translation ids than 32-bit ids name.
// It is not a bug and not bad input; the C API reports it as HDT_ENOTSUP
// (capi/guard.hpp), which reports a std::length_error of the standard
// library (a container past its max_size) as HDT_ENOMEM.
#pragma once

#include <stdexcept>
#include <string>

namespace hdt::exact {

struct Unsupported : std::runtime_error {
  explicit Unsupported(const std::string &what) : std::runtime_error(what) {}
};

}  // namespace hdt::exact
