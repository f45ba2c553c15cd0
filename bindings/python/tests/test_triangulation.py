"""hdt.Triangulation against the C semantics of include/hdt.h: round trips,
counts, geometry of faces, locate and nearest vertex by brute force, every
kind of bad input, both array paths, and the handle's lifetime."""

import gc
import math
import threading
import weakref

import pytest

import hdt
from hdt import _arrays
from hdt import triangulation as triangulation_module
from sample_points import as_list, random_points

HAVE_NUMPY = _arrays.numpy is not None
if HAVE_NUMPY:
    import numpy as np


# ---- helpers ----

def moebius(matrix, z):
    a, b = matrix
    return (a * z + b) / (b.conjugate() * z + a.conjugate())


def hyperbolic_distance(z, w):
    """The distance of two points of the Poincare disk (curvature -1)."""
    return math.acosh(1 + 2 * abs(z - w) ** 2 / ((1 - abs(z) ** 2) * (1 - abs(w) ** 2)))


def klein(z):
    """The Beltrami-Klein image of a Poincare disk point: geodesics become
    segments, so triangle tests are Euclidean there."""
    return 2 * z / (1 + abs(z) ** 2)


def orientation(p, q, r):
    return (q - p).real * (r - p).imag - (q - p).imag * (r - p).real








def canonical_corners(t, faces, points):
    """The three complex corners of each face's canonical copy."""
    matrices = {}
    corners = []
    for row, translations in zip(as_list(faces.vertices), as_list(faces.translations)):
        face = []
        for v, h in zip(row, translations):
            if h not in matrices:
                matrices[h] = t.translation_matrix(h)
            face.append(moebius(matrices[h], points[v]))
        corners.append(face)
    return corners, matrices


def vertex_points(t):
    ids, points, _ = (as_list(value) for value in t.vertices())
    return {v: complex(x, y) for v, (x, y) in zip(ids, points)}


@pytest.fixture(scope="module")
def filled():
    """A genus-2 triangulation of 300 points, dummies removed (read only)."""
    with hdt.Triangulation(2) as t:
        t.insert_many(random_points(300, seed=7))
        t.remove_dummies()
        yield t


# ---- creation and counts ----

@pytest.mark.parametrize("genus", (2, 3))
def test_a_new_triangulation_holds_only_dummies(genus):
    with hdt.Triangulation(genus) as t:
        assert t.genus == genus
        assert t.vertex_count == t.dummy_count == len(t) == t.vertex_id_bound > 0
        assert t.face_count == 2 * (t.vertex_count + 2 * genus - 2)
        ids, _, dummy = (as_list(value) for value in t.vertices())
        assert ids == list(range(t.vertex_count)) and all(dummy)
        assert all(t.is_dummy(v) for v in ids)
        assert t.validate() is None
        assert repr(t) == (f"<hdt.Triangulation genus={genus} vertices={t.vertex_count} "
                           f"({t.dummy_count} dummies) faces={t.face_count}>")


@pytest.mark.parametrize("genus, error, text", [
    (1, hdt.InvalidArgument, "genus must be at least 2, got 1"),
    (0, hdt.InvalidArgument, "genus must be at least 2"),
    (-7, hdt.InvalidArgument, "genus must be at least 2"),
    (-(2**40), hdt.InvalidArgument, "genus must be at least 2"),
    (2000, hdt.NotSupported, "HDT_GENUS_MAX"),
    (2**40, hdt.NotSupported, "does not fit"),
])
def test_a_bad_genus_is_refused(genus, error, text):
    with pytest.raises(error, match=text):
        hdt.Triangulation(genus)


def test_the_genus_must_be_an_int():
    with pytest.raises(TypeError, match="genus must be an int, not float"):
        hdt.Triangulation(2.0)


# ---- insertion ----

