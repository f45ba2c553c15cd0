/* The C ABI contract: statuses, error messages, argument checks, the
   two-call pattern, versions. */
#include <float.h>
#include <limits.h>
#include <pthread.h>

#include "hdt_test.h"

/* ---- Outputs that failing calls must leave alone ---- */

#define SENTINEL_D (-12345.5)
#define SENTINEL_W ((int32_t)-777)
#define SENTINEL_N ((size_t)987654321)

static double out_d[9];
static int32_t out_w[16];
static size_t out_n;

static void reset_outputs(void) {
  for (size_t i = 0; i < 9; ++i) out_d[i] = SENTINEL_D;
  for (size_t i = 0; i < 16; ++i) out_w[i] = SENTINEL_W;
  out_n = SENTINEL_N;
}

static void expect_outputs_untouched(const char *function) {
  const char *msg = hdt_last_error_message();
  for (size_t i = 0; i < 9; ++i)
    ck_assert_msg(out_d[i] == SENTINEL_D, "%s wrote a double output on failure (%s)", function, msg);
  for (size_t i = 0; i < 16; ++i)
    ck_assert_msg(out_w[i] == SENTINEL_W, "%s wrote a letter on failure (%s)", function, msg);
  ck_assert_msg(out_n == SENTINEL_N, "%s wrote a length on failure (%s)", function, msg);
}

/* ---- Status strings ---- */

START_TEST(status_strings) {
  const int codes[] = {HDT_OK,     HDT_ERROR, HDT_EINVAL,  HDT_EDOMAIN,  HDT_EEXISTS,
                       HDT_ENOMEM, HDT_EBUFS, HDT_ENOTSUP, HDT_EINTERNAL};
  const size_t n = sizeof codes / sizeof codes[0];
  /* The values are pinned forever. */
  const int pinned[] = {0, -1, -2, -3, -4, -5, -6, -7, -99};
  for (size_t i = 0; i < n; ++i) ck_assert_int_eq(codes[i], pinned[i]);
  for (size_t i = 0; i < n; ++i) {
    const char *s = hdt_status_string(codes[i]);
    ck_assert_ptr_nonnull(s);
    ck_assert_uint_gt(strlen(s), 0);
    ck_assert_str_ne(s, "unknown status");
    for (size_t j = 0; j < i; ++j) ck_assert_str_ne(s, hdt_status_string(codes[j]));
  }
  const int unknown[] = {12345, 1, -8, -98, -100, INT_MIN, INT_MAX};
  for (size_t i = 0; i < sizeof unknown / sizeof unknown[0]; ++i) {
    const char *s = hdt_status_string(unknown[i]);
    ck_assert_ptr_nonnull(s);
    ck_assert_str_eq(s, "unknown status");
  }
}
END_TEST

/* ---- NULL pointers ---- */

static const int32_t word3[3] = {0, 1, 2};

static hdt_status vertex_null_x(void) { return hdt_polygon_vertex(2, 0, NULL, &out_d[0]); }
static hdt_status vertex_null_y(void) { return hdt_polygon_vertex(2, 0, &out_d[0], NULL); }
static hdt_status midpoint_null_x(void) { return hdt_polygon_side_midpoint(2, 0, NULL, &out_d[0]); }
static hdt_status midpoint_null_y(void) { return hdt_polygon_side_midpoint(2, 0, &out_d[0], NULL); }
static hdt_status reduce_null_length(void) { return hdt_word_reduce(2, word3, 3, out_w, 16, NULL); }
static hdt_status reduce_null_out(void) { return hdt_word_reduce(2, word3, 3, NULL, 16, &out_n); }
static hdt_status reduce_null_word(void) { return hdt_word_reduce(2, NULL, 3, out_w, 16, &out_n); }
static hdt_status matrix_null_m(void) { return hdt_word_matrix(2, word3, 3, NULL); }
static hdt_status matrix_null_word(void) { return hdt_word_matrix(2, NULL, 3, out_d); }
static hdt_status lorentz_null_m(void) { return hdt_word_lorentz(2, word3, 3, NULL); }
static hdt_status lorentz_null_word(void) { return hdt_word_lorentz(2, NULL, 3, out_d); }
static hdt_status apply_null_x(void) { return hdt_word_apply(2, word3, 3, 0.1, 0.2, NULL, &out_d[0]); }
static hdt_status apply_null_y(void) { return hdt_word_apply(2, word3, 3, 0.1, 0.2, &out_d[0], NULL); }
static hdt_status apply_null_word(void) { return hdt_word_apply(2, NULL, 3, 0.1, 0.2, &out_d[0], &out_d[1]); }
static hdt_status count_null(void) { return hdt_neighbour_count(2, NULL); }
static hdt_status neighbour_null_length(void) { return hdt_neighbour_word(2, 3, out_w, 16, NULL); }
static hdt_status neighbour_null_out(void) { return hdt_neighbour_word(2, 3, NULL, 16, &out_n); }

