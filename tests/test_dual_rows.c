/* Every star and every Voronoi cell in one call (hdt_vertex_stars,
   hdt_voronoi_cells, HDT_0.5), checked entry for entry against the
   per-vertex functions (hdt_vertex_star, hdt_voronoi_cell: the same bits),
   and against the face list: each face corner is in its vertex's row once,
   consecutive entries are adjacent faces, and each translation undoes the
   corner's (its matrix maps the corner back to the representative). */
#define _DEFAULT_SOURCE

#include "hdt_test.h"
#include "limited_child.h"

static void *need(void *p) {
  ck_assert_ptr_nonnull(p);
  return p;
}


/* Removes every k-th live vertex that may go (gaps in the ids). */
static void remove_some(hdt_triangulation *t, size_t k, size_t from) {
  const size_t V = hdt_vertex_count(t);
  uint32_t *ids = need(malloc(V * sizeof *ids));
  size_t n = 0, removed = 0;
  OK(hdt_vertices(t, ids, NULL, NULL, V, &n));
  for (size_t i = from; i < V; i += k) removed += hdt_remove_vertex(t, ids[i]) == HDT_OK;
  expect(removed > 0, "no vertex could be removed");
  free(ids);
}

static void apply(const double m[4], double x, double y, double *ox, double *oy) {
  /* (a z + b) / (conj(b) z + conj(a)), a = m[0] + i m[1], b = m[2] + i m[3]. */
  const double nr = m[0] * x - m[1] * y + m[2], ni = m[0] * y + m[1] * x + m[3];
  const double dr = m[2] * x + m[3] * y + m[0], di = m[2] * y - m[3] * x - m[1];
  const double d = dr * dr + di * di;
  *ox = (nr * dr + ni * di) / d, *oy = (ni * dr - nr * di) / d;
}

