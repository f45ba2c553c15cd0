"""The type hints of the package (PEP 484, PEP 561), checked with the
standard library: every public function, method and property is annotated
(a new unannotated one fails here), the hints resolve, py.typed is in the
package, and mypy, where it is installed, finds no errors."""

import enum
import importlib
import inspect
import os
import re
import subprocess
import sys
import typing

import pytest

import hdt

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PACKAGE = os.path.dirname(os.path.abspath(hdt.__file__))

#: The modules whose public callables must be annotated (hdt: its re-exports).
MODULES = ("hdt", "hdt.triangulation", "hdt.surface", "hdt.group", "hdt.library", "hdt.picture", "hdt.fem",
           "hdt.mesh", "hdt.sampling", "hdt.viewer", "hdt._errors")

#: Modules whose functions are internal (the package's own helpers): their classes only.
CLASSES_ONLY = ("hdt._errors",)

#: Optional packages the annotations name, with the module to import for it.
OPTIONAL = {"numpy": "numpy", "scipy": "scipy.sparse", "matplotlib": "matplotlib.axes", "meshio": "meshio"}

#: Dunder methods are public too when a class defines them itself.
PRIVATE = re.compile(r"^_(?!_.*__$)")


def namespace():
    """What the annotations name beyond their modules' globals: the names the
    modules import for type checkers only (under typing.TYPE_CHECKING), and
    the optional packages that are importable; and the set of those that are
    not."""
    names = {"Triangulation": hdt.Triangulation}
    missing = set()
    for name, module in OPTIONAL.items():
        try:
            importlib.import_module(module)
        except ImportError:
            missing.add(name)
        else:
            names[name] = sys.modules[name]
    return names, missing


def is_named_tuple(value):
    return isinstance(value, type) and issubclass(value, tuple) and hasattr(value, "_fields")


def public_callables():
    """(qualified name, function or class) for every public function, every
    method and property defined in a public class (named tuples: the class,
    for its fields), of MODULES (of CLASSES_ONLY, the classes)."""
    found, seen = [], set()

    def add(name, value):
        if id(value) not in seen:
            seen.add(id(value))
            found.append((name, value))

    for module_name in MODULES:
        module = importlib.import_module(module_name)
        names = getattr(module, "__all__", None) or [name for name in vars(module) if not PRIVATE.match(name)]
        for name in names:
            value = getattr(module, name)
            if module_name != "hdt" and getattr(value, "__module__", None) != module_name:
                continue  # imported from elsewhere (typing, the standard library, another module)
            if inspect.isfunction(value) and module_name not in CLASSES_ONLY:
                add(f"{value.__module__}.{value.__qualname__}", value)
            elif is_named_tuple(value):
                add(f"{value.__module__}.{value.__qualname__}", value)
            elif isinstance(value, type):
                for attribute, raw in vars(value).items():
                    if PRIVATE.match(attribute):
                        continue
                    if isinstance(raw, property):
                        functions = [f for f in (raw.fget, raw.fset, raw.fdel) if f is not None]
                    elif isinstance(raw, (classmethod, staticmethod)):
                        functions = [raw.__func__]
                    elif inspect.isfunction(raw):
                        functions = [raw]
                    else:
                        continue
                    for function in functions:
                        if function.__module__ == value.__module__:  # not one that enum or the like added
                            add(f"{value.__module__}.{function.__qualname__}", function)
    return found


def resolve(name, value):
    """typing.get_type_hints of value, or None when they name an optional
    package that is not installed."""
    extra, missing = namespace()
    module = sys.modules[value.__module__]
    try:
        return typing.get_type_hints(value, globalns=dict(vars(module), **extra))
    except NameError as error:
        match = re.search(r"name '(\w+)' is not defined", str(error))
        if match and match.group(1) in missing:
            return None
        raise AssertionError(f"{name}: a hint does not resolve: {error}") from error


def test_every_public_name_imports():
    for name in hdt.__all__:
        assert getattr(hdt, name) is not None, name


