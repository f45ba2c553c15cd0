"""Arrays in and out of the C library, with NumPy or without (private).

NumPy is optional. When it is importable, :data:`numpy` is the module and the
functions that return many numbers (Triangulation.insert_many, .vertices,
.faces) return NumPy arrays that the library wrote into directly; a NumPy
array of points is passed to the library through its own buffer. Without
NumPy, :data:`numpy` is None and the same functions return lists.

Every function here reads :data:`numpy` when it is called, so setting
``hdt._arrays.numpy = None`` (the tests do, with monkeypatch) switches the
whole package to the list path at run time.
"""

from __future__ import annotations

import ctypes
from typing import Any, Iterable, List, Optional, Sequence, Tuple, Union

from ._convert import c_coordinate
from ._errors import InvalidArgument

try:
    import numpy
except ImportError:  # pragma: no cover - depends on the installation
    numpy = None  # type: ignore[assignment]

# The types of the package's annotations, defined once. "numpy.ndarray" is a
# forward reference: annotations naming these types never need NumPy at run
# time (typing.get_type_hints resolves them only given a namespace that holds
# numpy); a type checker without NumPy's stubs takes it as Any.

#: A disk point (x, y).
Point = Tuple[float, float]
#: A word: its letters 0..4g-1 (canonical words come as tuples).
Word = Tuple[int, ...]
#: What a word argument may be: any iterable of ints.
WordLike = Iterable[int]
#: An SU(1,1) matrix [[a, b], [conj b, conj a]] as the pair (a, b).
Matrix = Tuple[complex, complex]
#: Points given to the library: a NumPy array of shape (n, 2), or an
#: iterable of pairs (x, y).
PointsLike = Union["numpy.ndarray", Iterable[Sequence[float]]]
#: One int a row: a NumPy array of shape (n,), or a list of ints.
Ints = Union["numpy.ndarray", List[int]]
#: One float a row: a NumPy float64 array of shape (n,), or a list of floats.
Floats = Union["numpy.ndarray", List[float]]
#: One flag a row: a NumPy bool array of shape (n,), or a list of bools.
Bools = Union["numpy.ndarray", List[bool]]
#: One point a row: a NumPy float64 array of shape (n, 2), or a list of (x, y).
Points = Union["numpy.ndarray", List[Point]]
#: A few ints a row: a NumPy array of shape (n, k), or a list of k-tuples.
IntRows = Union["numpy.ndarray", List[Tuple[int, ...]]]
#: A few points a row: a NumPy float64 array of shape (n, k, 2), or a list of
#: k-tuples of (x, y).
PointRows = Union["numpy.ndarray", List[Tuple[Point, ...]]]
#: A few int tuples a row: a NumPy array of shape (n, k, m), or a list of
#: k-tuples of m-tuples of ints.
IntTupleRows = Union["numpy.ndarray", List[Tuple[Tuple[int, ...], ...]]]

_NUMPY_TYPES = {ctypes.c_double: "float64", ctypes.c_uint32: "uint32", ctypes.c_int32: "int32", ctypes.c_uint8: "uint8",
                ctypes.c_size_t: "uintp"}


def point_buffer(points: PointsLike) -> Tuple[Any, int, Any]:
    """The points as C doubles x0, y0, x1, y1, ...: (pointer, n, owner).

    ``owner`` holds the memory behind the pointer and must be kept alive
    until the C call returns. A NumPy array (when NumPy is in use) must have
    shape (n, 2) and a real dtype; a C-contiguous float64 array is passed as
    it is, any other is converted once with numpy.ascontiguousarray. Anything
    else must be an iterable of pairs (x, y) of real numbers.
    """
    np = numpy
    if np is not None and isinstance(points, np.ndarray):
        if points.dtype.kind not in "fiu":
            raise TypeError(f"points must be an array of real numbers, not of dtype {points.dtype}")
        if points.ndim != 2 or points.shape[1] != 2:
            raise InvalidArgument(f"points must be an array of shape (n, 2), not {points.shape}")
        array = np.ascontiguousarray(points, dtype=np.float64)  # no copy when already so
        return array.ctypes.data_as(ctypes.POINTER(ctypes.c_double)), array.shape[0], array
    try:
        iterator = iter(points)
    except TypeError:
        raise TypeError(f"points must be a sequence of pairs (x, y), not {type(points).__name__}") from None
    flat = []
    for index, point in enumerate(iterator):
        try:
            x, y = point
        except (TypeError, ValueError):
            raise TypeError(f"point {index} must be a pair (x, y), not {point!r}") from None
        flat.append(c_coordinate(x, f"x of point {index}"))
        flat.append(c_coordinate(y, f"y of point {index}"))
    buffer = (ctypes.c_double * len(flat))(*flat)
    return ctypes.cast(buffer, ctypes.POINTER(ctypes.c_double)), len(flat) // 2, buffer


def output(ctype: Any, rows: int, columns: Optional[int] = None) -> Tuple[Any, Any]:
    """A zeroed buffer for rows (x columns) values of a ctypes type: (pointer,
    owner). The owner is a NumPy array when NumPy is in use, else a ctypes
    array; :func:`result` turns it into the public value."""
    np = numpy
    count = rows * (columns or 1)
    if np is not None:
        array = np.zeros((rows, columns) if columns else rows, dtype=_NUMPY_TYPES[ctype])
        return array.ctypes.data_as(ctypes.POINTER(ctype)), array
    buffer = (ctype * count)()
    return ctypes.cast(buffer, ctypes.POINTER(ctype)), buffer


def result(owner: Any, columns: Optional[int] = None) -> Any:
    """The public value of an :func:`output` buffer: the NumPy array itself,
    or a list (of tuples of `columns` values when columns is given)."""
    if not isinstance(owner, ctypes.Array):
        return owner
    values = list(owner)
    if not columns:
        return values
    return [tuple(values[i : i + columns]) for i in range(0, len(values), columns)]


def flags(owner: Any) -> Any:
    """The public value of an :func:`output` buffer of 0/1 bytes: a NumPy
    bool array, or a list of bools."""
    if not isinstance(owner, ctypes.Array):
        return owner.astype(bool)
    return [bool(value) for value in owner]


def as_lists(value: Any) -> List[Any]:
    """A NumPy array (or a list) as nested Python lists of Python numbers."""
    return value.tolist() if hasattr(value, "tolist") else [list(v) if isinstance(v, tuple) else v for v in value]
