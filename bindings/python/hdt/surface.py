"""Facts about the surface M_g and its fundamental polygon F_g.

F_g is the regular hyperbolic 4g-gon centred at 0 in the Poincare disk, with
interior angles pi/(2g). Indices are taken mod 4g.
"""

from __future__ import annotations

import ctypes
import math
from typing import Tuple

from ._arrays import Point, Word
from ._convert import c_coordinate, c_genus, c_index, call_point, call_word
from ._errors import InvalidArgument
from ._lib import lib


def systole(genus: int) -> float:
    """The systole of M_g, 2 arccosh(1 + 2 cos(pi / 2g)), as a float.

    The C function returns NaN for genus < 2; this one raises
    :class:`hdt.InvalidArgument` (a ValueError) instead. There is no upper
    limit on the genus other than the C int it is passed as.
    """
    value = lib.hdt_systole(c_genus(genus))
    if math.isnan(value):
        raise InvalidArgument(f"systole: genus must be at least 2, got {genus}")
    return value


def polygon_vertex(genus: int, k: int) -> Point:
    """The vertex v_k of F_g, at angle (2k+1) pi / 4g, as a tuple (x, y).

    k is any int, taken mod 4g. Raises :class:`hdt.InvalidArgument` for
    genus < 2 and :class:`hdt.NotSupported` above HDT_GENUS_MAX.
    """
    genus = c_genus(genus)
    return call_point(lib.hdt_polygon_vertex, genus, c_index(k, genus))


def polygon_side_midpoint(genus: int, k: int) -> Point:
    """The midpoint m_k of side s_k of F_g, at angle k pi / 2g, as (x, y).

    Side s_k joins v_{k-1} and v_k and is paired with s_{k+2g} by the
    generator g_k. k is any int, taken mod 4g. Errors as for
    :func:`polygon_vertex`.
    """
    genus = c_genus(genus)
    return call_point(lib.hdt_polygon_side_midpoint, genus, c_index(k, genus))


def point_representative(genus: int, x: float, y: float) -> Tuple[Point, Word]:
    """The canonical representative of the disk point (x, y).

    Returns ((rx, ry), word): the element h of Gamma_g, as its canonical word,
    with h(x + iy) in the half-open fundamental domain (the interior of F_g,
    the open sides s_0 .. s_{2g-1} and the vertex v_0), and h(x + iy) rounded
    to floats. A point inside F_g gives ((x, y), ()). Raises
    :class:`hdt.OutOfDomain` (a ValueError) when (x, y) is not a finite point
    of the open unit disk.
    """
    rx, ry = ctypes.c_double(), ctypes.c_double()
    word = call_word(lib.hdt_point_representative, c_genus(genus), c_coordinate(x, "x"), c_coordinate(y, "y"),
                     ctypes.byref(rx), ctypes.byref(ry), capacity=32)
    return (rx.value, ry.value), word
