/* hdt_save and hdt_load: round trips give the same ids, the same faces in
   the same order (hdt_faces' bytes) and the same later behaviour; the file
   holds the points bit for bit where docs/format.md says; damaged, truncated
   or crafted bytes give HDT_EINVAL naming a byte offset, or a triangulation
   that hdt_validate accepts, never a crash. */
#define _DEFAULT_SOURCE
#define _POSIX_C_SOURCE 200809L

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "crafted_words.h"
#include "hdt_test.h"

#define SENTINEL ((hdt_triangulation *)(uintptr_t)0x5a5a5a5a)
#define HEADER 44
#define VERTEX_BYTES 25
#define FACE_BYTES 48

typedef struct bytes_t {
  unsigned char *b;
  size_t n;
} bytes_t;

static bytes_t save(const hdt_triangulation *t) {
  bytes_t out = {NULL, 0};
  hdt_status s = hdt_save(t, NULL, 0, &out.n);
  expect(s == HDT_OK, "hdt_save sizing: %s", hdt_last_error_message());
  out.b = malloc(out.n);
  ck_assert_ptr_nonnull(out.b);
  size_t again = 0;
  s = hdt_save(t, out.b, out.n, &again);
  expect(s == HDT_OK && again == out.n, "hdt_save: %s (%zu vs %zu bytes)", hdt_last_error_message(), again, out.n);
  return out;
}

static hdt_triangulation *load(bytes_t b) {
  hdt_triangulation *t = SENTINEL;
  const hdt_status s = hdt_load(&t, b.b, b.n);
  expect(s == HDT_OK, "hdt_load: %s (%s)", hdt_status_string(s), hdt_last_error_message());
  expect(t != SENTINEL && t != NULL, "hdt_load: no handle");
  return t;
}

/* An independent CRC-32 (ISO-HDLC, reflected, polynomial 0xEDB88320), bit by bit. */
static uint32_t crc32_of(const unsigned char *p, size_t n) {
  uint32_t c = 0xFFFFFFFFu;
  for (size_t i = 0; i < n; ++i) {
    c ^= p[i];
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
  }
  return ~c;
}
static uint32_t get32(const unsigned char *p) {
  return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}
static void put32(unsigned char *p, uint32_t v) {
  for (int i = 0; i < 4; ++i) p[i] = (unsigned char)(v >> 8 * i);
}
static double getf64(const unsigned char *p) {
  uint64_t v = 0;
  for (int i = 0; i < 8; ++i) v |= (uint64_t)p[i] << 8 * i;
  double d;
  memcpy(&d, &v, 8);
  return d;
}
/* Rewrites the checksum after a deliberate change: what a crafted file does. */
static void reseal(bytes_t b) { put32(b.b + b.n - 4, crc32_of(b.b, b.n - 4)); }

/* Offset of the vertex records: after the header and the words. */
static size_t vertices_at(bytes_t b) {
  size_t at = HEADER;
  const uint32_t words = get32(b.b + 16);
  for (uint32_t i = 0; i < words; ++i) at += 2 + 2 * ((size_t)b.b[at] | (size_t)b.b[at + 1] << 8);
  return at;
}

static void expect_same(const hdt_triangulation *a, const hdt_triangulation *b, const char *when) {
  expect(hdt_genus(a) == hdt_genus(b), "%s: genus", when);
  expect(hdt_vertex_count(a) == hdt_vertex_count(b) && hdt_dummy_count(a) == hdt_dummy_count(b) &&
             hdt_vertex_id_bound(a) == hdt_vertex_id_bound(b) && hdt_face_count(a) == hdt_face_count(b),
         "%s: counts differ", when);
  size_t nx, ny;
  unsigned char *x = observable_bytes(a, &nx), *y = observable_bytes(b, &ny);
  expect(nx == ny && memcmp(x, y, nx) == 0, "%s: hdt_faces / hdt_vertices bytes differ", when);
  free(x);
  free(y);
}

static void random_points(uint64_t *rng, double *xy, size_t n, double radius) {
  for (size_t i = 0; i < n;) {
    const double x = (2 * uniform01(rng) - 1) * radius, y = (2 * uniform01(rng) - 1) * radius;
    if (x * x + y * y >= radius * radius) continue;
    xy[2 * i] = x, xy[2 * i + 1] = y;
    ++i;
  }
}

