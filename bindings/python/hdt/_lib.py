"""Loading libhdt and declaring its C prototypes (private).

The library is looked for, in order:

1. the file named by the environment variable ``HDT_LIBRARY`` (when it is set
   and not empty, nothing else is tried);
2. the libhdt installed together with this package by ``meson install``:
   meson writes the module ``hdt/_installed.py`` (only into an install, never
   into the source tree or a pip install) with the install's libdir, absolute
   and relative to the package; the relative path is tried first, so that a
   copy of the whole install (a DESTDIR, a moved prefix) loads its own
   library. Neither HDT_LIBRARY nor LD_LIBRARY_PATH is needed then, for any
   prefix (outside /usr/local and /usr the package itself needs PYTHONPATH);
3. the SONAME ``libhdt.so.0`` through the dynamic loader (``/usr/local``
   after ``ldconfig``, ``/usr``, ``LD_LIBRARY_PATH``);
4. whatever ``ctypes.util.find_library('hdt')`` names.

A candidate is accepted when it loads, reports ``hdt_abi_version() == 0`` and
exports every function of the table below. Otherwise importing ``hdt`` raises
:class:`LibraryLoadError` (an :class:`ImportError`) that lists what was tried.

Calls into the library release the GIL (ctypes.CDLL). ``insert_many``,
``refine`` and ``epsilon_net`` stop on Ctrl-C (SIGINT) within about 0.05 s,
keeping the points inserted so far, and raise ``KeyboardInterrupt``
(hdt/_interrupt.py). Other calls cannot be interrupted: Python handles
Ctrl-C only when the call has returned, so a long one (``remove_dummies``,
``validate``, ``Triangulation(genus)`` of a large genus) finishes first, its
work done, and ``KeyboardInterrupt`` comes after it.
"""

import ctypes
import ctypes.util
import importlib
import os

#: The ABI these bindings speak: the number of the SONAME libhdt.so.N.
EXPECTED_ABI_VERSION = 0
SONAME = "libhdt.so.0"
ENVIRONMENT_VARIABLE = "HDT_LIBRARY"


class LibraryLoadError(ImportError):
    """libhdt could not be loaded, or is not the ABI these bindings speak."""


_int = ctypes.c_int
_size = ctypes.c_size_t
_status = ctypes.c_int  # hdt_status
_text = ctypes.c_char_p
_double = ctypes.c_double
_double_p = ctypes.POINTER(ctypes.c_double)
_size_p = ctypes.POINTER(ctypes.c_size_t)
_word = ctypes.POINTER(ctypes.c_int32)
_handle = ctypes.c_void_p  # hdt_triangulation *
_surface = ctypes.c_void_p  # hdt_surface *
_surface_p = ctypes.POINTER(ctypes.c_void_p)
_handle_p = ctypes.POINTER(ctypes.c_void_p)
_uint32 = ctypes.c_uint32
_uint32_p = ctypes.POINTER(ctypes.c_uint32)
_int32 = ctypes.c_int32
_int32_p = ctypes.POINTER(ctypes.c_int32)
_int_p = ctypes.POINTER(ctypes.c_int)
_uint64 = ctypes.c_uint64
_uint8_p = ctypes.POINTER(ctypes.c_uint8)
_unsigned = ctypes.c_uint
_char_p = ctypes.POINTER(ctypes.c_char)  # an output buffer of bytes
#: hdt_progress_fn: int (*)(void *user, size_t done, size_t total).
progress_fn = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_size_t, ctypes.c_size_t)

