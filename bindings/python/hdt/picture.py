"""Pictures of a triangulation in the Poincare disk: SVG text, or matplotlib.

The SVG picture is drawn by libhdt itself (``hdt_svg``, the code the
command-line tool hdt-triangulate uses too): :func:`svg` is
:meth:`hdt.Triangulation.to_svg`, and needs nothing beyond the standard
library.

Both pictures show M_g as the fundamental polygon F_g with its sides paired:
every copy h(T) of a face T that meets F_g (h in the neighbour set N), drawn
with geodesic edges and cut at F_g's sides, so that F_g is tiled exactly and
an edge leaving through one side comes back through the paired one. F_g is
filled lightly and outlined; user vertices are dark dots, dummy vertices
larger red ones, with a dot at each place a vertex has in the closed F_g (a
vertex on a side also on the paired side, one at the corner v_0 at every
corner). Optionally (neighbours=True) the 4g tiles g_k(F_g) across the sides
are drawn too, lighter, each with the triangulation (faces, vertices, and
with voronoi=True the Voronoi edges) cut at it. The caption is wrapped at
spaces (:func:`wrap`) to fit the picture's width.

:func:`plot` (matplotlib) computes the same pieces as the library, with the
same double arithmetic, and cuts them with a matplotlib clip path. Points
are complex numbers x + iy in :func:`moebius` and the geodesic helpers;
:class:`Scene` keeps real (x, y) pairs, as the library does.
"""

from __future__ import annotations

import cmath
import math
from typing import TYPE_CHECKING, Iterable, List, Optional, Sequence, Tuple, cast

from ._arrays import Matrix, Point, as_lists
from ._errors import NotSupported
from .group import neighbour_words, word_matrix
from .surface import polygon_side_midpoint, polygon_vertex

if TYPE_CHECKING:  # for the annotations only: matplotlib is optional, and triangulation imports this module
    import matplotlib.axes

    from .triangulation import Triangulation

#: An SU(1,1) matrix as the library's four doubles (Re a, Im a, Re b, Im b).
RealMatrix = Tuple[float, float, float, float]

# The library's colours (lib/picture/svg.cpp).
DISK_FILL, DISK_EDGE = "#f4f6fb", "#333333"
POLYGON_FILL, POLYGON_EDGE = "#ffd98a", "#c05a00"
FACE_EDGE, NEIGHBOUR_FACE_EDGE, NEIGHBOUR_POLYGON_EDGE = "#1f2a44", "#8a9ac0", "#e0b070"
VORONOI_EDGE, NEIGHBOUR_VORONOI_EDGE = "#2a8a3a", "#8cc498"
USER_VERTEX, DUMMY_VERTEX = "#1f2a44", "#d62728"
NEIGHBOUR_USER_VERTEX, NEIGHBOUR_DUMMY_VERTEX = "#7585b0", "#e89a9b"

# The caption's width estimate (lib/picture/svg.cpp's numbers): the advance
# widths of DejaVu Sans for ' ' to '~', in thousandths of an em, rounded up;
# 1 em for a character beyond ASCII; 5% more for the font's differences.
_ASCII_WIDTH = (
    318, 401, 460, 838, 637, 950, 780, 276, 391, 391, 500, 838, 318, 361, 318, 337,
    637, 637, 637, 637, 637, 637, 637, 637, 637, 637, 337, 337, 838, 838, 838, 531,
    1000, 685, 687, 699, 771, 632, 576, 775, 752, 295, 295, 656, 558, 863, 749, 788,
    604, 788, 695, 635, 611, 732, 685, 989, 686, 611, 686, 391, 337, 391, 838, 500,
    500, 613, 635, 550, 635, 616, 353, 635, 634, 278, 278, 580, 278, 975, 634, 613,
    635, 635, 412, 521, 393, 634, 592, 819, 592, 592, 525, 637, 337, 637, 838)


def text_width(text: str) -> int:
    """The estimated width of the text, in thousandths of an em (generous:
    the SVG picture and plot() wrap their captions with it)."""
    width = 0
    for c in text:
        if c == "\t":
            width += _ASCII_WIDTH[0]
        elif " " <= c <= "~":
            width += _ASCII_WIDTH[ord(c) - 32]
        elif ord(c) < 32:
            width += _ASCII_WIDTH[ord("?") - 32]
        else:
            width += 1000
    return width


