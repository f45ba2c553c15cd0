"""Triangulation.to_svg: the library's picture (hdt_svg) through the bindings:
well-formed, the file is the text, options and errors map as documented, and
the text is what hdt-triangulate --svg draws for the same points."""

import os
import subprocess
import xml.etree.ElementTree as ElementTree

import pytest

import hdt
from hdt import picture
from sample_points import square_points

SVG = "{http://www.w3.org/2000/svg}"
HERE = os.path.dirname(os.path.abspath(__file__))
REPOSITORY = os.path.normpath(os.path.join(HERE, "..", "..", ".."))





@pytest.fixture(scope="module")
def small():
    """A genus-2 triangulation of 60 points inside F_2, with its dummies."""
    with hdt.Triangulation(2) as t:
        t.insert_many(square_points(60, 4, 0.4))
        yield t


def parse(text):
    root = ElementTree.fromstring(text.encode("utf-8"))
    assert root.tag == SVG + "svg"
    return root


def dots(root, colour):
    """The vertex dots of one colour; None when there is no such group."""
    groups = [g for g in root.iter(f"{SVG}g") if g.get("fill") == colour]
    assert len(groups) <= 1
    return [c for c in groups[0] if c.tag == SVG + "circle"] if groups else None


def test_to_svg_is_well_formed_and_complete(small, tmp_path):
    path = tmp_path / "t.svg"
    text = small.to_svg(str(path))
    assert path.read_bytes() == text.encode("utf-8")  # to_svg(path) writes the same text
    assert small.to_svg() == text  # and draws the same again
    root = parse(text)
    assert (root.get("width"), root.get("height"), root.get("viewBox")) == ("800", "856", "0 0 800 856")
    # Every user vertex is inside F_2 here: one dot each.
    assert len(dots(root, picture.USER_VERTEX)) == small.vertex_count - small.dummy_count == 60
    scene = picture.Scene(small)
    assert len(dots(root, picture.DUMMY_VERTEX)) == sum(len(scene.places(p)) for p in scene.dummy_points)
    assert len(dots(root, picture.DUMMY_VERTEX)) > small.dummy_count  # v_0 at every corner
    clip = root.find(f"{SVG}defs/{SVG}clipPath")
    assert clip.get("id") == "hdt-polygon"
    faces = [p for p in root.iter(f"{SVG}path") if p.get("clip-path") == "url(#hdt-polygon)"]
    assert len(faces) == 1 and faces[0].get("d").count("M") >= small.face_count
    captions = ["".join(t.itertext()) for t in root.iter(f"{SVG}text")]
    assert captions[0] == "Delaunay triangulation of 60 points on M_2"
    assert captions[1].startswith(f"{small.vertex_count} vertices ({small.dummy_count} dummies, red), "
                                  f"{small.face_count} faces")


def test_title_is_escaped_by_the_library(small):
    title = 'a <title> & "quotes" \u00e9\u4e2d'
    text = small.to_svg(title=title)
    assert "<title>" not in text and '"quotes"' not in text and " & " not in text
    assert "a &lt;title&gt; &amp; &quot;quotes&quot; \u00e9\u4e2d" in text
    assert next(parse(text).iter(f"{SVG}text")).text == title
    # What a C string cannot hold, and what XML forbids, becomes '?'.
    text = small.to_svg(title="a\0b\x01c\ud800d")
    assert next(parse(text).iter(f"{SVG}text")).text == "a?b?c?d"
    assert next(parse(small.to_svg(title=42)).iter(f"{SVG}text")).text == "42"


def test_options(small):
    plain = parse(small.to_svg(dummies=False))
    assert dots(plain, picture.DUMMY_VERTEX) is None
    assert len(dots(plain, picture.USER_VERTEX)) == 60
    assert "not marked" in list(plain.iter(f"{SVG}text"))[1].text
    with_neighbours = parse(small.to_svg(neighbours=True, size=400))
    # The caption's second part wraps into one line more (17 at size 800).
    assert (with_neighbours.get("width"), with_neighbours.get("height")) == ("400", "436.5")
    tiles = [c.get("id") for c in with_neighbours.iter(f"{SVG}clipPath")]
    assert tiles == ["hdt-polygon"] + [f"hdt-tile-{k}" for k in range(8)]
    assert parse(small.to_svg(size=123.25)).get("width") == "123.25"
    labelled = small.to_svg(side_labels=True)
    labels = [t.text for t in parse(labelled).iter(f"{SVG}text")][:-2]  # before the caption
    assert labels == [picture.side_label(2, k) for k in range(8)]
    assert labels[:5] == ["g_0", "g_1", "g_2", "g_3", "g_0^-1"]
    assert "g_k maps s_(k+2g)" in "".join(list(parse(labelled).iter(f"{SVG}text"))[-1].itertext())


