/* hdt_svg: the picture's contract (bad arguments write nothing, the two-call
   pattern, escaping, determinism, flags) and what it shows (a dot per place
   of each vertex in the closed F_g, the caption's counts). */
#define _DEFAULT_SOURCE

#include <errno.h>
#include <float.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "hdt_test.h"
#include "limited_child.h"

#define USER_COLOUR "#1f2a44"
#define DUMMY_COLOUR "#d62728"
#define CANARY ((char)0x5a)
#define LENGTH_SENTINEL ((size_t)987654321)

/* The picture, through the two-call pattern (asserts success; free it). */
static char *picture(const hdt_triangulation *t, double size, const char *title, unsigned flags) {
  size_t length = LENGTH_SENTINEL;
  hdt_status s = hdt_svg(t, size, title, flags, NULL, 0, &length);
  expect(s == HDT_OK, "hdt_svg sizing call: %s (%s)", hdt_status_string(s), hdt_last_error_message());
  expect(length != LENGTH_SENTINEL && length > 0, "hdt_svg: no length");
  char *text = malloc(length + 1);
  ck_assert_ptr_nonnull(text);
  size_t again = 0;
  s = hdt_svg(t, size, title, flags, text, length + 1, &again);
  expect(s == HDT_OK, "hdt_svg: %s (%s)", hdt_status_string(s), hdt_last_error_message());
  expect(again == length, "hdt_svg: the sizing call said %zu bytes, the second call %zu", length, again);
  expect(strlen(text) == length, "hdt_svg: strlen %zu, length %zu", strlen(text), length);
  return text;
}

static size_t count(const char *text, const char *what) {
  size_t n = 0;
  for (const char *p = text; (p = strstr(p, what)) != NULL; p += strlen(what)) ++n;
  return n;
}

/* The circles in the group <g fill="COLOUR"> (the vertex dots of one kind);
   -1 when the picture has no such group. */
static long dots(const char *text, const char *colour) {
  char open[64];
  snprintf(open, sizeof open, "<g fill=\"%s\">\n", colour);
  const char *begin = strstr(text, open);
  if (!begin) return -1;
  const char *end = strstr(begin, "</g>");
  expect(end != NULL, "the group %s is not closed", colour);
  long n = 0;
  for (const char *p = begin; (p = strstr(p, "<circle ")) != NULL && p < end; ++p) ++n;
  return n;
}

/* The places of the disk point (x, y), a representative in the half-open
   F_g, in the closed F_g: 4g at the vertex v_0 (every corner), 2 on a side
   (also on the paired side), else 1. */
static long places(int genus, double x, double y) {
  double vx, vy;
  expect(hdt_polygon_vertex(genus, 0, &vx, &vy) == HDT_OK, "hdt_polygon_vertex");
  if (hypot(x - vx, y - vy) < 1e-9) return 4 * genus;
  for (int k = 0; k < 4 * genus; ++k) {
    double mx, my;
    expect(hdt_polygon_side_midpoint(genus, k, &mx, &my) == HDT_OK, "hdt_polygon_side_midpoint");
    /* The side's circle is orthogonal to the unit circle, centred on the ray
       through m_k: |c| = (|m| + 1/|m|) / 2, radius^2 = |c|^2 - 1. */
    const double m = hypot(mx, my), c = (m + 1 / m) / 2, cx = mx / m * c, cy = my / m * c;
    if (fabs(hypot(x - cx, y - cy) - sqrt(c * c - 1)) < 1e-9) return 2;
  }
  return 1;
}

/* ---- Bad arguments write nothing ---- */

static void expect_refused(hdt_status got, hdt_status want, const char *what, const char *buffer, size_t size,
                           size_t length) {
  expect(got == want, "%s: got %s, expected %s (%s)", what, hdt_status_string(got), hdt_status_string(want),
         hdt_last_error_message());
  const char *msg = hdt_last_error_message();
  expect(strstr(msg, "hdt_svg") != NULL && strlen(msg) > strlen("hdt_svg: "), "%s: message \"%s\"", what, msg);
  for (size_t i = 0; i < size; ++i) expect(buffer[i] == CANARY, "%s: byte %zu of the text was written", what, i);
  if (want != HDT_EBUFS) expect(length == LENGTH_SENTINEL, "%s: *length was written (%zu)", what, length);
}

