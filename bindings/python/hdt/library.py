"""Versions of the loaded libhdt."""

from ._lib import lib


def version():
    """The version of the loaded libhdt as the string "MAJOR.MINOR.PATCH"."""
    return lib.hdt_version_string().decode("ascii")


def abi_version():
    """The ABI version of the loaded libhdt: the N of its SONAME libhdt.so.N
    (always 0 here, as the loader checks it)."""
    return lib.hdt_abi_version()