def test_the_walk_finds_the_api():
    names = {name for name, _ in public_callables()}
    for expected in ("hdt.triangulation.Triangulation.insert_many", "hdt.triangulation.Triangulation.genus",
                     "hdt.triangulation.Triangulation.from_bytes", "hdt.triangulation.Triangulation.__init__",
                     "hdt.triangulation.Quality", "hdt.group.word_matrix", "hdt.picture.Scene.pieces",
                     "hdt.fem.p1_matrices", "hdt.fem.P1Matrices", "hdt._errors.Error.__init__", "hdt.viewer.html"):
        assert expected in names


def test_every_public_callable_is_annotated():
    unannotated = []
    for name, value in public_callables():
        if is_named_tuple(value):
            annotations = vars(value).get("__annotations__", {})
            missing = [field for field in value._fields if field not in annotations]
        else:
            annotations = value.__annotations__
            missing = [parameter for parameter in inspect.signature(value).parameters
                       if parameter not in ("self", "cls") and parameter not in annotations]
            if "return" not in annotations:
                missing.append("return")
        if missing:
            unannotated.append(f"{name}: {', '.join(missing)}")
    assert not unannotated, "not annotated:\n" + "\n".join(unannotated)


def test_every_hint_resolves():
    skipped = []
    for name, value in public_callables():
        hints = resolve(name, value)
        if hints is None:
            skipped.append(name)
        elif is_named_tuple(value):
            assert set(hints) == set(value._fields), name
    _, missing = namespace()
    assert not skipped or missing, skipped  # only an optional package that is not installed skips a name


def test_array_hints_allow_both_forms():
    """The methods returning many numbers are annotated with NumPy's array or
    the list form (numpy is not needed to import the package)."""
    hints = resolve("insert_many", hdt.Triangulation.insert_many)
    if hints is None:
        pytest.skip("numpy is not installed: its hints are not resolved")
    import numpy

    assert typing.get_args(hints["return"])[0] is numpy.ndarray
    assert typing.List[int] in typing.get_args(hints["return"])


def test_quality_min_angle_is_in_radians():
    assert "radians" in hdt.Quality.__doc__ and "radians" in hdt.Quality.min_angle.__doc__
    assert typing.get_type_hints(hdt.Quality)["min_angle"] is float


def test_named_tuples_are_still_tuples():
    import pickle

    for name in ("Vertices", "Faces", "Neighbours", "Star", "Stars", "Cells", "Edges", "Voronoi", "Refined",
                 "Quality", "Location"):
        cls = getattr(hdt, name)
        values = tuple(range(len(cls._fields)))
        value = cls(*values)
        assert value == values and isinstance(value, tuple) and cls.__module__ == "hdt.triangulation"
        assert pickle.loads(pickle.dumps(value)) == value and type(pickle.loads(pickle.dumps(value))) is cls


def test_status_is_an_int_enum():
    assert issubclass(hdt.Status, enum.IntEnum)


def test_py_typed_is_in_the_package():
    assert os.path.isfile(os.path.join(PACKAGE, "py.typed"))


@pytest.mark.skipif(not os.path.exists(os.path.join(SOURCE, "meson.build")), reason="not run from the source tree")
def test_py_typed_is_installed_by_meson_and_pip():
    with open(os.path.join(SOURCE, "meson.build"), encoding="utf-8") as file:
        assert "'hdt/py.typed'" in file.read()
    with open(os.path.join(SOURCE, "pyproject.toml"), encoding="utf-8") as file:
        package_data = re.search(r"^hdt = \[(.*)\]", file.read(), re.M)
    assert package_data and '"py.typed"' in package_data.group(1)


def test_mypy_finds_no_errors(tmp_path):
    probe = subprocess.run([sys.executable, "-m", "mypy", "--version"], stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT)
    if probe.returncode != 0:
        pytest.skip(f"mypy is not installed for {sys.executable} (python3 -m mypy): the hints are not type-checked")
    result = subprocess.run([sys.executable, "-m", "mypy", "--ignore-missing-imports", "--cache-dir",
                             str(tmp_path / "cache"), "-p", "hdt"], cwd=os.path.dirname(PACKAGE),
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
    assert result.returncode == 0, result.stdout
