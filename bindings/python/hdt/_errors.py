"""The status codes of libhdt and the exceptions they become."""

from __future__ import annotations

import enum
from typing import Optional, Union

from ._lib import lib


class Status(enum.IntEnum):
    """The hdt_status codes of include/hdt.h (values pinned forever)."""

    OK = 0
    ERROR = -1
    EINVAL = -2
    EDOMAIN = -3
    EEXISTS = -4
    ENOMEM = -5
    EBUFS = -6
    ENOTSUP = -7
    EINTERNAL = -99


class Error(Exception):
    """A failure reported by libhdt (or found by these bindings before the call).

    Attributes:
        status: the hdt_status code (a :class:`Status`, or the bare int for a
            code these bindings do not know).
        message: the library's detail of the failure (hdt_last_error_message),
            which is also ``str(error)``.
    """

    status: Union[Status, int] = Status.ERROR

    def __init__(self, message: str, status: Union[Status, int, None] = None) -> None:
        super().__init__(message)
        self.message = message
        if status is not None:
            self.status = status


class InvalidArgument(Error, ValueError):
    """HDT_EINVAL: genus < 2, a letter outside 0..4g-1, an id not in N, ..."""

    status = Status.EINVAL


class OutOfDomain(Error, ValueError):
    """HDT_EDOMAIN: a coordinate is NaN, infinite or outside the open unit disk."""

    status = Status.EDOMAIN


class AlreadyExists(Error):
    """HDT_EEXISTS: the point is already a user vertex.

    Attributes:
        vertex: the id of that vertex when the call reported it
            (:meth:`hdt.Triangulation.insert` does), else None.
    """

    status = Status.EEXISTS
    vertex: Optional[int] = None


class OutOfMemory(Error, MemoryError):
    """HDT_ENOMEM: the library ran out of memory."""

    status = Status.ENOMEM


class BufferTooSmall(Error):
    """HDT_EBUFS: an output buffer is too small (the bindings size their
    buffers themselves, so this escapes only if the library misbehaves)."""

    status = Status.EBUFS


class NotSupported(Error):
    """HDT_ENOTSUP: a valid request beyond what this build supports (genus
    above HDT_GENUS_MAX, or above HDT_CREATE_GENUS_MAX for a triangulation, a reduced word of more than 2048 letters needing a run-time precision),
    or a vertex removal refused because the triangulation would lose its
    circumdiameter guarantee (nothing is changed then)."""

    status = Status.ENOTSUP


class InternalError(Error):
    """HDT_EINTERNAL: a broken invariant, a bug in libhdt; please report it."""

    status = Status.EINTERNAL


class HandleClosed(InvalidArgument):
    """A :class:`hdt.Triangulation` or :class:`hdt.Surface` used after its
    close() (the Python side of the library's NULL-handle HDT_EINVAL; never
    passed to the library)."""


_CLASS_OF_STATUS = {
    cls.status: cls
    for cls in (Error, InvalidArgument, OutOfDomain, AlreadyExists, OutOfMemory, BufferTooSmall, NotSupported,
                InternalError)
}


def error_for_status(status):
    """The exception for a failed call's status, with the library's message
    (read at once: it is valid only until the next hdt_* call on this thread)."""
    message = lib.hdt_last_error_message().decode("utf-8", "replace")
    if not message:
        message = lib.hdt_status_string(status).decode("utf-8", "replace")
    try:
        status = Status(status)
    except ValueError:
        pass  # a code newer than these bindings: keep the bare int
    return _CLASS_OF_STATUS.get(status, Error)(message, status)


def check(status):
    """Raises the exception for status unless it is HDT_OK."""
    if status != Status.OK:
        raise error_for_status(status)