/* The rows of t against the per-vertex functions and the face list. */
static void check_rows(hdt_triangulation *t, const char *what) {
  const size_t V = hdt_vertex_count(t), F = hdt_face_count(t), bound = hdt_vertex_id_bound(t);
  size_t n = 0, m = 0;
  OK(hdt_vertex_stars(t, NULL, NULL, NULL, NULL, 0, &n));
  expect(n == 3 * F, "%s: hdt_vertex_stars asks for %zu entries, 3F = %zu", what, n, 3 * F);
  OK(hdt_voronoi_cells(t, NULL, NULL, 0, &n));
  expect(n == 3 * F, "%s: hdt_voronoi_cells asks for %zu points, 3F = %zu", what, n, 3 * F);
  size_t *offsets = need(malloc((bound + 1) * sizeof *offsets));
  size_t *cell_offsets = need(malloc((bound + 1) * sizeof *cell_offsets));
  uint32_t *faces = need(malloc(3 * F * sizeof *faces)), *fv = need(malloc(3 * F * sizeof *fv)),
           *nf = need(malloc(3 * F * sizeof *nf)), *one_faces = need(malloc(F * sizeof *one_faces));
  uint8_t *corners = need(malloc(3 * F)), *one_corners = need(malloc(F)), *seen = need(calloc(3 * F, 1));
  int32_t *tr = need(malloc(3 * F * sizeof *tr)), *ft = need(malloc(3 * F * sizeof *ft)),
          *nt = need(malloc(3 * F * sizeof *nt)), *one_tr = need(malloc(F * sizeof *one_tr));
  double *xy = need(malloc(6 * F * sizeof *xy)), *one_xy = need(malloc(2 * F * sizeof *one_xy));
  OK(hdt_faces(t, fv, ft, F, &n));
  OK(hdt_face_neighbours(t, nf, nt, F, &n));
  OK(hdt_vertex_stars(t, offsets, faces, corners, tr, 3 * F, &n));
  expect(n == 3 * F, "%s: %zu entries", what, n);
  OK(hdt_voronoi_cells(t, cell_offsets, xy, 3 * F, &m));
  expect(memcmp(offsets, cell_offsets, (bound + 1) * sizeof *offsets) == 0, "%s: the cells' rows are not the stars'",
         what);
  expect(offsets[0] == 0 && offsets[bound] == 3 * F, "%s: offsets from %zu to %zu, 3F = %zu", what, offsets[0],
         offsets[bound], 3 * F);
  size_t live = 0;
  for (uint32_t v = 0; v < bound; ++v) {
    const size_t b = offsets[v], e = offsets[v + 1];
    expect(b <= e, "%s: offsets decrease at %u", what, v);
    if (hdt_vertex_is_dummy(t, v) < 0) {
      expect(b == e, "%s: removed vertex %u has a row of %zu", what, v, e - b);
      continue;
    }
    ++live;
    OK(hdt_vertex_star(t, v, one_faces, one_corners, one_tr, F, &n));
    OK(hdt_voronoi_cell(t, v, one_xy, F, &m));
    expect(n == e - b && m == n, "%s: vertex %u: a row of %zu, a star of %zu, a cell of %zu", what, v, e - b, n, m);
    expect(memcmp(one_faces, faces + b, n * sizeof *faces) == 0 && memcmp(one_corners, corners + b, n) == 0 &&
               memcmp(one_tr, tr + b, n * sizeof *tr) == 0,
           "%s: vertex %u: its row is not hdt_vertex_star's", what, v);
    expect(memcmp(one_xy, xy + 2 * b, 2 * n * sizeof *xy) == 0, "%s: vertex %u: its cell is not hdt_voronoi_cell's",
           what, v);
    /* Against the face list alone. */
    double px, py;
    OK(hdt_vertex_point(t, v, &px, &py));
    for (size_t k = b; k < e; ++k) {
      const uint32_t f = faces[k];
      const int c = corners[k];
      expect(f < F && c < 3 && fv[3 * f + c] == v, "%s: vertex %u: entry %zu is not one of its corners", what, v, k);
      expect(!seen[3 * f + c], "%s: face %u corner %d twice", what, f, c);
      seen[3 * f + c] = 1;
      const size_t next = k + 1 < e ? k + 1 : b;
      expect(nf[3 * f + (c + 1) % 3] == faces[next], "%s: vertex %u: entries %zu and %zu are not adjacent", what, v,
             k, next);
      /* The corner is ft(rep v); tr maps it back to rep v (the group has
         no elliptic elements: a wrong translation moves it by at least the
         systole). */
      double mc[4], mt[4], cx, cy, x, y;
      OK(hdt_translation_matrix(t, ft[3 * f + c], mc));
      OK(hdt_translation_matrix(t, tr[k], mt));
      apply(mc, px, py, &cx, &cy);
      apply(mt, cx, cy, &x, &y);
      expect(hypot(x - px, y - py) < 1e-9, "%s: vertex %u: entry %zu's translation does not undo the corner's", what,
             v, k);
    }
  }
  expect(live == V, "%s: %zu live rows, %zu vertices", what, live, V);
  for (size_t i = 0; i < 3 * F; ++i) expect(seen[i], "%s: face %zu corner %zu in no row", what, i / 3, i % 3);
  /* With the centre cache full (the per-vertex cells above made it), the same bits. */
  double *again = need(malloc(6 * F * sizeof *again));
  OK(hdt_voronoi_cells(t, NULL, again, 3 * F, &m));
  expect(memcmp(again, xy, 6 * F * sizeof *xy) == 0, "%s: the cells differ once the cache is full", what);
  /* Each output alone gives the same entries. */
  uint32_t *faces_only = need(malloc(3 * F * sizeof *faces_only));
  OK(hdt_vertex_stars(t, NULL, faces_only, NULL, NULL, 3 * F, &n));
  expect(memcmp(faces_only, faces, 3 * F * sizeof *faces) == 0, "%s: faces alone differ", what);
  free(again), free(faces_only);
  free(offsets), free(cell_offsets), free(faces), free(fv), free(nf), free(one_faces), free(corners), free(one_corners),
      free(seen), free(tr), free(ft), free(nt), free(one_tr), free(xy), free(one_xy);
}

