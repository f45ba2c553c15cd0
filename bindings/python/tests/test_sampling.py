"""hdt.random_points: the same points as hdt-triangulate --random (an
independent implementation in C), every one in the half-open F_g, and
uniform for hyperbolic area (the fraction within hyperbolic radius r of 0
against the exact area ratio)."""

import json
import math
import os
import subprocess

import pytest

import hdt
from hdt import _arrays

CLI = os.environ.get("HDT_TRIANGULATE")


@pytest.mark.parametrize("genus, n, seed", [(2, 50, 1), (3, 200, 7), (5, 30, 2 ** 64 - 1)])
def test_the_same_points_as_the_command_line(genus, n, seed):
    if not CLI or not os.path.exists(CLI):
        pytest.skip("HDT_TRIANGULATE does not name hdt-triangulate (meson test sets it)")
    out = subprocess.run([CLI, "--genus", str(genus), "--random", str(n), "--seed", str(seed), "-f", "json",
                          "--keep-dummies"], check=True, capture_output=True, text=True, timeout=60).stdout
    data = json.loads(out)
    by_id = {v["id"]: (v["x"], v["y"]) for v in data["vertices"]}
    cli = [by_id[v] for v in data["points"]]  # the vertex of each input point, input order
    ours = [tuple(map(float, p)) for p in hdt.random_points(genus, n, seed)]
    assert ours == cli


def test_in_the_polygon_and_uniform():
    points = hdt.random_points(2, 4000, 11)
    assert all(hdt.point_representative(2, x, y)[1] == () for x, y in points[:500])
    # the area of the hyperbolic disk of radius r is 2 pi (cosh r - 1), and
    # F_2 (area 4 pi) contains the disk of its inradius: the fraction inside
    # radius r below the inradius is (cosh r - 1) / 2
    inradius = math.acosh(1 / math.tan(math.pi / 8))  # cosh(inradius) = cot(pi/4g) for g = 2
    r = 0.8 * inradius
    inside = sum(2 * math.atanh(math.hypot(x, y)) < r for x, y in points)
    expected = (math.cosh(r) - 1) / 2
    sigma = math.sqrt(expected * (1 - expected) / len(points))
    assert abs(inside / len(points) - expected) < 5 * sigma


def test_lists_without_numpy(monkeypatch):
    monkeypatch.setattr(_arrays, "numpy", None)
    points = hdt.random_points(2, 5, 3)
    assert isinstance(points, list) and len(points) == 5 and all(isinstance(p, tuple) for p in points)
    assert hdt.random_points(2, 0) == []


@pytest.mark.parametrize("args", [(1, 5), (2, -1), (2, 1.5), (2, 5, -1), (2, 5, 2 ** 64)])
def test_bad_arguments(args):
    with pytest.raises(hdt.InvalidArgument):
        hdt.random_points(*args)
