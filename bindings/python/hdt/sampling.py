"""Random points uniform for hyperbolic area in F_g: :func:`random_points`.

The same points, bit for bit, as ``hdt-triangulate --random N --seed S``
draws (bindings/cli/random_points.c; both call the C library's cos and sin):
F_g lies in the disk of hyperbolic radius R about 0, cosh R = cot^2(pi/4g);
there cosh r uniform in [1, cosh R] and the angle uniform give the uniform
distribution, and a candidate is kept when it lies in the half-open F_g
(its canonical representative is itself, decided exactly by the library).
A double-precision test against the side nearest in angle only rejects
candidates that are clearly outside before the library is asked.
"""

from __future__ import annotations

import math
from typing import Iterator, List, Tuple

from . import _arrays
from ._arrays import Points
from ._convert import c_genus
from ._errors import InvalidArgument
from .surface import point_representative, polygon_side_midpoint

_MASK = (1 << 64) - 1


def _splitmix64(seed: int) -> Iterator[int]:
    """The stream of 64-bit numbers of splitmix64 from seed."""
    state = seed & _MASK
    while True:
        state = (state + 0x9E3779B97F4A7C15) & _MASK
        z = state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & _MASK
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & _MASK
        yield z ^ (z >> 31)


def random_points(genus: int, n: int, seed: int = 1) -> Points:
    """n points drawn uniformly for hyperbolic area in the half-open
    fundamental polygon F_g of M_genus, from the seed (an int in 0 ..
    2^64 - 1): a float64 array of shape (n, 2) with NumPy, a list of (x, y)
    tuples without. The same seed gives the same points, and the same as
    the command-line tool's ``--random n --seed seed``.
    :class:`hdt.InvalidArgument` for a genus out of range, n < 0 or a seed
    out of range."""
    genus = c_genus(genus)
    if not isinstance(n, int) or isinstance(n, bool) or n < 0:
        raise InvalidArgument(f"random_points: n must be an int >= 0, not {n!r}")
    if not isinstance(seed, int) or isinstance(seed, bool) or not 0 <= seed <= _MASK:
        raise InvalidArgument(f"random_points: the seed must be an int from 0 to 2^64 - 1, not {seed!r}")
    pi = math.acos(-1.0)
    cot = 1.0 / math.tan(pi / (4.0 * genus))
    cosh_r_max = cot * cot
    mx, my = polygon_side_midpoint(genus, 0)
    mu = math.hypot(mx, my)
    c, step = (mu + 1.0 / mu) / 2.0, pi / (2.0 * genus)
    stream = _splitmix64(seed)
    points: List[Tuple[float, float]] = []
    while len(points) < n:
        ch = 1.0 + (next(stream) >> 11) * 2.0 ** -53 * (cosh_r_max - 1.0)
        rho = math.sqrt((ch - 1.0) / (ch + 1.0))
        theta = 2.0 * pi * ((next(stream) >> 11) * 2.0 ** -53)
        x, y = rho * math.cos(theta), rho * math.sin(theta)
        side_angle = step * math.floor(theta / step + 0.5)
        if 1.0 + rho * rho - 2.0 * c * rho * math.cos(theta - side_angle) < -1e-9:
            continue  # clearly beyond the nearest side
        if point_representative(genus, x, y)[1] != ():
            continue  # outside the half-open F_g
        points.append((x, y))
    np = _arrays.numpy
    if np is not None:
        return np.array(points, dtype=np.float64).reshape(n, 2)
    return points
