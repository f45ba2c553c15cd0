"""Versions and the loader (HDT_LIBRARY, the SONAME, clear import errors)."""

import _ctypes
import os
import re
import subprocess
import sys

import pytest

import hdt
from hdt import _lib

PACKAGE_PARENT = os.path.dirname(os.path.dirname(os.path.abspath(hdt.__file__)))

PROBE = """
import sys
try:
    import hdt
except ImportError as error:
    print(type(error).__name__, error.name)
    print(error)
    sys.exit(3)
print("loaded", hdt.version())
"""


def import_hdt(**environment):
    """Imports hdt in a fresh interpreter with the given variables (None
    removes one): (exit code, output)."""
    env = dict(os.environ, PYTHONPATH=PACKAGE_PARENT, PYTHONDONTWRITEBYTECODE="1")
    for key, value in environment.items():
        if value is None:
            env.pop(key, None)
        else:
            env[key] = value
    done = subprocess.run([sys.executable, "-c", PROBE], env=env, capture_output=True, text=True, timeout=60)
    return done.returncode, done.stdout + done.stderr


def test_versions():
    assert re.fullmatch(r"\d+\.\d+\.\d+", hdt.version())
    assert hdt.abi_version() == 0 == _lib.EXPECTED_ABI_VERSION


def test_every_function_has_a_prototype():
    for name, (restype, argtypes) in _lib.PROTOTYPES.items():
        function = getattr(_lib.lib, name)
        assert function.restype is restype and tuple(function.argtypes) == argtypes


def test_a_missing_library_file_is_a_clear_import_error():
    missing = "/nonexistent/libhdt.so.0"
    code, output = import_hdt(HDT_LIBRARY=missing)
    assert code == 3, output
    assert output.startswith("LibraryLoadError hdt\n")
    assert "cannot load libhdt (ABI version 0); tried:" in output
    assert f"HDT_LIBRARY={missing}: " in output
    assert "SONAME" not in output  # an explicit path is the only candidate


def test_a_library_that_is_not_libhdt_is_a_clear_import_error():
    code, output = import_hdt(HDT_LIBRARY=_ctypes.__file__)
    assert code == 3, output
    assert "does not export hdt_abi_version: not libhdt" in output


@pytest.mark.skipif(not os.environ.get("HDT_LIBRARY"), reason="needs HDT_LIBRARY naming a built libhdt")
def test_the_soname_is_found_through_the_dynamic_loader():
    directory = os.path.dirname(os.path.abspath(os.environ["HDT_LIBRARY"]))
    if not os.path.exists(os.path.join(directory, _lib.SONAME)):
        pytest.skip(f"no {_lib.SONAME} beside HDT_LIBRARY")
    code, output = import_hdt(HDT_LIBRARY=None, LD_LIBRARY_PATH=directory)
    assert code == 0, output
    assert output.strip() == f"loaded {hdt.version()}"


class FakeFunction:
    """Stands in for a ctypes function of a fake library."""

    def __init__(self, value=None):
        self.value = value

    def __call__(self, *args):
        return self.value


class FakeLibrary:
    """A library that exports hdt_abi_version (returning abi) and the given names."""

    def __init__(self, abi, names):
        for name in names:
            setattr(self, name, FakeFunction())
        self.hdt_abi_version = FakeFunction(abi)


def fake_loader(monkeypatch, library):
    monkeypatch.setattr(_lib.ctypes, "CDLL", lambda name: library)
    monkeypatch.setenv(_lib.ENVIRONMENT_VARIABLE, "/fake/libhdt.so.0")


def test_another_abi_version_is_a_clear_import_error(monkeypatch):
    fake_loader(monkeypatch, FakeLibrary(1, _lib.PROTOTYPES))
    with pytest.raises(_lib.LibraryLoadError, match="its ABI version is 1, these bindings need 0") as caught:
        _lib.load()
    assert isinstance(caught.value, ImportError) and caught.value.name == "hdt"
    assert "HDT_LIBRARY=/fake/libhdt.so.0: " in str(caught.value)


def test_a_library_without_the_triangulation_functions_is_too_old(monkeypatch):
    names = [name for name in _lib.PROTOTYPES if name != "hdt_nearest_vertex"]
    fake_loader(monkeypatch, FakeLibrary(0, names))
    with pytest.raises(_lib.LibraryLoadError, match="does not export hdt_nearest_vertex: too old for these bindings"):
        _lib.load()


def test_a_complete_library_of_abi_0_is_accepted(monkeypatch):
    library = FakeLibrary(0, _lib.PROTOTYPES)
    fake_loader(monkeypatch, library)
    assert _lib.load() is library
    assert library.hdt_create.restype is _lib.PROTOTYPES["hdt_create"][0]
