"""Pictures of a triangulation in the Poincare disk: SVG text, or matplotlib.

Each face is drawn once, as its canonical copy: corner c of face i is the
representative of vertex ``faces().vertices[i][c]`` moved by the Moebius map
of ``faces().translations[i][c]``. Edges are hyperbolic geodesics: arcs of
circles orthogonal to the unit circle, or segments through the origin. The
fundamental polygon F_g is filled lightly and outlined; user vertices are
dark dots, dummy vertices larger red ones. Optionally (neighbours=True) the
copies of F_g and of the faces under the 4g generators g_k are drawn too,
lighter.

:func:`svg` needs nothing beyond the standard library; :func:`plot` needs
matplotlib. Points are complex numbers x + iy throughout this module.
"""

import cmath
import math
from xml.sax.saxutils import escape

from ._arrays import as_lists
from .group import word_matrix
from .surface import polygon_vertex

# Colours of the C demo (examples/triangulate_demo.c), so both pictures match.
DISK_FILL, DISK_EDGE = "#f4f6fb", "#333333"
POLYGON_FILL, POLYGON_EDGE = "#ffd98a", "#c05a00"
FACE_EDGE, NEIGHBOUR_FACE_EDGE, NEIGHBOUR_POLYGON_EDGE = "#1f2a44", "#9aa8c8", "#e0b070"
USER_VERTEX, DUMMY_VERTEX = "#1f2a44", "#d62728"


def moebius(matrix, z):
    """The image of the disk point z (complex) under the SU(1,1) matrix
    (a, b): (a z + b) / (conj(b) z + conj(a))."""
    a, b = matrix
    return (a * z + b) / (b.conjugate() * z + a.conjugate())


def geodesic(p, q):
    """The geodesic from p to q (complex disk points): None when it is a
    straight segment (p, q and 0 collinear, to rounding), else (centre,
    radius, counterclockwise) of the circle orthogonal to the unit circle
    through p and q, the short arc from p to q turning counterclockwise about
    the centre when the flag is true (the arc is always under a half circle).
    """
    cross = p.real * q.imag - p.imag * q.real
    scale = (1 + abs(p) ** 2) * (1 + abs(q) ** 2)
    if abs(cross) <= 1e-9 * scale:
        return None
    # The centre c solves c.p = (1 + |p|^2) / 2 and c.q = (1 + |q|^2) / 2.
    bp, bq = (1 + abs(p) ** 2) / 2, (1 + abs(q) ** 2) / 2
    centre = complex((bp * q.imag - bq * p.imag) / cross, (p.real * bq - q.real * bp) / cross)
    radius = math.sqrt(max(abs(centre) ** 2 - 1, 0.0))
    u, v = p - centre, q - centre
    counterclockwise = u.real * v.imag - u.imag * v.real > 0
    return centre, radius, counterclockwise


def geodesic_points(p, q, step=0.025):
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


def geodesic_polygon_points(corners, step=0.025):
    """The closed geodesic polygon through the corners as a list of points,
    the first corner first and last."""
    points = [corners[0]]
    for k, corner in enumerate(corners):
        points.extend(geodesic_points(corner, corners[(k + 1) % len(corners)], step))
    return points


class Scene:
    """What a picture shows, read from a triangulation in one go (under its
    lock, so a consistent state): the genus, the corners of F_g, the
    canonical copy of every face (3 complex corners), the user and dummy
    vertices' representatives, and the generators' matrices (for the
    neighbouring copies)."""

    def __init__(self, triangulation):
        with triangulation._lock:
            ids, points, dummy = (as_lists(value) for value in triangulation.vertices())
            face_vertices, face_translations = (as_lists(value) for value in triangulation.faces())
            matrices = {}
            for translation in {t for row in face_translations for t in row}:
                matrices[translation] = triangulation.translation_matrix(translation)
            counts = (triangulation.vertex_count, triangulation.dummy_count, triangulation.face_count)
        self.genus = genus = triangulation.genus
        self.vertex_count, self.dummy_count, self.face_count = counts
        point_of = {vertex: complex(x, y) for vertex, (x, y) in zip(ids, points)}
        #: The canonical copy of each face: three complex corners.
        self.faces = [
            tuple(point_of[v] if t == 0 else moebius(matrices[t], point_of[v]) for v, t in zip(row, translations))
            for row, translations in zip(face_vertices, face_translations)
        ]
        #: The representatives of the user vertices and of the dummy vertices.
        self.user_points = [point_of[v] for v, d in zip(ids, dummy) if not d]
        self.dummy_points = [point_of[v] for v, d in zip(ids, dummy) if d]
        #: The corners v_0 .. v_{4g-1} of F_g.
        self.polygon = [complex(*polygon_vertex(genus, k)) for k in range(4 * genus)]
        #: The matrices of the generators g_0 .. g_{4g-1}.
        self.generators = [word_matrix(genus, [k]) for k in range(4 * genus)]

    def neighbour_polygons(self):
        """The images of F_g under the generators (lists of corners)."""
        return [[moebius(h, z) for z in self.polygon] for h in self.generators]

    def neighbour_faces(self, smallest=0.0):
        """The images of the faces' canonical copies under the generators,
        leaving out those whose sides are all shorter than `smallest`."""
        images = []
        for h in self.generators:
            for face in self.faces:
                image = tuple(moebius(h, z) for z in face)
                if max(abs(image[k] - image[k - 1]) for k in range(3)) > smallest:
                    images.append(image)
        return images

    def caption(self, neighbours, dummies=True, separator="; "):
        """The default caption: the counts, separator, what is drawn."""
        dummies = f" ({self.dummy_count} dummies{' in red' if dummies else ''})" if self.dummy_count else ""
        extra = " and their images under the generators" if neighbours else ""
        return (f"Delaunay triangulation on M_{self.genus}: {self.vertex_count} vertices{dummies}, "
                f"{self.face_count} faces{separator}canonical copies{extra}, F_{self.genus} outlined")


