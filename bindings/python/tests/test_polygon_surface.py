"""hdt.Surface, a surface given by a fundamental polygon (hdt_surface_*),
checked independently in Python from what it reports: each pairing against
the vertices it must move, the relation around each vertex cycle, and
Gauss-Bonnet from the angles measured at the vertices (as
tests/test_surfaces.c does in C)."""

import cmath
import math

import pytest

import hdt

#: The Bolza surface's octagon, v_k = 2^(-1/4) e^(i (2k+1) pi/8), in Q(a),
#: a = sqrt(sqrt2 + 1) (tests/test_surfaces.c, docs/polygons.md).
BOLZA = ("field a^4-2*a^2-1 a 1.5538+/-0.01\n8\n4 5 6 7 0 1 2 3\n"
         "1/2*a 1/2*a^3-a\n1/2*a^3-a 1/2*a\n-1/2*a^3+a 1/2*a\n-1/2*a 1/2*a^3-a\n"
         "-1/2*a -1/2*a^3+a\n-1/2*a^3+a -1/2*a\n1/2*a^3-a -1/2*a\n1/2*a -1/2*a^3+a\n")

#: (sides, seed, vertex cycles) of the random surfaces under test.
RANDOM = [(8, seed, 1) for seed in range(1, 6)] + [(10, seed, 2) for seed in range(1, 4)]


def points(surface):
    """The vertices as complex numbers, one vertex() call each."""
    return [complex(*surface.vertex(k)) for k in range(surface.side_count)]


def apply(matrix, z):
    """The Moebius map z -> (a z + b) / (conj(b) z + conj(a)) of (a, b)."""
    a, b = matrix
    return (a * z + b) / (b.conjugate() * z + a.conjugate())


def direction(v, w):
    """The direction at v of the geodesic from v to w: arg T_v(w)."""
    return cmath.phase((w - v) / (1 - v.conjugate() * w))


def interior_angles(v):
    """The interior angle at each vertex of the counterclockwise polygon v."""
    n, angles = len(v), []
    for k in range(n):
        angle = direction(v[k], v[k - 1]) - direction(v[k], v[(k + 1) % n])
        while angle <= 0:
            angle += 2 * math.pi
        angles.append(angle)
    return angles


@pytest.fixture(params=RANDOM, ids=lambda p: f"{p[0]}-gon-seed-{p[1]}")
def random_surface(request):
    sides, seed, cycles = request.param
    with hdt.Surface.random_symmetric(sides, seed) as surface:
        yield surface, sides, cycles