def test_insert_then_vertex_point_gives_the_point_back():
    with hdt.Triangulation(2) as t:
        bound = t.vertex_id_bound
        v = t.insert(0.125, -0.25)
        assert isinstance(v, int) and v == bound
        assert t.vertex_point(v) == (0.125, -0.25)
        assert t.is_dummy(v) is False
        assert len(t) == bound + 1 and t.dummy_count == bound
        w = t.insert(0, 0.5)  # ints are real numbers too
        assert w == v + 1 and t.vertex_point(w) == (0.0, 0.5)


def test_a_point_outside_f_is_stored_as_its_representative():
    with hdt.Triangulation(3) as t:
        v = t.insert(0.97, 0.1)
        (rx, ry), word = hdt.point_representative(3, 0.97, 0.1)
        assert word
        x, y = t.vertex_point(v)
        assert math.hypot(x - rx, y - ry) < 1e-15


def test_a_repeated_point_is_already_present_with_its_vertex():
    with hdt.Triangulation(2) as t:
        v = t.insert(0.3, 0.2)
        count = len(t)
        with pytest.raises(hdt.AlreadyExists, match=f"hdt_insert: the point is already vertex {v}") as caught:
            t.insert(0.3, 0.2)
        assert caught.value.vertex == v and caught.value.status == hdt.Status.EEXISTS
        assert not isinstance(caught.value, ValueError)
        assert len(t) == count


def test_inserting_a_dummy_point_makes_it_a_user_vertex():
    with hdt.Triangulation(2) as t:
        dummies = t.dummy_count
        (origin,) = [v for v in range(dummies) if t.vertex_point(v) == (0.0, 0.0)]
        assert t.is_dummy(origin)
        assert t.insert(0.0, 0.0) == origin
        assert not t.is_dummy(origin) and t.dummy_count == dummies - 1 and len(t) == dummies
        with pytest.raises(hdt.AlreadyExists) as caught:
            t.insert(0.0, 0.0)
        assert caught.value.vertex == origin


@pytest.mark.parametrize("x, y, text", [
    (math.nan, 0.0, "is not finite"),
    (0.0, math.nan, "is not finite"),
    (math.inf, 0.0, "is not finite"),
    (0.0, -math.inf, "is not finite"),
    (1.0, 0.0, "not inside the open unit disk"),
    (0.6, 0.8, "not inside the open unit disk"),
    (-0.5, -2.0, "not inside the open unit disk"),
    (10**400, 0, "is not finite"),
], ids=["nan x", "nan y", "inf", "-inf", "on the circle", "rounds onto the circle", "outside", "huge int"])
def test_insert_outside_the_open_disk_is_out_of_domain(x, y, text):
    with hdt.Triangulation(2) as t:
        count = len(t)
        with pytest.raises(hdt.OutOfDomain, match=text) as caught:
            t.insert(x, y)
        assert isinstance(caught.value, ValueError)
        assert caught.value.status == hdt.Status.EDOMAIN
        assert caught.value.message.startswith("hdt_insert: ")
        assert len(t) == count


@pytest.mark.parametrize("method", ["insert", "locate", "nearest_vertex"])
def test_coordinates_must_be_real_numbers(method):
    with hdt.Triangulation(2) as t:
        with pytest.raises(TypeError, match="x must be a real number, not str"):
            getattr(t, method)("0.1", 0.0)
        with pytest.raises(TypeError, match="y must be a real number, not complex"):
            getattr(t, method)(0.0, 0.1j)


# ---- insert_many, both array paths ----

def check_ids_answer_points(t, ids, points):
    """ids[i] is the vertex of points[i]: same representative."""
    for v, (x, y) in zip(as_list(ids), points):
        (rx, ry), _ = hdt.point_representative(t.genus, x, y)
        vx, vy = t.vertex_point(v)
        assert math.hypot(vx - rx, vy - ry) < 1e-12


