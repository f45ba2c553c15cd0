// Progress reports and cancellation for long calls (insert_many, refine):
// a caller's function, asked at most once per interval whether to go on.
// The clock is read once per kStride items only, so that a call without a
// reporter, or with one, costs the insertion loop a counter and a branch.
#pragma once

#include <chrono>
#include <cstddef>

namespace hdt::mesh {

struct Progress {
  // Returns non-zero to stop the call. total 0: not known in advance.
  int (*report)(void *user, std::size_t done, std::size_t total) = nullptr;
  void *user = nullptr;
  double interval = 0;  // seconds between reports; 0: every kStride items
};

class ProgressTicker {
 public:
  static constexpr std::size_t kStride = 256;

  ProgressTicker(const Progress *p, std::size_t total)
      : p_(p && p->report ? p : nullptr), total_(total), last_(std::chrono::steady_clock::now()) {}

  // After item `done` (1-based): true when the reporter asks to stop.
  bool stop(std::size_t done) {
    if (!p_ || done % kStride != 0) return false;
    const auto now = std::chrono::steady_clock::now();
    if (std::chrono::duration<double>(now - last_).count() < p_->interval) return false;
    last_ = now;
    return p_->report(p_->user, done, total_) != 0;
  }

  // The last report of a call that ran to the end: done == total.
  void finish(std::size_t done) const {
    if (p_) p_->report(p_->user, done, done);
  }

 private:
  const Progress *p_;
  std::size_t total_;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace hdt::mesh