/* Save, load, compare; then the same later operations on both agree too. */
static void round_trip(int genus, size_t n, int remove_every, int remove_dummies, uint64_t seed) {
  char when[96];
  snprintf(when, sizeof when, "genus %d, %zu points, removal every %d, dummies %s", genus, n, remove_every,
           remove_dummies ? "removed" : "kept");
  hdt_triangulation *t = NULL;
  ck_assert_int_eq(hdt_create(&t, genus), HDT_OK);
  double *xy = malloc((2 * n + 2) * sizeof *xy);
  uint32_t *ids = malloc((n + 1) * sizeof *ids);
  /* Radius 0.95: many points outside F_g, stored away from home. */
  random_points(&seed, xy, n, 0.95);
  expect(hdt_insert_many(t, xy, n, ids) == HDT_OK, "%s: insert: %s", when, hdt_last_error_message());
  if (remove_every > 0)
    for (size_t i = 0; i < n; i += (size_t)remove_every) {
      const hdt_status s = hdt_remove_vertex(t, ids[i]);
      expect(s == HDT_OK || s == HDT_ENOTSUP || s == HDT_EINVAL, "%s: remove: %s", when, hdt_status_string(s));
    }
  if (remove_dummies) ck_assert_int_eq(hdt_remove_dummies(t, NULL), HDT_OK);

  bytes_t file = save(t);
  /* The file holds every live point as given, bit for bit, at the documented place. */
  const size_t at = vertices_at(file);
  expect(get32(file.b + 20) == hdt_vertex_id_bound(t), "%s: vertex count in the header", when);
  for (size_t i = 0; i < n; ++i) {
    if (hdt_vertex_is_dummy(t, ids[i]) != 0) continue; /* removed */
    const unsigned char *r = file.b + at + VERTEX_BYTES * ids[i];
    const double x = getf64(r), y = getf64(r + 8);
    expect(memcmp(&x, &xy[2 * i], 8) == 0 && memcmp(&y, &xy[2 * i + 1], 8) == 0,
           "%s: vertex %u's point is not stored bit for bit", when, ids[i]);
  }
  /* The face records, in hdt_faces' order: their corners are its vertices. */
  size_t F = 0;
  ck_assert_int_eq(hdt_faces(t, NULL, NULL, 0, &F), HDT_OK);
  expect(get32(file.b + 24) == F, "%s: face count in the header", when);
  const size_t faces_at = at + VERTEX_BYTES * hdt_vertex_id_bound(t);
  expect(faces_at + FACE_BYTES * F + 4 == file.n, "%s: the file is not header, words, vertices, faces, checksum", when);
  uint32_t *fv = malloc(3 * F * sizeof *fv);
  ck_assert_int_eq(hdt_faces(t, fv, NULL, F, &F), HDT_OK);
  for (size_t f = 0; f < F; ++f)
    for (int i = 0; i < 3; ++i)
      expect(get32(file.b + faces_at + FACE_BYTES * f + 4 * (size_t)i) == fv[3 * f + (size_t)i],
             "%s: face record %zu, corner %d", when, f, i);
  free(fv);
  expect(get32(file.b + file.n - 4) == crc32_of(file.b, file.n - 4), "%s: the checksum is not CRC-32", when);

  hdt_triangulation *u = load(file);
  bytes_t again = save(u);
  expect(again.n == file.n && memcmp(again.b, file.b, file.n) == 0, "%s: saving the loaded one differs", when);
  expect_same(t, u, when);
  /* Queries may give translation ids to elements they meet (hdt.h): the
     same calls on both keep the ids in step. */
  expect(hdt_validate(u) == HDT_OK, "%s: the loaded triangulation: %s", when, hdt_last_error_message());
  ck_assert_int_eq(hdt_validate(t), HDT_OK);

  /* Later operations: the same points inserted one by one, then many, a removal. */
  random_points(&seed, xy, n / 2 + 1, 0.9);
  for (size_t i = 0; i < 10 && i <= n / 2; ++i) {
    uint32_t a = 0, b = 1;
    expect(hdt_insert(t, xy[2 * i], xy[2 * i + 1], &a) == hdt_insert(u, xy[2 * i], xy[2 * i + 1], &b) && a == b,
           "%s: a later insertion differs", when);
  }
  ck_assert_int_eq(hdt_insert_many(t, xy, n / 2 + 1, NULL), HDT_OK);
  ck_assert_int_eq(hdt_insert_many(u, xy, n / 2 + 1, NULL), HDT_OK);
  const uint32_t victim = (uint32_t)hdt_vertex_id_bound(t) - 3;
  expect(hdt_remove_vertex(t, victim) == hdt_remove_vertex(u, victim), "%s: a later removal differs", when);
  expect_same(t, u, when);
  size_t face = 1, face2 = 2;
  int32_t h = 1, h2 = 2;
  ck_assert_int_eq(hdt_locate(t, 0.3, -0.2, &face, &h), HDT_OK);
  ck_assert_int_eq(hdt_locate(u, 0.3, -0.2, &face2, &h2), HDT_OK);
  expect(face == face2 && h == h2, "%s: hdt_locate differs", when);
  free(again.b);
  free(file.b);
  free(xy);
  free(ids);
  hdt_destroy(t);
  hdt_destroy(u);
}

