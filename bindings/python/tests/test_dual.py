"""Adjacency, stars, edges, face corners and the Voronoi diagram through the
bindings: shapes and types on the NumPy and list paths, and the values
against independent computations in Python (distances over the neighbour
set, corner translations applied by hand, the cells' areas)."""

import cmath
import math

import pytest

import hdt
from hdt import _arrays
from hdt.picture import moebius
from sample_points import square_points





def distance(z, w):
    """Hyperbolic distance of disk points (complex), the cosh formula."""
    return math.acosh(1 + 2 * abs(z - w) ** 2 / ((1 - abs(z) ** 2) * (1 - abs(w) ** 2)))


@pytest.fixture(params=[(2, 80, True), (3, 40, False)], ids=["g2", "g3-dummies"])
def tri(request):
    genus, count, remove = request.param
    with hdt.Triangulation(genus) as t:
        t.insert_many(square_points(count, genus, 0.4))
        if remove:
            t.remove_dummies()
        yield t


def rows(value):
    return _arrays.as_lists(value)


def test_shapes(tri, arrays):
    F, E = tri.face_count, tri.edge_count
    assert E * 2 == 3 * F
    neighbours = tri.neighbours()
    edges = tri.edges()
    corners = tri.face_points()
    voronoi = tri.voronoi()
    star = tri.star(int(rows(tri.vertices().ids)[0]))
    cell = tri.voronoi_cell(int(rows(tri.vertices().ids)[0]))
    if arrays == "numpy":
        assert neighbours.faces.shape == (F, 3) and neighbours.faces.dtype.name == "uint32"
        assert neighbours.translations.shape == (F, 3) and neighbours.translations.dtype.name == "int32"
        assert edges.vertices.shape == (E, 2) and edges.translations.shape == (E,)
        assert edges.faces.shape == (E, 2) and edges.lengths.shape == (E,) and edges.lengths.dtype.name == "float64"
        assert corners.shape == (F, 3, 2)
        assert voronoi.centres.shape == (F, 2) and voronoi.radii.shape == (F,) and voronoi.edges.shape == (E, 2, 2)
        assert star.faces.shape == star.corners.shape == star.translations.shape
        assert cell.shape == (len(star.faces), 2)
    else:
        assert len(neighbours.faces) == F and all(len(row) == 3 for row in neighbours.faces)
        assert len(edges.lengths) == E and isinstance(edges.lengths[0], float)
        assert len(corners) == F and all(len(c) == 3 and len(c[0]) == 2 for c in corners)
        assert len(voronoi.edges) == E and len(voronoi.edges[0]) == 2 and len(voronoi.edges[0][0]) == 2
        assert len(cell) == len(star.faces)


def test_values_against_python(tri):
    """Corners, lengths, centres and cells recomputed in Python."""
    ids, reps, _ = (rows(v) for v in tri.vertices())
    rep = {v: complex(x, y) for v, (x, y) in zip(ids, reps)}
    face_vertices, face_translations = (rows(v) for v in tri.faces())
    matrix = {}

    def image(t, z):
        if t not in matrix:
            matrix[t] = tri.translation_matrix(t)
        return moebius(matrix[t], z)

    corners = rows(tri.face_points())
    for f, (vs, ts) in enumerate(zip(face_vertices, face_translations)):
        for c in range(3):
            assert abs(complex(*corners[f][c]) - image(ts[c], rep[vs[c]])) < 1e-13
    centres, radii, segments = (rows(v) for v in tri.voronoi())
    for f in range(len(face_vertices)):
        centre = complex(*centres[f])
        for c in range(3):
            assert distance(centre, complex(*corners[f][c])) == pytest.approx(radii[f], rel=1e-9)
    words = [tuple(w) for w in hdt.neighbour_words(tri.genus)]
    neighbours = [hdt.word_matrix(tri.genus, list(w)) for w in words]
    vertices, translations, faces, lengths = (rows(v) for v in tri.edges())
    for e, (a, b) in enumerate(vertices):
        best = min(range(len(neighbours)), key=lambda h: distance(rep[a], moebius(neighbours[h], rep[b])))
        assert lengths[e] == pytest.approx(distance(rep[a], moebius(neighbours[best], rep[b])), rel=1e-9)
        assert tri.translation_word(translations[e]) == words[best]
        assert complex(*segments[e][0]) == pytest.approx(complex(*centres[faces[e][0]]), abs=0)
    # The cells tile the surface: their areas add up to 4 pi (g - 1).
    area = 0.0
    for v in ids:
        cell = [complex(x, y) for x, y in rows(tri.voronoi_cell(v))]
        p = rep[v]
        for k, z1 in enumerate(cell):
            z2 = cell[(k + 1) % len(cell)]
            w1, w2 = (z1 - p) / (1 - p.conjugate() * z1), (z2 - p) / (1 - p.conjugate() * z2)
            area += -2 * cmath.phase(1 - w1.conjugate() * w2)
    assert area == pytest.approx(4 * math.pi * (tri.genus - 1), rel=1e-9)


