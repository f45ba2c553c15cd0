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
