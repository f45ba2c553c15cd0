#include "domain/field_lock.hpp"

namespace hdt::domain {

namespace {
std::recursive_mutex &field_mutex() {
  static std::recursive_mutex mutex;
  return mutex;
}
}  // namespace

FieldLock::FieldLock(bool needed) {
  if (needed) lock_ = std::unique_lock<std::recursive_mutex>(field_mutex());
}

}  // namespace hdt::domain