START_TEST(round_trips) {
  round_trip(2, 0, 0, 0, 1);    /* nothing inserted: the dummies alone */
  round_trip(2, 300, 0, 0, 2);  /* with dummies */
  round_trip(2, 300, 0, 1, 3);  /* after hdt_remove_dummies */
  round_trip(2, 300, 3, 0, 4);  /* removals leave gaps in the ids */
  round_trip(3, 250, 4, 1, 5);
  round_trip(3, 100, 0, 0, 6);
  round_trip(5, 200, 5, 1, 7);
}
END_TEST

START_TEST(two_call_pattern) {
  hdt_triangulation *t = NULL;
  ck_assert_int_eq(hdt_create(&t, 2), HDT_OK);
  size_t n = 0, m = 7;
  ck_assert_int_eq(hdt_save(t, NULL, 0, &n), HDT_OK);
  /* Header, 14 dummy vertices and 2 (14 + 2) faces, checksum, and the words
     (14: the thinned dummy set of genus 2, tests/test_dummies.c). */
  expect(n >= HEADER + 14 * VERTEX_BYTES + 32 * FACE_BYTES + 4, "size %zu", n);
  unsigned char *b = malloc(n + 8);
  memset(b, 0xA5, n + 8);
  ck_assert_int_eq(hdt_save(t, b, n - 1, &m), HDT_EBUFS);
  ck_assert_uint_eq(m, n);
  for (size_t i = 0; i < n + 8; ++i) expect(b[i] == 0xA5, "HDT_EBUFS wrote byte %zu", i);
  ck_assert_int_eq(hdt_save(t, b, n + 8, &m), HDT_OK);
  ck_assert_uint_eq(m, n);
  for (size_t i = n; i < n + 8; ++i) expect(b[i] == 0xA5, "hdt_save wrote past its size at %zu", i);
  ck_assert_int_eq(hdt_save(NULL, b, n, &m), HDT_EINVAL);
  ck_assert_int_eq(hdt_save(t, b, n, NULL), HDT_EINVAL);
  ck_assert_int_eq(hdt_save(t, NULL, n, &m), HDT_EINVAL);
  hdt_triangulation *u = SENTINEL;
  ck_assert_int_eq(hdt_load(NULL, b, n), HDT_EINVAL);
  ck_assert_int_eq(hdt_load(&u, NULL, n), HDT_EINVAL);
  ck_assert_int_eq(hdt_load(&u, NULL, 0), HDT_EINVAL);
  ck_assert_ptr_eq(u, SENTINEL);
  free(b);
  hdt_destroy(t);
}
END_TEST

/* A load that fails must say HDT_EINVAL with a byte offset and leave *out;
   one that succeeds must give a valid triangulation. Returns 1 on success. */
static int load_or_refuse(bytes_t b, const char *what, size_t i) {
  hdt_triangulation *t = SENTINEL;
  const hdt_status s = hdt_load(&t, b.b, b.n);
  if (s == HDT_OK) {
    expect(t != SENTINEL && hdt_validate(t) == HDT_OK, "%s %zu: loaded an invalid triangulation: %s", what, i,
           hdt_last_error_message());
    hdt_destroy(t);
    return 1;
  }
  expect(s == HDT_EINVAL, "%s %zu: %s (%s)", what, i, hdt_status_string(s), hdt_last_error_message());
  expect(strstr(hdt_last_error_message(), "hdt_load") && strstr(hdt_last_error_message(), "byte "),
         "%s %zu: the message names no byte: %s", what, i, hdt_last_error_message());
  expect(t == SENTINEL, "%s %zu: *out written on failure", what, i);
  return 0;
}

