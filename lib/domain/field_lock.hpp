// One thread at a time in number-field arithmetic.
//
// e-antic keeps one embedding per field, shared by every element of it and by
// every surface read with the same field line (its fields are unique), and
// refines that embedding in place when a comparison needs more bits. Two
// threads comparing numbers of one field race on it: e-antic 1.3 asserts
// ("An embedding cannot be safely refined in a multi-threaded environment")
// and aborts, and making a field reads every equal field's embedding. So all
// of libhdt's work on numbers of a field runs under one process-wide lock: a
// FieldLock is held around every call on a surface whose coordinates lie in
// a field, and around reading a polygon text that names one. Rational
// surfaces take no lock: e-antic's field Q never refines.
#pragma once

#include <mutex>

namespace hdt::domain {

class FieldLock {
 public:
  // Takes the lock when needed (recursive: a locked call may call another).
  explicit FieldLock(bool needed);

 private:
  std::unique_lock<std::recursive_mutex> lock_;
};

}  // namespace hdt::domain