START_TEST(bad_arguments_write_nothing) {
  hdt_triangulation *t = small_disk_triangulation(2, 30, 1, 1);
  char buffer[256];
  size_t length;
#define RESET() (memset(buffer, CANARY, sizeof buffer), length = LENGTH_SENTINEL)

  RESET();
  expect_refused(hdt_svg(NULL, 800, NULL, 0, buffer, sizeof buffer, &length), HDT_EINVAL, "t NULL", buffer,
                 sizeof buffer, length);
  expect(strstr(hdt_last_error_message(), "NULL") != NULL, "t NULL: %s", hdt_last_error_message());
  RESET();
  expect_refused(hdt_svg(t, 800, NULL, 0, buffer, sizeof buffer, NULL), HDT_EINVAL, "length NULL", buffer,
                 sizeof buffer, length);
  expect(strstr(hdt_last_error_message(), "length") != NULL, "length NULL: %s", hdt_last_error_message());

  const double bad_sizes[] = {0.0, -0.0, -800, NAN, INFINITY, -INFINITY, HDT_SVG_SIZE_MAX * 1.0000001, DBL_MAX};
  for (size_t i = 0; i < sizeof bad_sizes / sizeof bad_sizes[0]; ++i) {
    char what[64];
    snprintf(what, sizeof what, "size %g", bad_sizes[i]);
    RESET();
    expect_refused(hdt_svg(t, bad_sizes[i], NULL, 0, buffer, sizeof buffer, &length), HDT_EINVAL, what, buffer,
                   sizeof buffer, length);
    expect(strstr(hdt_last_error_message(), "size") != NULL, "%s: %s", what, hdt_last_error_message());
    RESET(); /* also for a sizing call */
    expect_refused(hdt_svg(t, bad_sizes[i], NULL, 0, NULL, 0, &length), HDT_EINVAL, what, buffer, 0, length);
  }

  const unsigned bad_flags[] = {16u, 32u, 1u << 31, HDT_SVG_NEIGHBOURS | HDT_SVG_VORONOI | HDT_SVG_SIDE_LABELS | 16u,
                                ~0u};
  for (size_t i = 0; i < sizeof bad_flags / sizeof bad_flags[0]; ++i) {
    char what[64];
    snprintf(what, sizeof what, "flags %#x", bad_flags[i]);
    RESET();
    expect_refused(hdt_svg(t, 800, NULL, bad_flags[i], buffer, sizeof buffer, &length), HDT_EINVAL, what, buffer,
                   sizeof buffer, length);
    expect(strstr(hdt_last_error_message(), "flag") != NULL, "%s: %s", what, hdt_last_error_message());
  }

  RESET();
  expect_refused(hdt_svg(t, 800, NULL, 0, NULL, 10, &length), HDT_EINVAL, "text NULL, capacity 10", buffer, 0,
                 length);

  /* Too small: HDT_EBUFS with *length set, not a byte of the text written. */
  size_t needed = 0;
  expect(hdt_svg(t, 800, NULL, 0, NULL, 0, &needed) == HDT_OK, "sizing call: %s", hdt_last_error_message());
  expect(needed > sizeof buffer, "the picture has %zu bytes only", needed);
  const size_t capacities[] = {1, 2, sizeof buffer};
  for (size_t i = 0; i < sizeof capacities / sizeof capacities[0]; ++i) {
    RESET();
    expect_refused(hdt_svg(t, 800, NULL, 0, buffer, capacities[i], &length), HDT_EBUFS, "capacity too small",
                   buffer, sizeof buffer, length);
    expect(length == needed, "HDT_EBUFS: *length %zu, the sizing call said %zu", length, needed);
  }
  /* One byte short: the text without room for its NUL. */
  char *text = malloc(needed + 64);
  ck_assert_ptr_nonnull(text);
  memset(text, CANARY, needed + 64);
  length = LENGTH_SENTINEL;
  expect_refused(hdt_svg(t, 800, NULL, 0, text, needed, &length), HDT_EBUFS, "capacity = length", text, needed + 64,
                 length);
  expect(length == needed, "HDT_EBUFS: *length %zu, expected %zu", length, needed);

  /* Exactly enough, and more than enough: the text and its NUL, nothing
     beyond them. */
  const size_t enough[] = {needed + 1, needed + 40};
  for (size_t i = 0; i < 2; ++i) {
    memset(text, CANARY, needed + 64);
    length = LENGTH_SENTINEL;
    expect(hdt_svg(t, 800, NULL, 0, text, enough[i], &length) == HDT_OK, "capacity %zu: %s", enough[i],
           hdt_last_error_message());
    expect(length == needed && text[needed] == '\0' && strlen(text) == needed, "capacity %zu: length %zu",
           enough[i], length);
    for (size_t k = needed + 1; k < needed + 64; ++k) expect(text[k] == CANARY, "byte %zu beyond the NUL written", k);
  }
  free(text);
  hdt_destroy(t);
#undef RESET
}
END_TEST

