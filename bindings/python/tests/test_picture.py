"""Pictures: the geodesic geometry, to_svg (well-formed, complete, right arcs)
and plot (matplotlib, Agg backend; skipped without matplotlib)."""

import cmath
import math
import random
import re
import sys
import xml.etree.ElementTree as ElementTree

import pytest

import hdt
from hdt import picture
from hdt._arrays import as_lists

SVG = "{http://www.w3.org/2000/svg}"


@pytest.fixture(scope="module")
def small():
    """A genus-2 triangulation of 60 points with its dummies (read only)."""
    generator = random.Random(4)
    with hdt.Triangulation(2) as t:
        t.insert_many([(0.6 * generator.random() - 0.3, 0.6 * generator.random() - 0.3) for _ in range(60)])
        yield t


def hyperbolic_midpoint(p, q):
    """The midpoint of the geodesic pq: move p to 0, halve, move back."""
    w = (q - p) / (1 - p.conjugate() * q)  # the image of q when p goes to 0
    half = cmath.rect(math.tanh(math.atanh(abs(w)) / 2), cmath.phase(w))
    return (half + p) / (1 + p.conjugate() * half)


# ---- geometry ----

def test_geodesic_circles_are_orthogonal_to_the_unit_circle_and_turn_the_right_way():
    generator = random.Random(8)
    arcs = 0
    for _ in range(200):
        p, q = (cmath.rect(0.95 * math.sqrt(generator.random()), 2 * math.pi * generator.random()) for _ in range(2))
        arc = picture.geodesic(p, q)
        if arc is None:
            continue
        arcs += 1
        centre, radius, counterclockwise = arc
        assert abs(centre) ** 2 == pytest.approx(radius**2 + 1, rel=1e-9)
        assert abs(p - centre) == pytest.approx(radius, rel=1e-9)
        assert abs(q - centre) == pytest.approx(radius, rel=1e-9)
        # The hyperbolic midpoint is on the short arc from p to q, in the
        # direction given.
        m = hyperbolic_midpoint(p, q)
        assert abs(m - centre) == pytest.approx(radius, rel=1e-7)
        turn_to_m = (cmath.phase((m - centre) / (p - centre)))
        turn_to_q = (cmath.phase((q - centre) / (p - centre)))
        assert (turn_to_m > 0) == (turn_to_q > 0) == counterclockwise
        assert abs(turn_to_m) < abs(turn_to_q) < math.pi
        # The sampled arc stays on the circle and ends at q.
        points = picture.geodesic_points(p, q)
        assert points[-1] == q
        assert all(abs(abs(z - centre) - radius) < 1e-9 * max(1, radius) for z in points)
    assert arcs > 150


def test_a_geodesic_through_the_origin_is_a_segment():
    assert picture.geodesic(0.5 + 0j, -0.25 + 0j) is None
    assert picture.geodesic(0.3 + 0.3j, -0.1 - 0.1j) is None
    assert picture.geodesic(0j, 0.2 - 0.7j) is None
    assert picture.geodesic_points(0.5 + 0j, -0.25 + 0j) == [-0.25 + 0j]


def test_moebius_agrees_with_word_apply():
    for word in ([0], [3, 5], [7, 2, 1]):
        z = 0.2 - 0.1j
        x, y = hdt.word_apply(2, word, z.real, z.imag)
        assert abs(picture.moebius(hdt.word_matrix(2, word), z) - complex(x, y)) < 1e-12


def test_the_scene_holds_each_face_once_in_its_canonical_copy(small):
    scene = picture.Scene(small)
    faces = small.faces()
    assert len(scene.faces) == small.face_count == scene.face_count
    assert len(scene.user_points) + len(scene.dummy_points) == small.vertex_count
    assert len(scene.dummy_points) == small.dummy_count
    for corners, row, translations in zip(scene.faces, as_lists(faces.vertices), as_lists(faces.translations)):
        for z, v, h in zip(corners, row, translations):
            if h == 0:
                assert z == complex(*small.vertex_point(v))
            assert abs(z) < 1
    assert len(scene.polygon) == 8 and len(scene.neighbour_polygons()) == 8


# ---- SVG ----

def parse(text):
    root = ElementTree.fromstring(text.encode("utf-8"))
    assert root.tag == SVG + "svg"
    return root


