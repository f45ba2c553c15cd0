"""Pictures: the geodesic geometry of hdt.picture, its Scene (the pieces the
library draws), and plot (matplotlib, Agg backend; skipped without
matplotlib), which must draw the pieces of to_svg. to_svg itself, the
library's picture: test_svg.py."""

import cmath
import math
import random
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
        u, v = picture._apply(picture._real_matrix(hdt.word_matrix(2, word)), z.real, z.imag)
        assert abs(complex(u, v) - complex(x, y)) < 1e-12


def test_the_scene_holds_each_face_in_its_canonical_copy(small):
    scene = picture.Scene(small)
    faces = small.faces()
    assert len(scene.faces) == small.face_count == scene.face_count
    assert len(scene.user_points) + len(scene.dummy_points) == small.vertex_count
    assert len(scene.dummy_points) == small.dummy_count
    for corners, row, translations in zip(scene.faces, as_lists(faces.vertices), as_lists(faces.translations)):
        for (x, y), v, h in zip(corners, row, translations):
            if h == 0:
                assert (x, y) == small.vertex_point(v)
            assert math.hypot(x, y) < 1
    assert len(scene.polygon) == 8 and len(scene.generators) == 8 and len(scene.neighbours) == 49


def test_the_pieces_tile_f_g(small):
    """A face's canonical copy meets F_g: it is among the pieces unless it
    only touches F_g at a vertex on the boundary; the boundary vertices have
    their places (v_0 at the 8 corners, a side's point on both sides)."""
    scene = picture.Scene(small)
    pieces = scene.pieces()
    assert len(pieces) >= small.face_count
    kept = set(pieces)
    for face in scene.faces:
        assert face in kept or any(len(scene.places(corner)) > 1 for corner in face)
    places = [len(scene.places(p)) for p in scene.dummy_points]
    assert set(places) <= {1, 2, 8}
    v0 = hdt.polygon_vertex(2, 0)
    assert all(n == 8 for p, n in zip(scene.dummy_points, places) if math.dist(p, v0) < 1e-9)
    assert all(len(scene.places(p)) == 1 for p in scene.user_points)  # all inside F_g


def svg_pieces(text, clip):
    """The number of closed paths (M commands) in the SVG path clipped by `clip`."""
    root = ElementTree.fromstring(text.encode("utf-8"))
    paths = [p for p in root.iter(f"{SVG}path") if p.get("clip-path") == f"url(#{clip})"]
    assert len(paths) == 1
    return paths[0].get("d").count("M")


def test_the_scene_has_the_pieces_of_the_library(small):
    """The Scene's pieces (plot's) are those of the library's SVG, in F_g and
    in each tile across a side."""
    scene = picture.Scene(small)
    text = small.to_svg(neighbours=True)
    assert svg_pieces(text, "hdt-polygon") == len(scene.pieces())
    pixel = 2.0 / (800 * 0.97)
    for k, generator in enumerate(scene.generators):
        assert svg_pieces(text, f"hdt-tile-{k}") == len(scene.pieces(generator, pixel))
    root = ElementTree.fromstring(text.encode("utf-8"))
    dummy_group = [g for g in root.iter(f"{SVG}g") if g.get("fill") == picture.DUMMY_VERTEX][0]
    assert len(dummy_group) == sum(len(scene.places(p)) for p in scene.dummy_points)
    # Wrapped into tspans, whose pieces joined are the caption.
    captions = ["".join(t.itertext()) for t in root.iter(f"{SVG}text")]
    assert "\n".join(captions) == scene.caption(True) + "; Poincare disk"
    # The tiles' vertices, lighter: each place of each vertex, in each tile.
    light = [g for g in root.iter(f"{SVG}g") if g.get("fill") == picture.NEIGHBOUR_DUMMY_VERTEX][0]
    assert len(light) == len(scene.generators) * sum(len(scene.places(p)) for p in scene.dummy_points)


