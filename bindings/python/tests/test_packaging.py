"""Every module of the package is installed by meson and by pip."""

import os
import re

import pytest

import hdt

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PACKAGE = os.path.dirname(os.path.abspath(hdt.__file__))


def modules():
    """The package's modules, less _installed.py (meson writes it into an install)."""
    return sorted(name for name in os.listdir(PACKAGE) if name.endswith(".py") and name != "_installed.py")


@pytest.mark.skipif(not os.path.exists(os.path.join(SOURCE, "meson.build")), reason="not run from the source tree")
def test_meson_installs_every_module():
    with open(os.path.join(SOURCE, "meson.build"), encoding="utf-8") as file:
        listed = re.findall(r"'hdt/([^'/]+\.py)'", file.read())
    assert sorted(listed) == modules()


def test_every_public_name_has_a_docstring():
    for name in hdt.__all__:
        assert getattr(hdt, name).__doc__, name
    for method_name in dir(hdt.Triangulation):
        if not method_name.startswith("_") or method_name in ("__init__", "__len__", "__enter__", "__exit__"):
            assert getattr(hdt.Triangulation, method_name).__doc__, method_name
    for name in dir(hdt.picture):
        value = getattr(hdt.picture, name)
        if not name.startswith("_") and callable(value) and getattr(value, "__module__", None) == "hdt.picture":
            assert value.__doc__, name