def wrap(text: str, width: float, font_size: float) -> List[str]:
    """The text cut at spaces into lines estimated to fit `width` at font
    size `font_size` (in the same unit), as the library wraps its caption:
    at the line's last space after a ',' or ';' if it has one; each line but
    the last keeps its space at its end."""
    limit = width * 1000 / (font_size * 1.05)
    lines: List[str] = []
    start = end = clause = 0
    while end < len(text):
        following = text.find(" ", end + 1)
        if following < 0:
            following = len(text)
        if end > start and text_width(text[start:following]) > limit:
            cut = clause if clause > start else end
            lines.append(text[start:cut + 1])
            start = end = cut + 1
            continue
        end = following
        if end < len(text) and text[end - 1] in ",;":
            clause = end
    if start < len(text) or not lines:
        lines.append(text[start:])
    return lines


def svg(triangulation: Triangulation, *, size: float = 800, dummies: bool = True, neighbours: bool = False,
        title: Optional[str] = None, voronoi: bool = False, side_labels: bool = False) -> str:
    """The picture of the triangulation as the text of an SVG document, drawn
    by libhdt: the same as ``triangulation.to_svg(...)`` (see there)."""
    return triangulation.to_svg(size=size, dummies=dummies, neighbours=neighbours, title=title, voronoi=voronoi,
                                side_labels=side_labels)


def side_label(genus: int, k: int) -> str:
    """The label of side s_k of F_g in the pictures: "g_k" for k < 2g, the
    generator that maps s_{k+2g} onto s_k, and "g_{k-2g}^-1" beyond."""
    return f"g_{k}" if k < 2 * genus else f"g_{k - 2 * genus}^-1"


# ---- Geometry ----

def moebius(matrix: Matrix, z: complex) -> complex:
    """The image of the disk point z (complex) under the SU(1,1) matrix
    (a, b): (a z + b) / (conj(b) z + conj(a))."""
    a, b = matrix
    return (a * z + b) / (b.conjugate() * z + a.conjugate())


def _real_matrix(matrix: Matrix) -> RealMatrix:
    """(a, b) as the library's (Re a, Im a, Re b, Im b)."""
    a, b = matrix
    return (a.real, a.imag, b.real, b.imag)


def _apply(m: RealMatrix, x: float, y: float) -> Point:
    """The library's Moebius map on (x, y), operation for operation (so the
    same doubles): m = (Re a, Im a, Re b, Im b)."""
    ar, ai, br, bi = m
    nr, ni = ar * x - ai * y + br, ar * y + ai * x + bi
    dr, di = br * x + bi * y + ar, br * y - bi * x - ai
    d2 = dr * dr + di * di
    return (nr * dr + ni * di) / d2, (ni * dr - nr * di) / d2


def geodesic(p: complex, q: complex) -> Optional[Tuple[complex, float, bool]]:
    """The geodesic from p to q (complex disk points): None when it is a
    straight segment (p, q and 0 collinear, to rounding), else (centre,
    radius, counterclockwise) of the circle orthogonal to the unit circle
    through p and q, the short arc from p to q turning counterclockwise about
    the centre when the flag is true (the arc is always under a half circle).
    """
    cross = p.real * q.imag - p.imag * q.real
    bp, bq = (1 + abs(p) ** 2) / 2, (1 + abs(q) ** 2) / 2
    if abs(cross) <= 1e-9 * bp * bq:
        return None
    # The centre c solves c.p = (1 + |p|^2) / 2 and c.q = (1 + |q|^2) / 2.
    centre = complex((bp * q.imag - bq * p.imag) / cross, (p.real * bq - q.real * bp) / cross)
    radius = math.sqrt(max(abs(centre) ** 2 - 1, 0.0))
    u, v = p - centre, q - centre
    counterclockwise = u.real * v.imag - u.imag * v.real > 0
    return centre, radius, counterclockwise


def geodesic_points(p: complex, q: complex, step: float = 0.025) -> List[complex]:
    """Points along the geodesic from p to q, p excluded and q included,
    about `step` apart (Euclidean) on arcs; [q] for a segment."""
    arc = geodesic(p, q)
    if arc is None:
        return [q]
    centre, radius, _ = arc
    start = cmath.phase(p - centre)
    turn = (cmath.phase(q - centre) - start + math.pi) % (2 * math.pi) - math.pi  # the short way
    count = max(1, min(64, math.ceil(abs(turn) * radius / step)))
    points = [centre + cmath.rect(radius, start + turn * k / count) for k in range(1, count)]
    points.append(q)
    return points


