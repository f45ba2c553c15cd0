#include "group/dehn.hpp"

namespace hdt::group {

namespace {

// The output stack of the reduction. For each letter it keeps the length of
// the longest relator run ending there, so a run of 2g+1 letters is seen the
// moment it appears.
class ReducedStack {
 public:
  // Room for `length` letters: a reduction rarely lengthens its word, and
  // the three stacks grew by doubling from empty, a fifth of intern()'s
  // instructions at genus 128 (products of runs hundreds of letters long).
  ReducedStack(const Presentation &p, std::size_t length) : p_(p) {
    letters_.reserve(length);
    run_length_.reserve(length);
    run_step_.reserve(length);
  }

  // Pushes one letter; afterwards the stack is Dehn-reduced again, and the
  // letters a replacement produced are left in `pending` (to be pushed next,
  // back() first).
  void push(Letter k, Word &pending) {
    if (!letters_.empty() && letters_.back() == p_.inverse(k)) {
      pop();
      return;
    }
    int run = 1;
    if (!letters_.empty()) {
      const int s = p_.step(letters_.back(), k);
      if (p_.is_run_step(s)) run = (run_length_.back() >= 2 && run_step_.back() == s) ? run_length_.back() + 1 : 2;
      run_step_.push_back(s);
    } else {
      run_step_.push_back(0);
    }
    letters_.push_back(k);
    run_length_.push_back(run);
    if (run > p_.half_relator()) replace_long_run(pending);
  }

  Word take() { return std::move(letters_); }

 private:
  void pop() {
    letters_.pop_back();
    run_length_.pop_back();
    run_step_.pop_back();
  }

  // The top 2g+1 letters u = y, y+d, ..., y+2g d are more than half of a
  // relator rotation u v; replace u by the shorter v^{-1} (2g-1 letters).
  void replace_long_run(Word &pending) {
    const int n = p_.letter_count(), h = p_.half_relator();
    const int d = run_step_.back();
    const Letter y = letters_[letters_.size() - 1 - h];
    for (int i = 0; i <= h; ++i) pop();
    // v = y+(2g+1)d, ..., y+(4g-1)d; v^{-1} read left to right is
    // inv(y+(4g-1)d), ..., inv(y+(2g+1)d). pending is consumed from the back.
    for (int j = h + 1; j <= n - 1; ++j) pending.push_back(p_.inverse(static_cast<Letter>((y + int64_t(j) * d) % n)));
  }

  const Presentation &p_;
  Word letters_;
  std::vector<int> run_length_;
  std::vector<int> run_step_;
};

}  // namespace

Word dehn_reduce(const Presentation &p, const Letter *w, std::size_t length) {
  ReducedStack stack(p, length);
  Word pending;
  // Letters still to push, consumed from the back: the input reversed.
  pending.reserve(length);
  for (std::size_t i = length; i-- > 0;) pending.push_back(w[i]);
  while (!pending.empty()) {
    const Letter k = pending.back();
    pending.pop_back();
    stack.push(k, pending);
  }
  return stack.take();
}

bool is_dehn_reduced(const Presentation &p, const Word &w) {
  int run = 1, last_step = 0;
  for (std::size_t i = 1; i < w.size(); ++i) {
    if (w[i] == p.inverse(w[i - 1])) return false;
    const int s = p.step(w[i - 1], w[i]);
    run = p.is_run_step(s) ? (run >= 2 && s == last_step ? run + 1 : 2) : 1;
    last_step = s;
    if (run > p.half_relator()) return false;
  }
  return true;
}

}  // namespace hdt::group