/* ---- The text ---- */

START_TEST(length_and_determinism) {
  hdt_triangulation *t = small_disk_triangulation(2, 80, 2, 1);
  const size_t faces = hdt_face_count(t), vertices = hdt_vertex_count(t);
  uint32_t *before = malloc(3 * faces * sizeof *before);
  int32_t *before_tr = malloc(3 * faces * sizeof *before_tr);
  size_t n = 0;
  expect(hdt_faces(t, before, before_tr, faces, &n) == HDT_OK && n == faces, "hdt_faces");

  const unsigned flag_sets[] = {0, HDT_SVG_NEIGHBOURS, HDT_SVG_HIDE_DUMMIES, HDT_SVG_NEIGHBOURS | HDT_SVG_HIDE_DUMMIES,
                                HDT_SVG_VORONOI, HDT_SVG_VORONOI | HDT_SVG_NEIGHBOURS, HDT_SVG_SIDE_LABELS};
  for (size_t i = 0; i < sizeof flag_sets / sizeof flag_sets[0]; ++i) {
    char *a = picture(t, 800, "x", flag_sets[i]); /* picture() checks length == strlen */
    char *b = picture(t, 800, "x", flag_sets[i]);
    expect(strcmp(a, b) == 0, "flags %u: two calls drew different pictures", flag_sets[i]);
    /* With the tiles or the side labels, the caption's second part wraps: one line more. */
    const int wraps = (flag_sets[i] & (HDT_SVG_NEIGHBOURS | HDT_SVG_SIDE_LABELS)) != 0;
    expect(strncmp(a,
                   wraps
                       ? "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"800\" height=\"873\""
                       : "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"800\" height=\"856\"",
                   62) == 0,
           "flags %u: the text starts with \"%.70s\"", flag_sets[i], a);
    expect(count(a, "<tspan") == (wraps ? 1u : 0u),
           "flags %u: %zu wrapped lines", flag_sets[i], count(a, "<tspan"));
    expect(count(a, "stroke=\"#8cc498\"") ==
               (flag_sets[i] & HDT_SVG_NEIGHBOURS && flag_sets[i] & HDT_SVG_VORONOI ? 8u : 0u),
           "flags %u: the tiles' Voronoi paths", flag_sets[i]);
    expect(count(a, "<g fill=\"#7585b0\">") == (flag_sets[i] & HDT_SVG_NEIGHBOURS ? 1u : 0u),
           "flags %u: the tiles' vertices", flag_sets[i]);
    /* The sides' labels: g_0 .. g_3 on s_0 .. s_3, g_0^-1 .. g_3^-1 on s_4 .. s_7. */
    const int labels = (flag_sets[i] & HDT_SVG_SIDE_LABELS) != 0;
    expect(count(a, ">g_") == (labels ? 8u : 0u) && count(a, "^-1</text>") == (labels ? 4u : 0u) &&
               count(a, ">g_3^-1</text>") == (labels ? 1u : 0u),
           "flags %u: %zu side labels", flag_sets[i], count(a, ">g_"));
    const size_t len = strlen(a);
    expect(len > 7 && strcmp(a + len - 7, "</svg>\n") == 0, "flags %u: the text ends with \"%s\"", flag_sets[i],
           a + (len > 20 ? len - 20 : 0));
    expect(count(a, "<svg") == 1 && count(a, "</svg>") == 1, "one svg element");
    const size_t tiles = count(a, "clipPath id=\"hdt-tile-");
    expect(tiles == (flag_sets[i] & HDT_SVG_NEIGHBOURS ? 8u : 0u), "flags %u: %zu tiles", flag_sets[i], tiles);
    expect(count(a, "stroke=\"#2a8a3a\"") == (flag_sets[i] & HDT_SVG_VORONOI ? 1u : 0u), "flags %u: Voronoi path",
           flag_sets[i]);
    free(a);
    free(b);
  }

  /* The triangulation is not changed. */
  uint32_t *after = malloc(3 * faces * sizeof *after);
  int32_t *after_tr = malloc(3 * faces * sizeof *after_tr);
  expect(hdt_faces(t, after, after_tr, faces, &n) == HDT_OK && n == faces, "hdt_faces after");
  expect(memcmp(before, after, 3 * faces * sizeof *after) == 0 &&
             memcmp(before_tr, after_tr, 3 * faces * sizeof *after_tr) == 0 && hdt_vertex_count(t) == vertices,
         "hdt_svg changed the triangulation");
  free(before);
  free(before_tr);
  free(after);
  free(after_tr);
  hdt_destroy(t);
}
END_TEST