typedef struct call_case {
  const char *function;
  hdt_status (*call)(void);
} call_case;

START_TEST(null_pointers_are_rejected) {
  const call_case cases[] = {
      {"hdt_polygon_vertex", vertex_null_x},
      {"hdt_polygon_vertex", vertex_null_y},
      {"hdt_polygon_side_midpoint", midpoint_null_x},
      {"hdt_polygon_side_midpoint", midpoint_null_y},
      {"hdt_word_reduce", reduce_null_length},
      {"hdt_word_reduce", reduce_null_out},
      {"hdt_word_reduce", reduce_null_word},
      {"hdt_word_matrix", matrix_null_m},
      {"hdt_word_matrix", matrix_null_word},
      {"hdt_word_lorentz", lorentz_null_m},
      {"hdt_word_lorentz", lorentz_null_word},
      {"hdt_word_apply", apply_null_x},
      {"hdt_word_apply", apply_null_y},
      {"hdt_word_apply", apply_null_word},
      {"hdt_neighbour_count", count_null},
      {"hdt_neighbour_word", neighbour_null_length},
      {"hdt_neighbour_word", neighbour_null_out},
  };
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
    reset_outputs();
    expect_failure(cases[i].call(), HDT_EINVAL, cases[i].function);
    expect_outputs_untouched(cases[i].function);
  }
}
END_TEST

/* The empty word may be NULL: it is the identity. */
START_TEST(empty_word_is_identity) {
  double m[4], L[9], x, y;
  size_t len = SENTINEL_N;
  ck_assert_int_eq(hdt_word_matrix(3, NULL, 0, m), HDT_OK);
  ck_assert(m[0] == 1 && m[1] == 0 && m[2] == 0 && m[3] == 0);
  ck_assert_int_eq(hdt_word_lorentz(3, NULL, 0, L), HDT_OK);
  for (int i = 0; i < 9; ++i) ck_assert(L[i] == (i % 4 == 0 ? 1 : 0));
  ck_assert_int_eq(hdt_word_apply(3, NULL, 0, 0.25, -0.5, &x, &y), HDT_OK);
  ck_assert(x == 0.25 && y == -0.5);
  ck_assert_int_eq(hdt_word_reduce(3, NULL, 0, NULL, 0, &len), HDT_OK);
  ck_assert_uint_eq(len, 0);
}
END_TEST

/* ---- Genus checks ---- */

static const int32_t letter0[1] = {0};

static hdt_status genus_vertex(int g) { return hdt_polygon_vertex(g, 0, &out_d[0], &out_d[1]); }
static hdt_status genus_midpoint(int g) { return hdt_polygon_side_midpoint(g, 0, &out_d[0], &out_d[1]); }
static hdt_status genus_reduce(int g) { return hdt_word_reduce(g, letter0, 1, out_w, 16, &out_n); }
static hdt_status genus_matrix(int g) { return hdt_word_matrix(g, letter0, 1, out_d); }
static hdt_status genus_lorentz(int g) { return hdt_word_lorentz(g, letter0, 1, out_d); }
static hdt_status genus_apply(int g) { return hdt_word_apply(g, letter0, 1, 0.1, 0.2, &out_d[0], &out_d[1]); }
static hdt_status genus_count(int g) { return hdt_neighbour_count(g, &out_n); }
static hdt_status genus_neighbour(int g) { return hdt_neighbour_word(g, 1, out_w, 16, &out_n); }

typedef struct genus_case {
  const char *function;
  hdt_status (*call)(int genus);
} genus_case;

static const genus_case genus_cases[] = {
    {"hdt_polygon_vertex", genus_vertex}, {"hdt_polygon_side_midpoint", genus_midpoint},
    {"hdt_word_reduce", genus_reduce},    {"hdt_word_matrix", genus_matrix},
    {"hdt_word_lorentz", genus_lorentz},  {"hdt_word_apply", genus_apply},
    {"hdt_neighbour_count", genus_count}, {"hdt_neighbour_word", genus_neighbour},
};

