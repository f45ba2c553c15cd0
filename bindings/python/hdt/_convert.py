"""Converting Python arguments to C ones and C results back (private).

Every public function goes through these helpers, so that all of them check
types and ranges alike: a value of the wrong type is a TypeError, and an int
that a C parameter cannot hold is reported as the library would report the
value (ctypes itself would silently truncate it).
"""

import ctypes
import math
import numbers
import operator

from ._errors import InternalError, InvalidArgument, NotSupported, Status, check

_INT_BITS = 8 * ctypes.sizeof(ctypes.c_int)
_INT_MIN, _INT_MAX = -(1 << (_INT_BITS - 1)), (1 << (_INT_BITS - 1)) - 1
_INT32_MIN, _INT32_MAX = -(1 << 31), (1 << 31) - 1
_UINT32_MAX = (1 << 32) - 1
_SIZE_MAX = (1 << (8 * ctypes.sizeof(ctypes.c_size_t))) - 1


def as_int(value, what):
    """value as a Python int (anything with __index__); else TypeError."""
    try:
        return operator.index(value)
    except TypeError:
        raise TypeError(f"{what} must be an int, not {type(value).__name__}") from None


def c_genus(genus):
    """A genus for a C int parameter."""
    genus = as_int(genus, "genus")
    if genus > _INT_MAX:
        raise NotSupported(f"genus {genus} does not fit the C int of the ABI")
    if genus < _INT_MIN:
        raise InvalidArgument(f"genus must be at least 2, got {genus}")
    return genus


def c_index(k, genus):
    """A polygon index for a C int parameter; the library takes it mod 4g, so
    an index beyond a C int is reduced mod 4g here (genus from c_genus)."""
    k = as_int(k, "k")
    if not _INT_MIN <= k <= _INT_MAX and genus > 0:
        k %= 4 * genus
    # Still too large only when the genus is, and the library rejects that.
    return k if _INT_MIN <= k <= _INT_MAX else 0


def c_id(translation_id):
    """A translation id for a size_t parameter."""
    translation_id = as_int(translation_id, "id")
    if not 0 <= translation_id <= _SIZE_MAX:
        raise InvalidArgument(f"translation id {translation_id} is not in N")
    return translation_id


def c_vertex(vertex):
    """A vertex id for a uint32_t parameter (an id beyond it is no vertex)."""
    vertex = as_int(vertex, "vertex")
    if not 0 <= vertex <= _UINT32_MAX:
        raise InvalidArgument(f"vertex {vertex} is not a live vertex")
    return vertex


def c_translation(translation_id):
    """A translation id of a triangulation for an int32_t parameter."""
    translation_id = as_int(translation_id, "translation id")
    if not _INT32_MIN <= translation_id <= _INT32_MAX:
        raise InvalidArgument(f"unknown translation id {translation_id}")
    return translation_id


def c_word(word):
    """A word (any iterable of ints) as (int32_t array, length)."""
    try:
        items = list(word)
    except TypeError:
        raise TypeError(f"word must be an iterable of ints, not {type(word).__name__}") from None
    letters = []
    for position, item in enumerate(items):
        letter = as_int(item, f"letter at position {position}")
        if not _INT32_MIN <= letter <= _INT32_MAX:
            raise InvalidArgument(f"letter {letter} at position {position} is outside the range of int32_t")
        letters.append(letter)
    return (ctypes.c_int32 * len(letters))(*letters), len(letters)


def c_coordinate(value, what):
    """A real number for a C double parameter (an int too large for a double
    becomes an infinity, which the library reports as outside the disk)."""
    if not isinstance(value, numbers.Real):
        raise TypeError(f"{what} must be a real number, not {type(value).__name__}")
    try:
        return float(value)
    except OverflowError:
        return math.inf if value > 0 else -math.inf


def call_point(function, *args):
    """function(*args, &x, &y) -> (x, y)."""
    x, y = ctypes.c_double(), ctypes.c_double()
    check(function(*args, ctypes.byref(x), ctypes.byref(y)))
    return x.value, y.value


def call_doubles(function, count, *args):
    """function(*args, double m[count]) -> list of count floats."""
    values = (ctypes.c_double * count)()
    check(function(*args, values))
    return list(values)


def call_size(function, *args):
    """function(*args, &n) -> n."""
    value = ctypes.c_size_t()
    check(function(*args, ctypes.byref(value)))
    return value.value


def call_word(function, *args, capacity=0):
    """function(*args, out, capacity, &out_length) under the two-call pattern
    -> the word as a tuple of ints. capacity is the first call's guess (0 asks
    for the length first); a guess too small costs one more call."""
    for _ in range(2):
        out = (ctypes.c_int32 * capacity)()
        length = ctypes.c_size_t()
        status = function(*args, out, capacity, ctypes.byref(length))
        too_small = status == Status.EBUFS or (status == Status.OK and length.value > capacity)
        if not too_small:
            check(status)
            return tuple(out[: length.value])
        capacity = length.value
    raise InternalError(f"{function.__name__}: the word's length changed between calls (now {capacity})")
