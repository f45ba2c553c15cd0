"""The triangulation as a mesh for other programs: :func:`to_meshio`.

Two layouts, both with triangles only, the coordinates in the Poincare disk
(z = 0), and the genus and libhdt's version as field data:

``"representatives"``
    one node per live vertex, at its representative in F_g; the triangles by
    node. A face's corners generally sit in other copies of F_g than the
    representatives (the face crosses a side), so each corner's translation
    travels as cell data: corner c of triangle i is the point
    ``translation_matrix(translation[i, c])`` applied to its node. This is
    the mesh of the surface itself (every vertex once), for codes that know
    the identification.

``"unfolded"``
    each face drawn in its canonical copy: one node per distinct (vertex,
    corner translation) pair, so nodes are shared inside a copy and
    repeated across the sides of F_g, and every triangle is a true triangle
    of the disk. The point data ``vertex`` maps each node to its vertex: the
    identification list that periodic finite-element codes take (the nodes
    with the same vertex are one degree of freedom).

Point data: ``vertex`` (the vertex id, uint32) and ``dummy`` (0 or 1).
Cell data: ``face`` (the index of :meth:`Triangulation.faces`, uint32) and,
for "representatives", ``translation`` (int32, one column per corner).
meshio's own writers then give VTU, Gmsh, OBJ, OFF and the rest:
``t.to_meshio("unfolded").write("mesh.vtu")``. docs/mesh_files.md of the
source tree explains taking the mesh into a solver.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Tuple

if TYPE_CHECKING:  # for the annotations only: meshio is optional, and triangulation imports this module
    import meshio

    from .triangulation import Triangulation

#: The layouts :func:`to_meshio` takes.
LAYOUTS = ("representatives", "unfolded")


def _modules() -> Tuple[Any, Any]:
    try:
        import meshio
        import numpy
    except ImportError as error:
        raise ImportError("to_meshio() needs meshio and NumPy (Debian: python3-meshio)", name=error.name) from error
    return meshio, numpy


def to_meshio(triangulation: Triangulation, layout: str = "representatives") -> meshio.Mesh:
    """The triangulation as a ``meshio.Mesh`` in one of :data:`LAYOUTS`
    (see the module's documentation). :class:`ValueError` for another
    layout; :class:`ImportError` without meshio or NumPy."""
    if layout not in LAYOUTS:
        raise ValueError(f"layout must be one of {', '.join(LAYOUTS)}, not {layout!r}")
    meshio, np = _modules()
    ids, points, dummy = (np.asarray(a) for a in triangulation.vertices())
    face_vertices, translations = (np.asarray(a) for a in triangulation.faces())
    faces = np.arange(len(face_vertices), dtype=np.uint32)
    fields = {"genus": np.array([triangulation.genus], dtype=np.int32)}
    if layout == "representatives":
        node_of = np.zeros(int(ids.max()) + 1 if len(ids) else 0, dtype=np.int64)
        node_of[ids.astype(np.int64)] = np.arange(len(ids))
        cells = node_of[face_vertices.astype(np.int64)]
        return meshio.Mesh(np.column_stack([points, np.zeros(len(points))]), [("triangle", cells)],
                           point_data={"vertex": ids.astype(np.uint32), "dummy": dummy.astype(np.uint8)},
                           cell_data={"face": [faces], "translation": [translations.astype(np.int32)]},
                           field_data=fields)
    corners = np.asarray(triangulation.face_points()).reshape(-1, 2)
    # One node per (vertex, translation) pair: the same corner of two faces
    # in one copy is one point, bit for bit (the library computes it once).
    keys = np.column_stack([face_vertices.reshape(-1).astype(np.int64), translations.reshape(-1).astype(np.int64)])
    unique, first, inverse = np.unique(keys, axis=0, return_index=True, return_inverse=True)
    inverse = inverse.reshape(-1)
    nodes = corners[first]
    is_dummy = np.zeros(int(ids.max()) + 1 if len(ids) else 0, dtype=np.uint8)
    is_dummy[ids.astype(np.int64)] = dummy.astype(np.uint8)
    node_vertex = unique[:, 0].astype(np.uint32)
    return meshio.Mesh(np.column_stack([nodes, np.zeros(len(nodes))]), [("triangle", inverse.reshape(-1, 3))],
                       point_data={"vertex": node_vertex, "dummy": is_dummy[node_vertex]},
                       cell_data={"face": [faces]}, field_data=fields)