/* Random sets of genus 2 and 3, inside F_g and spread over the disk,
   dummies kept and removed, and after removals (gaps in the ids). */
START_TEST(rows_equal_the_per_vertex_functions) {
  for (int g = 2; g <= 3; ++g) {
    char what[64];
    hdt_triangulation *t = small_disk_triangulation(g, 300, 0x5a + g, 0);
    snprintf(what, sizeof what, "genus %d, dummies kept", g);
    check_rows(t, what);
    OK(hdt_remove_dummies(t, NULL));
    snprintf(what, sizeof what, "genus %d, dummies removed", g);
    check_rows(t, what);
    remove_some(t, 5, 1);
    snprintf(what, sizeof what, "genus %d, every fifth vertex removed", g);
    check_rows(t, what);
    hdt_destroy(t);
    t = wide_disk_triangulation(g, 400, 0x77 + g, 0);
    snprintf(what, sizeof what, "genus %d, spread over the disk", g);
    check_rows(t, what);
    OK(hdt_remove_dummies(t, NULL));
    remove_some(t, 3, 0);
    snprintf(what, sizeof what, "genus %d, spread, every third vertex removed", g);
    check_rows(t, what);
    hdt_destroy(t);
  }
  /* A vertex of degree 40 (rows of 16 and more take another path): the
     origin and 40 points on a circle about it. */
  {
    hdt_triangulation *w = new_triangulation(2);
    double xy[82] = {0, 0};
    for (int k = 0; k < 40; ++k) xy[2 + 2 * k] = 0.1 * cos(k * M_PI / 20), xy[3 + 2 * k] = 0.1 * sin(k * M_PI / 20);
    uint32_t ids[41];
    OK(hdt_insert_many(w, xy, 41, ids));
    size_t n = 0;
    OK(hdt_vertex_star(w, ids[0], NULL, NULL, NULL, 0, &n));
    expect(n == 40, "the centre has degree %zu", n);
    check_rows(w, "genus 2, a vertex of degree 40");
    hdt_destroy(w);
  }
  /* The dummy set alone (cocircular faces) and a larger set. */
  hdt_triangulation *t = new_triangulation(2);
  check_rows(t, "genus 2, the dummies alone");
  hdt_destroy(t);
  t = wide_disk_triangulation(2, 3000, 0x99, 0);
  OK(hdt_remove_dummies(t, NULL));
  check_rows(t, "genus 2, 3000 points");
  hdt_destroy(t);
}
END_TEST

/* The triangulation changes between calls: the rows follow (the centre
   cache's stale entries are never read). */
START_TEST(rows_follow_changes) {
  hdt_triangulation *t = wide_disk_triangulation(2, 150, 0xce11, 0);
  OK(hdt_remove_dummies(t, NULL));
  uint64_t seed = 0xce12;
  for (int round = 0; round < 3; ++round) {
    char what[32];
    snprintf(what, sizeof what, "round %d", round);
    check_rows(t, what);
    for (int k = 0; k < 20;) {
      const double x = 1.9 * uniform01(&seed) - 0.95, y = 1.9 * uniform01(&seed) - 0.95;
      if (x * x + y * y >= 0.95 * 0.95) continue;
      OK(hdt_insert(t, x, y, NULL));
      ++k;
    }
    remove_some(t, 7, (size_t)round);
  }
  check_rows(t, "the last round");
  hdt_destroy(t);
}
END_TEST

/* The contract: NULL handle or count, too small a capacity (count set,
   nothing written), xy NULL, the size query writing nothing. */