START_TEST(genus_is_checked) {
  const int too_small[] = {1, 0, -1, -5, INT_MIN};
  const int too_large[] = {HDT_GENUS_MAX + 1, 2000, INT_MAX};
  const int fine[] = {2, 3, 17, HDT_GENUS_MAX};
  for (size_t c = 0; c < sizeof genus_cases / sizeof genus_cases[0]; ++c) {
    const genus_case *gc = &genus_cases[c];
    for (size_t i = 0; i < sizeof too_small / sizeof too_small[0]; ++i) {
      reset_outputs();
      expect_failure(gc->call(too_small[i]), HDT_EINVAL, gc->function);
      expect_outputs_untouched(gc->function);
    }
    for (size_t i = 0; i < sizeof too_large / sizeof too_large[0]; ++i) {
      reset_outputs();
      expect_failure(gc->call(too_large[i]), HDT_ENOTSUP, gc->function);
      expect_outputs_untouched(gc->function);
    }
    for (size_t i = 0; i < sizeof fine / sizeof fine[0]; ++i) {
      const hdt_status s = gc->call(fine[i]);
      ck_assert_msg(s == HDT_OK, "%s(genus %d): %s", gc->function, fine[i], hdt_last_error_message());
    }
  }
}
END_TEST

/* ---- Letter checks ---- */

static hdt_status letters_reduce(int g, const int32_t *w, size_t n) {
  return hdt_word_reduce(g, w, n, out_w, 16, &out_n);
}
static hdt_status letters_matrix(int g, const int32_t *w, size_t n) { return hdt_word_matrix(g, w, n, out_d); }
static hdt_status letters_lorentz(int g, const int32_t *w, size_t n) { return hdt_word_lorentz(g, w, n, out_d); }
static hdt_status letters_apply(int g, const int32_t *w, size_t n) {
  return hdt_word_apply(g, w, n, 0.1, 0.2, &out_d[0], &out_d[1]);
}

typedef struct word_case {
  const char *function;
  hdt_status (*call)(int genus, const int32_t *word, size_t length);
} word_case;

static const word_case word_cases[] = {
    {"hdt_word_reduce", letters_reduce},
    {"hdt_word_matrix", letters_matrix},
    {"hdt_word_lorentz", letters_lorentz},
    {"hdt_word_apply", letters_apply},
};

START_TEST(letters_are_checked) {
  for (size_t c = 0; c < sizeof word_cases / sizeof word_cases[0]; ++c) {
    const word_case *wc = &word_cases[c];
    for (int g = 2; g <= 3; ++g) {
      const int32_t bad[] = {-1, 4 * g, 4 * g + 1, 2 * 4 * g, INT32_MIN, INT32_MAX};
      int32_t w[5] = {1, 2, 3, 4, 5};
      for (size_t b = 0; b < sizeof bad / sizeof bad[0]; ++b)
        for (size_t pos = 0; pos < 5; pos += 2) {
          w[pos] = bad[b];
          reset_outputs();
          expect_failure(wc->call(g, w, 5), HDT_EINVAL, wc->function);
          expect_outputs_untouched(wc->function);
          w[pos] = (int32_t)pos + 1;
        }
      /* The last valid letter is fine. */
      const int32_t last[2] = {0, 4 * g - 1};
      ck_assert_int_eq(wc->call(g, last, 2), HDT_OK);
    }
  }
}
END_TEST

START_TEST(word_length_limit) {
  const size_t n = (size_t)HDT_WORD_MAX_LENGTH + 1;
  int32_t *w = malloc(n * sizeof *w);
  ck_assert_ptr_nonnull(w);
  /* g_0 g_0^-1 g_0 g_0^-1 ...: the longest accepted word reduces to nothing. */
  for (size_t i = 0; i < n; ++i) w[i] = (i % 2) ? 4 : 0;
  size_t len = SENTINEL_N;
  ck_assert_int_eq(hdt_word_reduce(2, w, n - 1, NULL, 0, &len), HDT_OK);
  ck_assert_uint_eq(len, 0);
  for (size_t c = 0; c < sizeof word_cases / sizeof word_cases[0]; ++c) {
    reset_outputs();
    const hdt_status s = word_cases[c].call(2, w, n);
    ck_assert_msg(s != HDT_OK, "%s accepts %zu letters", word_cases[c].function, n);
    expect_failure(s, s, word_cases[c].function); /* any failure status, named */
    expect_outputs_untouched(word_cases[c].function);
  }
  free(w);
}
END_TEST

/* ---- The domain of hdt_word_apply ---- */