START_TEST(title_is_escaped) {
  hdt_triangulation *t = small_disk_triangulation(2, 10, 3, 1);
  char *text = picture(t, 800, "a<b & c>\"d\" \xc3\xa9 x\x01y\xffz\tw", 0);
  expect(strstr(text, ">a&lt;b &amp; c&gt;&quot;d&quot; \xc3\xa9 x?y?z\tw</text>") != NULL,
         "the title is not escaped as expected:\n%s", strstr(text, "<text"));
  expect(strstr(text, "<b") == NULL && strstr(text, "c>") == NULL && strstr(text, "\"d\"") == NULL &&
             strstr(text, "& c") == NULL,
         "a raw character of the title is in the picture");
  /* Every '&' starts an entity, every '<' a tag. */
  for (const char *p = text; (p = strchr(p, '&')) != NULL; ++p)
    expect(strncmp(p, "&amp;", 5) == 0 || strncmp(p, "&lt;", 4) == 0 || strncmp(p, "&gt;", 4) == 0 ||
               strncmp(p, "&quot;", 6) == 0,
           "a raw '&': %.20s", p);
  free(text);

  /* The empty title, and the defaults. */
  text = picture(t, 800, "", 0);
  expect(strstr(text, "font-size=\"16\"></text>") != NULL, "the empty title");
  free(text);
  text = picture(t, 800, NULL, 0);
  expect(strstr(text, ">Delaunay triangulation of 10 points on M_2</text>") != NULL, "the default title: %s",
         strstr(text, "<text"));
  free(text);
  hdt_destroy(t);

  hdt_triangulation *one = small_disk_triangulation(3, 1, 4, 0);
  text = picture(one, 800, NULL, 0);
  expect(strstr(text, ">Delaunay triangulation of 1 point on M_3</text>") != NULL, "one point: %s",
         strstr(text, "<text"));
  free(text);
  hdt_destroy(one);

  hdt_triangulation *fresh = NULL;
  expect(hdt_create(&fresh, 2) == HDT_OK, "hdt_create");
  text = picture(fresh, 800, NULL, 0);
  expect(strstr(text, ">The dummy point set of M_2, before any insertion, and its Delaunay triangulation</text>") !=
             NULL,
         "the dummy set's default title: %s", strstr(text, "<text"));
  free(text);
  hdt_destroy(fresh);
}
END_TEST

