"""Mesh files: Triangulation.to_meshio in both layouts, checked against the
library's own faces, translations and corner points; meshio's writers and
readers round-trip them; and hdt-triangulate's own VTU, Gmsh, OBJ and OFF
writers read back with meshio, with VTK's XML reader and with Gmsh, giving the
same nodes and triangles as to_meshio's unfolded layout."""

import os
import shutil
import subprocess

import pytest

import hdt

meshio = pytest.importorskip("meshio", reason="meshio is not installed (Debian: python3-meshio)")
np = pytest.importorskip("numpy")

CLI = os.environ.get("HDT_TRIANGULATE")


def triangulation(genus=2, n=60, seed=3):
    t = hdt.Triangulation(genus)
    rng = np.random.default_rng(seed)
    r = np.sqrt(rng.uniform(0, 0.36, n))
    a = rng.uniform(0, 2 * np.pi, n)
    t.insert_many(np.column_stack([r * np.cos(a), r * np.sin(a)]))
    return t


def apply(matrix, z):
    a, b = matrix
    return (a * z + b) / (b.conjugate() * z + a.conjugate())


@pytest.mark.parametrize("genus", [2, 3])
def test_representatives_layout(genus):
    with triangulation(genus) as t:
        t.remove_dummies()
        m = t.to_meshio()
        ids, points, dummy = t.vertices()
        (cells,) = [c.data for c in m.cells if c.type == "triangle"]
        assert len(m.points) == len(t) and len(cells) == t.face_count
        assert np.array_equal(m.point_data["vertex"], ids) and np.array_equal(m.point_data["dummy"], dummy)
        assert np.array_equal(m.points[:, :2], points) and not m.points[:, 2].any()
        assert int(m.field_data["genus"][0]) == genus
        faces, translations = t.faces()
        assert np.array_equal(m.point_data["vertex"][cells], faces)
        assert np.array_equal(m.cell_data["translation"][0], translations)
        # each corner: the translation applied to its node is the corner of the canonical copy
        corners = t.face_points()
        for f in range(0, t.face_count, 7):
            for c in range(3):
                node = m.points[cells[f, c]]
                z = apply(t.translation_matrix(int(translations[f, c])), complex(node[0], node[1]))
                assert abs(z - complex(*corners[f, c])) < 1e-12


@pytest.mark.parametrize("genus", [2, 3])
def test_unfolded_layout(genus):
    with triangulation(genus) as t:
        m = t.to_meshio("unfolded")
        (cells,) = [c.data for c in m.cells if c.type == "triangle"]
        faces, translations = t.faces()
        corners = t.face_points()
        assert len(cells) == t.face_count
        # every triangle is its face's canonical copy, bit for bit, counterclockwise
        assert np.array_equal(m.points[cells][:, :, :2], corners)
        a, b, c = (m.points[cells][:, k, :2] for k in range(3))
        cross = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
        assert (cross > 0).all()
        # the nodes are the distinct (vertex, translation) pairs; vertex maps them back
        pairs = {(int(v), int(s)) for v, s in zip(faces.reshape(-1), translations.reshape(-1))}
        assert len(m.points) == len(pairs)
        assert np.array_equal(m.point_data["vertex"][cells], faces)
        assert set(m.point_data["vertex"].tolist()) == set(t.vertices().ids.tolist())
        # repeated across the sides: more nodes than vertices, each vertex at least once
        assert len(m.points) > len(t)
        dummies = {int(v) for v, d in zip(*t.vertices()[::2]) if d}
        assert {int(v) for v, d in zip(m.point_data["vertex"], m.point_data["dummy"]) if d} == dummies


def test_bad_layout():
    with triangulation() as t:
        with pytest.raises(ValueError, match="layout"):
            t.to_meshio("folded")


@pytest.mark.parametrize("extension, kwargs", [("vtu", {}), ("msh", {"file_format": "gmsh22", "binary": False}),
                                               ("obj", {}), ("off", {})])