def geodesic_polygon_points(corners: Sequence[complex], step: float = 0.025) -> List[complex]:
    """The closed geodesic polygon through the corners (complex) as a list
    of points, the first corner first and last."""
    points = [corners[0]]
    for k, corner in enumerate(corners):
        points.extend(geodesic_points(corner, corners[(k + 1) % len(corners)], step))
    return points


class Scene:
    """What a picture shows, read from a triangulation in one go (under its
    lock, so a consistent state), and the pieces the library draws: the
    canonical copies of the faces (3 (x, y) corners each), the vertices'
    representatives, F_g's corners and sides' circles, the generators and
    the neighbour set N as real matrices (Re a, Im a, Re b, Im b)."""

    #: A vertex closer than this (in power) to a side's circle is on it.
    BOUNDARY = 1e-9

    def __init__(self, triangulation: Triangulation, voronoi: bool = False) -> None:
        if triangulation.surface is not None:  # F_g's picture only, so far
            raise NotSupported("pictures of triangulations of surfaces given by a polygon are not supported yet")
        with triangulation._lock:
            #: The Voronoi edges (p, q) as placed by Triangulation.voronoi(), with voronoi.
            self.voronoi = [tuple(tuple(point) for point in edge)
                            for edge in as_lists(triangulation.voronoi().edges)] if voronoi else []
            ids, points, dummy = (as_lists(value) for value in triangulation.vertices())
            face_vertices, face_translations = (as_lists(value) for value in triangulation.faces())
            matrices = {}
            for translation in {t for row in face_translations for t in row} - {0}:
                matrices[translation] = _real_matrix(triangulation.translation_matrix(translation))
            counts = (triangulation.vertex_count, triangulation.dummy_count, triangulation.face_count)
        self.genus = genus = triangulation.genus
        self.vertex_count, self.dummy_count, self.face_count = counts
        point_of = {vertex: (x, y) for vertex, (x, y) in zip(ids, points)}
        #: The canonical copy of each face: three (x, y) corners.
        self.faces = [
            tuple(point_of[v] if t == 0 else _apply(matrices[t], *point_of[v]) for v, t in zip(row, translations))
            for row, translations in zip(face_vertices, face_translations)
        ]
        #: The representatives of the user vertices and of the dummy vertices, by id.
        self.user_points = [point_of[v] for v, d in zip(ids, dummy) if not d]
        self.dummy_points = [point_of[v] for v, d in zip(ids, dummy) if d]
        n = 4 * genus
        #: The corners v_0 .. v_{4g-1} of F_g, as (x, y).
        self.polygon = [polygon_vertex(genus, k) for k in range(n)]
        #: The centres of the circles carrying the sides s_0 .. s_{4g-1}.
        self.side_centres: List[Point] = []
        for k in range(n):
            mx, my = polygon_side_midpoint(genus, k)
            m2 = mx * mx + my * my
            scale = (1 + m2) / (2 * m2)
            self.side_centres.append((mx * scale, my * scale))
        #: The generators g_0 .. g_{4g-1}.
        self.generators = [_real_matrix(word_matrix(genus, [k])) for k in range(n)]
        #: The elements of N by translation id (id 0, the identity, first).
        self.neighbours = [_real_matrix(word_matrix(genus, word)) for word in neighbour_words(genus)]

    def _side_power(self, k: int, x: float, y: float) -> float:
        cx, cy = self.side_centres[k]
        return 1 + x * x + y * y - 2 * (cx * x + cy * y)

    def _may_meet_polygon(self, corners: Sequence[Point]) -> bool:
        for k in range(len(self.side_centres)):
            if all(self._side_power(k, x, y) < 0 for x, y in corners):
                return False
        return True

    def pieces(self, then: Optional[RealMatrix] = None, smallest: float = 0.0) -> List[Tuple[Point, ...]]:
        """The copies h(T), h in N, of the faces' canonical copies T that may
        meet F_g (those with all three corners beyond one side of F_g are
        left out), in the library's order, each then mapped by the real
        matrix `then` when given; with smallest > 0, copies whose corners are
        all within smallest of each other are left out."""
        result = []
        for face in self.faces:
            for h, matrix in enumerate(self.neighbours):
                corners = face if h == 0 else tuple(_apply(matrix, x, y) for x, y in face)
                if not self._may_meet_polygon(corners):
                    continue
                if then is not None:
                    corners = tuple(_apply(then, x, y) for x, y in corners)
                if smallest > 0 and all(math.hypot(corners[a][0] - corners[a - 1][0], corners[a][1] - corners[a - 1][1])
                                        <= smallest for a in range(3)):
                    continue
                result.append(corners)
        return result

    def voronoi_pieces(self, pixel: float = 2.0 / (800 * 0.97),
                       then: Optional[RealMatrix] = None) -> List[Tuple[Point, ...]]:
        """The copies h(e), h in N, of the Voronoi edges that may meet F_g
        (both ends beyond one side of F_g are left out), in the library's
        order; edges shorter than `pixel` are left out, as the library does
        at size 800. With the real matrix `then`, each copy is mapped by it,
        and left out when it is then shorter than `pixel`."""
        result: List[Tuple[Tuple[float, float], ...]] = []
        for p, q in self.voronoi:
            if math.hypot(q[0] - p[0], q[1] - p[1]) <= pixel:
                continue
            for h, matrix in enumerate(self.neighbours):
                ends = cast(Tuple[Tuple[float, float], ...],
                            (p, q) if h == 0 else (_apply(matrix, *p), _apply(matrix, *q)))
                if not self._may_meet_polygon(ends):
                    continue
                if then is not None:
                    ends = (_apply(then, *ends[0]), _apply(then, *ends[1]))
                    if math.hypot(ends[1][0] - ends[0][0], ends[1][1] - ends[0][1]) <= pixel:
                        continue
                result.append(ends)
        return result

    def places(self, point: Point) -> List[Point]:
        """The places of a representative in the closed F_g: itself, and for
        a point on F_g's boundary its images there under N."""
        x, y = point
        found = [point]
        if any(abs(self._side_power(k, x, y)) < self.BOUNDARY for k in range(len(self.side_centres))):
            for matrix in self.neighbours[1:]:
                u, v = _apply(matrix, x, y)
                if all(self._side_power(k, u, v) > -self.BOUNDARY for k in range(len(self.side_centres))):
                    found.append((u, v))
        return found

    def polygon_copy(self, matrix: Optional[RealMatrix] = None) -> List[Point]:
        """The corners of F_g, or of its image under the real matrix."""
        return list(self.polygon) if matrix is None else [_apply(matrix, x, y) for x, y in self.polygon]

    def caption(self, neighbours: bool, dummies: bool = True, voronoi: bool = False, side_labels: bool = False) -> str:
        """The library's default caption, both lines."""
        user = self.vertex_count - self.dummy_count
        if user == 0:
            title = f"The dummy point set of M_{self.genus} and its Delaunay triangulation"
        else:
            title = f"Delaunay triangulation of {user} point{'' if user == 1 else 's'} on M_{self.genus}"
        line = f"{self.vertex_count} vertices"
        if self.dummy_count:
            line += (f" ({self.dummy_count} dumm{'y' if self.dummy_count == 1 else 'ies'}, "
                     f"{'red' if dummies else 'not marked'})")
        line += f", {self.face_count} faces, drawn in F_{self.genus} and cut at its sides"
        if neighbours:
            line += f", and in the {4 * self.genus} tiles across them"
        if voronoi:
            line += "; Voronoi diagram green"
        if side_labels:
            line += "; side s_k labelled g_k: g_k maps s_(k+2g), labelled g_k^-1, onto it"
        return f"{title}\n{line}"


