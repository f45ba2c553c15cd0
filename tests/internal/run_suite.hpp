// The main() of an internal Check suite: one test case, the listed tests,
// Check's summary line, exit status 0 when every test passed.
#pragma once

#include <check.h>

#include <functional>

// `add` registers the tests on the test case (tcase_add_test and friends).
inline int run_suite(const char *name, double timeout_seconds, const std::function<void(TCase *)> &add) {
  Suite *suite = suite_create(name);
  TCase *tc = tcase_create(name);
  tcase_set_timeout(tc, timeout_seconds);
  add(tc);
  suite_add_tcase(suite, tc);
  SRunner *runner = srunner_create(suite);
  srunner_run_all(runner, CK_NORMAL);
  const int failed = srunner_ntests_failed(runner);
  srunner_free(runner);
  return failed == 0 ? 0 : 1;
}
