/* hdt-triangulate: the triangulation as a mesh file for other programs
 * (--format vtu, msh, obj or off), written by the tool itself.
 *
 * The layout is the unfolded one of the Python package's to_meshio: each
 * face in its canonical copy in the Poincare disk (z = 0), one node per
 * distinct (vertex, corner translation) pair, so that nodes are shared
 * inside a copy and repeated across the sides of F_g. VTU and Gmsh carry the
 * node-to-vertex map ("vertex": the identification list of periodic finite
 * elements) and the dummy flags; VTU also the face index of each triangle.
 * OBJ and OFF hold the geometry only. Coordinates are printed with %.17g.
 */
#ifndef HDT_CLI_MESH_WRITER_H
#define HDT_CLI_MESH_WRITER_H

#include "snapshot.h"

#include <hdt.h>
#include <stdio.h>

typedef enum { MESH_FORMAT_VTU, MESH_FORMAT_MSH, MESH_FORMAT_OBJ, MESH_FORMAT_OFF } mesh_format;

/* Writes the mesh of t (its faces and vertices as in s) to f; 0 on a
   failure of the library or of memory (reported on stderr). The stream's
   error state is left for the caller to check. */
int mesh_writer_write(FILE *f, mesh_format format, const hdt_triangulation *t, const snapshot *s);

#endif