@pytest.mark.parametrize("size", [0, -1, float("nan"), float("inf"), 1e6])
def test_a_bad_size_is_an_invalid_argument(small, size):
    with pytest.raises(hdt.InvalidArgument, match="hdt_svg: size must be") as caught:
        small.to_svg(size=size)
    assert isinstance(caught.value, ValueError)


def test_a_bad_size_writes_no_file(small, tmp_path):
    path = tmp_path / "none.svg"
    with pytest.raises(ValueError):
        small.to_svg(str(path), size=0)
    assert not path.exists()


def test_more_text_than_the_first_guess(small, monkeypatch):
    """The EBUFS path of to_svg: a first buffer too small, then the size the
    library reported."""
    from hdt import triangulation

    calls = []
    real = triangulation.lib

    class Spy:
        def __getattr__(self, name):
            return getattr(real, name)

        @staticmethod
        def hdt_face_count(handle):
            return 0  # the guess becomes 4096 + 64 V bytes: too small

        @staticmethod
        def hdt_svg(*args):
            status = real.hdt_svg(*args)
            calls.append((args[5], status))
            return status

    expected = small.to_svg(neighbours=True)
    monkeypatch.setattr(triangulation, "lib", Spy())
    assert small.to_svg(neighbours=True) == expected
    assert [status for _, status in calls] == [hdt.Status.EBUFS, hdt.Status.OK]
    assert calls[1][0] == len(expected.encode("utf-8")) + 1


def test_the_dummy_set_is_the_committed_picture():
    """The default caption of an untouched triangulation is the one the tool
    gives the dummy set (--random 0 --keep-dummies): the same picture."""
    committed = os.path.join(REPOSITORY, "examples", "pictures", "dummies-g2.svg")
    if not os.path.exists(committed):
        pytest.skip("no source tree (an installed package)")
    with open(committed, "rb") as file, hdt.Triangulation(2) as t:
        assert t.to_svg().encode("utf-8") == file.read()


# ---- the same picture as hdt-triangulate ----

def cli_path():
    """hdt-triangulate of the build whose libhdt the tests load (meson sets
    HDT_LIBRARY to BUILD/lib/libhdt.so...), or of HDT_TRIANGULATE."""
    path = os.environ.get("HDT_TRIANGULATE")
    if not path and os.environ.get("HDT_LIBRARY"):
        build = os.path.dirname(os.path.dirname(os.path.abspath(os.environ["HDT_LIBRARY"])))
        path = os.path.join(build, "bindings", "cli", "hdt-triangulate")
    if not path or not os.access(path, os.X_OK):
        pytest.skip("hdt-triangulate not found (set HDT_TRIANGULATE)")
    return path


CASES = [
    # genus, points, dummies removed, neighbours
    (2, 120, True, False),
    (3, 200, True, True),
    (2, 40, False, False),
]


@pytest.mark.parametrize("genus,count,remove,neighbours", CASES)
def test_to_svg_is_the_cli_picture(tmp_path, genus, count, remove, neighbours):
    tool = cli_path()
    xy = square_points(count, 10 * genus + count, 0.9)
    data = tmp_path / "points.txt"
    data.write_text("".join(f"{x!r} {y!r}\n" for x, y in xy))  # repr: read back to the same doubles
    options = ["--genus", str(genus)] + ([] if remove else ["--keep-dummies"]) + (["--neighbours"] if neighbours else [])
    with hdt.Triangulation(genus) as t:
        t.insert_many(xy)
        if remove:
            t.remove_dummies()
        # From standard input the tool's caption is the library's default.
        out = tmp_path / "stdin.svg"
        with open(data, "rb") as stdin:
            subprocess.run([tool, *options, "--svg", str(out), "-o", os.devnull], stdin=stdin, check=True)
        assert out.read_bytes() == t.to_svg(neighbours=neighbours).encode("utf-8")
        # From a file it names the file: the same title through to_svg.
        out = tmp_path / "file.svg"
        subprocess.run([tool, *options, str(data), "--svg", str(out), "-o", os.devnull], check=True)
        title = f"Delaunay triangulation of the {count} points of points.txt on M_{genus}"
        assert out.read_bytes() == t.to_svg(neighbours=neighbours, title=title).encode("utf-8")