static bytes_t small_file(void) {
  hdt_triangulation *t = NULL;
  ck_assert_int_eq(hdt_create(&t, 2), HDT_OK);
  const double xy[] = {0.1, 0.2, -0.3, 0.25, 0.05, -0.4, 0.6, 0.1, -0.85, -0.3};
  ck_assert_int_eq(hdt_insert_many(t, xy, 5, NULL), HDT_OK);
  ck_assert_int_eq(hdt_remove_vertex(t, 17), HDT_OK);
  bytes_t b = save(t);
  hdt_destroy(t);
  return b;
}

START_TEST(truncated_and_flipped) {
  bytes_t b = small_file();
  bytes_t c = {malloc(b.n), 0};
  for (size_t n = 0; n < b.n; ++n) { /* every truncation */
    memcpy(c.b, b.b, n);
    c.n = n;
    expect(!load_or_refuse(c, "truncated to", n), "truncated to %zu bytes: loaded", n);
  }
  c.n = b.n;
  for (size_t i = 0; i < b.n; ++i) /* every byte damaged: the checksum sees it */
    for (int mask = 1; mask < 256; mask <<= 3) {
      memcpy(c.b, b.b, b.n);
      c.b[i] ^= (unsigned char)mask;
      expect(!load_or_refuse(c, "flipped byte", i), "byte %zu flipped: loaded", i);
    }
  free(c.b);
  free(b.b);
}
END_TEST

/* The checksum is the standard CRC-32 (ISO-HDLC, as zlib's crc32), stored
   little-endian, so that any CRC-32 tool can check a file: the test's own
   CRC gives the catalogue's check value 0xCBF43926 for "123456789" (so it
   is that CRC, and round_trips' comparison with it pins the library's), the
   file's last 4 bytes are it of the bytes before, and the CRC of the whole
   file, checksum included, is that CRC's constant 0x2144DF1C. */
START_TEST(checksum_is_standard_crc32) {
  const unsigned char check[] = "123456789";
  ck_assert_uint_eq(crc32_of(check, 9), 0xCBF43926u);
  ck_assert_uint_eq(crc32_of(check, 0), 0);
  bytes_t b = small_file();
  ck_assert_uint_eq(get32(b.b + b.n - 4), crc32_of(b.b, b.n - 4));
  ck_assert_uint_eq(crc32_of(b.b, b.n), 0x2144DF1Cu);
  free(b.b);
}
END_TEST

/* Under a sanitizer or valgrind (which sets LD_PRELOAD) the library runs
   10-40 times slower: the long cases then do a sample of their work. */
static int slow_tools(void) { return UNDER_SANITIZER || getenv("LD_PRELOAD") != NULL; }

/* Damage with the checksum rewritten, as a crafted file would be: every
   byte, three ways (every 7th byte under slow tools: 3 s natively). Each
   load is refused or valid. */
START_TEST(crafted_bytes) {
  bytes_t b = small_file();
  bytes_t c = {malloc(b.n), b.n};
  size_t loaded = 0, tried = 0;
  const size_t step = slow_tools() ? 7 : 1;
  for (size_t i = 0; i + 4 < b.n; i += step)
    for (int way = 0; way < 3; ++way) {
      memcpy(c.b, b.b, b.n);
      c.b[i] = way == 0 ? (unsigned char)(c.b[i] ^ 1) : way == 1 ? 0xFF : 0;
      if (c.b[i] == b.b[i]) continue;
      reseal(c);
      loaded += (size_t)load_or_refuse(c, "crafted byte", i);
      ++tried;
    }
  printf("save: %zu crafted files, %zu loaded as valid triangulations, the rest refused\n", tried, loaded);
  free(c.b);
  free(b.b);
}
END_TEST

/* Every interior edge flipped, one at a time, in a saved Delaunay
   triangulation (the two faces' records rewritten as the other diagonal's,
   the four faces around them and the vertices' faces kept consistent, the
   checksum resealed): the result is a triangulation of the same points but
   not the Delaunay one (ties are broken by the symbolic perturbation, so
   exactly one diagonal is), and hdt_load must refuse it, whichever of the
   two faces has the smaller index. An edge whose quadrilateral is not convex
   gives clockwise faces, refused as well. */