def svg_arc_centre(x1, y1, r, sweep, x2, y2):
    """The centre of an SVG arc with rx = ry = r, no rotation, large-arc 0
    (the endpoint-to-centre conversion of the SVG specification)."""
    hx, hy = (x1 - x2) / 2, (y1 - y2) / 2
    d2 = hx * hx + hy * hy
    coefficient = math.sqrt(max(0.0, (r * r - d2) / d2)) * (1 if sweep == 1 else -1)  # + when large-arc (0) != sweep
    return coefficient * hy + (x1 + x2) / 2, -coefficient * hx + (y1 + y2) / 2


def test_to_svg_writes_a_well_formed_complete_svg(arrays, small, tmp_path):
    path = tmp_path / "t.svg"
    text = small.to_svg(str(path))
    assert path.read_text(encoding="utf-8") == text
    root = parse(text)
    assert root.get("viewBox") == "0 0 800 856"
    circles = root.findall(f".//{SVG}circle")
    assert len(circles) == 1 + small.vertex_count  # the disk and every vertex
    red = [c for c in circles if c.get("r") == "2.6"]
    assert len(red) == small.dummy_count > 0
    paths = root.findall(f".//{SVG}path")
    assert len(paths) == 3  # F_g filled, the faces, F_g outlined
    faces_path = [p for p in paths if p.get("stroke") == picture.FACE_EDGE][0]
    assert faces_path.get("d").count("M") == small.face_count
    assert "Delaunay triangulation on M_2" in root.find(f"{SVG}title").text


def test_svg_options(small, tmp_path):
    plain = parse(small.to_svg(dummies=False))
    assert all(c.get("r") != "2.6" for c in plain.iter(f"{SVG}circle"))
    with_neighbours = parse(small.to_svg(neighbours=True, size=400, title='a <title> & "quotes"'))
    assert with_neighbours.get("width") == "400"
    assert len(with_neighbours.findall(f".//{SVG}path")) == 5
    assert with_neighbours.find(f"{SVG}title").text == 'a <title> & "quotes"'
    with pytest.raises(ValueError, match="size must be a positive number"):
        small.to_svg(size=0)


def test_svg_arcs_of_the_polygon_are_its_sides(small):
    """End to end: each arc command of F_g's outline, read back with the SVG
    rules, has the centre of the circle carrying that side (centre at angle
    k pi / 2g, |c| = (mu + 1/mu) / 2 for mu the midpoints' radius)."""
    root = parse(small.to_svg())
    outline = [p for p in root.iter(f"{SVG}path") if p.get("stroke") == picture.POLYGON_EDGE][0].get("d")
    numbers = [float(n) for n in re.findall(r"-?\d+(?:\.\d+)?", outline)]
    commands = re.findall(r"[MAZL]", outline)
    assert commands == ["M"] + ["A"] * 8 + ["Z"]
    scale, top = 400 * 0.97, 56.0
    mu = abs(complex(*hdt.polygon_side_midpoint(2, 0)))
    centres = [cmath.rect((mu + 1 / mu) / 2, k * math.pi / 4) for k in range(8)]
    x, y = numbers[0], numbers[1]
    for k in range(8):
        r, _, _, large, sweep, x2, y2 = numbers[2 + 7 * k : 9 + 7 * k]
        assert large == 0
        cx, cy = svg_arc_centre(x, y, r, sweep, x2, y2)
        centre = complex((cx - 400) / scale, (top + 400 - cy) / scale)
        assert min(abs(centre - c) for c in centres) < 0.02
        x, y = x2, y2


def test_to_svg_needs_no_matplotlib(small, monkeypatch):
    monkeypatch.setitem(sys.modules, "matplotlib", None)  # import matplotlib fails now
    parse(small.to_svg())
    with pytest.raises(ImportError, match="needs matplotlib"):
        small.plot()


# ---- matplotlib ----

def test_plot_draws_on_given_or_new_axes(small):
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    try:
        fig, ax = plt.subplots()
        assert small.plot(ax) is ax
        labels = {artist.get_label() for artist in ax.collections + ax.patches}
        assert {"faces", "vertices", "dummy vertices", "F_2"} <= labels
        faces = [c for c in ax.collections if c.get_label() == "faces"][0]
        assert len(faces.get_segments()) == small.face_count
        ax.legend()
        fig.canvas.draw()
        ax2 = small.plot(dummies=False, neighbours=True)
        assert ax2 is not ax and ax2.figure is not fig
        assert "dummy vertices" not in {c.get_label() for c in ax2.collections}
        ax2.figure.canvas.draw()
    finally:
        plt.close("all")
