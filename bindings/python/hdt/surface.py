"""Facts about the surface M_g and its fundamental polygon F_g, and
:class:`Surface`, a closed surface given by any fundamental polygon.

F_g is the regular hyperbolic 4g-gon centred at 0 in the Poincare disk, with
interior angles pi/(2g). Indices are taken mod 4g.

A :class:`Surface` (the C functions hdt_surface_* of symbol version HDT_0.7)
is a convex geodesic polygon v_0 .. v_{n-1} of the disk with its sides
paired, read from CGAL's text format (docs/polygons.md of the source tree)
and checked exactly by the library, or drawn at random. Side k runs from
v_k to v_{k+1}, and indices are taken mod n. It owns one C handle, freed by
:meth:`Surface.close`, by leaving a ``with`` block, or by garbage
collection; any other use after that raises :class:`hdt.HandleClosed`.
"""

from __future__ import annotations

import ctypes
import math
import os
import threading
import weakref
from typing import List, Optional, Tuple, Type, TypeVar, Union

from . import _arrays
from ._arrays import Matrix, Point, Points, Word
from ._convert import as_int, c_coordinate, c_genus, c_index, call_doubles, call_point, call_size, call_word
from ._errors import HandleClosed, InvalidArgument, check
from ._lib import lib

_S = TypeVar("_S", bound="Surface")
_UINT64_MAX = (1 << 64) - 1


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


def _destroy_surface(handle: ctypes.c_void_p) -> None:
    """Frees a C surface handle (the finalizer of every Surface)."""
    lib.hdt_surface_destroy(handle)