def test_insert_many_returns_the_id_of_each_point(arrays):
    points = random_points(120, seed=3)
    with hdt.Triangulation(2) as t:
        before = len(t)
        ids = t.insert_many(points)
        if arrays == "numpy":
            assert isinstance(ids, np.ndarray) and ids.dtype == np.uint32 and ids.shape == (120,)
        else:
            assert isinstance(ids, list) and all(type(v) is int for v in ids)
        assert len(set(as_list(ids))) == 120 and len(t) <= before + 120
        check_ids_answer_points(t, ids, points)
        t.validate()


def test_insert_many_takes_any_iterable_of_pairs(arrays):
    with hdt.Triangulation(2) as t:
        ids = t.insert_many(((0.1 * k, -0.05 * k) for k in range(5)))  # a generator of tuples
        assert as_list(t.insert_many([[0.1, -0.05], [0.2, -0.1]])) == as_list(ids)[1:3]
        assert as_list(t.insert_many(())) == []
        if arrays == "lists" and HAVE_NUMPY:  # an array goes through the list path too
            assert as_list(t.insert_many(np.array([[0.2, -0.1]]))) == as_list(ids)[2:3]


def test_insert_many_shares_ids_between_repeats(arrays):
    with hdt.Triangulation(2) as t:
        first = t.insert(0.1, 0.2)
        ids = as_list(t.insert_many([(0.1, 0.2), (0.3, -0.1), (0.1, 0.2), (-0.25, 0.125), (0.3, -0.1)]))
        assert ids[0] == ids[2] == first and ids[1] == ids[4]
        assert len({ids[0], ids[1], ids[3]}) == 3


@pytest.mark.parametrize("points, text", [
    ([(0.1, 0.1), (0.2, math.nan)], "point 1 .* not a finite point of the open unit disk"),
    ([(0.1, 0.1), (0.3, 0.2), (0.8, 0.6)], "point 2 .* not a finite point of the open unit disk"),
    ([(math.inf, 0.0)], "point 0"),
])
def test_insert_many_rejects_the_whole_call_for_one_bad_point(arrays, points, text):
    with hdt.Triangulation(2) as t:
        count, faces = len(t), as_list(t.faces().vertices)
        with pytest.raises(hdt.OutOfDomain, match=text) as caught:
            t.insert_many(points)
        assert caught.value.message.startswith("hdt_insert_many: ")
        assert len(t) == count and as_list(t.faces().vertices) == faces


@pytest.mark.parametrize("points, text", [
    (5, "points must be a sequence of pairs"),
    ([(0.1, 0.2, 0.3)], r"point 0 must be a pair \(x, y\)"),
    ([(0.1, 0.2), 0.5], r"point 1 must be a pair \(x, y\)"),
    ([(0.1, 0.2), None], r"point 1 must be a pair \(x, y\)"),
    ([("0.1", 0.2)], "x of point 0 must be a real number, not str"),
    ([(0.1, 0.2), (0.0, 1j)], "y of point 1 must be a real number, not complex"),
])
def test_insert_many_wants_pairs_of_real_numbers(arrays, points, text):
    with hdt.Triangulation(2) as t:
        with pytest.raises(TypeError, match=text):
            t.insert_many(points)


