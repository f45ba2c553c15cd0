/* An independent Delaunay method for small triangulations: the Delaunay
 * faces of the live vertices found by brute force over their images under
 * the neighbour set N, compared with hdt_faces. Shared by the Check test
 * tests/test_brute_force.c and the differential fuzz target
 * tests/fuzz/fuzz_brute_force.c, so it reports through return values and
 * messages, not through Check.
 *
 * Nothing here goes through the incremental code path: the only inputs taken
 * from the triangulation are its vertices' representatives (hdt_vertex_point),
 * and the group elements come from hdt_neighbour_word + hdt_word_matrix.
 *
 * Why N suffices: every face of the triangulation has hyperbolic
 * circumdiameter < sys/2 (the guarantee of the header), so its circumdisk
 * lies within distance sys/2 of its corner a in F_g, and the ball of radius
 * sys/2 about any point of F_g lies in D_N = union of h(F_g), h in N (checked
 * by test_brute_force's half_systole_balls_lie_in_d_n). So the orbit points
 * that can lie in such a disk are exactly the N-images of the vertices.
 *
 * In-circle tests are Euclidean determinants on Poincare coordinates: a
 * hyperbolic circle is a Euclidean circle inside the disk, so the Euclidean
 * answer is the hyperbolic one. Decisions within a tiny relative margin of 0
 * are "ambiguous": the dummy points sit at symmetric positions (0, the
 * midpoints and vertex of F_g ...) and are cocircular, where any
 * triangulation of the cocircular polygon is Delaunay. So the check is
 *   strict  subset of  library faces  subset of  weak,
 * where strict = triangles with every other point clearly outside their
 * circle, weak = triangles with no point clearly inside; when nothing is
 * ambiguous the two sets coincide and the faces must equal them exactly.
 *
 * The margins assume images accurate to ~1e-14 and vertices well apart
 * compared with that: two vertices within ~1e-6 (hyperbolic) of each other
 * make the determinants' rounding larger than the margin. bf_outcome.min_u
 * tells a caller with arbitrary points when the answer cannot be trusted. */
#ifndef HDT_TESTS_BRUTE_FORCE_H
#define HDT_TESTS_BRUTE_FORCE_H

#include <stddef.h>
#include <stdint.h>

#include "hdt.h"

/* The neighbour set N of a genus: canonical words and SU(1,1) matrices, by
   translation id. */
typedef struct bf_nset {
  int g;
  size_t count;
  size_t *start;    /* word of id: letters[start[id] .. start[id + 1]) */
  int32_t *letters;
  double (*m)[4];
} bf_nset;

/* 0, or nonzero with a message in msg. */
int bf_nset_make(bf_nset *n, int g, char *msg, size_t size);
void bf_nset_free(bf_nset *n);
/* The letters of id's canonical word; *len receives its length. */
const int32_t *bf_nset_word(const bf_nset *n, size_t id, size_t *len);
/* The translation id of the element with canonical word w, or -1. */
long bf_nset_find(const bf_nset *n, const int32_t *w, size_t len);

/* What one comparison saw. */
typedef struct bf_outcome {
  size_t vertices, faces;
  size_t ambiguous;  /* candidate triangles with an undecided test (0: exact equality was checked) */
  double min_u;      /* smallest u-distance |z-w|^2 / ((1-|z|^2)(1-|w|^2)) between two distinct
                        orbit points seen from a corner (INFINITY when none); cosh d = 1 + 2u */
  uint32_t closest[2]; /* two vertices that far apart */
} bf_outcome;

enum {
  BF_OK = 0,
  BF_BROKEN = 1,  /* a check that does not depend on the brute force's rounding failed */
  BF_DIFFERS = 2, /* the faces differ from the brute force's */
};

/* Compares hdt_faces of t with the brute force. BF_BROKEN unless
   F = 2 (V + 2g - 2), no face is listed twice, each face's smallest vertex
   sits at translation 0 and its other corners at translations of N, and the
   live vertices agree with hdt_vertex_count and hdt_dummy_count; then
   BF_DIFFERS unless strict subset of faces subset of weak, and faces = strict
   when nothing was ambiguous. A message in msg unless BF_OK. */
int bf_cross_check(const bf_nset *ns, const hdt_triangulation *t, bf_outcome *out, char *msg, size_t size);

#endif /* HDT_TESTS_BRUTE_FORCE_H */
