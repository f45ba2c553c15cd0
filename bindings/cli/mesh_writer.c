/* hdt-triangulate: the triangulation as VTU, Gmsh, OBJ or OFF. */
#define _POSIX_C_SOURCE 200809L

#include "mesh_writer.h"

#include "cli_util.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* The unfolded mesh: nodes (x, y, their vertex) and 3 nodes per face. */
typedef struct mesh {
  size_t node_count, face_count;
  double *xy;
  uint32_t *node_vertex;
  size_t *corner_node; /* 3 per face */
} mesh;

typedef struct corner_key {
  uint32_t vertex;
  int32_t translation;
  size_t corner; /* 3 face + c */
} corner_key;

static int by_key(const void *a, const void *b) {
  const corner_key *p = a, *q = b;
  if (p->vertex != q->vertex) return p->vertex < q->vertex ? -1 : 1;
  if (p->translation != q->translation) return p->translation < q->translation ? -1 : 1;
  return p->corner < q->corner ? -1 : p->corner > q->corner;
}

static void mesh_free(mesh *m) {
  free(m->xy);
  free(m->node_vertex);
  free(m->corner_node);
}

/* Nodes numbered by (vertex, translation), each at the corner point the
   library gives (the same bits for every face that shares it). */
static int mesh_build(const hdt_triangulation *t, const snapshot *s, mesh *m) {
  memset(m, 0, sizeof *m);
  const size_t F = s->face_count, corners = 3 * F;
  double *points = cli_alloc(2 * corners, sizeof *points);
  corner_key *keys = cli_alloc(corners, sizeof *keys);
  m->xy = cli_alloc(2 * corners, sizeof *m->xy);
  m->node_vertex = cli_alloc(corners, sizeof *m->node_vertex);
  m->corner_node = cli_alloc(corners, sizeof *m->corner_node);
  size_t got = 0;
  int ok = points && keys && m->xy && m->node_vertex && m->corner_node &&
           cli_check(hdt_face_points(t, points, F, &got), "hdt_face_points");
  if (ok) {
    for (size_t k = 0; k < corners; ++k) keys[k] = (corner_key){s->face_vertices[k], s->face_translations[k], k};
    qsort(keys, corners, sizeof *keys, by_key);
    for (size_t k = 0; k < corners; ++k) {
      if (k == 0 || keys[k].vertex != keys[k - 1].vertex || keys[k].translation != keys[k - 1].translation) {
        m->xy[2 * m->node_count] = points[2 * keys[k].corner];
        m->xy[2 * m->node_count + 1] = points[2 * keys[k].corner + 1];
        m->node_vertex[m->node_count++] = keys[k].vertex;
      }
      m->corner_node[keys[k].corner] = m->node_count - 1;
    }
    m->face_count = F;
  }
  free(points);
  free(keys);
  if (!ok) mesh_free(m);
  return ok;
}

static void write_vtu(FILE *f, const mesh *m, const snapshot *s) {
  fprintf(f,
          "<?xml version=\"1.0\"?>\n"
          "<!-- hdt-triangulate %s (libhdt %s): Delaunay triangulation on M_%d, each face in its canonical copy "
          "in the Poincare disk; point data vertex: the vertex of each node -->\n"
          "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
          "<UnstructuredGrid>\n<FieldData>\n"
          "<DataArray type=\"Int32\" Name=\"genus\" NumberOfTuples=\"1\" format=\"ascii\">%d</DataArray>\n"
          "</FieldData>\n"
          "<Piece NumberOfPoints=\"%zu\" NumberOfCells=\"%zu\">\n<Points>\n"
          "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n",
          HDT_CLI_VERSION, hdt_version_string(), s->genus, s->genus, m->node_count, m->face_count);
  for (size_t i = 0; i < m->node_count; ++i) fprintf(f, "%.17g %.17g 0\n", m->xy[2 * i], m->xy[2 * i + 1]);
  fputs("</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n", f);
  for (size_t i = 0; i < m->face_count; ++i)
    fprintf(f, "%zu %zu %zu\n", m->corner_node[3 * i], m->corner_node[3 * i + 1], m->corner_node[3 * i + 2]);
  fputs("</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n", f);
  for (size_t i = 0; i < m->face_count; ++i) fprintf(f, "%zu\n", 3 * (i + 1));
  fputs("</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n", f);
  for (size_t i = 0; i < m->face_count; ++i) fputs("5\n", f); /* VTK_TRIANGLE */
  fputs("</DataArray>\n</Cells>\n<PointData>\n<DataArray type=\"UInt32\" Name=\"vertex\" format=\"ascii\">\n", f);
  for (size_t i = 0; i < m->node_count; ++i) fprintf(f, "%lu\n", (unsigned long)m->node_vertex[i]);
  fputs("</DataArray>\n<DataArray type=\"UInt8\" Name=\"dummy\" format=\"ascii\">\n", f);
  for (size_t i = 0; i < m->node_count; ++i) fprintf(f, "%d\n", s->kind[m->node_vertex[i]] == 1);
  fputs("</DataArray>\n</PointData>\n<CellData>\n<DataArray type=\"UInt32\" Name=\"face\" format=\"ascii\">\n", f);
  for (size_t i = 0; i < m->face_count; ++i) fprintf(f, "%zu\n", i);
  fputs("</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n", f);
}

