"""Python bindings of libhdt: Delaunay triangulations of the symmetric
hyperbolic surfaces M_g.

:class:`Triangulation` (module :mod:`hdt.triangulation`) holds a point set on
M_g and its Delaunay triangulation; :mod:`hdt.picture` draws one (SVG, or
matplotlib); :mod:`hdt.surface` and :mod:`hdt.group` give the polygon F_g,
the systole and words in the group Gamma_g; :class:`Surface` (also in
:mod:`hdt.surface`) is a surface given by any fundamental polygon. NumPy
is optional: with it, methods returning many numbers return NumPy arrays,
without it lists.

A pure-Python ctypes package over the C ABI of include/hdt.h. The library is
found through the environment variable HDT_LIBRARY (a file path), else by its
SONAME libhdt.so.0; importing fails with an ImportError saying what was tried
when neither gives a libhdt of ABI version 0.

Conventions follow the C library: indices are 0-based and taken mod 4g; a
word is an iterable of letters 0..4g-1 (letter k is the generator g_k, letter
k+2g its inverse) read as the product g_k1 g_k2 ... g_km. A failed call raises
a subclass of :class:`hdt.Error` that carries the status code and the
library's message.
"""

from ._errors import (
    AlreadyExists,
    BufferTooSmall,
    Error,
    HandleClosed,
    InternalError,
    InvalidArgument,
    NotSupported,
    OutOfDomain,
    OutOfMemory,
    Status,
)
from . import fem  # P1 finite elements; needs NumPy and SciPy only when called
from .group import (
    neighbour_count,
    neighbour_word,
    neighbour_words,
    reduce_word,
    word_apply,
    word_lorentz,
    word_matrix,
)
from .library import abi_version, version
from .sampling import random_points
from .surface import Surface, point_representative, polygon_side_midpoint, polygon_vertex, systole
from .triangulation import (Cells, Edges, Faces, Location, Neighbours, Quality, Refined, Star, Stars, Triangulation,
                            Vertices, Voronoi)

#: The version of these bindings (the library's is version()).
__version__ = "0.8.0"

__all__ = [
    "AlreadyExists",
    "BufferTooSmall",
    "Cells",
    "Edges",
    "Error",
    "Faces",
    "HandleClosed",
    "InternalError",
    "InvalidArgument",
    "Location",
    "Neighbours",
    "NotSupported",
    "OutOfDomain",
    "OutOfMemory",
    "Quality",
    "Refined",
    "Star",
    "Stars",
    "Status",
    "Surface",
    "Triangulation",
    "Vertices",
    "Voronoi",
    "abi_version",
    "neighbour_count",
    "neighbour_word",
    "neighbour_words",
    "point_representative",
    "random_points",
    "polygon_side_midpoint",
    "polygon_vertex",
    "reduce_word",
    "systole",
    "version",
    "word_apply",
    "word_lorentz",
    "word_matrix",
]
