"""The loader finds the libhdt installed with the package (hdt/_installed.py,
written by meson into an install) before the dynamic loader's search."""

import os
import shutil
import subprocess
import sys
import types

import pytest

import hdt
from hdt import _lib

PACKAGE = os.path.dirname(os.path.abspath(hdt.__file__))
MODULE = f"hdt.{_lib.INSTALLED_MODULE}"


def fake_installed(monkeypatch, package, libdir, libdir_from_package):
    """hdt._installed as meson writes it, for a package in directory package."""
    module = types.ModuleType(MODULE)
    module.__file__ = os.path.join(package, _lib.INSTALLED_MODULE + ".py")
    module.LIBDIR = libdir
    module.LIBDIR_FROM_PACKAGE = libdir_from_package
    monkeypatch.setitem(sys.modules, MODULE, module)


def names(candidates):
    return [name for _, name in candidates]


def test_without_an_install_the_loader_searches(monkeypatch):
    monkeypatch.delenv(_lib.ENVIRONMENT_VARIABLE, raising=False)
    if os.path.exists(os.path.join(PACKAGE, _lib.INSTALLED_MODULE + ".py")):
        pytest.skip("run on an installed package")
    assert names(_lib._candidates())[0] == _lib.SONAME


def test_the_installed_library_comes_first_relative_then_absolute(monkeypatch):
    monkeypatch.delenv(_lib.ENVIRONMENT_VARIABLE, raising=False)
    fake_installed(monkeypatch, "/staged/opt/x/lib/python3/dist-packages/hdt", "/opt/x/lib", "../../..")
    found = names(_lib._candidates())
    assert found[:3] == ["/staged/opt/x/lib/libhdt.so.0", "/opt/x/lib/libhdt.so.0", _lib.SONAME]


def test_one_candidate_when_the_install_was_not_moved(monkeypatch):
    monkeypatch.delenv(_lib.ENVIRONMENT_VARIABLE, raising=False)
    fake_installed(monkeypatch, "/opt/x/lib/python3/dist-packages/hdt", "/opt/x/lib", "../../..")
    found = names(_lib._candidates())
    assert found[:2] == ["/opt/x/lib/libhdt.so.0", _lib.SONAME]


def test_hdt_library_still_wins(monkeypatch):
    monkeypatch.setenv(_lib.ENVIRONMENT_VARIABLE, "/elsewhere/libhdt.so.0")
    fake_installed(monkeypatch, "/opt/x/lib/python3/dist-packages/hdt", "/opt/x/lib", "../../..")
    assert names(_lib._candidates()) == ["/elsewhere/libhdt.so.0"]


def test_a_missing_installed_library_is_named_in_the_import_error(monkeypatch):
    monkeypatch.delenv(_lib.ENVIRONMENT_VARIABLE, raising=False)
    fake_installed(monkeypatch, "/nonexistent/lib/python3/dist-packages/hdt", "/nonexistent/lib", "../../..")
    monkeypatch.setattr(_lib, "_open", lambda name: (_ for _ in ()).throw(OSError(f"{name}: cannot open")))
    with pytest.raises(_lib.LibraryLoadError) as caught:
        _lib.load()
    assert "installed with the package: /nonexistent/lib/libhdt.so.0" in str(caught.value)


@pytest.mark.skipif(not os.environ.get("HDT_LIBRARY"), reason="needs HDT_LIBRARY naming a built libhdt")
def test_an_install_layout_loads_its_library_without_any_variable(tmp_path):
    """A prefix as meson lays it out: the package in lib/python3/dist-packages,
    the library in lib/x86_64-linux-gnu; imported with neither HDT_LIBRARY nor
    LD_LIBRARY_PATH, from a moved copy of the prefix."""
    prefix = tmp_path / "moved-prefix"
    site = prefix / "lib" / "python3" / "dist-packages"
    libdir = prefix / "lib" / "x86_64-linux-gnu"
    shutil.copytree(PACKAGE, site / "hdt", ignore=shutil.ignore_patterns("__pycache__", "_installed.py"))
    libdir.mkdir(parents=True)
    shutil.copy(os.path.realpath(os.environ["HDT_LIBRARY"]), libdir / _lib.SONAME)
    (site / "hdt" / "_installed.py").write_text(
        "LIBDIR = '/nonexistent/original-prefix/lib/x86_64-linux-gnu'\n"
        "LIBDIR_FROM_PACKAGE = '../../../x86_64-linux-gnu'\n"
    )
    env = {key: value for key, value in os.environ.items() if key not in ("HDT_LIBRARY", "LD_LIBRARY_PATH")}
    env.update(PYTHONPATH=str(site), PYTHONDONTWRITEBYTECODE="1")
    done = subprocess.run(
        [sys.executable, "-c", "import hdt; print(hdt._lib.lib._name); print(hdt.Triangulation(2))"],
        env=env,
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert done.returncode == 0, done.stdout + done.stderr
    loaded, triangulation = done.stdout.splitlines()
    assert loaded == str(libdir / _lib.SONAME)
    assert triangulation.startswith("<hdt.Triangulation genus=2 ")