START_TEST(bad_arguments) {
  hdt_triangulation *t = small_disk_triangulation(2, 30, 9, 1);
  const size_t F = hdt_face_count(t), bound = hdt_vertex_id_bound(t);
  size_t n = 7;
  expect_failure(hdt_vertex_stars(NULL, NULL, NULL, NULL, NULL, 0, &n), HDT_EINVAL, "hdt_vertex_stars");
  expect_failure(hdt_voronoi_cells(NULL, NULL, NULL, 0, &n), HDT_EINVAL, "hdt_voronoi_cells");
  expect(n == 7, "a NULL handle set the count");
  expect_failure(hdt_vertex_stars(t, NULL, NULL, NULL, NULL, 0, NULL), HDT_EINVAL, "hdt_vertex_stars");
  expect_failure(hdt_voronoi_cells(t, NULL, NULL, 0, NULL), HDT_EINVAL, "hdt_voronoi_cells");
  size_t *offsets = need(malloc((bound + 1) * sizeof *offsets));
  uint32_t *faces = need(malloc(3 * F * sizeof *faces));
  uint8_t *corners = need(malloc(3 * F));
  int32_t *tr = need(malloc(3 * F * sizeof *tr));
  double *xy = need(malloc(6 * F * sizeof *xy));
  const size_t sizes[] = {0, 3 * F - 1, 1};
  for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; ++s) {
    for (size_t i = 0; i <= bound; ++i) offsets[i] = 77;
    memset(faces, 0xab, 3 * F * sizeof *faces), memset(corners, 0xab, 3 * F), memset(tr, 0xab, 3 * F * sizeof *tr);
    for (size_t i = 0; i < 6 * F; ++i) xy[i] = -7;
    n = 0;
    const hdt_status expected = sizes[s] == 0 ? HDT_OK : HDT_EBUFS;
    const hdt_status stars = hdt_vertex_stars(t, offsets, faces, corners, tr, sizes[s], &n);
    if (expected != HDT_OK) expect_failure(stars, expected, "hdt_vertex_stars");
    expect(stars == expected && n == 3 * F, "capacity %zu: stars %d, count %zu, 3F %zu", sizes[s], (int)stars, n,
           3 * F);
    n = 0;
    const hdt_status cells = hdt_voronoi_cells(t, offsets, xy, sizes[s], &n);
    if (expected != HDT_OK) expect_failure(cells, expected, "hdt_voronoi_cells");
    expect(cells == expected && n == 3 * F, "capacity %zu: cells %d, count %zu, 3F %zu", sizes[s], (int)cells, n,
           3 * F);
    for (size_t i = 0; i <= bound; ++i) expect(offsets[i] == 77, "capacity %zu wrote offset %zu", sizes[s], i);
    for (size_t i = 0; i < 3 * F; ++i)
      expect(faces[i] == 0xabababab && corners[i] == 0xab && tr[i] == (int32_t)0xabababab,
             "capacity %zu wrote entry %zu", sizes[s], i);
    for (size_t i = 0; i < 6 * F; ++i) expect(xy[i] == -7, "capacity %zu wrote xy %zu", sizes[s], i);
  }
  expect_failure(hdt_voronoi_cells(t, offsets, NULL, 3 * F, &n), HDT_EINVAL, "hdt_voronoi_cells");
  for (size_t i = 0; i <= bound; ++i) expect(offsets[i] == 77, "xy NULL: offset %zu written", i);
  /* Every output may be NULL: the offsets alone. */
  OK(hdt_vertex_stars(t, offsets, NULL, NULL, NULL, 3 * F, &n));
  expect(offsets[0] == 0 && offsets[bound] == 3 * F, "offsets alone: %zu to %zu", offsets[0], offsets[bound]);
  free(offsets), free(faces), free(corners), free(tr), free(xy);
  hdt_destroy(t);
}
END_TEST

/* Out of memory: under an address-space limit 1 MiB above what the process
   uses, both functions need more scratch than that (the rows 24 bytes a
   face, the cells' centre cache 48): HDT_ENOMEM, no byte of the buffers
   written (count set); with the memory back, the rows as before. In a
   child process (limited_child.h); not under a sanitizer or valgrind,
   which reserve address space of their own. */