START_TEST(apply_domain) {
  const double nan_ = nan(""), inf = INFINITY, below1 = nextafter(1.0, 0.0);
  const struct {
    double x, y;
    int inside;
  } points[] = {
      {nan_, 0, 0},
      {0, nan_, 0},
      {-nan_, 0.5, 0},
      {inf, 0, 0},
      {0, -inf, 0},
      {-inf, inf, 0},
      {1, 0, 0},
      {0, 1, 0},
      {-1, 0, 0},
      {0, -1, 0},
      {2, 0, 0},
      {DBL_MAX, 0, 0},
      /* 0.6^2 + 0.8^2 rounds to 1 in doubles; exactly, as the doubles nearest
         0.6 and 0.8, it is 1 + 4.4e-17: outside. */
      {0.6, 0.8, 0},
      {-0.8, 0.6, 0},
      {0.5403023058681398, 0.8414709848078965, 0}, /* cos 1, sin 1: 1 + 4.8e-17 */
      /* Exactly inside although the rounded sum of squares is 1 (or more). */
      {0.28, 0.96, 1},
      {0.5999999999999999, 0.8, 1},
      {0.955336489125606, 0.29552020666133955, 1}, /* cos 0.3, sin 0.3 */
      {below1, 0, 1},
      {0, -below1, 1},
      {0, 0, 1},
      {-0.0, -0.0, 1},
      {DBL_TRUE_MIN, -DBL_MIN, 1},
  };
  const int32_t gen[1] = {3};
  for (size_t i = 0; i < sizeof points / sizeof points[0]; ++i) {
    const double x = points[i].x, y = points[i].y;
    const int cmp = exact_norm_vs_one(x, y);
    if (isfinite(x) && isfinite(y) && cmp != 2)
      ck_assert_msg((cmp < 0) == points[i].inside, "test table: (%.17g, %.17g) misclassified", x, y);
    for (size_t len = 0; len <= 1; ++len) {
      reset_outputs();
      const hdt_status s = hdt_word_apply(2, gen, len, x, y, &out_d[0], &out_d[1]);
      if (points[i].inside && len == 1 && s == HDT_EDOMAIN) {
        /* An inside point whose image rounds onto the circle: refused. */
        ck_assert_msg(strstr(hdt_last_error_message(), "rounds to the unit circle"), "(%.17g, %.17g): %s", x, y,
                      hdt_last_error_message());
        expect_outputs_untouched("hdt_word_apply");
      } else if (points[i].inside) {
        ck_assert_msg(s == HDT_OK, "(%.17g, %.17g) rejected: %s", x, y, hdt_last_error_message());
        ck_assert(isfinite(out_d[0]) && isfinite(out_d[1]));
        /* The image is a point of the open disk (the identity: the input). */
        const int image = exact_norm_vs_one(out_d[0], out_d[1]);
        ck_assert(image == 2 ? hypot(out_d[0], out_d[1]) < 1 : image < 0);
        if (len == 0) ck_assert(out_d[0] == x && out_d[1] == y);
      } else {
        expect_failure(s, HDT_EDOMAIN, "hdt_word_apply");
        expect_outputs_untouched("hdt_word_apply");
      }
    }
  }
}
END_TEST

/* ---- The two-call pattern ---- */

typedef struct two_call_case {
  const char *function;
  int genus;
  hdt_status (*call)(int32_t *out, size_t capacity, size_t *length);
} two_call_case;

static const int32_t some_word[5] = {1, 2, 3, 1, 6};
static hdt_status two_call_reduce(int32_t *out, size_t capacity, size_t *length) {
  return hdt_word_reduce(2, some_word, 5, out, capacity, length);
}
/* The last neighbour of genus 3 has 2g = 6 letters. */
static hdt_status two_call_neighbour(int32_t *out, size_t capacity, size_t *length) {
  return hdt_neighbour_word(3, 11 * 11 - 1, out, capacity, length);
}