def test_random_surfaces_have_genus_2_and_their_cycles(random_surface):
    surface, sides, cycles = random_surface
    assert (surface.genus, surface.side_count, len(surface.vertex_cycles())) == (2, sides, cycles)
    assert repr(surface) == f"Surface(genus=2, sides={sides}, cycles={cycles})"
    assert [surface.paired_side(k) for k in range(sides)] == [(k + sides // 2) % sides for k in range(sides)]


def test_random_surfaces_depend_on_the_seed_only():
    same = [hdt.Surface.random_symmetric(8, 4).polygon_text() for _ in range(2)]
    assert same[0] == same[1] != hdt.Surface.random_symmetric(8, 5).polygon_text()


def test_pairings_send_the_paired_side_onto_the_side(random_surface):
    surface, n, _ = random_surface
    v = points(surface)
    for k in range(n):
        j, (a, b) = surface.paired_side(k), surface.pairing(k)
        assert surface.paired_side(j) == k != j
        assert abs(abs(a) ** 2 - abs(b) ** 2 - 1) < 1e-12 and a.real >= 0
        assert abs(apply((a, b), v[(j + 1) % n]) - v[k]) < 1e-10
        assert abs(apply((a, b), v[j]) - v[(k + 1) % n]) < 1e-10


def test_pairings_compose_to_the_identity_around_each_cycle(random_surface):
    surface, n, _ = random_surface
    member = {vertex: c for c, cycle in enumerate(surface.vertex_cycles()) for vertex in cycle}
    for start in range(n):
        big_a, big_b, k, walked = 1, 0, start, []
        while True:
            walked.append(k)
            a, b = surface.pairing(k)
            big_a, big_b = big_a * a + big_b * b.conjugate(), big_a * b + big_b * a.conjugate()
            k = (surface.paired_side(k) + 1) % n
            if k == start or len(walked) > n:
                break
        assert k == start
        assert sorted(walked) == surface.vertex_cycles()[member[start]]
        assert abs(big_b) < 1e-9 and abs(abs(big_a) - 1) < 1e-9 and abs(big_a.imag) < 1e-9


def test_gauss_bonnet_from_the_vertices(random_surface):
    surface, n, _ = random_surface
    angles = interior_angles(points(surface))
    assert all(0 < angle < math.pi for angle in angles)
    for cycle in surface.vertex_cycles():
        assert abs(sum(angles[v] for v in cycle) - 2 * math.pi) < 1e-9
    area = (n - 2) * math.pi - sum(angles)
    assert abs(area - 4 * math.pi * (surface.genus - 1)) < 1e-9


def test_the_text_reads_back_as_the_same_surface(random_surface):
    surface = random_surface[0]
    text = surface.polygon_text()
    with hdt.Surface.from_polygon(text) as again:
        assert again.polygon_text() == text
        assert points(again) == points(surface)
    assert text.split()[0] == str(surface.side_count)


def test_vertices_in_one_call(random_surface, arrays):
    surface, n, _ = random_surface
    v = surface.vertices()
    if arrays == "numpy":
        assert v.shape == (n, 2) and v.dtype.name == "float64"
    else:
        assert isinstance(v, list) and all(isinstance(point, tuple) for point in v)
    assert [tuple(point) for point in v] == [surface.vertex(k) for k in range(n)]


def test_the_bolza_octagon_is_f_2():
    with hdt.Surface.from_polygon(BOLZA) as surface:
        assert (surface.genus, surface.side_count, surface.vertex_cycles()) == (2, 8, [list(range(8))])
        for k in range(8):
            x, y = hdt.polygon_vertex(2, k)
            assert abs(complex(*surface.vertex(k)) - complex(x, y)) < 1e-15
            assert surface.vertex(k + 8) == surface.vertex(k) == surface.vertex(k - 8)
        text = surface.polygon_text()
        assert text.startswith("field ") and hdt.Surface.from_polygon(text.encode()).polygon_text() == text


def test_the_bolza_pairings_are_generators_of_m2():
    surface = hdt.Surface.from_polygon(BOLZA)
    generators = [hdt.word_matrix(2, [letter]) for letter in range(8)]
    for k in range(8):
        a, b = surface.pairing(k)
        assert any(abs(a - s * g[0]) < 1e-13 and abs(b - s * g[1]) < 1e-13 for g in generators for s in (1, -1))


def moved_bolza_vertex():
    """The Bolza octagon with v_1 moved inwards: no longer convex."""
    return BOLZA.replace("\n1/2*a^3-a 1/2*a\n", "\n1/4*a^3-a 1/4*a\n", 1)


@pytest.mark.parametrize("text, phrase", [
    ("8\n4 5 6 7 0 1 2 x\n", "token 9"),
    ("7\n1 0 3 2 6 5 4\n0 0 0 0 0 0 0 0 0 0 0 0 0 0\n", "an even number"),
    ("4\n2 3 0 1\n1 0 0 1/2 -1/2 0 0 -1/2\n", "vertex 0 is not in the open unit disk"),
    ("8\n4 5 6 7 0 1 2 3\n1/5 1/10 1/10 1/5 -1/10 1/5 -1/5 1/10 -1/5 -1/10 -1/10 -1/5 1/10 -1/5 1/5 -1/10\n",
     "the angle sum must be 2 pi"),
    (moved_bolza_vertex(), "not strictly convex"),
    ("field a^2-4 a 2+/-0.1\n4\n", "not irreducible"),
    ("", "token 1"),
])
def test_refused_polygons_raise_the_library_reason(text, phrase):
    with pytest.raises(hdt.InvalidArgument, match=phrase) as caught:
        hdt.Surface.from_polygon(text)
    assert caught.value.status == hdt.Status.EINVAL and isinstance(caught.value, ValueError)
    assert phrase in caught.value.message


def test_refused_arguments():
    for sides in (12, 9, 0, -8, 2**40 + 8):
        with pytest.raises(hdt.InvalidArgument, match="sides must be 8 or 10"):
            hdt.Surface.random_symmetric(sides, 1)
    for seed in (-1, 2**64):
        with pytest.raises(hdt.InvalidArgument, match="seed"):
            hdt.Surface.random_symmetric(8, seed)
    assert hdt.Surface.random_symmetric(8, 2**64 - 1).genus == 2
    with pytest.raises(TypeError):
        hdt.Surface.from_polygon(8)
    with pytest.raises(TypeError):
        hdt.Surface.random_symmetric(8.0)
    with pytest.raises(TypeError):
        hdt.Surface()


def test_from_file(tmp_path):
    path = tmp_path / "bolza.txt"
    path.write_text(BOLZA)
    with hdt.Surface.from_file(path) as surface, hdt.Surface.from_file(str(path)) as same:
        assert surface.polygon_text() == same.polygon_text() == hdt.Surface.from_polygon(BOLZA).polygon_text()
        assert surface.genus == 2
    (tmp_path / "bad.txt").write_text("6\n3 4 5 0 1\n")
    with pytest.raises(hdt.InvalidArgument, match="token 7"):
        hdt.Surface.from_file(tmp_path / "bad.txt")
    with pytest.raises(FileNotFoundError):
        hdt.Surface.from_file(tmp_path / "missing.txt")


def test_indices_are_taken_mod_n():
    surface = hdt.Surface.random_symmetric(10, 2)
    huge = 2**70 + 3
    assert surface.vertex(huge) == surface.vertex(huge % 10) == surface.vertex(-(10 - huge % 10))
    assert surface.pairing(-1) == surface.pairing(9) and surface.paired_side(13) == surface.paired_side(3) == 8


def test_use_after_close_raises_handle_closed():
    surface = hdt.Surface.random_symmetric(8, 1)
    with surface as same:
        assert same is surface and not surface.closed
    assert surface.closed
    surface.close()  # twice is fine
    for call in (lambda: surface.vertex(0), surface.vertices, lambda: surface.pairing(0),
                 lambda: surface.paired_side(0), surface.vertex_cycles, surface.polygon_text,
                 surface.__enter__):
        with pytest.raises(hdt.HandleClosed, match="the surface is closed"):
            call()
    assert (surface.genus, surface.side_count) == (2, 8)
    assert repr(surface) == "Surface(genus=2, sides=8, closed)"


def test_garbage_collection_frees_the_surface():
    import gc
    import weakref

    surface = hdt.Surface.random_symmetric(8, 1)
    finalizer = surface._finalizer
    reference = weakref.ref(surface)
    del surface
    gc.collect()
    assert reference() is None and not finalizer.alive


def test_the_bolza_group_is_the_built_in_m2():
    with hdt.Surface.from_polygon(BOLZA) as s:
        lo, hi = s.systole()
        assert lo <= hdt.systole(2) <= hi and hi - lo < 1e-12
        assert s.neighbour_count() == hdt.neighbour_count(2)
        for k in range(60):
            z = cmath.rect(0.99 * math.sqrt((k + 0.5) / 60), 2.399963 * k)
            (rx, ry), _ = s.representative(z.real, z.imag)
            (bx, by), _ = hdt.point_representative(2, z.real, z.imag)
            assert abs(rx - bx) < 1e-12 and abs(ry - by) < 1e-12


def test_representatives_are_images_under_their_words(random_surface):
    random_surface, _, _ = random_surface
    for k in range(40):
        z = cmath.rect(0.98 * math.sqrt((k + 0.5) / 40), 2.399963 * k)
        (rx, ry), word = random_surface.representative(z.real, z.imag)
        image = z
        for letter in reversed(word):
            image = apply(random_surface.pairing(letter), image)
        assert abs(image - complex(rx, ry)) < 1e-9


def test_a_thin_polygon_has_its_systole_certified():
    with hdt.Surface.random_symmetric(8, 3) as s:
        lo, hi = s.systole()
        assert 0 < lo <= hi < lo + 1e-12
    with hdt.Surface.random_symmetric(8, 1) as s:
        with pytest.raises(hdt.OutOfDomain):
            s.representative(1.0, 0.0)


def test_the_picture_labels_every_side_with_its_partner(random_surface):
    surface, sides, _ = random_surface
    svg = surface.to_svg(400)
    assert svg.startswith("<svg ") and svg.endswith("</svg>\n")
    for k in range(sides):
        assert f">{k}~{surface.paired_side(k)}</text>" in svg
    with pytest.raises(hdt.InvalidArgument):
        surface.to_svg(0)
