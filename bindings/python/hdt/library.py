"""Versions of the loaded libhdt."""

from __future__ import annotations

from ._lib import lib


def version() -> str:
    """The version of the loaded libhdt as the string "MAJOR.MINOR.PATCH"."""
    return lib.hdt_version_string().decode("ascii")


def abi_version() -> int:
    """The ABI version of the loaded libhdt: the N of its SONAME libhdt.so.N
    (always 0 here, as the loader checks it)."""
    return lib.hdt_abi_version()
