"""hdt.Triangulation(surface): triangulations of surfaces given by a polygon
(libhdt 0.8.0), checked against properties computed here and against the
built-in M_2."""

import math
import pickle
import random

import pytest

import hdt
from hdt._arrays import as_lists

from test_polygon_surface import BOLZA


def disk_points(n, seed, radius=0.95):
    """n points uniform in the disk of the radius (most outside the polygon)."""
    rng = random.Random(seed)
    result = []
    while len(result) < n:
        x, y = rng.uniform(-radius, radius), rng.uniform(-radius, radius)
        if x * x + y * y < radius * radius:
            result.append((x, y))
    return result


@pytest.fixture(params=[(8, 1), (8, 2), (10, 3)], ids=lambda p: f"{p[0]}-gon-seed-{p[1]}")
def surface(request):
    sides, seed = request.param
    with hdt.Surface.random_symmetric(sides, seed) as s:
        yield s


def test_a_new_triangulation_holds_only_dummies(surface):
    with hdt.Triangulation(surface) as t:
        assert t.genus == surface.genus == 2
        assert len(t) == t.dummy_count > 0
        assert t.face_count == 2 * (len(t) + 2 * t.genus - 2)
        t.validate()


def test_insertion_and_removal_keep_euler_and_validity(surface):
    with hdt.Triangulation(surface) as t:
        ids = as_lists(t.insert_many(disk_points(300, 4)))
        assert len(set(ids)) == 300
        t.remove_dummies()
        for vertex in ids[::9]:
            try:
                t.remove(vertex)
            except hdt.NotSupported:
                pass  # refused: the faces would grow past sys/2
        assert t.face_count == 2 * (len(t) + 2 * t.genus - 2)
        assert t.edge_count == 3 * t.face_count // 2
        t.validate()


def test_vertex_points_are_the_representatives(surface):
    with hdt.Triangulation(surface) as t:
        points = disk_points(50, 6)
        ids = as_lists(t.insert_many(points))
        for vertex, point in zip(ids, points):
            x, y = t.vertex_point(vertex)
            rx, ry = surface.representative(*point)[0]
            assert x == pytest.approx(rx, abs=1e-12) and y == pytest.approx(ry, abs=1e-12)


def test_the_surface_given_back_is_the_polygon(surface):
    t = hdt.Triangulation(surface)
    text = surface.polygon_text()
    surface.close()  # the triangulation keeps its own copy
    assert t.surface is not None and t.surface.polygon_text() == text
    t.insert(0.1, 0.2)
    t.validate()
    with hdt.Triangulation(2) as m:
        assert m.surface is None


def test_m2_as_the_bolza_octagon_has_the_built_in_faces():
    """The same points on both: the same faces as triples of the points'
    indices (test_surface_triangulations.c compares the translations too)."""
    points = disk_points(500, 8)
    faces = []
    for t in (hdt.Triangulation(hdt.Surface.from_polygon(BOLZA)), hdt.Triangulation(2)):
        with t:
            index = {v: i for i, v in enumerate(as_lists(t.insert_many(points)))}
            assert t.remove_dummies() == 0
            rows = as_lists(t.faces().vertices)
            rotated = set()
            for row in rows:
                k = [index[v] for v in row]
                first = k.index(min(k))
                rotated.add(tuple(k[first:] + k[:first]))
            faces.append((len(rows), rotated))
    assert faces[0] == faces[1]


def test_calls_not_supported_yet_raise_and_change_nothing(surface, tmp_path):
    with hdt.Triangulation(surface) as t:
        t.insert_many(disk_points(100, 9))
        before = as_lists(t.faces().vertices)
        assert t.translation_homology(0) == (0,) * 4
        for call in (lambda: hdt.picture.Scene(t), lambda: t.to_html()):
            with pytest.raises(hdt.NotSupported, match="polygon"):
                call()
        assert as_lists(t.faces().vertices) == before
        with pytest.raises(hdt.OutOfDomain):
            t.insert(1.0, 0.0)
        assert as_lists(t.faces().vertices) == before
        assert "genus=2" in repr(t)


def test_translation_words_compose_to_the_matrices(surface):
    with hdt.Triangulation(surface) as t:
        t.insert_many(disk_points(100, 10))
        pairings = [surface.pairing(k) for k in range(surface.side_count)]
        for translation in {h for row in as_lists(t.faces().translations) for h in row}:
            a, b = 1 + 0j, 0j
            for letter in t.translation_word(translation):
                pa, pb = pairings[letter]
                a, b = a * pa + b * pb.conjugate(), a * pb + b * pa.conjugate()
            ta, tb = t.translation_matrix(translation)
            assert min(abs(a - ta) + abs(b - tb), abs(a + ta) + abs(b + tb)) < 1e-9 * (abs(ta) + abs(tb))


def test_an_epsilon_net_meets_its_bounds(surface):
    with hdt.Triangulation(surface) as t:
        refined = t.epsilon_net(0.05)
        assert refined.added > 0 and refined.unmet == 0
        quality = t.quality()
        assert quality.max_radius <= 0.05 * (1 + 1e-9)
        t.validate()
        cells = t.voronoi_cells()
        assert len(as_lists(cells.offsets)) == t.vertex_id_bound + 1


def test_saved_and_loaded_and_pickled(surface, tmp_path):
    with hdt.Triangulation(surface) as t:
        t.insert_many(disk_points(200, 11))
        t.remove_dummies()
        path = tmp_path / "t.hdtri"
        t.save(path)
        for u in (hdt.Triangulation.load(path), pickle.loads(pickle.dumps(t))):
            with u:
                assert u.surface is not None and u.surface.polygon_text() == surface.polygon_text()
                assert as_lists(u.faces().vertices) == as_lists(t.faces().vertices)
                assert as_lists(u.faces().translations) == as_lists(t.faces().translations)
                assert u.to_bytes() == t.to_bytes()
                u.validate()


def test_to_svg_draws_the_polygon(surface):
    with hdt.Triangulation(surface) as t:
        t.insert_many(disk_points(100, 12))
        svg = t.to_svg(voronoi=True)
        assert svg.startswith("<svg ") and "on a surface of genus 2" in svg
        assert f"{surface.side_count}-sided polygon" in svg