@pytest.mark.skipif(not HAVE_NUMPY, reason="NumPy is not installed")
class TestNumpyInput:
    """Arrays of points: read in place when C-contiguous float64, else converted once."""

    def points(self):
        return np.array(random_points(40, seed=11), dtype=np.float64)

    def test_a_c_contiguous_float64_array_is_passed_without_a_copy(self):
        array = self.points()
        _, count, owner = _arrays.point_buffer(array)
        assert owner is array and count == 40

    @pytest.mark.parametrize("make", [
        lambda a: np.asfortranarray(a),
        lambda a: np.repeat(a, 2, axis=0)[::2],
        lambda a: a.astype(np.float32),
        lambda a: a.astype(">f8"),
        lambda a: np.zeros((1, 2), dtype=np.int64),
    ], ids=["fortran order", "strided", "float32", "big endian", "int64"])
    def test_other_layouts_and_dtypes_are_converted(self, make):
        array = make(self.points())
        _, count, owner = _arrays.point_buffer(array)
        assert owner is not array and owner.flags.c_contiguous and owner.dtype == np.float64
        assert count == len(array)
        with hdt.Triangulation(2) as t:
            ids = t.insert_many(array)
            check_ids_answer_points(t, ids, array.astype(np.float64).tolist())

    @pytest.mark.parametrize("shape", [(10, 3), (10,), (2, 5, 2), (2, 1)])
    def test_a_wrong_shape_is_an_invalid_argument(self, shape):
        with hdt.Triangulation(2) as t, pytest.raises(hdt.InvalidArgument, match=r"shape \(n, 2\)"):
            t.insert_many(np.zeros(shape))

    @pytest.mark.parametrize("dtype", ["complex128", object, bool, "U3"])
    def test_a_dtype_that_is_not_real_is_a_type_error(self, dtype):
        with hdt.Triangulation(2) as t, pytest.raises(TypeError, match="array of real numbers"):
            t.insert_many(np.zeros((3, 2), dtype=dtype))

    def test_an_empty_array_inserts_nothing(self):
        with hdt.Triangulation(2) as t:
            ids = t.insert_many(np.empty((0, 2)))
            assert ids.shape == (0,) and ids.dtype == np.uint32

    def test_a_bad_point_in_an_array_is_named(self):
        array = self.points()
        array[17] = (0.0, np.nan)
        with hdt.Triangulation(2) as t, pytest.raises(hdt.OutOfDomain, match="point 17"):
            t.insert_many(array)


# ---- vertices and faces ----

def test_vertices_layout(arrays, filled):
    ids, points, dummy = vertices = filled.vertices()
    assert isinstance(vertices, hdt.Vertices)
    n = filled.vertex_count
    if arrays == "numpy":
        assert ids.dtype == np.uint32 and ids.shape == (n,)
        assert points.dtype == np.float64 and points.shape == (n, 2)
        assert dummy.dtype == bool and dummy.shape == (n,)
    else:
        assert type(ids) is list and type(points) is list and type(dummy) is list
        assert all(type(p) is tuple and len(p) == 2 for p in points)
    ids, points, dummy = as_list(ids), as_list(points), as_list(dummy)
    assert ids == sorted(ids) and len(ids) == n
    assert sum(dummy) == filled.dummy_count
    for v in ids[::25]:
        assert tuple(points[ids.index(v)]) == filled.vertex_point(v)
        assert dummy[ids.index(v)] == filled.is_dummy(v)


def test_faces_layout(arrays, filled):
    faces = filled.faces()
    assert isinstance(faces, hdt.Faces)
    count = filled.face_count
    if arrays == "numpy":
        assert faces.vertices.dtype == np.uint32 and faces.vertices.shape == (count, 3)
        assert faces.translations.dtype == np.int32 and faces.translations.shape == (count, 3)
    else:
        assert len(faces.vertices) == len(faces.translations) == count
        assert all(type(row) is tuple and len(row) == 3 for row in faces.vertices + faces.translations)


@pytest.mark.parametrize("genus", (2, 3))
def test_faces_satisfy_euler_and_the_canonical_copy_rules(genus):
    with hdt.Triangulation(genus) as t:
        t.insert_many(random_points(150, seed=genus))
        for stage in ("with dummies", "dummies removed"):
            faces = t.faces()
            V, F = t.vertex_count, t.face_count
            assert len(faces.vertices) == F
            E = 3 * F // 2
            assert 3 * F == 2 * E and V - E + F == 2 - 2 * genus, stage
            live = set(as_list(t.vertices().ids))
            used = set()
            for row, translations in zip(as_list(faces.vertices), as_list(faces.translations)):
                assert len(set(row)) == 3 and set(row) <= live
                assert translations[row.index(min(row))] == 0  # the smallest id sits at its representative
                assert all(h >= 0 for h in translations)
                used.update(row)
            assert used == live
            t.remove_dummies()