# ---- SVG ----

class _SvgCanvas:
    """Disk coordinates to SVG ones (y down) and path data in SVG syntax."""

    def __init__(self, size, top):
        self.size, self.top = size, top
        self.scale = size / 2 * 0.97  # the unit circle's radius in pixels

    def x(self, z):
        """The SVG x of the disk point z."""
        return self.size / 2 + self.scale * z.real

    def y(self, z):
        """The SVG y of the disk point z."""
        return self.top + self.size / 2 - self.scale * z.imag

    def polygon(self, corners):
        """Path data of the closed geodesic polygon through the corners: one
        exact SVG arc (or line) per side."""
        parts = [f"M{self.x(corners[0]):.2f} {self.y(corners[0]):.2f}"]
        for k, p in enumerate(corners):
            q = corners[(k + 1) % len(corners)]
            arc = geodesic(p, q)
            if arc is None:
                parts.append(f"L{self.x(q):.2f} {self.y(q):.2f}")
            else:
                _, radius, counterclockwise = arc
                r = radius * self.scale
                # Counterclockwise in the disk is clockwise with y down: sweep flag 0.
                parts.append(f"A{r:.2f} {r:.2f} 0 0 {0 if counterclockwise else 1} {self.x(q):.2f} {self.y(q):.2f}")
        parts.append("Z")
        return "".join(parts)

    def polygons(self, polygons):
        """Path data of many closed geodesic polygons, eight to a line."""
        lines = []
        for start in range(0, len(polygons), 8):
            lines.append("".join(self.polygon(corners) for corners in polygons[start : start + 8]))
        return "\n".join(lines)