/* ---- What it shows ---- */

static void check_dots(int genus, size_t n, int remove_dummies) {
  hdt_triangulation *t = small_disk_triangulation(genus, n, 5 + (uint64_t)genus, remove_dummies);
  const size_t vertices = hdt_vertex_count(t), dummies = hdt_dummy_count(t), users = vertices - dummies;
  /* The places of the dummies in the closed F_g. */
  long dummy_places = 0;
  const size_t bound = hdt_vertex_id_bound(t);
  for (uint32_t v = 0; v < bound; ++v) {
    if (hdt_vertex_is_dummy(t, v) != 1) continue;
    double x, y;
    expect(hdt_vertex_point(t, v, &x, &y) == HDT_OK, "hdt_vertex_point");
    dummy_places += places(genus, x, y);
  }
  expect(dummy_places >= (long)dummies, "places");

  char *text = picture(t, 800, "dots", 0);
  expect(dots(text, USER_COLOUR) == (long)users, "genus %d: %ld user dots for %zu user vertices (none on the boundary)",
         genus, dots(text, USER_COLOUR), users);
  expect(dots(text, DUMMY_COLOUR) == dummy_places, "genus %d: %ld dummy dots for %zu dummies at %ld places", genus,
         dots(text, DUMMY_COLOUR), dummies, dummy_places);
  char caption[128];
  if (dummies)
    snprintf(caption, sizeof caption, ">%zu vertices (%zu dumm%s, red), %zu faces, drawn in F_%d", vertices, dummies,
             dummies == 1 ? "y" : "ies", hdt_face_count(t), genus);
  else
    snprintf(caption, sizeof caption, ">%zu vertices, %zu faces, drawn in F_%d", vertices, hdt_face_count(t), genus);
  expect(strstr(text, caption) != NULL, "the caption \"%s\" is not in the picture", caption);

  /* HIDE_DUMMIES: no dummy dot at all, the rest as before. */
  char *hidden = picture(t, 800, "dots", HDT_SVG_HIDE_DUMMIES);
  expect(dots(hidden, DUMMY_COLOUR) == -1 && count(hidden, DUMMY_COLOUR) == 0, "genus %d: dummy marks with HIDE",
         genus);
  expect(dots(hidden, USER_COLOUR) == (long)users, "genus %d: user dots with HIDE", genus);
  const char *dummy_group = strstr(text, "<g fill=\"" DUMMY_COLOUR "\">");
  if (dummy_group) /* the same picture up to the dummy dots */
    expect(strncmp(text, hidden, (size_t)(dummy_group - text)) == 0, "genus %d: HIDE changed more than the dots",
           genus);
  else
    expect(dummies == 0, "genus %d: no dummy group for %zu dummies", genus, dummies);
  free(hidden);
  free(text);
  hdt_destroy(t);
}

START_TEST(a_dot_per_place) {
  check_dots(2, 0, 0);   /* the dummy set alone: v_0, midpoints, inner points */
  check_dots(2, 40, 0);  /* dummies kept */
  check_dots(2, 300, 1); /* dummies removed */
  check_dots(3, 200, 0);
  check_dots(3, 400, 1);
}
END_TEST

START_TEST(size_scales_the_picture) {
  hdt_triangulation *t = small_disk_triangulation(2, 50, 6, 1);
  char *small = picture(t, 400, NULL, 0);
  expect(strstr(small, "width=\"400\" height=\"428\" viewBox=\"0 0 400 428\"") != NULL, "size 400: %.120s", small);
  expect(strstr(small, "<circle cx=\"200\" cy=\"228\" r=\"194\" ") != NULL, "size 400: the disk");
  expect(strstr(small, "<text x=\"6\" y=\"11\" font-family=\"sans-serif\" font-size=\"8\">") != NULL,
         "size 400: the caption");
  char *odd = picture(t, 123.5, NULL, HDT_SVG_NEIGHBOURS);
  expect(strstr(odd, "width=\"123.5\"") != NULL, "size 123.5");
  char *tiny = picture(t, 1e-3, NULL, 0);
  char *large = picture(t, HDT_SVG_SIZE_MAX, NULL, 0);
  expect(strstr(large, "width=\"100000\"") != NULL, "the largest size");
  /* The same drawing at every size: as many path pieces. */
  char *normal = picture(t, 800, NULL, 0);
  expect(count(small, "M") == count(normal, "M") && count(tiny, "M") == count(normal, "M") &&
             count(large, "M") == count(normal, "M"),
         "the sizes draw different numbers of pieces");
  free(small);
  free(odd);
  free(tiny);
  free(large);
  free(normal);
  hdt_destroy(t);
}
END_TEST

