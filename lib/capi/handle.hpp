// The opaque handle behind hdt_triangulation: a core triangulation, made
// by hdt_create (a genus), hdt_load (a restored triangulation) or
// hdt_create_on_surface (a surface given by a polygon), shared by the files
// of lib/capi that take one. It holds one of the two kinds of mesh: M_g's
// or a polygon surface's, and every call runs on either (visit).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <variant>

#include "capi/guard.hpp"
#include "dual/outputs.hpp"
#include "dummies/dummy_points.hpp"
#include "hdt.h"
#include "domain/field_lock.hpp"
#include "mesh/polygon_triangulation.hpp"
#include "mesh/progress.hpp"
#include "mesh/triangulation.hpp"

struct hdt_triangulation {
  // The genus's dummy set (built on the process's first call for it).
  explicit hdt_triangulation(int genus) : tri(hdt::dummies::new_triangulation(genus)) {}
  explicit hdt_triangulation(hdt::mesh::Triangulation &&t) : tri(std::move(t)) {}
  // in_field: the polygon's coordinates lie in a number field, so every
  // call that computes on it holds the field lock (domain/field_lock.hpp).
  hdt_triangulation(hdt::mesh::PolygonTriangulation &&t, bool in_field) : tri(std::move(t)), in_field(in_field) {}
  std::variant<hdt::mesh::Triangulation, hdt::mesh::PolygonTriangulation> tri;
  const bool in_field = false;
  hdt::mesh::Progress progress;  // hdt_set_progress; none by default
  // The dual outputs' caches and scratch, kept from call to call. Const
  // queries use them: one thread uses a handle at a time (hdt.h).
  mutable hdt::dual::Outputs outputs;
  // The long call running on this handle, which runs the caller's progress
  // function (hdt_insert_many, hdt_refine, hdt_epsilon_net; nullptr when
  // none): a call on the handle from that function is re-entry and is
  // refused (hdt::capi::check_usable), as the core is in the middle of its work.
  const char *busy = nullptr;
  // hdt_destroy from inside that call: the call frees the handle as it ends.
  bool destroy_pending = false;
};

namespace hdt::capi {

// A handle a call may use: not NULL, and no long call running on it (the
// caller's progress function calling back into its own handle). Throws
// ApiError (HDT_EINVAL) otherwise.
inline void check_usable(const hdt_triangulation *t) {
  if (!t) throw ApiError(HDT_EINVAL, "the triangulation handle is NULL");
  if (t->busy) throw ApiError(HDT_EINVAL, std::string("the triangulation is busy in ") + t->busy);
}

// f(triangulation) on either kind of mesh, under the field lock where the
// surface needs it (only there: queries called once per vertex, stars and
// cells, pay nothing for it on M_g). Const for a const handle (queries
// fill only the core's documented caches).
template <class F>
decltype(auto) visit(hdt_triangulation *t, F &&f) {
  check_usable(t);
  if (!t->in_field) return std::visit(std::forward<F>(f), t->tri);
  const domain::FieldLock lock(true);
  return std::visit(std::forward<F>(f), t->tri);
}
template <class F>
decltype(auto) visit(const hdt_triangulation *t, F &&f) {
  check_usable(t);
  if (!t->in_field) return std::visit(std::forward<F>(f), std::as_const(t->tri));
  const domain::FieldLock lock(true);
  return std::visit(std::forward<F>(f), std::as_const(t->tri));
}
// The same for the counts, which take no lock and answer for NULL too.
template <class F>
auto count(const hdt_triangulation *t, F &&f) -> decltype(f(std::declval<const mesh::Triangulation &>())) {
  if (!t) return {};
  return std::visit(std::forward<F>(f), t->tri);
}

// Frees a handle (its mesh's numbers under the field lock).
inline void destroy(hdt_triangulation *t) {
  const domain::FieldLock lock(t->in_field);
  delete t;
}

// A long call that runs the caller's progress function (hdt_insert_many,
// hdt_refine, hdt_epsilon_net), held for the call's duration: it marks the
// handle busy, and reads the progress function once, so that
// hdt_set_progress (refused meanwhile anyway) never changes a running call.
// When the progress function destroys the handle (hdt_destroy defers), the
// call stops at that report and the destructor frees the handle: the
// guard must be the last thing in the call to touch it.
class LongCall {
 public:
  LongCall(hdt_triangulation *t, const char *function)
      : t_((check_usable(t), t)), lock_(t->in_field), caller_(t->progress) {
    if (caller_.report) progress_ = {&report_unless_destroyed, this, caller_.interval};
    t->busy = function;
  }
  LongCall(const LongCall &) = delete;
  LongCall &operator=(const LongCall &) = delete;
  ~LongCall() {
    t_->busy = nullptr;
    if (t_->destroy_pending) delete t_;  // the lock is still held
  }

  // f on the mesh, either kind.
  template <class F>
  decltype(auto) visit(F &&f) const {
    return std::visit(std::forward<F>(f), t_->tri);
  }
  // For the core: the caller's function, read once; none when unset.
  const mesh::Progress *progress() const { return &progress_; }

 private:
  // The caller's report, and a stop once the caller destroyed the handle:
  // nothing of it can be read any more, so the rest of the work is wasted.
  static int report_unless_destroyed(void *self, std::size_t done, std::size_t total) {
    const LongCall &call = *static_cast<const LongCall *>(self);
    const int stop = call.caller_.report(call.caller_.user, done, total);
    return stop != 0 || call.t_->destroy_pending;
  }

  hdt_triangulation *t_;
  const domain::FieldLock lock_;
  const mesh::Progress caller_;  // the handle's progress function as the call began
  mesh::Progress progress_;      // what the core calls: none, or the function above
};

}  // namespace hdt::capi