#: Every function of include/hdt.h: name -> (restype, argtypes).
PROTOTYPES = {
    "hdt_status_string": (_text, (_int,)),
    "hdt_last_error_message": (_text, ()),
    "hdt_version_string": (_text, ()),
    "hdt_version": (_int, ()),
    "hdt_abi_version": (_int, ()),
    "hdt_systole": (_double, (_int,)),
    "hdt_polygon_vertex": (_status, (_int, _int, _double_p, _double_p)),
    "hdt_polygon_side_midpoint": (_status, (_int, _int, _double_p, _double_p)),
    "hdt_point_representative": (_status, (_int, _double, _double, _double_p, _double_p, _word, _size, _size_p)),
    "hdt_word_reduce": (_status, (_int, _word, _size, _word, _size, _size_p)),
    "hdt_word_matrix": (_status, (_int, _word, _size, _double_p)),
    "hdt_word_lorentz": (_status, (_int, _word, _size, _double_p)),
    "hdt_word_apply": (_status, (_int, _word, _size, _double, _double, _double_p, _double_p)),
    "hdt_neighbour_count": (_status, (_int, _size_p)),
    "hdt_neighbour_word": (_status, (_int, _size, _word, _size, _size_p)),
    "hdt_create": (_status, (_handle_p, _int)),
    "hdt_destroy": (None, (_handle,)),
    "hdt_genus": (_int, (_handle,)),
    "hdt_insert": (_status, (_handle, _double, _double, _uint32_p)),
    "hdt_insert_many": (_status, (_handle, _double_p, _size, _uint32_p)),
    "hdt_remove_vertex": (_status, (_handle, _uint32)),
    "hdt_remove_dummies": (_status, (_handle, _size_p)),
    "hdt_vertex_count": (_size, (_handle,)),
    "hdt_dummy_count": (_size, (_handle,)),
    "hdt_vertex_id_bound": (_size, (_handle,)),
    "hdt_face_count": (_size, (_handle,)),
    "hdt_vertex_point": (_status, (_handle, _uint32, _double_p, _double_p)),
    "hdt_vertex_is_dummy": (_int, (_handle, _uint32)),
    "hdt_vertices": (_status, (_handle, _uint32_p, _double_p, _uint8_p, _size, _size_p)),
    "hdt_faces": (_status, (_handle, _uint32_p, _int32_p, _size, _size_p)),
    "hdt_translation_word": (_status, (_handle, _int32, _word, _size, _size_p)),
    "hdt_translation_matrix": (_status, (_handle, _int32, _double_p)),
    "hdt_translation_homology": (_status, (_handle, _int32, _int32_p, _size, _size_p)),
    "hdt_locate": (_status, (_handle, _double, _double, _size_p, _int32_p)),
    "hdt_nearest_vertex": (_status, (_handle, _double, _double, _uint32_p)),
    "hdt_validate": (_status, (_handle,)),
    "hdt_svg": (_status, (_handle, _double, _text, _unsigned, _char_p, _size, _size_p)),
    "hdt_save": (_status, (_handle, _char_p, _size, _size_p)),
    "hdt_load": (_status, (_handle_p, _text, _size)),  # bytes passed as they are, no copy
    "hdt_face_neighbours": (_status, (_handle, _uint32_p, _int32_p, _size, _size_p)),
    "hdt_vertex_star": (_status, (_handle, _uint32, _uint32_p, _uint8_p, _int32_p, _size, _size_p)),
    "hdt_edge_count": (_size, (_handle,)),
    "hdt_edges": (_status, (_handle, _uint32_p, _int32_p, _uint32_p, _double_p, _size, _size_p)),
    "hdt_face_points": (_status, (_handle, _double_p, _size, _size_p)),
    "hdt_voronoi_vertices": (_status, (_handle, _double_p, _double_p, _size, _size_p)),
    "hdt_voronoi_edges": (_status, (_handle, _double_p, _size, _size_p)),
    "hdt_voronoi_cell": (_status, (_handle, _uint32, _double_p, _size, _size_p)),
    "hdt_vertex_stars": (_status, (_handle, _size_p, _uint32_p, _uint8_p, _int32_p, _size, _size_p)),
    "hdt_voronoi_cells": (_status, (_handle, _size_p, _double_p, _size, _size_p)),
    "hdt_refine": (_status, (_handle, _double, _double, _size, _size_p, _size_p)),
    "hdt_epsilon_net": (_status, (_handle, _double, _size, _size_p, _size_p)),
    "hdt_quality": (_status, (_handle, _double_p, _double_p, _double_p, _double_p)),
    "hdt_set_progress": (_status, (_handle, progress_fn, ctypes.c_void_p, _double)),
    # Surfaces given by a fundamental polygon (HDT_0.7).
    "hdt_surface_from_polygon": (_status, (_surface_p, _text, _size)),  # bytes passed as they are, no copy
    "hdt_surface_random_symmetric": (_status, (_surface_p, _int, _uint64)),
    "hdt_surface_destroy": (None, (_surface,)),
    "hdt_surface_genus": (_int, (_surface,)),
    "hdt_surface_side_count": (_int, (_surface,)),
    "hdt_surface_vertex": (_status, (_surface, _int, _double_p, _double_p)),
    "hdt_surface_pairing": (_status, (_surface, _int, _int_p, _double_p)),
    "hdt_surface_vertex_cycles": (_status, (_surface, _int_p, _size, _size_p)),
    "hdt_surface_polygon_text": (_status, (_surface, _char_p, _size, _size_p)),
    "hdt_surface_systole": (_status, (_surface, _double_p, _double_p)),
    "hdt_surface_svg": (_status, (_surface, _double, _char_p, _size, _size_p)),
    "hdt_surface_neighbour_count": (_status, (_surface, _size_p)),
    "hdt_surface_representative": (_status, (_surface, _double, _double, _double_p, _double_p, _word, _size,
                                             _size_p)),
    # Triangulations of surfaces given by a polygon (HDT_0.8).
    "hdt_create_on_surface": (_status, (_handle_p, _surface)),
    "hdt_triangulation_surface": (_status, (_handle, _surface_p)),
    "hdt_surface_neighbour_word": (_status, (_surface, _size, _word, _size, _size_p)),
}