START_TEST(two_call_pattern) {
  const two_call_case cases[] = {{"hdt_word_reduce", 2, two_call_reduce},
                                 {"hdt_neighbour_word", 3, two_call_neighbour}};
  for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
    const two_call_case *tc = &cases[c];
    size_t need = SENTINEL_N;
    ck_assert_int_eq(tc->call(NULL, 0, &need), HDT_OK);
    ck_assert_uint_ge(need, 2);
    ck_assert_uint_le(need, 10);
    /* Capacity 0 with a buffer: the length only. */
    reset_outputs();
    ck_assert_int_eq(tc->call(out_w, 0, &out_n), HDT_OK);
    ck_assert_uint_eq(out_n, need);
    for (size_t i = 0; i < 16; ++i) ck_assert_int_eq(out_w[i], SENTINEL_W);
    /* Too small: HDT_EBUFS, the length set, the buffer untouched. */
    for (size_t cap = 1; cap < need; ++cap) {
      reset_outputs();
      expect_failure(tc->call(out_w, cap, &out_n), HDT_EBUFS, tc->function);
      ck_assert_uint_eq(out_n, need);
      for (size_t i = 0; i < 16; ++i) ck_assert_int_eq(out_w[i], SENTINEL_W);
    }
    /* Exactly enough, and more: the word and nothing beyond it. */
    for (size_t cap = need; cap <= need + 3; cap += 3) {
      reset_outputs();
      ck_assert_int_eq(tc->call(out_w, cap, &out_n), HDT_OK);
      ck_assert_uint_eq(out_n, need);
      for (size_t i = 0; i < need; ++i) ck_assert(out_w[i] >= 0 && out_w[i] < 4 * tc->genus);
      for (size_t i = need; i < 16; ++i) ck_assert_int_eq(out_w[i], SENTINEL_W);
    }
  }
}
END_TEST

START_TEST(neighbour_id_is_checked) {
  for (int g = 2; g <= 4; ++g) {
    size_t count = 0;
    ck_assert_int_eq(hdt_neighbour_count(g, &count), HDT_OK);
    const size_t bad[] = {count, count + 1, SIZE_MAX};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
      reset_outputs();
      expect_failure(hdt_neighbour_word(g, bad[i], out_w, 16, &out_n), HDT_EINVAL, "hdt_neighbour_word");
      expect_outputs_untouched("hdt_neighbour_word");
    }
    ck_assert_int_eq(hdt_neighbour_word(g, count - 1, out_w, 16, &out_n), HDT_OK);
  }
}
END_TEST

/* ---- Versions ---- */

START_TEST(versions) {
  const char *s = hdt_version_string();
  ck_assert_ptr_nonnull(s);
  ck_assert_str_eq(s, HDT_TEST_PROJECT_VERSION);
  int major = -1, minor = -1, patch = -1, used = 0;
  ck_assert_int_eq(sscanf(s, "%d.%d.%d%n", &major, &minor, &patch, &used), 3);
  ck_assert_uint_eq((size_t)used, strlen(s));
  ck_assert(major >= 0 && minor >= 0 && minor < 100 && patch >= 0 && patch < 100);
  ck_assert_int_eq(hdt_version(), major * 10000 + minor * 100 + patch);
  /* The header this test was compiled with is the library's. */
  ck_assert_int_eq(hdt_version(), HDT_VERSION);
  ck_assert_int_eq(HDT_VERSION_MAJOR * 10000 + HDT_VERSION_MINOR * 100 + HDT_VERSION_PATCH, HDT_VERSION);
  ck_assert_int_eq(hdt_abi_version(), 0);
}
END_TEST

/* ---- The error message is per thread ---- */

static void *fail_in_thread(void *arg) {
  char *result = arg;
  /* Nothing failed on this thread yet. */
  char before[128];
  snprintf(before, sizeof before, "%s", hdt_last_error_message());
  double x, y;
  const hdt_status s = hdt_polygon_vertex(0, 0, &x, &y);
  snprintf(result, 256, "%s|%d|%s", before, (int)s, hdt_last_error_message());
  return NULL;
}

START_TEST(error_message_is_thread_local) {
  double m[4];
  expect_failure(hdt_word_matrix(1, letter0, 1, m), HDT_EINVAL, "hdt_word_matrix");
  char mine[256], theirs[256] = "";
  snprintf(mine, sizeof mine, "%s", hdt_last_error_message());
  pthread_t thread;
  ck_assert_int_eq(pthread_create(&thread, NULL, fail_in_thread, theirs), 0);
  ck_assert_int_eq(pthread_join(thread, NULL), 0);
  ck_assert_msg(strncmp(theirs, "|-2|", 4) == 0, "other thread saw \"%s\"", theirs);
  ck_assert_ptr_nonnull(strstr(theirs, "hdt_polygon_vertex"));
  ck_assert_str_eq(hdt_last_error_message(), mine);
}
END_TEST

int main(void) {
  const TTest *const tests[] = {
      status_strings,
      null_pointers_are_rejected,
      empty_word_is_identity,
      genus_is_checked,
      letters_are_checked,
      word_length_limit,
      apply_domain,
      two_call_pattern,
      neighbour_id_is_checked,
      versions,
      error_message_is_thread_local,
  };
  return run_tests("api", tests, sizeof tests / sizeof tests[0]);
}
