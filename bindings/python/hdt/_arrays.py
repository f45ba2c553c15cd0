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

import ctypes

from ._convert import c_coordinate
from ._errors import InvalidArgument

try:
    import numpy
except ImportError:  # pragma: no cover - depends on the installation
    numpy = None

_NUMPY_TYPES = {ctypes.c_double: "float64", ctypes.c_uint32: "uint32", ctypes.c_int32: "int32", ctypes.c_uint8: "uint8",
                ctypes.c_size_t: "uintp"}


def point_buffer(points):
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


def output(ctype, rows, columns=None):
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


def result(owner, columns=None):
    """The public value of an :func:`output` buffer: the NumPy array itself,
    or a list (of tuples of `columns` values when columns is given)."""
    if not isinstance(owner, ctypes.Array):
        return owner
    values = list(owner)
    if not columns:
        return values
    return [tuple(values[i : i + columns]) for i in range(0, len(values), columns)]


def flags(owner):
    """The public value of an :func:`output` buffer of 0/1 bytes: a NumPy
    bool array, or a list of bools."""
    if not isinstance(owner, ctypes.Array):
        return owner.astype(bool)
    return [bool(value) for value in owner]


def as_lists(value):
    """A NumPy array (or a list) as nested Python lists of Python numbers."""
    return value.tolist() if hasattr(value, "tolist") else [list(v) if isinstance(v, tuple) else v for v in value]