class Surface:
    """A closed orientable hyperbolic surface given by a fundamental polygon.

    Made by :meth:`from_polygon` (the polygon's text), :meth:`from_file` or
    :meth:`random_symmetric`; the library checks exactly that the polygon
    defines a closed surface of genus at least 2, and a polygon that fails
    raises :class:`hdt.InvalidArgument` with the library's reason. A surface
    does not change once made. Calls on one object are serialised by a lock.

    Example::

        with hdt.Surface.random_symmetric(8, seed=3) as s:
            s.genus, s.side_count, s.vertex(0), s.pairing(0)
    """

    _handle: Optional[ctypes.c_void_p] = None  # an hdt_surface * as ctypes.c_void_p; None once closed

    def __init__(self) -> None:
        """Not for use: make a surface with :meth:`from_polygon`,
        :meth:`from_file` or :meth:`random_symmetric`."""
        raise TypeError("make a Surface with Surface.from_polygon, Surface.from_file or Surface.random_symmetric")

    @classmethod
    def _made(cls: Type[_S], handle: ctypes.c_void_p) -> _S:
        """A new Surface owning a C handle (from hdt_surface_from_polygon or
        hdt_surface_random_symmetric)."""
        surface = cls.__new__(cls)
        surface._adopt(handle)
        return surface

    def _adopt(self, handle: ctypes.c_void_p) -> None:
        """Takes ownership of a C handle."""
        self._genus = lib.hdt_surface_genus(handle)
        self._sides = lib.hdt_surface_side_count(handle)
        self._lock = threading.RLock()
        self._handle = handle
        self._finalizer = weakref.finalize(self, _destroy_surface, handle)

    @classmethod
    def from_polygon(cls: Type[_S], text: Union[str, bytes]) -> _S:
        """The surface of a fundamental polygon given as text (str, or bytes
        in UTF-8): CGAL's format, n, the n paired sides, then the n vertices
        as exact rationals or decimals, optionally after a line "field
        MINPOLY GEN MID+/-RAD" (docs/polygons.md of the source tree).
        :class:`hdt.InvalidArgument` (a ValueError) for malformed text or a
        polygon that fails a check, its message the library's (naming the
        token, side, vertex or cycle at fault); TypeError for other types."""
        if isinstance(text, str):
            text = text.encode("utf-8")
        if not isinstance(text, bytes):
            raise TypeError(f"from_polygon: expected str or bytes, got {type(text).__name__}")
        handle = ctypes.c_void_p()
        check(lib.hdt_surface_from_polygon(ctypes.byref(handle), text, len(text)))
        return cls._made(handle)

    @classmethod
    def from_file(cls: Type[_S], path: Union[str, os.PathLike]) -> _S:
        """The surface of the polygon text in the file at path; as
        :meth:`from_polygon`."""
        with open(os.fspath(path), "rb") as source:
            return cls.from_polygon(source.read())

    @classmethod
    def random_symmetric(cls: Type[_S], sides: int = 8, seed: int = 1) -> _S:
        """A random genus-2 surface, built as CGAL's
        Hyperbolic_fundamental_domain_factory_2 builds them: a centrally
        symmetric polygon with rational vertices, side k paired with side
        k + sides/2. sides: 8 (one vertex cycle) or 10 (two); seed: an int
        from 0 to 2^64 - 1, the same polygon for the same seed on every
        platform. :class:`hdt.InvalidArgument` otherwise."""
        sides, seed = as_int(sides, "sides"), as_int(seed, "seed")
        if sides not in (8, 10):
            raise InvalidArgument(f"random_symmetric: sides must be 8 or 10, not {sides}")
        if not 0 <= seed <= _UINT64_MAX:
            raise InvalidArgument(f"random_symmetric: the seed must be an int from 0 to 2^64 - 1, not {seed}")
        handle = ctypes.c_void_p()
        check(lib.hdt_surface_random_symmetric(ctypes.byref(handle), sides, seed))
        return cls._made(handle)

    # ---- lifetime ----

    def close(self) -> None:
        """Frees the C surface now. Closing again does nothing; any other use
        afterwards raises :class:`hdt.HandleClosed`."""
        with self._lock:
            self._handle = None
            self._finalizer()

    @property
    def closed(self) -> bool:
        """Whether :meth:`close` was called (the handle is freed)."""
        return self._handle is None

    def __enter__(self: _S) -> _S:
        """Returns the surface itself; the ``with`` block closes it."""
        self._live("__enter__")
        return self

    def __exit__(self, *exception: object) -> None:
        """Closes the surface."""
        self.close()

    def _live(self, what: str) -> ctypes.c_void_p:
        """The handle; HandleClosed when closed (call with the lock held)."""
        handle = self._handle
        if handle is None:
            raise HandleClosed(f"{what}: the surface is closed")
        return handle

    def __repr__(self) -> str:
        """Surface(genus=G, sides=N, cycles=C), or closed."""
        if self.closed:
            return f"Surface(genus={self._genus}, sides={self._sides}, closed)"
        return f"Surface(genus={self._genus}, sides={self._sides}, cycles={len(self.vertex_cycles())})"

    # ---- the polygon ----

    @property
    def genus(self) -> int:
        """The genus, from Euler's formula (also after close())."""
        return self._genus

    @property
    def side_count(self) -> int:
        """n, the number of sides (= vertices) of the polygon (also after
        close())."""
        return self._sides

    def _index(self, k: int) -> int:
        """A side or vertex index, any int, reduced mod n for the C int."""
        return as_int(k, "k") % self._sides

    def vertex(self, k: int) -> Point:
        """The vertex v_k (k taken mod n) as (x, y), each coordinate the
        exact one rounded to a float."""
        k = self._index(k)
        with self._lock:
            return call_point(lib.hdt_surface_vertex, self._live("vertex"), k)

    def vertices(self) -> Points:
        """The vertices v_0 .. v_{n-1}, counterclockwise: a float64 array of
        shape (n, 2) with NumPy, a list of (x, y) tuples without."""
        pointer, owner = _arrays.output(ctypes.c_double, self._sides, 2)
        with self._lock:
            handle = self._live("vertices")
            for k in range(self._sides):
                pointer[2 * k], pointer[2 * k + 1] = call_point(lib.hdt_surface_vertex, handle, k)
        return _arrays.result(owner, 2)

    def paired_side(self, k: int) -> int:
        """The side glued to side k (k taken mod n)."""
        k, paired = self._index(k), ctypes.c_int()
        with self._lock:
            check(lib.hdt_surface_pairing(self._live("paired_side"), k, ctypes.byref(paired), None))
        return paired.value

    def pairing(self, k: int) -> Matrix:
        """The pairing isometry of side k (k taken mod n) as the pair (a, b)
        of its SU(1,1) matrix [[a, b], [conj b, conj a]], |a|^2 - |b|^2 = 1,
        Re a >= 0: the map z -> (a z + b) / (conj(b) z + conj(a)), which
        sends side j = paired_side(k), from v_{j+1} to v_j, onto side k
        from v_k to v_{k+1}. Accurate to a few units in the last place."""
        k = self._index(k)
        with self._lock:
            re_a, im_a, re_b, im_b = call_doubles(lib.hdt_surface_pairing, 4, self._live("pairing"), k, None)
        return complex(re_a, im_a), complex(re_b, im_b)

    def vertex_cycles(self) -> List[List[int]]:
        """The vertex cycles, the sets of polygon vertices that are one point
        of the surface: a list of lists of vertex indices, each increasing,
        the cycles in the order of their smallest vertex."""
        n = self._sides
        cycle = (ctypes.c_int * n)()
        with self._lock:
            count = call_size(lib.hdt_surface_vertex_cycles, self._live("vertex_cycles"), cycle, n)
        cycles: List[List[int]] = [[] for _ in range(count)]
        for vertex, index in enumerate(cycle):
            cycles[index].append(vertex)
        return cycles

    def polygon_text(self) -> str:
        """The polygon as text that :meth:`from_polygon` reads back as the
        same surface (the same pairing, exactly the same coordinates): CGAL's
        format, with the field line first when the coordinates need one."""
        length = ctypes.c_size_t()
        with self._lock:
            handle = self._live("polygon_text")
            check(lib.hdt_surface_polygon_text(handle, None, 0, ctypes.byref(length)))
            buffer = ctypes.create_string_buffer(length.value + 1)
            check(lib.hdt_surface_polygon_text(handle, buffer, length.value + 1, ctypes.byref(length)))
        return buffer.raw[: length.value].decode("utf-8")

    def to_svg(self, size: float = 800) -> str:
        """The polygon drawn in the Poincare disk as SVG text (hdt_surface_svg):
        glued sides in one colour, each labelled "k~j", vertices coloured by
        vertex cycle; size is the width in pixels."""
        length = ctypes.c_size_t()
        with self._lock:
            handle = self._live("to_svg")
            check(lib.hdt_surface_svg(handle, float(size), None, 0, ctypes.byref(length)))
            buffer = ctypes.create_string_buffer(length.value + 1)
            check(lib.hdt_surface_svg(handle, float(size), buffer, length.value + 1, ctypes.byref(length)))
        return buffer.raw[: length.value].decode("utf-8")

    # ---- the group ----

    def systole(self) -> Tuple[float, float]:
        """The systole, certified: (lo, hi) with lo <= sys <= hi, a few units
        in the last place apart, found by a certified walk over the tiles
        near the polygon (computed once, kept). Raises
        :class:`hdt.NotSupported` at once for a walk estimated past 20000
        tiles."""
        lo, hi = ctypes.c_double(), ctypes.c_double()
        with self._lock:
            check(lib.hdt_surface_systole(self._live("systole"), ctypes.byref(lo), ctypes.byref(hi)))
        return lo.value, hi.value

    def neighbour_count(self) -> int:
        """|N|, the group elements h (the identity included) with h(P)
        meeting the polygon P."""
        count = ctypes.c_size_t()
        with self._lock:
            check(lib.hdt_surface_neighbour_count(self._live("neighbour_count"), ctypes.byref(count)))
        return count.value

    def representative(self, x: float, y: float) -> Tuple[Point, Word]:
        """The representative of the disk point (x, y): ((rx, ry), word), the
        word w of the element t = g_{w_0} g_{w_1} ... (letter k the pairing
        of side k) with t(x + iy) in the polygon's half-open fundamental set,
        and t(x + iy) rounded to floats; computed exactly. Raises
        :class:`hdt.OutOfDomain` when (x, y) is not a finite point of the open
        unit disk."""
        rx, ry = ctypes.c_double(), ctypes.c_double()
        with self._lock:
            word = call_word(lib.hdt_surface_representative, self._live("representative"), c_coordinate(x, "x"),
                             c_coordinate(y, "y"), ctypes.byref(rx), ctypes.byref(ry), capacity=32)
        return (rx.value, ry.value), word
