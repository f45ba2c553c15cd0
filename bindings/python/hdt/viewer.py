"""The interactive viewer: a triangulation as one self-contained HTML page.

:func:`html` is :meth:`hdt.Triangulation.to_html`: the template
``viewer.html`` of this package (inline script and style, no network
access) with the data of the triangulation inlined as JSON, the format of
docs/viewer.md. :func:`data_json` writes that JSON text. hdt-triangulate's
``--html`` writes the same page, byte for byte, for the same triangulation,
title and Voronoi choice (bindings/cli/html_writer.c, tested against this
module): keep the two writers in step, number for number.

The JSON is compact, its members in a fixed order, each number written with
the fewest of 15, 16 or 17 significant digits (``%.15g`` .. ``%.17g``) that
reads back as the same double, so that C's printf and Python's % give the
same text.
"""

from __future__ import annotations

import os
from typing import TYPE_CHECKING, Iterable, Optional, Tuple, Union

from ._arrays import Matrix, WordLike, as_lists
from ._errors import NotSupported
from .group import neighbour_words, word_matrix
from .surface import polygon_vertex

if TYPE_CHECKING:  # triangulation imports this module
    from .triangulation import Triangulation

#: The version of the JSON format (its member "version").
FORMAT_VERSION = 1

#: The element of the template that the data replaces, exactly once.
DATA_MARKER = '<script id="hdt-data" type="application/json">null</script>'

_TEMPLATE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "viewer.html")


def template() -> str:
    """The text of the viewer's template (``viewer.html``, which holds no data)."""
    with open(_TEMPLATE, encoding="utf-8", newline="") as file:
        return file.read()


def number(x: float) -> str:
    """x as JSON: the fewest of 15, 16 or 17 significant digits that read
    back as the same double (as html_writer.c writes it)."""
    x = float(x)
    for digits in (15, 16):
        text = "%.*g" % (digits, x)
        if float(text) == x:
            return text
    return "%.17g" % x


def string(text: object) -> str:
    """text as a JSON string that is also safe inside a script element:
    quote, backslash, control characters, ``<``, ``>`` and ``&`` as escapes,
    lone surrogates as '?', everything else as UTF-8 (html_writer.c's rule)."""
    parts = ['"']
    for ch in str(text):
        code = ord(ch)
        if ch == '"':
            parts.append('\\"')
        elif ch == "\\":
            parts.append("\\\\")
        elif code < 0x20 or ch in "<>&":
            parts.append("\\u%04x" % code)
        elif 0xD800 <= code <= 0xDFFF:
            parts.append("?")
        else:
            parts.append(ch)
    parts.append('"')
    return "".join(parts)


def _numbers(values: Iterable[float]) -> str:
    return "[" + ",".join(number(x) for x in values) + "]"


def _ints(values: Iterable[int]) -> str:
    return "[" + ",".join("%d" % int(x) for x in values) + "]"


def _words(words: Iterable[WordLike]) -> str:
    return "[" + ",".join(_ints(word) for word in words) + "]"


def _matrix(pair: Matrix) -> Tuple[float, float, float, float]:
    a, b = pair
    return (a.real, a.imag, b.real, b.imag)


def data_json(triangulation: Triangulation, *, title: Optional[str] = None, voronoi: bool = False) -> str:
    """The viewer's data for the triangulation as JSON text (docs/viewer.md):
    F_g and its generators, the neighbour set N, the vertices, the faces
    with their corners' translations (ids, canonical words, matrices), and
    with voronoi the Voronoi edges. title (plain text, or None for the
    page's default caption) is the page's heading."""
    if triangulation.surface is not None:
        raise NotSupported("the viewer of triangulations of surfaces given by a polygon is not supported yet")
    genus = triangulation.genus
    sides = 4 * genus
    with triangulation._lock:
        ids, points, dummy = (as_lists(value) for value in triangulation.vertices())
        face_vertices, face_translations = (as_lists(value) for value in triangulation.faces())
        used = sorted({t for row in face_translations for t in row})
        translation_words = [triangulation.translation_word(t) for t in used]
        translation_matrices = [_matrix(triangulation.translation_matrix(t)) for t in used]
        segments = as_lists(triangulation.voronoi().edges) if voronoi else None
    polygon = [c for k in range(sides) for c in polygon_vertex(genus, k)]
    generators = [c for k in range(sides) for c in _matrix(word_matrix(genus, [k]))]
    words = neighbour_words(genus)
    neighbour_matrices = [c for word in words for c in _matrix(word_matrix(genus, word))]

    lines = [
        '{"format":"hdt-viewer","version":%d,"genus":%d,"title":%s,' % (
            FORMAT_VERSION, genus, "null" if title is None else string(title)),
        '"polygon":%s,' % _numbers(polygon),
        '"generators":%s,' % _numbers(generators),
        '"neighbours":{"words":%s,"matrices":%s},' % (_words(words), _numbers(neighbour_matrices)),
        '"vertices":{"ids":%s,"xy":%s,"dummy":%s},' % (
            _ints(ids), _numbers(c for point in points for c in point), _ints(1 if d else 0 for d in dummy)),
        '"faces":{"vertices":%s,"translations":%s},' % (
            _ints(v for row in face_vertices for v in row), _ints(t for row in face_translations for t in row)),
        '"translations":{"ids":%s,"words":%s,"matrices":%s},' % (
            _ints(used), _words(translation_words), _numbers(c for m in translation_matrices for c in m)),
        '"voronoi":%s}' % ("null" if segments is None else
                           '{"edges":%s}' % _numbers(c for edge in segments for point in edge for c in point)),
    ]
    return "\n".join(lines)


def fill(template_text: str, data: str) -> str:
    """The page: the template with its data element holding data (JSON text)."""
    if template_text.count(DATA_MARKER) != 1:
        raise ValueError("the viewer's template must hold its data element exactly once")
    head, tail = template_text.split(DATA_MARKER)
    return head + DATA_MARKER.replace(">null<", ">" + data + "<") + tail


def html(triangulation: Triangulation, path: Union[str, os.PathLike, None] = None, *, title: Optional[str] = None,
         voronoi: bool = False) -> str:
    """The viewer page for the triangulation: the same as
    ``triangulation.to_html(path, title=title, voronoi=voronoi)`` (see there)."""
    page = fill(template(), data_json(triangulation, title=title, voronoi=voronoi))
    if path is not None:
        with open(path, "w", encoding="utf-8", newline="") as file:
            file.write(page)
    return page


def iframe(page: str, height: int = 660) -> str:
    """The page inside an iframe (its srcdoc), as a notebook cell shows it:
    the page's script and ids stay in a document of their own."""
    import html as _html

    return ('<iframe srcdoc="%s" style="width: 100%%; height: %dpx; border: 0" '
            'title="libhdt viewer"></iframe>' % (_html.escape(page, quote=True), height))