static void out_of_memory_child(void) {
  hdt_triangulation *t = wide_disk_triangulation(2, 100000, 0xe0e0, 0);
  const size_t F = hdt_face_count(t), bound = hdt_vertex_id_bound(t);
  size_t *offsets = malloc((bound + 1) * sizeof *offsets);
  uint32_t *faces = malloc(3 * F * sizeof *faces), *before = malloc(3 * F * sizeof *before);
  double *xy = malloc(6 * F * sizeof *xy);
  require(offsets && faces && before && xy, "no memory for the buffers");
  memset(offsets, 0x5a, (bound + 1) * sizeof *offsets), memset(faces, 0x5a, 3 * F * sizeof *faces);
  memset(xy, 0x5a, 6 * F * sizeof *xy);
  struct rlimit old;
  require(getrlimit(RLIMIT_AS, &old) == 0, "getrlimit: %s", strerror(errno));
  struct rlimit tight = {(rlim_t)(address_space_bytes() + ((size_t)1 << 20)), old.rlim_max};
  require(setrlimit(RLIMIT_AS, &tight) == 0, "setrlimit: %s", strerror(errno));
  size_t count = 0;
  hdt_status s = hdt_vertex_stars(t, offsets, faces, NULL, NULL, 3 * F, &count);
  require(s == HDT_ENOMEM && count == 3 * F, "hdt_vertex_stars under the limit: %s, count %zu",
          hdt_status_string(s), count);
  require(strstr(hdt_last_error_message(), "hdt_vertex_stars"), "message \"%s\"", hdt_last_error_message());
  count = 0;
  s = hdt_voronoi_cells(t, offsets, xy, 3 * F, &count);
  require(s == HDT_ENOMEM && count == 3 * F, "hdt_voronoi_cells under the limit: %s, count %zu",
          hdt_status_string(s), count);
  const unsigned char *bytes = (const unsigned char *)offsets;
  for (size_t i = 0; i < (bound + 1) * sizeof *offsets; ++i) require(bytes[i] == 0x5a, "offsets byte %zu written", i);
  bytes = (const unsigned char *)faces;
  for (size_t i = 0; i < 3 * F * sizeof *faces; ++i) require(bytes[i] == 0x5a, "faces byte %zu written", i);
  bytes = (const unsigned char *)xy;
  for (size_t i = 0; i < 6 * F * sizeof *xy; ++i) require(bytes[i] == 0x5a, "xy byte %zu written", i);
  require(setrlimit(RLIMIT_AS, &old) == 0, "setrlimit back: %s", strerror(errno));
  require(hdt_vertex_stars(t, offsets, faces, NULL, NULL, 3 * F, &count) == HDT_OK &&
              hdt_voronoi_cells(t, offsets, xy, 3 * F, &count) == HDT_OK,
          "with memory back: %s", hdt_last_error_message());
  /* The first row against hdt_vertex_star. */
  uint32_t v = 0;
  while (offsets[v] == offsets[v + 1]) ++v;
  require(hdt_vertex_star(t, v, before, NULL, NULL, F, &count) == HDT_OK && count == offsets[v + 1] - offsets[v] &&
              memcmp(before, faces + offsets[v], count * sizeof *faces) == 0,
          "with memory back: the row of vertex %u differs", v);
  hdt_destroy(t);
  free(offsets), free(faces), free(before), free(xy);
  _exit(0);
}

START_TEST(out_of_memory) {
  const char *preload = getenv("LD_PRELOAD");
  if (UNDER_SANITIZER || (preload && strstr(preload, "vgpreload"))) return;
  run_child(out_of_memory_child);
}
END_TEST

int main(void) {
  const TTest *const tests[] = {rows_equal_the_per_vertex_functions, rows_follow_changes, bad_arguments,
                                out_of_memory};
  return run_tests("dual_rows", tests, sizeof tests / sizeof tests[0]);
}