static uint32_t face_u32(const unsigned char *faces, uint32_t f, int field, int i) {
  return get32(faces + (size_t)FACE_BYTES * f + 12 * field + 4 * i);
}
static void set_face(unsigned char *faces, uint32_t f, const uint32_t v[3], const uint32_t n[3]) {
  for (int i = 0; i < 3; ++i) {
    put32(faces + (size_t)FACE_BYTES * f + 4 * i, v[i]);
    put32(faces + (size_t)FACE_BYTES * f + 12 + 4 * i, 0);
    put32(faces + (size_t)FACE_BYTES * f + 24 + 4 * i, n[i]);
    put32(faces + (size_t)FACE_BYTES * f + 36 + 4 * i, 0);
  }
}
/* Face h's neighbour across its edge from a to b (either way) becomes to. */
static void repoint(unsigned char *faces, uint32_t h, uint32_t a, uint32_t b, uint32_t to) {
  for (int k = 0; k < 3; ++k) {
    const uint32_t x = face_u32(faces, h, 0, (k + 1) % 3), y = face_u32(faces, h, 0, (k + 2) % 3);
    if ((x == a && y == b) || (x == b && y == a)) {
      put32(faces + (size_t)FACE_BYTES * h + 24 + 4 * k, to);
      return;
    }
  }
  ck_abort_msg("face %u has no edge %u-%u", h, a, b);
}
static int untranslated(const unsigned char *faces, uint32_t f) {
  for (int i = 0; i < 3; ++i)
    if (face_u32(faces, f, 1, i) != 0 || face_u32(faces, f, 3, i) != 0) return 0;
  return 1;
}

START_TEST(flipped_edges_are_refused) {
  hdt_triangulation *t = small_disk_triangulation(2, 40, 7, 1);
  bytes_t b = save(t);
  hdt_destroy(t);
  const uint32_t W = get32(b.b + 16), V = get32(b.b + 20), F = get32(b.b + 24);
  size_t at = HEADER;
  for (uint32_t w = 0; w < W; ++w) at += 2 + 2 * (size_t)(b.b[at] | b.b[at + 1] << 8);
  const size_t vertices_at = at, faces_at = at + (size_t)VERTEX_BYTES * V;
  ck_assert_uint_eq(faces_at + (size_t)FACE_BYTES * F + 4, b.n);
  bytes_t c = {malloc(b.n), b.n};
  ck_assert_ptr_nonnull(c.b);
  size_t flipped = 0, not_delaunay = 0;
  for (uint32_t f = 0; f < F; ++f)
    for (int i = 0; i < 3; ++i) {
      const uint32_t g = face_u32(b.b + faces_at, f, 2, i);
      if (g < f || !untranslated(b.b + faces_at, f) || !untranslated(b.b + faces_at, g)) continue;
      memcpy(c.b, b.b, b.n);
      unsigned char *faces = c.b + faces_at;
      /* f = (c, p, q) from corner i, g = (d, q, p) from its corner k. */
      const uint32_t vc = face_u32(faces, f, 0, i), vp = face_u32(faces, f, 0, (i + 1) % 3),
                     vq = face_u32(faces, f, 0, (i + 2) % 3);
      int k = -1;
      for (int j = 0; j < 3; ++j)
        if (face_u32(faces, g, 2, j) == f && face_u32(faces, g, 0, (j + 1) % 3) == vq) k = j;
      ck_assert_int_ge(k, 0);
      const uint32_t vd = face_u32(faces, g, 0, k);
      const uint32_t fa_p = face_u32(faces, f, 2, (i + 1) % 3), fa_q = face_u32(faces, f, 2, (i + 2) % 3);
      const uint32_t gb_q = face_u32(faces, g, 2, (k + 1) % 3), gb_p = face_u32(faces, g, 2, (k + 2) % 3);
      if (vc == vd || fa_p == g || fa_q == g || gb_q == f || gb_p == f) continue; /* a degenerate neighbourhood */
      /* The outer faces first (they may be f or g's other neighbours only). */
      repoint(faces, gb_q, vp, vd, f);
      repoint(faces, fa_p, vq, vc, g);
      /* f' = (c, p, d), g' = (d, q, c). */
      const uint32_t fv[3] = {vc, vp, vd}, fn[3] = {gb_q, g, fa_q};
      const uint32_t gv[3] = {vd, vq, vc}, gn[3] = {fa_p, f, gb_p};
      set_face(faces, f, fv, fn);
      set_face(faces, g, gv, gn);
      put32(c.b + vertices_at + (size_t)VERTEX_BYTES * vq + 20, g);
      put32(c.b + vertices_at + (size_t)VERTEX_BYTES * vp + 20, f);
      put32(c.b + vertices_at + (size_t)VERTEX_BYTES * vc + 20, f);
      put32(c.b + vertices_at + (size_t)VERTEX_BYTES * vd + 20, f);
      reseal(c);
      hdt_triangulation *u = SENTINEL;
      expect(hdt_load(&u, c.b, c.n) == HDT_EINVAL, "edge %u-%u of faces %u, %u flipped: loaded", vp, vq, f, g);
      expect(u == SENTINEL, "*out written on failure");
      ++flipped;
      not_delaunay += strstr(hdt_last_error_message(), "not locally Delaunay") != NULL;
    }
  printf("save: %zu interior edges flipped, each refused, %zu as not locally Delaunay\n", flipped, not_delaunay);
  expect(flipped > 50 && not_delaunay > flipped / 2, "%zu flips, %zu refused for the Delaunay test", flipped, not_delaunay);
  free(c.b);
  free(b.b);
}
END_TEST

