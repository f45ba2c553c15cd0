"""Refinement, epsilon-nets and quality through the bindings: the bounds
recomputed here from face_points() on the hyperboloid (Lorentz products, in
Python floats, so within a relative 1e-9 on these faces), the cap, and bad
arguments that change nothing."""

import math

import pytest

import hdt


def lift(x, y):
    """The hyperboloid point of the disk point (x, y)."""
    n = x * x + y * y
    return ((1 + n) / (1 - n), 2 * x / (1 - n), 2 * y / (1 - n))


def lorentz(a, b):
    return a[0] * b[0] - a[1] * b[1] - a[2] * b[2]


def shape(corners):
    """(circumradius, shortest edge) of a face from its three disk corners."""
    p = [lift(x, y) for x, y in corners]
    d1 = [p[1][k] - p[0][k] for k in range(3)]
    d2 = [p[2][k] - p[0][k] for k in range(3)]
    n = (d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0])
    c = (n[0], -n[1], -n[2])
    radius = math.acosh(abs(lorentz(c, p[0])) / math.sqrt(lorentz(c, c)))
    shortest = min(math.acosh(max(1.0, lorentz(p[i], p[(i + 1) % 3]))) for i in range(3))
    return radius, shortest


def faces_of(t):
    return [[tuple(map(float, corner)) for corner in face] for face in t.face_points()]


@pytest.mark.parametrize("genus, radius, ratio", [(2, 0.2, 1.0), (3, 0.25, 1.5), (2, 0.15, math.inf)])
def test_refine_meets_the_bounds(genus, radius, ratio):
    with hdt.Triangulation(genus) as t:
        result = t.refine(radius, ratio)
        assert isinstance(result, hdt.Refined) and result.added > 0 and result.unmet == 0
        t.validate()
        assert t.face_count == 2 * (len(t) + 2 * genus - 2)
        for face in faces_of(t):
            r, e = shape(face)
            assert r <= radius * (1 + 1e-9)
            assert r <= ratio * e * (1 + 1e-9)
        q = t.quality()
        assert isinstance(q, hdt.Quality) and q.max_radius <= radius and q.max_ratio <= ratio
        assert 0 < q.min_angle < math.pi / 3 and q.min_edge > 0
        assert t.refine(radius, ratio) == (0, 0)


def test_epsilon_net_covers_and_packs():
    with hdt.Triangulation(2) as t:
        eps = 0.12
        assert t.quality().min_edge >= eps  # the dummies are eps apart
        assert t.epsilon_net(eps).unmet == 0
        q = t.quality()
        assert q.max_radius <= eps <= q.min_edge * (1 + 1e-8)
        worst = max(shape(face)[0] for face in faces_of(t))
        assert worst <= eps * (1 + 1e-9)


def test_the_cap():
    with hdt.Triangulation(2) as t:
        n = len(t)
        assert t.refine(0.2, 1.2, max_points=5) == (5, t.refine(0.2, 1.2, max_points=0).unmet)
        assert len(t) == n + 5 and t.refine(0.2, 1.2, 0).unmet > 0
        t.validate()
        assert t.refine(0.2, 1.2).unmet == 0


def test_bad_arguments_change_nothing():
    with hdt.Triangulation(2) as t:
        t.insert_many([(0.1, 0.2), (-0.3, 0.1)])
        before = t.to_bytes()
        for radius, ratio in [(math.nan, 2), (0, 2), (-1, 2), (0.2, 0.5), (0.2, math.nan)]:
            with pytest.raises(hdt.InvalidArgument):
                t.refine(radius, ratio)
        for eps in [math.nan, math.inf, 0, -0.1]:
            with pytest.raises(hdt.InvalidArgument):
                t.epsilon_net(eps)
        with pytest.raises(hdt.InvalidArgument):
            t.refine(0.2, max_points=-1)
        with pytest.raises(TypeError):
            t.refine(0.2, max_points=1.5)
        with pytest.raises(TypeError):
            t.refine("0.2")
        assert t.to_bytes() == before


@pytest.mark.parametrize("second", [math.nextafter(0.1, 1), 0.1 + 2 ** -52])
def test_near_duplicates_refine_without_error(second):
    """Two points an ulp or two apart: refinement returns, the few faces next
    to the pair (which double cannot refine) counted in unmet, the faces
    away from it meeting the bound; it raised InternalError with the bytes
    changed."""
    with hdt.Triangulation(2) as t:
        t.insert_many([(0.3, 0.1), (0.3, second)])
        t.remove_dummies()
        added, unmet = t.refine(max_ratio=2.0)
        t.validate()
        assert added > 0 and 1 <= unmet <= 8
        # Python floats resolve the shapes of faces away from the pair only
        # (test_refine.c checks them all in MPFR).
        far = [f for f in faces_of(t) if min(math.hypot(x - 0.3, y - 0.1) for x, y in f) > 1e-3]
        assert len(far) >= 100
        assert all(shape(f)[0] <= 2.0 * shape(f)[1] * (1 + 1e-6) for f in far)


def test_work_that_cannot_fit_is_refused_at_once():
    with hdt.Triangulation(2) as t:
        before = t.to_bytes()
        with pytest.raises(MemoryError, match="vertices"):
            t.epsilon_net(1e-4)
        with pytest.raises(hdt.OutOfMemory):
            t.refine(1e-6, 2.0)
        assert t.to_bytes() == before
        assert t.epsilon_net(1e-4, max_points=100) == (100, t.refine(1e-4, max_points=0).unmet)