def test_the_caption_fits(small):
    """The caption wraps where its estimated width would pass the picture's
    (issue 37: "Voronoi diagran" was cut off), and the band grows with it."""
    text = small.to_svg(neighbours=True, voronoi=True)
    root = ElementTree.fromstring(text.encode("utf-8"))
    texts = list(root.iter(f"{SVG}text"))
    assert len(texts) == 2 and len(list(texts[0])) == 0 and len(list(texts[1])) == 1
    assert root.get("height") == "873"
    for piece in [texts[1].text] + [t.text for t in texts[1]]:
        assert picture.text_width(piece.rstrip()) * 13 * 1.05 / 1000 <= 800 - 24
    assert "".join(texts[1].itertext()).endswith("; Voronoi diagram green; Poincare disk")
    assert picture.wrap("ab, cd ef", 4.0 * 13 * 1.05, 13) == ["ab, ", "cd ef"]
    assert picture.wrap("", 10, 13) == [""]


def test_tiles_show_voronoi_edges(small):
    scene = picture.Scene(small, voronoi=True)
    text = small.to_svg(neighbours=True, voronoi=True)
    root = ElementTree.fromstring(text.encode("utf-8"))
    pixel = 2.0 / (800 * 0.97)
    paths = [p for p in root.iter(f"{SVG}path") if p.get("stroke") == picture.NEIGHBOUR_VORONOI_EDGE]
    assert [p.get("clip-path") for p in paths] == [f"url(#hdt-tile-{k})" for k in range(len(scene.generators))]
    for path, generator in zip(paths, scene.generators):
        assert path.get("d").count("M") == len(scene.voronoi_pieces(pixel, generator))


def test_svg_is_to_svg(small):
    assert picture.svg(small, size=300, neighbours=True, title="t") == small.to_svg(size=300, neighbours=True,
                                                                                  title="t")


def test_to_svg_needs_no_matplotlib(small, monkeypatch):
    # import matplotlib fails now, also when an earlier test imported it and
    # its submodules (None in sys.modules stops each import).
    for name in [m for m in sys.modules if m == "matplotlib" or m.startswith("matplotlib.")] + ["matplotlib"]:
        monkeypatch.setitem(sys.modules, name, None)
    ElementTree.fromstring(small.to_svg().encode("utf-8"))
    with pytest.raises(ImportError, match="needs matplotlib"):
        small.plot()


# ---- matplotlib ----

def test_plot_draws_the_pieces_of_the_svg_clipped_to_f_g(small):
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    try:
        fig, ax = plt.subplots()
        assert small.plot(ax) is ax
        labels = {artist.get_label() for artist in ax.collections + ax.patches}
        assert {"faces", "vertices", "dummy vertices", "F_2"} <= labels
        faces = [c for c in ax.collections if c.get_label() == "faces"][0]
        assert len(faces.get_segments()) == svg_pieces(small.to_svg(), "hdt-polygon") >= small.face_count
        assert faces.get_clip_path() is not None  # cut at F_g's sides
        dummies = [c for c in ax.collections if c.get_label() == "dummy vertices"][0]
        root = ElementTree.fromstring(small.to_svg().encode("utf-8"))
        dummy_dots = [g for g in root.iter(f"{SVG}g") if g.get("fill") == picture.DUMMY_VERTEX][0]
        assert len(dummies.get_offsets()) == len(dummy_dots)
        ax.legend()
        fig.canvas.draw()
        ax2 = small.plot(dummies=False, neighbours=True)
        assert ax2 is not ax and ax2.figure is not fig
        assert "dummy vertices" not in {c.get_label() for c in ax2.collections}
        text = small.to_svg(neighbours=True)
        tiles = [c for c in ax2.collections if c.get_label() != "faces" and c.get_clip_path() is not None]
        assert [len(c.get_segments()) for c in tiles] == [svg_pieces(text, f"hdt-tile-{k}") for k in range(8)]
        ax2.figure.canvas.draw()
    finally:
        plt.close("all")
