/* hdt-triangulate: random points uniform for hyperbolic area in F_g. */
#ifndef HDT_CLI_RANDOM_POINTS_H
#define HDT_CLI_RANDOM_POINTS_H

#include <stddef.h>
#include <stdint.h>

#include <hdt.h>

/* Fills xy[0 .. 2n-1] with n points drawn uniformly for hyperbolic area in
   the half-open fundamental polygon F_g of M_genus, from a splitmix64 stream
   seeded with `seed` (the same seed gives the same points with the same C
   library; cos and sin may differ in the last bit elsewhere).
   *tried (may be NULL) receives the number of candidates drawn. Returns 0
   on a library failure (reported on stderr). */
int random_points(int genus, uint64_t seed, size_t n, double *xy, size_t *tried);

/* The same on a surface given by a polygon: uniform for hyperbolic area in
   the polygon's half-open fundamental set (the candidates drawn in the disk
   about 0 through its farthest vertex, kept when their representative is
   themselves). */
int random_surface_points(const hdt_surface *s, uint64_t seed, size_t n, double *xy, size_t *tried);

#endif