/* Corners 1 and 2 of a face record swapped, with their translations and
   neighbours: the same face, clockwise. */
static void swap_corners(unsigned char *f) {
  for (int field = 0; field < 4; ++field)
    for (int k = 0; k < 4; ++k) {
      unsigned char *a = f + 12 * field + 4 + k, *b = f + 12 * field + 8 + k;
      const unsigned char x = *a;
      *a = *b, *b = x;
    }
}

static const char *refusal(bytes_t c) {
  hdt_triangulation *t = SENTINEL;
  expect(hdt_load(&t, c.b, c.n) == HDT_EINVAL, "loaded: %s", hdt_last_error_message());
  ck_assert_ptr_eq(t, SENTINEL);
  return hdt_last_error_message();
}

START_TEST(messages_name_the_byte) {
  bytes_t b = small_file();
  bytes_t c = {malloc(b.n + 64), b.n};
  const size_t at = vertices_at(b);
  const size_t faces = at + VERTEX_BYTES * get32(b.b + 20);
#define CRAFT(change, expected)                                                              \
  do {                                                                                       \
    memcpy(c.b, b.b, b.n);                                                                   \
    c.n = b.n;                                                                               \
    change;                                                                                  \
    reseal(c);                                                                               \
    const char *m = refusal(c);                                                              \
    expect(strstr(m, expected), "%s: the message is \"%s\", expected \"%s\"", #change, m, expected); \
  } while (0)
  CRAFT(c.b[1] = 'X', "byte 0:");
  CRAFT(put32(c.b + 8, 3), "byte 8: format version 3");
  /* Version 2 is a polygon surface's: an M_g file marked so is refused
     (its bytes after the header are no polygon text). */
  CRAFT(put32(c.b + 8, 2), "byte ");
  CRAFT(put32(c.b + 12, 1), "byte 12: genus 1");
  CRAFT(put32(c.b + 12, 5000), "byte 12: genus 5000");
  /* Huge counts: refused from the header, before any allocation. */
  CRAFT(put32(c.b + 20, 0xFFFFFFFFu), "byte 16:");
  CRAFT(put32(c.b + 24, 0xFFFFFFFFu), "byte 16:");
  CRAFT(put32(c.b + 16, 0xFFFFFFFFu), "byte 16:");
  /* Vertex 18: a user point. Outside the disk; NaN; the site v_0 (vertex 1) moved. */
  {
    char text[64];
    snprintf(text, sizeof text, "byte %zu: vertex 18 is not a point", at + VERTEX_BYTES * 18);
    const double out = 1.5, nan = NAN;
    CRAFT(memcpy(c.b + at + VERTEX_BYTES * 18, &out, 8), text);
    CRAFT(memcpy(c.b + at + VERTEX_BYTES * 18, &nan, 8), text);
    snprintf(text, sizeof text, "byte %zu: vertex 1 is not the site", at + VERTEX_BYTES * 1);
    CRAFT(c.b[at + VERTEX_BYTES + 3] ^= 1, text);
    snprintf(text, sizeof text, "byte %zu: vertex 17 is removed", at + VERTEX_BYTES * 17);
    CRAFT(c.b[at + VERTEX_BYTES * 17] = 1, text);
  }
  /* Face 2: a corner's vertex out of range; its corners in clockwise order. */
  {
    char text[64];
    snprintf(text, sizeof text, "byte %zu: face 2 names vertex", faces + 2 * FACE_BYTES);
    CRAFT(put32(c.b + faces + 2 * FACE_BYTES + 4, 1000), text);
    CRAFT(swap_corners(c.b + faces + 2 * FACE_BYTES), "invalid triangulation");
  }
  /* Bytes after the faces (the size grows: the header's counts still fit). */
  CRAFT((memmove(c.b + b.n, c.b + b.n - 4, 4), c.n = b.n + 4), "bytes after the last face");
#undef CRAFT
  free(c.b);
  free(b.b);
}
END_TEST

/* Extra translation words in a crafted file (ids no face uses, the
   checksum rewritten): new canonical words load, and save back to the same
   bytes; a word that is not canonical, a repeat, an element of N, and a
   canonical word whose element lies far beyond any point's translation
   (the format's limit, docs/format.md) are refused at the word's byte. */
static void expect_words_refused(bytes_t b, const crafted_words_t *w, const char *expected, const char *what) {
  bytes_t c;
  c.b = crafted_file(b.b, b.n, w, &c.n);
  const char *m = refusal(c);
  char at[32];
  snprintf(at, sizeof at, "byte %zu:", vertices_at(b));
  expect(strstr(m, expected) && strstr(m, at), "%s: the message is \"%s\", expected \"%s\" at \"%s\"", what, m,
         expected, at);
  free(c.b);
}

START_TEST(crafted_words_are_checked) {
  bytes_t b = small_file();
  const uint32_t W = get32(b.b + 16);
  /* 300 new canonical words of 9 to 20 letters, and g_0^n up to the format's 128 letters. */
  crafted_words_t w = {0};
  ck_assert(crafted_canonical_words(2, 300, 24, 128, 5, &w));
  crafted_power(2, 128, &w);
  crafted_power(2, 100, &w);
  bytes_t c;
  c.b = crafted_file(b.b, b.n, &w, &c.n);
  hdt_triangulation *t = load(c);
  bytes_t again = save(t);
  expect(again.n == c.n && memcmp(again.b, c.b, c.n) == 0, "the crafted file does not save back to its bytes");
  expect(hdt_validate(t) == HDT_OK, "%s", hdt_last_error_message());
  hdt_destroy(t);
  free(again.b);
  free(c.b);
  crafted_words_free(&w);

  /* Not canonical: a freely reduced word that hdt_word_reduce changes. */
  uint64_t rng = 3;
  int32_t x[8], y[8];
  size_t n = 0;
  do {
    for (int i = 0; i < 8; ++i) do x[i] = rng_below(&rng, 8);
      while (i > 0 && x[i] == inv_letter(2, x[i - 1]));
    ck_assert_int_eq(hdt_word_reduce(2, x, 8, y, 8, &n), HDT_OK);
  } while (n == 8 && memcmp(x, y, sizeof x) == 0);
  crafted_words_add(&w, x, 8);
  expect_words_refused(b, &w, "is not the canonical word", "a word not canonical");
  crafted_words_free(&w);
  /* Not reduced. */
  const int32_t back[] = {0, 1, 5, 0};
  crafted_words_add(&w, back, 4);
  expect_words_refused(b, &w, "is not the canonical word", "a word not reduced");
  crafted_words_free(&w);
  /* A repeat, after a new word; an element of N (id 7 of genus 2). */
  crafted_power(2, 5, &w);
  crafted_power(2, 5, &w);
  {
    bytes_t d;
    d.b = crafted_file(b.b, b.n, &w, &d.n);
    const char *m = refusal(d);
    expect(strstr(m, "word") && strstr(m, "is not the canonical word of a new element"), "a repeat: %s", m);
    free(d.b);
  }
  crafted_words_free(&w);
  int32_t neighbour[8];
  ck_assert_int_eq(hdt_neighbour_word(2, 7, neighbour, 8, &n), HDT_OK);
  crafted_words_add(&w, neighbour, n);
  expect_words_refused(b, &w, "is not the canonical word", "an element of N");
  crafted_words_free(&w);
  /* Far: canonical words of 128 letters from random ones (their points go
     hundreds of translation lengths out; a point of the disk stays within
     cosh d = 2^54 of O). The first is refused, at its byte. */
  ck_assert(crafted_canonical_words(2, 3, 160, 128, 9, &w));
  expect_words_refused(b, &w, "lies too far from O", "a far element");
  crafted_words_free(&w);
  (void)W;
  free(b.b);
}
END_TEST

/* A header that claims 2^32 - 1 faces in a 1000-byte file: refused with
   the address space capped far below what the claim would take. */
START_TEST(huge_counts_allocate_nothing) {
  if (UNDER_SANITIZER || getenv("LD_PRELOAD")) {
    printf("save: huge_counts_allocate_nothing skipped under a sanitizer or valgrind (RLIMIT_AS does not apply)\n");
    return;
  }
  bytes_t b = small_file();
  fflush(stdout);
  const pid_t pid = fork();
  ck_assert(pid >= 0);
  if (pid == 0) {
    put32(b.b + 24, 0xFFFFFFFFu);
    put32(b.b + 20, 0xFFFFFFFFu);
    reseal(b);
    hdt_triangulation *t = SENTINEL;
    hdt_status s = hdt_load(&t, b.b, b.n); /* warm: thread-local state */
    struct rlimit r;
    getrlimit(RLIMIT_AS, &r);
    r.rlim_cur = 1ull << 32; /* 4 GiB of address space; the claim needs over 200 */
    if (setrlimit(RLIMIT_AS, &r) != 0) _exit(3);
    s = hdt_load(&t, b.b, b.n);
    _exit(s == HDT_EINVAL && t == SENTINEL ? 0 : 1);
  }
  int status = 0;
  ck_assert(waitpid(pid, &status, 0) == pid);
  ck_assert_msg(WIFEXITED(status) && WEXITSTATUS(status) == 0, "the child failed: %d", status);
  free(b.b);
}
END_TEST

/* What a load costs against building the triangulation: 10^5 random points
   of genus 2, 2000 under slow tools (HDT_SAVE_POINTS changes the count).
   Printed, not asserted (a shared machine's timings are noisy);
   docs/format.md quotes them. */
START_TEST(load_cost) {
  const char *env = getenv("HDT_SAVE_POINTS");
  const size_t n = env ? (size_t)strtoull(env, NULL, 10) : slow_tools() ? 2000 : 100000;
  uint64_t seed = 11;
  double *xy = malloc((2 * n + 2) * sizeof *xy);
  ck_assert_ptr_nonnull(xy);
  random_points(&seed, xy, n, 0.95);
  hdt_triangulation *t = NULL;
  ck_assert_int_eq(hdt_create(&t, 2), HDT_OK);
  double t0 = seconds();
  ck_assert_int_eq(hdt_insert_many(t, xy, n, NULL), HDT_OK);
  const double insert = seconds() - t0;
  ck_assert_int_eq(hdt_remove_dummies(t, NULL), HDT_OK);
  t0 = seconds();
  bytes_t file = save(t);
  const double saving = seconds() - t0;
  t0 = seconds();
  hdt_triangulation *u = load(file);
  const double loading = seconds() - t0;
  t0 = seconds();
  ck_assert_int_eq(hdt_validate(t), HDT_OK);
  const double validating = seconds() - t0;
  expect_same(t, u, "load_cost");
  printf("save: %zu points of genus 2: hdt_insert_many %.3f s, hdt_save %.3f s (%zu bytes), hdt_load %.3f s "
         "(%.2f x the insertion), hdt_validate %.3f s\n",
         n, insert, saving, file.n, loading, loading / insert, validating);
  free(file.b);
  free(xy);
  hdt_destroy(t);
  hdt_destroy(u);
}
END_TEST

int main(void) {
  const TTest *const tests[] = {round_trips,
                                two_call_pattern,
                                truncated_and_flipped,
                                checksum_is_standard_crc32,
                                crafted_bytes,
                                messages_name_the_byte,
                                flipped_edges_are_refused,
                                huge_counts_allocate_nothing,
                                crafted_words_are_checked,
                                load_cost};
  return run_tests("save", tests, sizeof tests / sizeof tests[0]);
}