def test_neighbours_and_stars(tri):
    faces, translations = (rows(v) for v in tri.neighbours())
    for f, row in enumerate(faces):
        for c, n in enumerate(row):
            back = [k for k in range(3) if faces[n][k] == f]
            assert len(back) == 1
            word = list(tri.translation_word(translations[f][c])) + list(tri.translation_word(translations[n][back[0]]))
            assert hdt.reduce_word(tri.genus, word) == ()
    total = 0
    for v in rows(tri.vertices().ids):
        star = tri.star(v)
        total += len(rows(star.faces))
        assert len(rows(tri.voronoi_cell(v))) == len(rows(star.faces))
    assert total == 3 * tri.face_count


def test_stars_and_cells_in_one_call(tri, arrays):
    """Every row of stars() and voronoi_cells() is star(v) and
    voronoi_cell(v), also after removals (empty rows at the gaps)."""
    for round in range(2):
        stars, cells = tri.stars(), tri.voronoi_cells()
        F, bound = tri.face_count, tri.vertex_id_bound
        if arrays == "numpy":
            assert stars.offsets.shape == (bound + 1,) and stars.faces.shape == (3 * F,)
            assert stars.corners.dtype.name == "uint8" and stars.translations.dtype.name == "int32"
            assert cells.points.shape == (3 * F, 2) and cells.points.dtype.name == "float64"
        offsets = rows(stars.offsets)
        assert rows(cells.offsets) == offsets and len(offsets) == bound + 1
        assert offsets[0] == 0 and offsets[-1] == 3 * F
        faces, corners, translations = rows(stars.faces), rows(stars.corners), rows(stars.translations)
        points = [tuple(p) for p in rows(cells.points)]
        live = set(rows(tri.vertices().ids))
        for v in range(bound):
            b, e = offsets[v], offsets[v + 1]
            if v not in live:
                assert b == e
                continue
            star = tri.star(v)
            assert faces[b:e] == rows(star.faces) and corners[b:e] == rows(star.corners)
            assert translations[b:e] == rows(star.translations)
            assert points[b:e] == [tuple(p) for p in rows(tri.voronoi_cell(v))]
        # Independently: the cells' hyperbolic areas add up to 4 pi (g - 1).
        reps = dict(zip(rows(tri.vertices().ids), (complex(x, y) for x, y in rows(tri.vertices().points))))
        area = 0.0
        for v in live:
            p, cell = reps[v], [complex(*q) for q in points[offsets[v]:offsets[v + 1]]]
            for k, z1 in enumerate(cell):
                z2 = cell[(k + 1) % len(cell)]
                w1, w2 = (z1 - p) / (1 - p.conjugate() * z1), (z2 - p) / (1 - p.conjugate() * z2)
                area += -2 * cmath.phase(1 - w1.conjugate() * w2)
        assert area == pytest.approx(4 * math.pi * (tri.genus - 1), rel=1e-9)
        for v in sorted(live)[round::4]:
            try:
                tri.remove(v)
            except hdt.Error:
                pass  # a vertex the guarantee needs