#: The module meson generates into an install (bindings/python/meson.build).
INSTALLED_MODULE = "_installed"


def _installed_candidates():
    """The libhdt installed with this package by meson, relative to the
    package first, then at its absolute path; none without hdt/_installed.py."""
    try:
        installed = importlib.import_module(f"{__package__}.{INSTALLED_MODULE}")
    except ImportError:
        return []
    package = os.path.dirname(os.path.abspath(installed.__file__))
    paths = [
        os.path.normpath(os.path.join(package, installed.LIBDIR_FROM_PACKAGE, SONAME)),
        os.path.join(installed.LIBDIR, SONAME),
    ]
    if paths[0] == paths[1]:
        del paths[1]
    return [(f"installed with the package: {path}", path) for path in paths]


def _candidates():
    """(description, name given to the loader) pairs, in the order tried."""
    path = os.environ.get(ENVIRONMENT_VARIABLE)
    if path:
        # A file path: made absolute so that the loader never searches for it.
        return [(f"{ENVIRONMENT_VARIABLE}={path}", os.path.abspath(path))]
    candidates = _installed_candidates()
    candidates.append((f"SONAME {SONAME}", SONAME))
    found = ctypes.util.find_library("hdt")
    if found and found != SONAME:
        candidates.append((f"ctypes.util.find_library('hdt') = {found}", found))
    return candidates


def _open(name):
    """The library loaded from name, its prototypes declared; raises OSError or
    LookupError with the reason when name is not a usable libhdt."""
    library = ctypes.CDLL(name)
    try:
        abi_version = library.hdt_abi_version
    except AttributeError:
        raise LookupError("it does not export hdt_abi_version: not libhdt") from None
    abi_version.restype, abi_version.argtypes = PROTOTYPES["hdt_abi_version"]
    if abi_version() != EXPECTED_ABI_VERSION:
        raise LookupError(f"its ABI version is {abi_version()}, these bindings need {EXPECTED_ABI_VERSION}")
    for function_name, (restype, argtypes) in PROTOTYPES.items():
        try:
            function = getattr(library, function_name)
        except AttributeError:
            raise LookupError(f"it does not export {function_name}: too old for these bindings") from None
        function.restype, function.argtypes = restype, argtypes
    return library


def load():
    """The first usable candidate; LibraryLoadError naming all that were tried."""
    failures = []
    for description, name in _candidates():
        try:
            return _open(name)
        except (OSError, LookupError) as error:
            failures.append(f"  {description}: {error}")
    raise LibraryLoadError(
        f"cannot load libhdt (ABI version {EXPECTED_ABI_VERSION}); tried:\n"
        + "\n".join(failures)
        + f"\nSet {ENVIRONMENT_VARIABLE} to the path of {SONAME}, or install libhdt "
        "where the dynamic loader finds it (after meson install into /usr/local: ldconfig).",
        name="hdt",
    )


lib = load()
