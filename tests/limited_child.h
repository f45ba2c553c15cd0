/* The out-of-memory tests' child process: a test forks, the child sets a
   tight address-space limit (RLIMIT_AS) above what it already uses, runs
   into it, reports a broken expectation on stderr and exits 1, or exits 0.
   POSIX; included by test_enomem.c, test_svg.c and test_refine.c. */
#ifndef HDT_LIMITED_CHILD_H
#define HDT_LIMITED_CHILD_H

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <check.h>

/* In the child: reports a broken expectation on stderr and exits with 1
   (Check's assertions would not reach the parent). */
#define require(cond, ...)                                \
  do {                                                    \
    if (!(cond)) {                                        \
      fputs("limited child: ", stderr);                   \
      fprintf(stderr, __VA_ARGS__);                       \
      fputc('\n', stderr);                                \
      _exit(1);                                           \
    }                                                     \
  } while (0)

/* The process's address space now, in bytes (first field of statm). */
static inline size_t address_space_bytes(void) {
  FILE *f = fopen("/proc/self/statm", "r");
  unsigned long pages = 0;
  if (f) {
    if (fscanf(f, "%lu", &pages) != 1) pages = 0;
    fclose(f);
  }
  return (size_t)pages * (size_t)sysconf(_SC_PAGESIZE);
}

/* Runs child() in a forked process (it must end with _exit) and fails the
   test unless that process exits with 0. */
static inline void run_child(void (*child)(void)) {
  fflush(stdout);
  fflush(stderr);
  const pid_t pid = fork();
  ck_assert_msg(pid >= 0, "fork: %s", strerror(errno));
  if (pid == 0) {
    child();
    _exit(0);
  }
  int status = 0;
  ck_assert_msg(waitpid(pid, &status, 0) == pid, "waitpid: %s", strerror(errno));
  ck_assert_msg(WIFEXITED(status) && WEXITSTATUS(status) == 0,
                "the child failed (its message is on stderr): exit %d, signal %d",
                WIFEXITED(status) ? WEXITSTATUS(status) : -1, WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

#endif /* HDT_LIMITED_CHILD_H */