def test_canonical_copies_are_counterclockwise_and_meet_each_other_at_edges(filled):
    points = vertex_points(filled)
    faces = filled.faces()
    corners, _ = canonical_corners(filled, faces, points)
    for face in corners:
        assert orientation(*(klein(z) for z in face)) > 0
    # Each edge {u, v} is shared by exactly two faces (a closed surface).
    edges = {}
    for row in as_list(faces.vertices):
        for k in range(3):
            edge = frozenset((row[k], row[(k + 1) % 3]))
            edges[edge] = edges.get(edge, 0) + 1
    assert set(edges.values()) == {2}
    assert len(edges) == 3 * filled.face_count // 2


# ---- translations ----

def test_translation_zero_is_the_identity(filled):
    assert filled.translation_word(0) == ()
    assert filled.translation_matrix(0) == (1, 0)


def test_translations_in_n_are_the_neighbour_words(filled):
    for h in range(hdt.neighbour_count(2)):
        assert filled.translation_word(h) == hdt.neighbour_word(2, h)


def test_translation_matrices_are_those_of_their_words(filled):
    for h in sorted({h for row in as_list(filled.faces().translations) for h in row}):
        a, b = filled.translation_matrix(h)
        c, d = hdt.word_matrix(2, filled.translation_word(h))
        assert min(abs(a - s * c) + abs(b - s * d) for s in (1, -1)) < 1e-9 * max(1, abs(a))
        assert abs(a) ** 2 - abs(b) ** 2 == pytest.approx(1, rel=1e-9)


@pytest.mark.parametrize("translation, error", [
    (-1, hdt.InvalidArgument), (10**6, hdt.InvalidArgument), (2**31, hdt.InvalidArgument),
    (-(2**40), hdt.InvalidArgument), (1.0, TypeError), ("0", TypeError),
])
@pytest.mark.parametrize("method", ["translation_word", "translation_matrix"])
def test_an_unknown_translation_id_is_refused(filled, method, translation, error):
    with pytest.raises(error, match="translation id"):
        getattr(filled, method)(translation)


# ---- locate and nearest vertex ----

def test_locate_finds_a_face_copy_containing_the_point(filled):
    points = vertex_points(filled)
    faces = filled.faces()
    corners, matrices = canonical_corners(filled, faces, points)
    queries = random_points(40, seed=21, radius=0.99) + [(0.0, 0.0), filled.vertex_point(min(points))]
    for x, y in queries:
        location = filled.locate(x, y)
        assert isinstance(location, hdt.Location)
        face, h = location
        assert 0 <= face < filled.face_count
        matrix = matrices[h] if h in matrices else filled.translation_matrix(h)
        a, b, c = (klein(moebius(matrix, z)) for z in corners[face])
        z = klein(complex(x, y))
        scale = max(abs(a - b), abs(b - c), abs(c - a))
        for p, q in ((a, b), (b, c), (c, a)):
            assert orientation(p, q, z) >= -1e-9 * scale, (x, y)


def nearest_by_brute_force(t, x, y, points):
    """(distance, vertex) pairs of every vertex, nearest first: the distance
    on M_g from (x, y) to each vertex, over the N-images of its
    representative (enough here: every face is small, so the nearest vertex
    is far closer than any copy outside N)."""
    (rx, ry), _ = hdt.point_representative(t.genus, x, y)
    z = complex(rx, ry)
    images = [hdt.word_matrix(t.genus, word) for word in hdt.neighbour_words(t.genus)]
    distances = []
    for v, p in points.items():
        distances.append((min(hyperbolic_distance(z, moebius(m, p)) for m in images), v))
    return sorted(distances)


def test_nearest_vertex_agrees_with_brute_force(filled):
    points = vertex_points(filled)
    for x, y in random_points(6, seed=5, radius=0.9) + [(0.0, 0.0), (0.7, -0.65)]:
        v = filled.nearest_vertex(x, y)
        ranking = nearest_by_brute_force(filled, x, y, points)
        distance_of = {w: d for d, w in ranking}
        assert distance_of[v] <= ranking[0][0] + 1e-9
        if ranking[1][0] - ranking[0][0] > 1e-9:
            assert v == ranking[0][1]


