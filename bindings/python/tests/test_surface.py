"""hdt.systole and the polygon F_g against the formulas of include/hdt.h."""

import math

import pytest

import hdt

GENERA = (2, 3, 4, 7)


def test_systole_of_genus_2_is_that_of_the_bolza_surface():
    assert hdt.systole(2) == pytest.approx(2 * math.acosh(1 + math.sqrt(2)), rel=1e-15)


@pytest.mark.parametrize("genus, expected", [(2, 3.0571418389619963), (3, 3.3257717821172422),
                                             (4, 3.4146412257142814)])
def test_systole_matches_the_checked_values(genus, expected):
    assert hdt.systole(genus) == pytest.approx(expected, rel=1e-15)


@pytest.mark.parametrize("genus", [1, 0, -3])
def test_systole_rejects_a_genus_below_2(genus):
    with pytest.raises(hdt.InvalidArgument, match=f"genus must be at least 2, got {genus}") as caught:
        hdt.systole(genus)
    assert isinstance(caught.value, ValueError)
    assert caught.value.status == hdt.Status.EINVAL


@pytest.mark.parametrize("genus", GENERA)
def test_vertices_lie_at_their_angles_and_radius(genus):
    radius = math.sqrt(math.cos(math.pi / (2 * genus)))
    for k in range(4 * genus):
        x, y = hdt.polygon_vertex(genus, k)
        angle = (2 * k + 1) * math.pi / (4 * genus)
        assert x == pytest.approx(radius * math.cos(angle), abs=1e-14)
        assert y == pytest.approx(radius * math.sin(angle), abs=1e-14)


@pytest.mark.parametrize("genus", GENERA)
def test_side_midpoints_lie_at_their_angles_and_distance(genus):
    cosh_distance = 1 / math.tan(math.pi / (4 * genus))
    for k in range(4 * genus):
        x, y = hdt.polygon_side_midpoint(genus, k)
        r2 = x * x + y * y
        assert (1 + r2) / (1 - r2) == pytest.approx(cosh_distance, rel=1e-13)
        assert math.atan2(y, x) % (2 * math.pi) == pytest.approx(k * math.pi / (2 * genus), abs=1e-13)


@pytest.mark.parametrize("function", [hdt.polygon_vertex, hdt.polygon_side_midpoint])
def test_polygon_indices_are_taken_mod_4g(function):
    assert function(2, -1) == function(2, 7)
    assert function(3, 12 + 5) == function(3, 5)
    huge = 2**70 + 3
    assert function(2, huge) == function(2, huge % 8)
    assert function(2, -huge) == function(2, -huge % 8)


@pytest.mark.parametrize("function", [hdt.polygon_vertex, hdt.polygon_side_midpoint])
def test_polygon_functions_report_the_library_errors(function):
    with pytest.raises(hdt.InvalidArgument, match="genus must be at least 2, got 1"):
        function(1, 0)
    with pytest.raises(hdt.NotSupported, match="HDT_GENUS_MAX"):
        function(2000, 0)
    with pytest.raises(hdt.NotSupported, match="does not fit"):
        function(2**40, 0)
    with pytest.raises(hdt.InvalidArgument, match="genus must be at least 2"):
        function(-(2**40), 2**70)
    with pytest.raises(TypeError, match="genus must be an int, not float"):
        function(2.0, 0)
    with pytest.raises(TypeError, match="k must be an int, not str"):
        function(2, "0")


def test_point_inside_f_is_its_own_representative():
    assert hdt.point_representative(2, 0.25, -0.125) == ((0.25, -0.125), ())


@pytest.mark.parametrize("genus", GENERA)
def test_representative_is_the_image_under_its_word(genus):
    x, y = 0.97, 0.1
    (rx, ry), word = hdt.point_representative(genus, x, y)
    assert word and hdt.reduce_word(genus, word) == word
    ix, iy = hdt.word_apply(genus, word, x, y)
    assert math.hypot(ix - rx, iy - ry) < 1e-9
    # The image of the point under any element has the same representative.
    jx, jy = hdt.word_apply(genus, [1, 2], x, y)
    (sx, sy), _ = hdt.point_representative(genus, jx, jy)
    assert math.hypot(sx - rx, sy - ry) < 1e-9


def test_representative_rejects_points_outside_the_disk():
    with pytest.raises(hdt.OutOfDomain, match="hdt_point_representative") as caught:
        hdt.point_representative(2, 0.6, 0.8)
    assert isinstance(caught.value, ValueError)