/* Gmsh's format 2.2 (ASCII): nodes and triangles numbered from 1, the
   node-to-vertex map and the dummy flags as node data. */
static void write_node_data(FILE *f, const char *name, const mesh *m, const snapshot *s, int dummy) {
  fprintf(f, "$NodeData\n1\n\"%s\"\n1\n0.0\n3\n0\n1\n%zu\n", name, m->node_count);
  for (size_t i = 0; i < m->node_count; ++i) {
    const uint32_t v = m->node_vertex[i];
    fprintf(f, "%zu %lu\n", i + 1, dummy ? (unsigned long)(s->kind[v] == 1) : (unsigned long)v);
  }
  fputs("$EndNodeData\n", f);
}

static void write_msh(FILE *f, const mesh *m, const snapshot *s) {
  fputs("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n", f);
  fprintf(f, "$Nodes\n%zu\n", m->node_count);
  for (size_t i = 0; i < m->node_count; ++i) fprintf(f, "%zu %.17g %.17g 0\n", i + 1, m->xy[2 * i], m->xy[2 * i + 1]);
  fprintf(f, "$EndNodes\n$Elements\n%zu\n", m->face_count);
  for (size_t i = 0; i < m->face_count; ++i)
    fprintf(f, "%zu 2 2 1 1 %zu %zu %zu\n", i + 1, m->corner_node[3 * i] + 1, m->corner_node[3 * i + 1] + 1,
            m->corner_node[3 * i + 2] + 1);
  fputs("$EndElements\n", f);
  write_node_data(f, "vertex", m, s, 0);
  write_node_data(f, "dummy", m, s, 1);
}

static void write_obj(FILE *f, const mesh *m, const snapshot *s) {
  fprintf(f, "# hdt-triangulate %s (libhdt %s): Delaunay triangulation on M_%d, unfolded in the Poincare disk\n",
          HDT_CLI_VERSION, hdt_version_string(), s->genus);
  for (size_t i = 0; i < m->node_count; ++i) fprintf(f, "v %.17g %.17g 0\n", m->xy[2 * i], m->xy[2 * i + 1]);
  for (size_t i = 0; i < m->face_count; ++i)
    fprintf(f, "f %zu %zu %zu\n", m->corner_node[3 * i] + 1, m->corner_node[3 * i + 1] + 1, m->corner_node[3 * i + 2] + 1);
}

static void write_off(FILE *f, const mesh *m) {
  fprintf(f, "OFF\n%zu %zu 0\n", m->node_count, m->face_count);
  for (size_t i = 0; i < m->node_count; ++i) fprintf(f, "%.17g %.17g 0\n", m->xy[2 * i], m->xy[2 * i + 1]);
  for (size_t i = 0; i < m->face_count; ++i)
    fprintf(f, "3 %zu %zu %zu\n", m->corner_node[3 * i], m->corner_node[3 * i + 1], m->corner_node[3 * i + 2]);
}

int mesh_writer_write(FILE *f, mesh_format format, const hdt_triangulation *t, const snapshot *s) {
  mesh m;
  if (!mesh_build(t, s, &m)) return 0;
  switch (format) {
    case MESH_FORMAT_VTU: write_vtu(f, &m, s); break;
    case MESH_FORMAT_MSH: write_msh(f, &m, s); break;
    case MESH_FORMAT_OBJ: write_obj(f, &m, s); break;
    case MESH_FORMAT_OFF: write_off(f, &m); break;
  }
  mesh_free(&m);
  return 1;
}