def test_errors(tri):
    bound = tri.vertex_id_bound
    with pytest.raises(hdt.InvalidArgument):
        tri.star(bound)
    with pytest.raises(hdt.InvalidArgument):
        tri.voronoi_cell(bound)
    with pytest.raises(TypeError):
        tri.star("x")


def test_voronoi_picture(tri):
    text = tri.to_svg(voronoi=True)
    assert text.count('stroke="#2a8a3a"') == 1
    assert "Voronoi diagram green" in text
    assert 'stroke="#2a8a3a"' not in tri.to_svg()


def test_closed():
    t = hdt.Triangulation(2)
    t.close()
    for call in (t.neighbours, t.edges, t.face_points, t.voronoi, lambda: t.star(0), lambda: t.voronoi_cell(0)):
        with pytest.raises(hdt.HandleClosed):
            call()


def test_plot_draws_the_library_voronoi_pieces(tri):
    """plot(voronoi=True) draws the pieces the library draws: as many
    segments as the SVG's green path has, each starting where the SVG's does."""
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from hdt.picture import Scene

    scene = Scene(tri, voronoi=True)
    pieces = scene.voronoi_pieces()
    text = tri.to_svg(voronoi=True)
    path = text.split('stroke="#2a8a3a"')[1].split(' d="')[1].split('"')[0]
    starts = [chunk.split("A")[0].split("L")[0].split() for chunk in path.replace("\n", "").split("M")[1:]]
    assert len(starts) == len(pieces)
    band = float(text.split('height="')[1].split('"')[0]) - 800  # the caption's, 56 or more where it wraps
    for (p, _), (sx, sy) in zip(pieces, starts):
        assert float(sx) == pytest.approx(400 * (1 + 0.97 * p[0]), abs=0.006)
        assert float(sy) == pytest.approx(band + 400 * (1 - 0.97 * p[1]), abs=0.006)
    ax = tri.plot(voronoi=True)
    assert any(c.get_label() == "Voronoi diagram" for c in ax.collections)
    plt.close(ax.figure)


def test_copies_under_n_cover_the_voronoi_edges():
    """The picture draws each Voronoi edge's copies under N: no other copy,
    under the products of two elements of N, has a point inside F_g
    (sampled along the geodesic), so nothing is missing from the picture."""
    from hdt.picture import Scene, _apply, geodesic_points

    with hdt.Triangulation(2) as t:
        t.insert_many(square_points(20, 2, 0.8))
        t.remove_dummies()
        scene = Scene(t, voronoi=True)
    matrices = [tuple(m) for m in scene.neighbours]

    def product(m, n):
        a = complex(m[0], m[1]) * complex(n[0], n[1]) + complex(m[2], m[3]) * complex(n[2], -n[3])
        b = complex(m[0], m[1]) * complex(n[2], n[3]) + complex(m[2], m[3]) * complex(n[0], -n[1])
        return (a.real, a.imag, b.real, b.imag)

    def key(m):
        return tuple(round(v, 6) for v in m)

    inside_n = {key(m) for m in matrices}
    beyond = {}
    for m in matrices:
        for n in matrices[1:]:
            p = product(m, n)
            if key(p) not in inside_n:
                beyond[key(p)] = p
    sides = range(len(scene.side_centres))
    for p, q in scene.voronoi:
        samples = [complex(*p)] + geodesic_points(complex(*p), complex(*q), step=0.02)
        for m in beyond.values():
            for z in samples:
                x, y = _apply(m, z.real, z.imag)
                assert not all(scene._side_power(k, x, y) > 1e-12 for k in sides), "a copy outside N meets F_g"