def svg(triangulation, *, size=800, dummies=True, neighbours=False, title=None):
    """The picture of the triangulation as the text of an SVG document.

    size: the width in pixels (the disk's square, with a caption band
    above). dummies: mark the dummy vertices (red, larger); the faces around
    them are drawn either way. neighbours: also draw the copies of F_g and of
    the faces under the 4g generators. title: the caption (default: the
    counts). Needs only the standard library.
    """
    size = float(size)
    if not size > 0 or math.isinf(size):
        raise ValueError(f"size must be a positive number of pixels, not {size}")
    scene = Scene(triangulation)
    top = 56.0 * size / 800
    canvas = _SvgCanvas(size, top)
    height = size + top
    centre = complex(0, 0)
    caption = scene.caption(neighbours, dummies) if title is None else str(title)
    lines = [
        '<?xml version="1.0" encoding="UTF-8"?>',
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{size:g}" height="{height:g}" '
        f'viewBox="0 0 {size:g} {height:g}">',
        f"<title>{escape(caption)}</title>",
        '<rect width="100%" height="100%" fill="white"/>',
        f'<circle cx="{canvas.x(centre):.2f}" cy="{canvas.y(centre):.2f}" r="{canvas.scale:.2f}" '
        f'fill="{DISK_FILL}" stroke="{DISK_EDGE}" stroke-width="1.5"/>',
        f'<path fill="{POLYGON_FILL}" fill-opacity="0.35" stroke="none" d="{canvas.polygon(scene.polygon)}"/>',
    ]
    if neighbours:
        pixel = 2 / canvas.scale
        lines += [
            '<g fill="none" stroke-linejoin="round">',
            f'<path stroke="{NEIGHBOUR_POLYGON_EDGE}" stroke-width="0.8" '
            f'd="{canvas.polygons(scene.neighbour_polygons())}"/>',
            f'<path stroke="{NEIGHBOUR_FACE_EDGE}" stroke-width="0.4" '
            f'd="{canvas.polygons(scene.neighbour_faces(smallest=pixel))}"/>',
            "</g>",
        ]
    lines += [
        f'<path fill="none" stroke="{FACE_EDGE}" stroke-width="0.6" stroke-linejoin="round" '
        f'd="{canvas.polygons(scene.faces)}"/>',
        f'<path fill="none" stroke="{POLYGON_EDGE}" stroke-width="1.8" stroke-opacity="0.85" '
        f'd="{canvas.polygon(scene.polygon)}"/>',
        f'<g fill="{USER_VERTEX}">',
    ]
    lines += [f'<circle cx="{canvas.x(z):.2f}" cy="{canvas.y(z):.2f}" r="1.6"/>' for z in scene.user_points]
    lines.append("</g>")
    if dummies:
        lines.append(f'<g fill="{DUMMY_VERTEX}">')
        lines += [f'<circle cx="{canvas.x(z):.2f}" cy="{canvas.y(z):.2f}" r="2.6"/>' for z in scene.dummy_points]
        lines.append("</g>")
    lines.append(f'<text x="12" y="{top * 0.5:.1f}" font-family="sans-serif" font-size="{max(8.0, top * 0.26):.1f}">'
                 f"{escape(caption)}</text>")
    lines.append("</svg>")
    return "\n".join(lines) + "\n"


# ---- matplotlib ----

def _xy(points):
    """Complex points as a list of (x, y) pairs."""
    return [(z.real, z.imag) for z in points]


def plot(triangulation, ax=None, *, dummies=True, neighbours=False):
    """Draws the triangulation on the matplotlib Axes ax (a new figure's when
    None) and returns the Axes; the picture of :func:`svg`, with geodesic
    edges drawn as fine polylines.

    The collections carry labels ("faces", "vertices", "dummy vertices",
    "F_g"), so ax.legend() explains the picture. Raises ImportError when
    matplotlib is not installed.
    """
    try:
        from matplotlib.collections import LineCollection
        from matplotlib.patches import Circle, Polygon
    except ImportError as error:
        raise ImportError("Triangulation.plot() needs matplotlib (to_svg() does not)", name=error.name) from error
    scene = Scene(triangulation)
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=(7, 7))
    boundary = _xy(geodesic_polygon_points(scene.polygon))
    ax.add_patch(Circle((0, 0), 1, facecolor=DISK_FILL, edgecolor=DISK_EDGE, linewidth=1.2, zorder=0))
    ax.add_patch(Polygon(boundary, closed=True, facecolor=POLYGON_FILL, alpha=0.35, edgecolor="none", zorder=1))
    if neighbours:
        ax.add_collection(LineCollection([_xy(geodesic_polygon_points(p)) for p in scene.neighbour_polygons()],
                                         colors=NEIGHBOUR_POLYGON_EDGE, linewidths=0.8, zorder=2))
        ax.add_collection(LineCollection([_xy(geodesic_polygon_points(f)) for f in scene.neighbour_faces(0.004)],
                                         colors=NEIGHBOUR_FACE_EDGE, linewidths=0.4, zorder=2))
    ax.add_collection(LineCollection([_xy(geodesic_polygon_points(f)) for f in scene.faces], colors=FACE_EDGE,
                                     linewidths=0.6, zorder=3, label="faces"))
    ax.add_patch(Polygon(boundary, closed=True, facecolor="none", edgecolor=POLYGON_EDGE, linewidth=1.6,
                         alpha=0.85, zorder=4, label=f"F_{scene.genus}"))
    if scene.user_points:
        ax.scatter([z.real for z in scene.user_points], [z.imag for z in scene.user_points], s=6, c=USER_VERTEX,
                   zorder=5, label="vertices")
    if dummies and scene.dummy_points:
        ax.scatter([z.real for z in scene.dummy_points], [z.imag for z in scene.dummy_points], s=22,
                   c=DUMMY_VERTEX, marker="D", zorder=6, label="dummy vertices")
    ax.set_xlim(-1.03, 1.03)
    ax.set_ylim(-1.03, 1.03)
    ax.set_aspect("equal")
    ax.set_axis_off()
    ax.set_title(scene.caption(neighbours, dummies, "\n"), fontsize=9)
    return ax