def test_meshio_round_trip(tmp_path, extension, kwargs):
    with triangulation() as t:
        m = t.to_meshio("unfolded")
    path = tmp_path / f"mesh.{extension}"
    meshio.write(path, m, **kwargs)
    back = meshio.read(path)
    (cells,) = [c.data for c in back.cells if c.type == "triangle"]
    assert np.allclose(back.points[:, :2], m.points[:, :2], rtol=0, atol=1e-15)
    assert np.array_equal(cells, m.cells[0].data)


def cli_mesh(tmp_path, fmt):
    if not CLI or not os.path.exists(CLI):
        pytest.skip("HDT_TRIANGULATE does not name hdt-triangulate (meson test sets it)")
    path = tmp_path / f"cli.{fmt}"
    subprocess.run([CLI, "--genus", "3", "--random", "80", "--seed", "5", "--format", fmt, "-o", str(path)],
                   check=True, timeout=60)
    return path


def reference_mesh(tmp_path):
    """The same triangulation through the library, saved by the CLI and loaded."""
    saved = tmp_path / "same.hdtri"
    subprocess.run([CLI, "--genus", "3", "--random", "80", "--seed", "5", "--save", str(saved), "-o", os.devnull],
                   check=True, timeout=60)
    with hdt.Triangulation.load(str(saved)) as t:
        return t.to_meshio("unfolded")


def same_mesh(points, cells, reference, digits=15):
    """Equal up to the numbering of the nodes: the same set of triangles
    (coordinates to `digits` decimals)."""
    key = lambda p, c: sorted(tuple(sorted(map(tuple, np.round(p[tri][:, :2], digits)))) for tri in c)
    assert len(points) == len(reference.points) and len(cells) == len(reference.cells[0].data)
    assert key(points, cells) == key(reference.points, reference.cells[0].data)


@pytest.mark.parametrize("fmt", ["vtu", "msh", "obj", "off"])
def test_cli_mesh_files_read_back_with_meshio(tmp_path, fmt):
    path = cli_mesh(tmp_path, fmt)
    back = meshio.read(path)
    (cells,) = [c.data for c in back.cells if c.type == "triangle"]
    reference = reference_mesh(tmp_path)
    same_mesh(back.points, cells, reference)
    if fmt in ("vtu", "msh"):
        vertex = np.asarray(back.point_data["vertex"]).reshape(-1).astype(np.int64)
        # the identification list: each triangle's corners are its face's vertices
        assert sorted(map(tuple, np.sort(vertex[cells], axis=1))) == \
            sorted(map(tuple, np.sort(reference.point_data["vertex"][reference.cells[0].data].astype(np.int64), axis=1)))


def test_cli_vtu_reads_in_vtk(tmp_path):
    vtk = pytest.importorskip("vtk", reason="VTK's Python module is not installed (Debian: python3-vtk9)")
    path = cli_mesh(tmp_path, "vtu")
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(path))
    reader.Update()
    grid = reader.GetOutput()
    reference = reference_mesh(tmp_path)
    points = np.array([grid.GetPoint(i) for i in range(grid.GetNumberOfPoints())])
    cells = np.array([[grid.GetCell(i).GetPointId(k) for k in range(3)] for i in range(grid.GetNumberOfCells())])
    assert all(grid.GetCellType(i) == vtk.VTK_TRIANGLE for i in range(grid.GetNumberOfCells()))
    same_mesh(points, cells, reference)
    assert grid.GetPointData().GetArray("vertex").GetNumberOfTuples() == len(points)


def test_cli_msh_opens_in_gmsh(tmp_path):
    gmsh = shutil.which("gmsh")
    if not gmsh:
        pytest.skip("gmsh is not installed (Debian: gmsh)")
    path = cli_mesh(tmp_path, "msh")
    out = tmp_path / "again.msh"
    # Gmsh reads the file and writes it again in format 2.2: the same mesh.
    subprocess.run([gmsh, str(path), "-0", "-format", "msh22", "-o", str(out)], check=True, timeout=60,
                   capture_output=True)
    back = meshio.read(out)
    (cells,) = [c.data for c in back.cells if c.type == "triangle"]
    same_mesh(back.points, cells, reference_mesh(tmp_path), digits=9)  # Gmsh writes fewer digits