def test_the_nearest_vertex_of_a_vertex_is_itself(filled):
    for v in as_list(filled.vertices().ids)[::40]:
        assert filled.nearest_vertex(*filled.vertex_point(v)) == v


@pytest.mark.parametrize("method", ["locate", "nearest_vertex"])
@pytest.mark.parametrize("x, y, text", [
    (math.nan, 0.0, "finite"), (1.0, 0.0, "open unit disk"), (0.0, -math.inf, "finite"),
])
def test_queries_outside_the_open_disk_are_out_of_domain(filled, method, x, y, text):
    with pytest.raises(hdt.OutOfDomain, match=text) as caught:
        getattr(filled, method)(x, y)
    assert isinstance(caught.value, ValueError)
    assert caught.value.message.startswith(f"hdt_{method}: ")


# ---- removal ----

def test_removing_user_vertices():
    with hdt.Triangulation(2) as t:
        ids = as_list(t.insert_many(random_points(200, seed=13)))
        t.remove_dummies()
        removed = 0
        for v in ids[:40:4]:
            count = len(t)
            try:
                t.remove(v)
            except hdt.NotSupported:
                assert len(t) == count
                continue
            removed += 1
            assert len(t) == count - 1 and t.face_count == 2 * (len(t) + 2)
            with pytest.raises(hdt.InvalidArgument, match=f"vertex {v} is not a live vertex"):
                t.vertex_point(v)
            with pytest.raises(hdt.InvalidArgument, match=f"vertex {v} is not a live vertex"):
                t.remove(v)
            with pytest.raises(hdt.InvalidArgument, match="not a live vertex"):
                t.is_dummy(v)
        assert removed > 0
        t.validate()
        # A removed id is never given again.
        bound = t.vertex_id_bound
        assert t.insert(0.0123, -0.0456) == bound


def test_a_refused_removal_changes_nothing():
    with hdt.Triangulation(2) as t:  # only dummies: each is needed
        faces = as_list(t.faces().vertices)
        with pytest.raises(hdt.NotSupported, match="hdt_remove_vertex: removing vertex 3 would leave") as caught:
            t.remove(3)
        assert caught.value.status == hdt.Status.ENOTSUP
        assert as_list(t.faces().vertices) == faces and t.is_dummy(3)


def test_remove_dummies_returns_how_many_are_left():
    with hdt.Triangulation(2) as t:
        assert t.remove_dummies() == t.dummy_count == len(t)  # nothing can go yet
        t.insert_many(random_points(400, seed=17, radius=0.99))
        left = t.remove_dummies()
        assert left == t.dummy_count < t.vertex_id_bound
        assert t.remove_dummies() == left
        t.validate()


@pytest.mark.parametrize("vertex, error, text", [
    (-1, hdt.InvalidArgument, "vertex -1 is not a live vertex"),
    (2**32, hdt.InvalidArgument, "vertex 4294967296 is not a live vertex"),
    (2**32 - 1, hdt.InvalidArgument, "vertex 4294967295 is not a live vertex"),
    (10**30, hdt.InvalidArgument, "not a live vertex"),
    (1.0, TypeError, "vertex must be an int, not float"),
    (None, TypeError, "vertex must be an int, not NoneType"),
])
@pytest.mark.parametrize("method", ["remove", "vertex_point", "is_dummy"])
def test_a_bad_vertex_id_is_refused(method, vertex, error, text):
    with hdt.Triangulation(2) as t:
        with pytest.raises(error, match=text):
            getattr(t, method)(vertex)
        with pytest.raises(hdt.InvalidArgument, match=f"vertex {t.vertex_id_bound} is not a live vertex"):
            getattr(t, method)(t.vertex_id_bound)


# ---- lifetime ----

