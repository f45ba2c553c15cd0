"""Facts about the surface M_g and its fundamental polygon F_g.

F_g is the regular hyperbolic 4g-gon centred at 0 in the Poincare disk, with
interior angles pi/(2g). Indices are taken mod 4g.
"""

import math

from ._convert import c_genus, c_index, call_point
from ._errors import InvalidArgument
from ._lib import lib


def systole(genus):
    """The systole of M_g, 2 arccosh(1 + 2 cos(pi / 2g)), as a float.

    The C function returns NaN for genus < 2; this one raises
    :class:`hdt.InvalidArgument` (a ValueError) instead. There is no upper
    limit on the genus other than the C int it is passed as.
    """
    value = lib.hdt_systole(c_genus(genus))
    if math.isnan(value):
        raise InvalidArgument(f"systole: genus must be at least 2, got {genus}")
    return value


def polygon_vertex(genus, k):
    """The vertex v_k of F_g, at angle (2k+1) pi / 4g, as a tuple (x, y).

    k is any int, taken mod 4g. Raises :class:`hdt.InvalidArgument` for
    genus < 2 and :class:`hdt.NotSupported` above HDT_GENUS_MAX.
    """
    genus = c_genus(genus)
    return call_point(lib.hdt_polygon_vertex, genus, c_index(k, genus))


def polygon_side_midpoint(genus, k):
    """The midpoint m_k of side s_k of F_g, at angle k pi / 2g, as (x, y).

    Side s_k joins v_{k-1} and v_k and is paired with s_{k+2g} by the
    generator g_k. k is any int, taken mod 4g. Errors as for
    :func:`polygon_vertex`.
    """
    genus = c_genus(genus)
    return call_point(lib.hdt_polygon_side_midpoint, genus, c_index(k, genus))