/* Each face's copies meeting F_g are drawn: at least one piece per face. */
START_TEST(every_face_is_drawn) {
  for (int genus = 2; genus <= 4; ++genus) {
    hdt_triangulation *t = small_disk_triangulation(genus, 100, 7, 1);
    char *text = picture(t, 800, NULL, 0);
    const char *faces = strstr(text, "<path clip-path=\"url(#hdt-polygon)\"");
    expect(faces != NULL, "no faces path");
    const char *end = strstr(faces, "/>");
    size_t pieces = 0;
    for (const char *p = faces; p < end; ++p) pieces += *p == 'M';
    expect(pieces >= hdt_face_count(t), "genus %d: %zu pieces for %zu faces", genus, pieces, hdt_face_count(t));
    free(text);
    hdt_destroy(t);
  }
}
END_TEST

/* ---- Out of memory ---- */

static void enomem_child(void) {
  hdt_triangulation *t = small_disk_triangulation(2, 20000, 8, 1);
  size_t needed = 0;
  if (hdt_svg(t, 800, NULL, 0, NULL, 0, &needed) != HDT_OK) _exit(2);
  char *text = malloc(needed + 1);
  if (!text) _exit(3);
  memset(text, CANARY, needed + 1);
  struct rlimit old;
  if (getrlimit(RLIMIT_AS, &old) != 0) _exit(4);
  const size_t used = address_space_bytes();
  if (used == 0) _exit(5);
  const struct rlimit tight = {(rlim_t)used + ((rlim_t)1 << 20), old.rlim_max};
  if (setrlimit(RLIMIT_AS, &tight) != 0) _exit(6);
  size_t length = LENGTH_SENTINEL;
  const hdt_status s = hdt_svg(t, 800, NULL, HDT_SVG_NEIGHBOURS, text, needed + 1, &length);
  char message[256];
  snprintf(message, sizeof message, "%s", hdt_last_error_message());
  if (setrlimit(RLIMIT_AS, &old) != 0) _exit(7);
  if (s != HDT_ENOMEM) {
    fprintf(stderr, "svg enomem: %s (%s)\n", hdt_status_string(s), message);
    _exit(8);
  }
  if (!strstr(message, "hdt_svg") || !strstr(message, "memory")) {
    fprintf(stderr, "svg enomem: message \"%s\"\n", message);
    _exit(9);
  }
  if (length != LENGTH_SENTINEL) _exit(10);
  for (size_t i = 0; i <= needed; ++i)
    if (text[i] != CANARY) _exit(11);
  /* Memory back: it draws. */
  if (hdt_svg(t, 800, NULL, 0, text, needed + 1, &length) != HDT_OK || length != needed) _exit(12);
  free(text);
  hdt_destroy(t);
  _exit(0);
}

START_TEST(out_of_memory) {
  if (UNDER_SANITIZER || getenv("LD_PRELOAD")) {
    printf("svg: out_of_memory skipped under a sanitizer or valgrind (RLIMIT_AS does not apply)\n");
    return;
  }
  run_child(enomem_child);
}
END_TEST

int main(void) {
  const TTest *const tests[] = {bad_arguments_write_nothing, length_and_determinism, title_is_escaped, a_dot_per_place,
                                size_scales_the_picture, every_face_is_drawn, out_of_memory};
  return run_tests("svg", tests, sizeof tests / sizeof tests[0]);
}