# ---- matplotlib ----

def _complex(points: Iterable[Point]) -> List[complex]:
    return [complex(x, y) for x, y in points]


def _outline(corners: Iterable[Point]) -> List[Point]:
    """The closed geodesic polygon through (x, y) corners as (x, y) points."""
    return [(z.real, z.imag) for z in geodesic_polygon_points(_complex(corners))]


def plot(triangulation: Triangulation, ax: Optional[matplotlib.axes.Axes] = None, *, dummies: bool = True,
         neighbours: bool = False, voronoi: bool = False, side_labels: bool = False) -> matplotlib.axes.Axes:
    """Draws the triangulation on the matplotlib Axes ax (a new figure's when
    None) and returns the Axes: the picture of :func:`svg`, the same pieces
    cut at F_g's sides by a clip path, with geodesic edges drawn as fine
    polylines.

    The artists carry labels ("faces", "vertices", "dummy vertices", "F_g"),
    so ax.legend() explains the picture. Raises ImportError when matplotlib
    is not installed.
    """
    try:
        from matplotlib.collections import LineCollection
        from matplotlib.patches import Circle, Polygon
    except ImportError as error:
        raise ImportError("Triangulation.plot() needs matplotlib (to_svg() does not)", name=error.name) from error
    scene = Scene(triangulation, voronoi)
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=(7, 7))
    line = 0.3 if scene.face_count > 6000 else 0.6
    dot = 0.9 if scene.vertex_count > 3000 else 1.6
    boundary = _outline(scene.polygon)
    ax.add_patch(Circle((0, 0), 1, facecolor=DISK_FILL, edgecolor=DISK_EDGE, linewidth=1.2, zorder=0))
    ax.add_patch(Polygon(boundary, closed=True, facecolor=POLYGON_FILL, alpha=0.35, edgecolor="none", zorder=1))
    if neighbours:
        pixel = 2.0 / (800 * 0.97)  # the library's "below a pixel" at its size 800
        for generator in scene.generators:
            tile = Polygon(_outline(scene.polygon_copy(generator)), closed=True, facecolor="none",
                           edgecolor=NEIGHBOUR_POLYGON_EDGE, linewidth=1.0, zorder=2)
            ax.add_patch(tile)
            faces = LineCollection([_outline(p) for p in scene.pieces(generator, pixel)], colors=NEIGHBOUR_FACE_EDGE,
                                   linewidths=line * 2 / 3, zorder=2)
            ax.add_collection(faces)
            faces.set_clip_path(tile)
            if voronoi:
                cells = LineCollection([[p] + [(z.real, z.imag) for z in geodesic_points(complex(*p), complex(*q))]
                                        for p, q in scene.voronoi_pieces(pixel, generator)],
                                       colors=NEIGHBOUR_VORONOI_EDGE, linewidths=line, zorder=2)
                ax.add_collection(cells)
                cells.set_clip_path(tile)
            kinds = [(scene.user_points, NEIGHBOUR_USER_VERTEX, dot)]
            if dummies:
                kinds.append((scene.dummy_points, NEIGHBOUR_DUMMY_VERTEX, dot + 1))
            for points, colour, size in kinds:
                places = [_apply(generator, *place) for point in points for place in scene.places(point)]
                if places:
                    ax.scatter([x for x, _ in places], [y for _, y in places], s=(1.3 * size * 0.85) ** 2, c=colour,
                               zorder=2)
    clip = Polygon(boundary, closed=True, facecolor="none", edgecolor="none")
    ax.add_patch(clip)
    faces = LineCollection([_outline(p) for p in scene.pieces()], colors=FACE_EDGE, linewidths=line, zorder=3,
                           label="faces")
    ax.add_collection(faces)
    faces.set_clip_path(clip)
    if voronoi:
        cells = LineCollection([[(z.real, z.imag) for z in [complex(*p)] + geodesic_points(complex(*p), complex(*q))]
                                for p, q in scene.voronoi_pieces()], colors=VORONOI_EDGE, linewidths=line * 1.5,
                               zorder=3, label="Voronoi diagram")
        ax.add_collection(cells)
        cells.set_clip_path(clip)
    ax.add_patch(Polygon(boundary, closed=True, facecolor="none", edgecolor=POLYGON_EDGE, linewidth=1.8,
                         alpha=0.85, zorder=4, label=f"F_{scene.genus}"))
    user = [place for point in scene.user_points for place in scene.places(point)]
    if user:
        ax.scatter([x for x, _ in user], [y for _, y in user], s=(1.3 * dot) ** 2, c=USER_VERTEX, zorder=5,
                   label="vertices")
    if dummies and scene.dummy_points:
        places = [place for point in scene.dummy_points for place in scene.places(point)]
        ax.scatter([x for x, _ in places], [y for _, y in places], s=(1.3 * (dot + 1)) ** 2, c=DUMMY_VERTEX, zorder=6,
                   label="dummy vertices")
    if side_labels:
        for k in range(len(scene.polygon)):
            mx, my = polygon_side_midpoint(scene.genus, k)
            m = math.hypot(mx, my)
            ax.text(mx + 0.05 * mx / m, my + 0.05 * my / m, side_label(scene.genus, k), fontsize=8, ha="center",
                    va="center", color=POLYGON_EDGE, zorder=7)
    ax.set_xlim(-1.03, 1.03)
    ax.set_ylim(-1.03, 1.03)
    ax.set_aspect("equal")
    ax.set_axis_off()
    # The caption wrapped to the Axes' width (matplotlib does not wrap it).
    width = ax.figure.get_figwidth() * 72 * ax.get_position().width  # points
    first, second = scene.caption(neighbours, dummies, voronoi, side_labels).split("\n")
    lines = [part.rstrip() for text in (first, second) for part in wrap(text, width, 9)]
    ax.set_title("\n".join(lines), fontsize=9)
    return ax