CALLS = {
    "insert": lambda t: t.insert(0.1, 0.1),
    "insert_many": lambda t: t.insert_many([(0.1, 0.1)]),
    "remove": lambda t: t.remove(14),  # the user vertex inserted first below (after genus 2's 14 dummies)
    "remove_dummies": lambda t: t.remove_dummies(),
    "is_dummy": lambda t: t.is_dummy(0),
    "vertex_point": lambda t: t.vertex_point(0),
    "vertices": lambda t: t.vertices(),
    "faces": lambda t: t.faces(),
    "translation_word": lambda t: t.translation_word(0),
    "translation_matrix": lambda t: t.translation_matrix(0),
    "locate": lambda t: t.locate(0.1, 0.1),
    "nearest_vertex": lambda t: t.nearest_vertex(0.1, 0.1),
    "validate": lambda t: t.validate(),
    "vertex_count": lambda t: t.vertex_count,
    "dummy_count": lambda t: t.dummy_count,
    "face_count": lambda t: t.face_count,
    "vertex_id_bound": lambda t: t.vertex_id_bound,
    "__len__": len,
    "to_svg": lambda t: t.to_svg(),
}


@pytest.mark.parametrize("name", sorted(CALLS))
def test_every_use_after_close_raises(name):
    t = hdt.Triangulation(2)
    assert t.insert(-0.2, 0.15) == 14
    CALLS[name](t)  # works while open
    t.close()
    with pytest.raises(hdt.HandleClosed, match="the triangulation is closed") as caught:
        CALLS[name](t)
    assert isinstance(caught.value, hdt.InvalidArgument) and isinstance(caught.value, ValueError)


def test_close_twice_and_what_still_works_after_close():
    t = hdt.Triangulation(3)
    assert not t.closed
    t.close()
    t.close()
    assert t.closed and t.genus == 3
    assert repr(t) == "<hdt.Triangulation genus=3 closed>"
    with pytest.raises(hdt.HandleClosed):
        with t:
            pass


def test_the_with_block_closes_even_on_an_exception():
    with pytest.raises(ZeroDivisionError):
        with hdt.Triangulation(2) as t:
            assert not t.closed
            1 / 0
    assert t.closed


def count_destroys(monkeypatch):
    """Counts the C handles freed from now on (hdt_destroy still runs)."""
    freed = []

    def destroy(handle):
        freed.append(handle.value)
        lib_destroy(handle)

    lib_destroy = triangulation_module._destroy
    monkeypatch.setattr(triangulation_module, "_destroy", destroy)
    return freed


def test_garbage_collection_frees_the_handle(monkeypatch):
    freed = count_destroys(monkeypatch)
    t = hdt.Triangulation(2)
    t.insert(0.1, 0.2)
    handle = t._handle.value
    alive = weakref.ref(t)
    del t
    gc.collect()
    assert alive() is None
    assert freed == [handle]


def test_close_frees_the_handle_once(monkeypatch):
    freed = count_destroys(monkeypatch)
    t = hdt.Triangulation(2)
    handle = t._handle.value
    t.close()
    assert freed == [handle]
    t.close()
    del t
    gc.collect()
    assert freed == [handle]


def test_a_failed_constructor_frees_nothing(monkeypatch):
    freed = count_destroys(monkeypatch)
    with pytest.raises(hdt.InvalidArgument):
        hdt.Triangulation(1)
    gc.collect()
    assert freed == []


def test_threads_sharing_a_triangulation_take_turns():
    with hdt.Triangulation(2) as t:
        errors = []

        def work(seed):
            try:
                for x, y in random_points(60, seed=seed, radius=0.9):
                    try:
                        t.insert(x, y)
                    except hdt.AlreadyExists:
                        pass
                    t.nearest_vertex(y, x)
                    len(t.faces().vertices)
            except Exception as error:  # reported below
                errors.append(error)

        threads = [threading.Thread(target=work, args=(seed,)) for seed in (1, 2)]
        for thread in threads:
            thread.start()
        for thread in threads:
            thread.join()
        assert not errors
        t.validate()
        assert t.face_count == 2 * (len(t) + 2)
