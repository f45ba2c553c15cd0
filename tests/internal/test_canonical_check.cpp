// group::check_canonical (what hdt_load uses) against canonical_word (what
// the triangulation computes): a word passes exactly when canonicalising it
// gives it back. Random words of every length up to 40 at genus 2, 3 and 5,
// their canonical forms, and those forms with one letter changed.
#include <cstdint>

#include "group/canonical.hpp"
#include "group/presentation.hpp"

extern "C" {
#include <check.h>
}

#include "random.hpp"
#include "run_suite.hpp"

using namespace hdt;

namespace {

// The check's answer where it must decide (words near O: never open).
void agrees(const group::Presentation &p, const group::Word &w, int *canonical, int *not_canonical) {
  const bool is = group::canonical_word(p, w) == w;
  const group::CanonicalCheck c = group::check_canonical(p, w.data(), w.size());
  ck_assert_msg(c != group::CanonicalCheck::kOpen, "g=%d: the check left a %zu-letter word open", p.genus(), w.size());
  ck_assert_msg((c == group::CanonicalCheck::kCanonical) == is, "g=%d: a %zu-letter word is%s canonical, the check says %s",
                p.genus(), w.size(), is ? "" : " not", c == group::CanonicalCheck::kCanonical ? "it is" : "it is not");
  ++*(is ? canonical : not_canonical);
}

}  // namespace

START_TEST(check_agrees_with_canonical_word) {
  for (const int g : {2, 3, 5}) {
    const group::Presentation p(g);
    uint64_t rng = 1000 + uint64_t(g);
    int canonical = 0, not_canonical = 0;
    for (int i = 0; i < 300; ++i) {
      group::Word w(splitmix(&rng) % 41);
      for (group::Letter &l : w) l = group::Letter(splitmix(&rng) % uint64_t(p.letter_count()));
      agrees(p, w, &canonical, &not_canonical);
      group::Word c = group::canonical_word(p, w);
      agrees(p, c, &canonical, &not_canonical);
      if (!c.empty()) {
        c[splitmix(&rng) % c.size()] = group::Letter(splitmix(&rng) % uint64_t(p.letter_count()));
        agrees(p, c, &canonical, &not_canonical);
      }
    }
    ck_assert_msg(canonical >= 300 && not_canonical >= 150, "g=%d: %d canonical, %d not", g, canonical, not_canonical);
  }
}
END_TEST

int main() {
  return run_suite("canonical_check", 300, [](TCase *tc) { tcase_add_test(tc, check_agrees_with_canonical_word); });
}
