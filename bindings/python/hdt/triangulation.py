"""The Delaunay triangulation of a point set on M_g: :class:`Triangulation`.

A triangulation owns one C handle (hdt_triangulation). It is freed by
:meth:`Triangulation.close`, by leaving a ``with`` block, or when the object
is garbage collected, whichever comes first; using the object after that
raises :class:`hdt.HandleClosed` (never a crash). Calls on one object are
serialised by a lock, so sharing it between threads is safe (but not
parallel).

A signal handler can run inside :meth:`Triangulation.insert_many`,
:meth:`~Triangulation.refine` and :meth:`~Triangulation.epsilon_net` (they
run Python code during the library call so that Ctrl-C works): the object is
busy then, and every method called from the handler raises
:class:`hdt.InvalidArgument` ("busy"), changing nothing, except close()
(and leaving a ``with`` block), which stops the call early and closes the
triangulation as it returns, and the properties genus, closed and repr().

Vertex ids are ints, dense and stable: the dummy vertices of a new
triangulation are 0..d-1, each new distinct point gets the next id, and a
removed id is never reused. A vertex keeps its point; :meth:`vertex_point`
gives its representative in the half-open fundamental polygon F_g.

Faces are listed by :meth:`Triangulation.faces` as three vertex ids
(counterclockwise) and, per corner, a translation id: the element of
Gamma_g that maps the vertex's representative to that corner of the face's
canonical copy (the copy in which the face's smallest vertex id has
translation 0, the identity, so the copy meets F_g). Translation ids
0..|N|-1 are the neighbour set N (:func:`hdt.neighbour_word`); larger ones
are given by the triangulation and valid for it only
(:meth:`Triangulation.translation_word`, :meth:`Triangulation.translation_matrix`).
Face indices are positions in that list and hold until the next change.

Saving: :meth:`Triangulation.save` and :meth:`Triangulation.load` (a file),
:meth:`Triangulation.to_bytes` and :meth:`Triangulation.from_bytes`, in
libhdt's format (hdt_save); a loaded triangulation is the saved one, with
the same ids and faces. Pickling, copy.copy and copy.deepcopy go through
that format and give an independent triangulation.

Adjacency, edges and the Voronoi diagram: :meth:`neighbours`, :meth:`star`,
:meth:`edges`, :meth:`face_points`, :meth:`voronoi` and :meth:`voronoi_cell`
(the C functions of symbol version HDT_0.4), every star and cell at once:
:meth:`stars`, :meth:`voronoi_cells` (HDT_0.5); docs/dual.md of the source tree.

Refinement: :meth:`refine`, :meth:`epsilon_net` and :meth:`quality`
(docs/refinement.md of the source tree).

Arrays: with NumPy installed, :meth:`insert_many`, :meth:`vertices`,
:meth:`faces` and the methods above return NumPy arrays; without it, lists
(see each method).
"""

from __future__ import annotations

import contextlib
import ctypes
import math
import numbers
import os
import threading
import weakref
from typing import (TYPE_CHECKING, Any, BinaryIO, Callable, Dict, Iterator, NamedTuple, Optional, Tuple, Type, TypeVar,
                    Union)

from . import _arrays, mesh, picture, viewer
from ._arrays import (Bools, Floats, IntRows, Ints, IntTupleRows, Matrix, Point, PointRows, Points, PointsLike,
                      Word)
from ._interrupt import interruptible
from ._convert import c_coordinate, c_genus, c_translation, c_vertex, call_doubles, call_point, call_word
from ._errors import HandleClosed, InternalError, InvalidArgument, Status, check, error_for_status
from ._lib import lib
from .surface import Surface

if TYPE_CHECKING:  # for the annotations only: matplotlib and meshio are optional
    import matplotlib.axes
    import meshio

_T = TypeVar("_T", bound="Triangulation")

# hdt_svg's flags (include/hdt.h).
_SVG_NEIGHBOURS, _SVG_HIDE_DUMMIES, _SVG_VORONOI, _SVG_SIDE_LABELS = 1, 2, 4, 8

#: :meth:`Triangulation.vertices`: the live vertices by increasing id.
class Vertices(NamedTuple):
    ids: Ints
    points: Points
    dummy: Bools


Vertices.__doc__ = """The live vertices of a triangulation, by increasing id.

ids: the vertex ids (NumPy uint32 array of shape (n,), or a list of ints);
points: their representatives in F_g (float64 array of shape (n, 2), or a
list of (x, y) tuples); dummy: whether each is a dummy vertex (bool array of
shape (n,), or a list of bools)."""
Vertices.ids.__doc__ = "The vertex ids, increasing."
Vertices.points.__doc__ = "The representative (x, y) in F_g of each vertex."
Vertices.dummy.__doc__ = "Whether each vertex is a dummy vertex."

#: :meth:`Triangulation.faces`: vertex ids and translation ids per corner.
class Faces(NamedTuple):
    vertices: IntRows
    translations: IntRows


Faces.__doc__ = """The faces of a triangulation: row i is face i.

vertices: three vertex ids per face, counterclockwise (NumPy uint32 array of
shape (F, 3), or a list of 3-tuples); translations: per corner, the
translation id placing that vertex in the face's canonical copy (int32
array of shape (F, 3), or a list of 3-tuples)."""
Faces.vertices.__doc__ = "Three vertex ids per face, counterclockwise."
Faces.translations.__doc__ = "Per corner, the translation id of the vertex in the face's canonical copy."

#: :meth:`Triangulation.neighbours`: per face and corner, the face across and its translation.
class Neighbours(NamedTuple):
    faces: IntRows
    translations: IntRows


Neighbours.__doc__ = """The adjacency of the faces: row i is face i.

faces[i][c]: the face across the edge opposite corner c (uint32 array of
shape (F, 3), or a list of 3-tuples); translations[i][c]: the translation id
h such that h(canonical copy of that face) shares the edge with face i's
canonical copy (int32, same shape)."""

#: :meth:`Triangulation.star`: the faces around a vertex.
class Star(NamedTuple):
    faces: Ints
    corners: Ints
    translations: Ints


Star.__doc__ = """The faces around a vertex, counterclockwise: faces (indices
into faces()), corners (the vertex's corner 0..2 in each) and translations
(the id h such that h(canonical copy) has the vertex at its representative)."""

#: :meth:`Triangulation.stars`: every vertex's star, in rows by vertex id.
class Stars(NamedTuple):
    offsets: Ints
    faces: Ints
    corners: Ints
    translations: Ints


Stars.__doc__ = """Every live vertex's star in one array per field: the star of
vertex v is entries offsets[v] to offsets[v + 1] - 1 of faces, corners and
translations (each of length 3F), the same as :meth:`Triangulation.star`
gives; offsets has vertex_id_bound + 1 entries, a removed id an empty row."""

#: :meth:`Triangulation.voronoi_cells`: every vertex's Voronoi cell, in rows by vertex id.
class Cells(NamedTuple):
    offsets: Ints
    points: Points


Cells.__doc__ = """Every live vertex's Voronoi cell: points[offsets[v]:offsets[v + 1]]
(float64, shape (3F, 2) in all) is the cell of v, the same as
:meth:`Triangulation.voronoi_cell` gives; offsets as in :class:`Stars`."""

#: :meth:`Triangulation.edges`: every edge once.
class Edges(NamedTuple):
    vertices: IntRows
    translations: Ints
    faces: IntRows
    lengths: Floats


Edges.__doc__ = """Every edge once: row e is edge e.

vertices (E, 2): the edge runs from the representative of vertices[e][0] to
h(representative of vertices[e][1]), h = translations[e] (E,); faces (E, 2):
the face on its left, then on its right; lengths (E,): its hyperbolic
length."""

#: :meth:`Triangulation.voronoi`: the Voronoi diagram.
class Voronoi(NamedTuple):
    centres: Points
    radii: Floats
    edges: PointRows


Voronoi.__doc__ = """The Voronoi diagram, the dual of the triangulation.

centres (F, 2): the hyperbolic circumcentre of each face's canonical copy
(the Voronoi vertices); radii (F,): the hyperbolic circumradii; edges
(E, 2, 2): per edge of edges(), the Voronoi edge from the left face's centre
to the right face's centre placed beside it."""

#: :meth:`Triangulation.locate`: a face index and the translation of its copy.
#: :meth:`Triangulation.refine` and :meth:`Triangulation.epsilon_net`.
class Refined(NamedTuple):
    added: int
    unmet: int


Refined.__doc__ = """What a refinement did: added, the points it inserted; unmet, the
faces still breaking a bound (0 unless max_points stopped it or faces next to
near-duplicate points were left, see Triangulation.refine)."""
Refined.added.__doc__ = "The number of points inserted."
Refined.unmet.__doc__ = "The faces still breaking a bound: 0 when the refinement completed on points no closer than about 1e-9."

#: :meth:`Triangulation.quality`.
class Quality(NamedTuple):
    min_angle: float  # radians
    max_ratio: float
    max_radius: float
    min_edge: float


Quality.__doc__ = """The shape of the faces: min_angle, the smallest hyperbolic angle
(radians); max_ratio, the largest circumradius / shortest edge; max_radius,
the largest circumradius (the covering radius); min_edge, the shortest
edge (the distance of the two closest vertices). An epsilon-net has
max_radius <= eps <= min_edge."""
Quality.min_angle.__doc__ = "The smallest hyperbolic angle of a face, in radians."
Quality.max_ratio.__doc__ = "The largest radius-edge ratio of a face."
Quality.max_radius.__doc__ = "The largest circumradius: every point of M_g is that close to a vertex."
Quality.min_edge.__doc__ = "The shortest edge: the distance on M_g of the two closest vertices."

class Location(NamedTuple):
    face: int
    translation: int


Location.__doc__ = """Where a point lies: the face (an index into faces()) and
the translation id h such that the point is in the closed triangle
h(canonical copy of the face)."""
Location.face.__doc__ = "The index of the face in the order of faces()."
Location.translation.__doc__ = "The translation id of the face's copy that contains the point."


def _pairs(owner: Any, rows: int, groups: int) -> Any:
    """An output buffer of rows x (2 groups) doubles as points: a NumPy array
    of shape (rows, groups, 2), or a list of `groups` (x, y) tuples per row."""
    if not isinstance(owner, ctypes.Array):
        return owner.reshape(rows, groups, 2)
    values = list(owner)
    return [tuple((values[i + 2 * k], values[i + 2 * k + 1]) for k in range(groups))
            for i in range(0, len(values), 2 * groups)]


def _destroy(handle: ctypes.c_void_p) -> None:
    """Frees a C handle (the finalizer of every Triangulation)."""
    lib.hdt_destroy(handle)


class Triangulation:
    """The Delaunay triangulation of a point set on the surface M_genus.

    A new triangulation holds the dummy points of its genus, which keep it a
    simplicial complex whose faces have circumdiameter below half the
    systole; insert points, then :meth:`remove_dummies`. Points are given in
    the Poincare disk (any point of the open unit disk stands for its image
    on M_g).

    Raises :class:`hdt.InvalidArgument` (a ValueError) for genus < 2,
    :class:`hdt.NotSupported` above HDT_CREATE_GENUS_MAX (256) and TypeError when genus
    is not an int.

    Example::

        with hdt.Triangulation(2) as t:
            ids = t.insert_many([(0.1, 0.2), (-0.3, 0.05)])
            t.remove_dummies()
            t.validate()
            print(len(t), t.face_count)
    """

    _handle: Optional[ctypes.c_void_p] = None  # an hdt_triangulation * as ctypes.c_void_p; None once closed
    _busy: Optional[str] = None  # the method whose library call is running (a signal handler may run inside it)
    _close_pending = False  # close() from inside that call: done as the call returns

    def __init__(self, genus: Union[int, Surface]) -> None:
        """A new triangulation of M_genus holding the dummy points of its
        genus, or, given a :class:`hdt.Surface`, of that surface holding
        dummy points built for it (libhdt 0.8.0 on). On a surface,
        insertion, removal, queries, faces, stars, the Voronoi diagram,
        refinement, epsilon-nets, quality, homology (in a basis of the
        surface's own H_1), saving, pickling and :meth:`to_svg` work as on
        M_g; :meth:`plot` and the viewer, which draw F_g, raise
        :class:`hdt.NotSupported` for now. The triangulation keeps its own
        copy of the polygon: the surface may be closed afterwards."""
        handle = ctypes.c_void_p()
        if isinstance(genus, Surface):
            with genus._lock:
                check(lib.hdt_create_on_surface(ctypes.byref(handle), genus._live("Triangulation")))
        else:
            check(lib.hdt_create(ctypes.byref(handle), c_genus(genus)))
        self._adopt(handle)

    def _adopt(self, handle: ctypes.c_void_p) -> None:
        """Takes ownership of a C handle (from hdt_create or hdt_load)."""
        self._genus = lib.hdt_genus(handle)
        self._lock = threading.RLock()
        self._handle = handle
        self._finalizer = weakref.finalize(self, _destroy, handle)
        surface = ctypes.c_void_p()
        check(lib.hdt_triangulation_surface(handle, ctypes.byref(surface)))
        # The surface triangulated, None on a built-in M_g.
        self._surface: Optional[Surface] = Surface._made(surface) if surface else None

    # ---- lifetime ----

    def close(self) -> None:
        """Frees the C triangulation now. Closing again does nothing; any
        other use afterwards raises :class:`hdt.HandleClosed`. From a
        signal handler inside a long call (insert_many, refine,
        epsilon_net), the call stops early and the triangulation is closed
        as it returns."""
        with self._lock:
            if self._busy is not None:
                # The library is in the middle of its work on the handle.
                self._close_pending = True
                return
            self._handle = None
            self._finalizer()

    @contextlib.contextmanager
    def _calling(self, what: str) -> Iterator[ctypes.c_void_p]:
        """The handle for a library call that runs Python code inside it
        (interruptible), the object busy meanwhile (call with the lock
        held): a signal handler running there cannot use or free the
        handle under the library's feet."""
        handle = self._live(what)
        self._busy = what
        try:
            with interruptible(handle, lambda: self._close_pending):
                yield handle
        finally:
            self._busy = None
            if self._close_pending:
                self._close_pending = False
                self.close()

    @property
    def closed(self) -> bool:
        """Whether :meth:`close` was called (the handle is freed)."""
        return self._handle is None

    def __enter__(self: _T) -> _T:
        """Returns the triangulation itself; the ``with`` block closes it."""
        self._live("__enter__")
        return self

    def __exit__(self, *exception: object) -> None:
        """Closes the triangulation."""
        self.close()

    def __copy__(self) -> Triangulation:
        """An independent triangulation equal to this one (through
        :meth:`to_bytes`): a Triangulation owns its C handle, so a copy
        cannot share it."""
        return Triangulation.from_bytes(self.to_bytes())

    def __deepcopy__(self, memo: Dict[int, Any]) -> Triangulation:
        """The same as :meth:`__copy__`."""
        return self.__copy__()

    def __reduce__(self) -> Tuple[Callable[[bytes], Triangulation], Tuple[bytes]]:
        """Pickling: the saved bytes (:meth:`to_bytes`), loaded back by
        :meth:`from_bytes`."""
        return (Triangulation.from_bytes, (self.to_bytes(),))

    # ---- saving and loading ----

    def to_bytes(self) -> bytes:
        """The triangulation in libhdt's saved format (hdt_save; docs/format.md
        of the source tree): genus, every point exactly as given, ids with
        their gaps, dummy flags, the faces in their order, with a checksum.
        About 121 bytes a vertex."""
        size = ctypes.c_size_t()
        with self._lock:
            handle = self._live("to_bytes")
            check(lib.hdt_save(handle, None, 0, ctypes.byref(size)))
            buffer = ctypes.create_string_buffer(max(size.value, 1))
            check(lib.hdt_save(handle, buffer, size.value, ctypes.byref(size)))
        return buffer.raw[: size.value]

    @classmethod
    def from_bytes(cls: Type[_T], data: Union[bytes, bytearray, memoryview]) -> _T:
        """The triangulation saved in data (bytes, bytearray or memoryview, as
        :meth:`to_bytes` gives): the same genus, ids and faces. Every field is
        checked and the result validated; bytes that are truncated, corrupted
        or crafted raise :class:`hdt.InvalidArgument` (a ValueError) naming
        the byte offset at fault. TypeError for other types."""
        if not isinstance(data, (bytes, bytearray, memoryview)):
            raise TypeError(f"from_bytes: expected bytes, got {type(data).__name__}")
        data = bytes(data)
        handle = ctypes.c_void_p()
        check(lib.hdt_load(ctypes.byref(handle), data, len(data)))
        triangulation = cls.__new__(cls)
        triangulation._adopt(handle)
        return triangulation

    def save(self, file: Union[str, os.PathLike, BinaryIO]) -> None:
        """Writes :meth:`to_bytes` to file: a path (str or os.PathLike) or a
        binary file object (anything with write())."""
        data = self.to_bytes()
        if hasattr(file, "write"):
            file.write(data)
        else:
            with open(os.fspath(file), "wb") as out:
                out.write(data)

    @classmethod
    def load(cls: Type[_T], file: Union[str, os.PathLike, BinaryIO]) -> _T:
        """The triangulation saved in file: a path or a binary file object
        (anything with read()); as :meth:`from_bytes`."""
        if hasattr(file, "read"):
            return cls.from_bytes(file.read())
        with open(os.fspath(file), "rb") as source:
            return cls.from_bytes(source.read())

    def _live(self, what: str) -> ctypes.c_void_p:
        """The handle; HandleClosed when closed, InvalidArgument when busy
        (from a signal handler inside a long call; call with the lock held)."""
        handle = self._handle
        if handle is None:
            raise HandleClosed(f"{what}: the triangulation is closed")
        if self._busy is not None:
            raise InvalidArgument(f"{what}: the triangulation is busy in {self._busy} (a signal handler "
                                  "running inside that call cannot use it; only close() is deferred to its end)")
        return handle

    def __repr__(self) -> str:
        """<hdt.Triangulation genus=G vertices=V (D dummies) faces=F>, or closed."""
        with self._lock:
            if self._handle is None:
                return f"<hdt.Triangulation genus={self._genus} closed>"
            handle = self._handle
            return (f"<hdt.Triangulation genus={self._genus} vertices={lib.hdt_vertex_count(handle)} "
                    f"({lib.hdt_dummy_count(handle)} dummies) faces={lib.hdt_face_count(handle)}>")

    # ---- counts ----

    @property
    def surface(self) -> Optional[Surface]:
        """The :class:`hdt.Surface` triangulated (its own copy of the
        polygon given), or None for a triangulation of the built-in M_g."""
        return self._surface

    @property
    def genus(self) -> int:
        """The genus g of the surface M_g (also after close())."""
        return self._genus

    @property
    def vertex_count(self) -> int:
        """The number of live vertices, dummies included."""
        with self._lock:
            return lib.hdt_vertex_count(self._live("vertex_count"))

    def __len__(self) -> int:
        """The number of live vertices, dummies included (vertex_count)."""
        return self.vertex_count

    @property
    def dummy_count(self) -> int:
        """The number of live dummy vertices."""
        with self._lock:
            return lib.hdt_dummy_count(self._live("dummy_count"))

    @property
    def face_count(self) -> int:
        """The number of faces, F = 2 (V + 2g - 2)."""
        with self._lock:
            return lib.hdt_face_count(self._live("face_count"))

    @property
    def vertex_id_bound(self) -> int:
        """One past the largest vertex id ever given: every id below it is
        live or removed."""
        with self._lock:
            return lib.hdt_vertex_id_bound(self._live("vertex_id_bound"))

    # ---- changes ----

    def insert(self, x: float, y: float) -> int:
        """Inserts the point (x, y) of the open unit disk; returns its vertex id.

        A point equal to a dummy vertex turns it into a user vertex (its id
        is returned). A point that already is a user vertex raises
        :class:`hdt.AlreadyExists` whose ``vertex`` is that vertex's id.
        Raises :class:`hdt.OutOfDomain` (a ValueError) for NaN, infinities
        or |z| >= 1, TypeError when x or y is not a real number.
        """
        x, y = c_coordinate(x, "x"), c_coordinate(y, "y")
        vertex = ctypes.c_uint32()
        with self._lock:
            status = lib.hdt_insert(self._live("insert"), x, y, ctypes.byref(vertex))
            if status == Status.EEXISTS:
                error = error_for_status(status)
                error.vertex = vertex.value
                raise error
            check(status)
        return vertex.value

    def insert_many(self, points: PointsLike) -> Ints:
        """Inserts many points at once (in a spatial order, much faster than
        one by one); returns the vertex id of each point, in input order.

        points is an iterable of pairs (x, y), or (with NumPy) an array of
        shape (n, 2) of real numbers: a C-contiguous float64 array is read
        in place, another is converted once. The ids come as a NumPy uint32
        array of shape (n,) when NumPy is installed, else as a list of ints.

        Repeated points, and points that already are vertices, get the
        existing vertex's id (no error); a point equal to a dummy vertex
        turns it into a user vertex. New vertices get their ids in the
        spatial order, not in input order. Every point is checked first: a
        point outside the open unit disk raises :class:`hdt.OutOfDomain`
        naming its index, and nothing is inserted. Ctrl-C stops it within
        about 0.05 s with KeyboardInterrupt, the points inserted so far
        staying in a valid triangulation (likewise :meth:`refine`).
        """
        xy, count, owner = _arrays.point_buffer(points)
        ids_pointer, ids = _arrays.output(ctypes.c_uint32, count)
        with self._lock, self._calling("insert_many") as handle:
            check(lib.hdt_insert_many(handle, xy, count, ids_pointer))
        del owner  # the points stay alive until here
        return _arrays.result(ids)

    def remove(self, vertex: int) -> None:
        """Removes a vertex (user or dummy).

        Raises :class:`hdt.NotSupported`, changing nothing, when the
        triangulation without it would lose its guarantee (a face of
        circumdiameter >= half the systole), and :class:`hdt.InvalidArgument`
        when vertex is not a live vertex id.
        """
        vertex = c_vertex(vertex)
        with self._lock:
            check(lib.hdt_remove_vertex(self._live("remove"), vertex))

    def remove_dummies(self) -> int:
        """Removes every dummy vertex that can go without breaking the
        guarantee; returns how many dummies are left."""
        remaining = ctypes.c_size_t()
        with self._lock:
            check(lib.hdt_remove_dummies(self._live("remove_dummies"), ctypes.byref(remaining)))
        return remaining.value

    # ---- refinement ----

    def refine(self, max_radius: float = math.inf, max_ratio: float = math.inf,
               max_points: Optional[int] = None) -> Refined:
        """Delaunay refinement (hdt_refine): inserts circumcentres of the
        faces breaking a bound, largest first, until every face has
        hyperbolic circumradius <= max_radius and circumradius / shortest
        edge <= max_ratio (>= 1; inf: no bound), or max_points points were
        added (None, the default: no cap; the work is bounded by memory,
        below). Returns a :class:`Refined` (added, unmet); unmet > 0 when
        the cap stopped it, or for the few faces next to points closer than
        about 1e-9 (near-duplicates), which a double Steiner point cannot
        refine and which are left; the triangulation is valid either way.
        :class:`hdt.InvalidArgument`, nothing changed, for a bound that is
        NaN, max_radius <= 0 or max_ratio < 1. MemoryError, nothing
        changed, at once when the vertices that max_radius certainly needs
        (disks of that radius cover M_g; up to max_points) do not fit in
        this process's memory; later MemoryError keeps the points added.
        docs/refinement.md of the source tree proves that it terminates."""
        return self._refine("refine", lambda h, cap, a, u: lib.hdt_refine(
            h, c_coordinate(max_radius, "max_radius"), c_coordinate(max_ratio, "max_ratio"), cap, a, u), max_points)

    def epsilon_net(self, epsilon: float, max_points: Optional[int] = None) -> Refined:
        """Refines into an epsilon-net (hdt_epsilon_net): every point of M_g
        within epsilon of a vertex, and the points added at least epsilon
        from every vertex (the whole set is an epsilon-net when the vertices
        before were epsilon apart: on a new triangulation, for epsilon up to
        the dummies' spacing, 0.77 at genus 2). Returns a :class:`Refined`;
        :meth:`quality` checks the result. max_points and MemoryError as
        :meth:`refine`: an epsilon too small for memory (1e-4 on M_2 needs
        more than 4e8 vertices) is refused at once."""
        return self._refine("epsilon_net", lambda h, cap, a, u: lib.hdt_epsilon_net(
            h, c_coordinate(epsilon, "epsilon"), cap, a, u), max_points)

    def _refine(self, what: str, call: Callable[..., int], max_points: Optional[int]) -> Refined:
        if max_points is None:
            cap = ctypes.c_size_t(-1).value
        else:
            if not isinstance(max_points, numbers.Integral) or isinstance(max_points, bool):
                raise TypeError(f"max_points must be an int or None, not {type(max_points).__name__}")
            if max_points < 0:
                raise InvalidArgument(f"{what}: max_points must be >= 0")
            cap = min(int(max_points), ctypes.c_size_t(-1).value)
        added, unmet = ctypes.c_size_t(), ctypes.c_size_t()
        with self._lock, self._calling(what) as handle:
            check(call(handle, cap, ctypes.byref(added), ctypes.byref(unmet)))
        return Refined(added.value, unmet.value)

    def quality(self) -> Quality:
        """The shape of the faces as a :class:`Quality` (min_angle,
        max_ratio, max_radius, min_edge), computed in double (hdt_quality)."""
        values = [ctypes.c_double() for _ in range(4)]
        with self._lock:
            check(lib.hdt_quality(self._live("quality"), *(ctypes.byref(v) for v in values)))
        return Quality(*(v.value for v in values))

    # ---- vertices ----

    def is_dummy(self, vertex: int) -> bool:
        """Whether the live vertex is a dummy vertex; :class:`hdt.InvalidArgument`
        when vertex is not a live vertex id."""
        vertex = c_vertex(vertex)
        with self._lock:
            answer = lib.hdt_vertex_is_dummy(self._live("is_dummy"), vertex)
        if answer < 0:
            raise InvalidArgument(f"is_dummy: vertex {vertex} is not a live vertex")
        return answer == 1

    def vertex_point(self, vertex: int) -> Point:
        """The representative (x, y) of the vertex in the half-open F_g,
        rounded to floats; :class:`hdt.InvalidArgument` when vertex is not
        a live vertex id."""
        vertex = c_vertex(vertex)
        with self._lock:
            return call_point(lib.hdt_vertex_point, self._live("vertex_point"), vertex)

    def vertices(self) -> Vertices:
        """The live vertices as a :class:`Vertices` named tuple (ids, points,
        dummy), by increasing id.

        With NumPy: ids a uint32 array of shape (n,), points a float64 array
        of shape (n, 2) (the representatives in F_g), dummy a bool array of
        shape (n,). Without: a list of ints, a list of (x, y) tuples and a
        list of bools.
        """
        with self._lock:
            handle = self._live("vertices")
            count = lib.hdt_vertex_count(handle)
            found = ctypes.c_size_t()
            ids_pointer, ids = _arrays.output(ctypes.c_uint32, count)
            points_pointer, points = _arrays.output(ctypes.c_double, count, 2)
            dummy_pointer, dummy = _arrays.output(ctypes.c_uint8, count)
            check(lib.hdt_vertices(handle, ids_pointer, points_pointer, dummy_pointer, count, ctypes.byref(found)))
            if found.value != count:
                raise InternalError(f"vertices: hdt_vertices listed {found.value}, hdt_vertex_count says {count}")
        return Vertices(_arrays.result(ids), _arrays.result(points, 2), _arrays.flags(dummy))

    # ---- faces ----

    def faces(self) -> Faces:
        """The faces as a :class:`Faces` named tuple (vertices, translations);
        row i is face i (the index :meth:`locate` gives).

        With NumPy: two arrays of shape (F, 3), vertex ids (uint32) counter-
        clockwise and the translation id of each corner (int32). Without: two
        lists of 3-tuples. The corner (vertices[i][c], translations[i][c]) is
        the point translation_matrix(t) applied to vertex_point(v).
        """
        with self._lock:
            handle = self._live("faces")
            count = lib.hdt_face_count(handle)
            found = ctypes.c_size_t()
            vertices_pointer, vertices = _arrays.output(ctypes.c_uint32, count, 3)
            translations_pointer, translations = _arrays.output(ctypes.c_int32, count, 3)
            status = lib.hdt_faces(handle, vertices_pointer, translations_pointer, count, ctypes.byref(found))
            check(status)
            if found.value != count:
                raise InternalError(f"faces: hdt_faces listed {found.value} faces, hdt_face_count says {count}")
        return Faces(_arrays.result(vertices, 3), _arrays.result(translations, 3))

    def translation_word(self, translation: int) -> Word:
        """The canonical word (a tuple of letters) of a translation id of
        this triangulation; () for id 0, the identity.
        :class:`hdt.InvalidArgument` for an id the triangulation does not know."""
        translation = c_translation(translation)
        with self._lock:
            return call_word(lib.hdt_translation_word, self._live("translation_word"), translation, capacity=16)

    def translation_matrix(self, translation: int) -> Matrix:
        """The SU(1,1) matrix [[a, b], [conj b, conj a]] of a translation id
        as the pair (a, b) of complex numbers (as :func:`hdt.word_matrix`):
        it maps z to (a z + b) / (conj(b) z + conj(a)).
        :class:`hdt.InvalidArgument` for an unknown id."""
        translation = c_translation(translation)
        with self._lock:
            re_a, im_a, re_b, im_b = call_doubles(lib.hdt_translation_matrix, 4, self._live("translation_matrix"),
                                                  translation)
        return complex(re_a, im_a), complex(re_b, im_b)

    def translation_homology(self, translation: int) -> Tuple[int, ...]:
        """The class [h] in Z^{2g} of a translation id h (hdt_translation_homology,
        symbol version HDT_0.6): a tuple of 2g ints, coordinate k the number
        of letters k minus the number of letters k + 2g in its word; a
        homomorphism ([h h'] = [h] + [h']); id 0, the identity, gives zeros. :class:`hdt.InvalidArgument` for an unknown id."""
        translation = c_translation(translation)
        with self._lock:
            handle = self._live("translation_homology")
            size = 2 * lib.hdt_genus(handle)
            out = (ctypes.c_int32 * size)()
            count = ctypes.c_size_t()
            check(lib.hdt_translation_homology(handle, translation, out, size, ctypes.byref(count)))
            if count.value != size:
                raise InternalError(f"translation_homology: {count.value} coordinates, 2g is {size}")
        return tuple(out)

    def corner_homology(self) -> IntTupleRows:
        """Per face and corner, the class in Z^{2g} of the corner's translation
        (:meth:`faces`, :meth:`translation_homology`): an int32 array of shape
        (F, 3, 2g) with NumPy, else a list (per face) of three tuples. The
        relative class of corners i and j of a face, row[j] - row[i], does not
        depend on the face's copy; hdt.fem twists by it."""
        translations = self.faces().translations
        np = _arrays.numpy
        if np is None:
            classes = {h: self.translation_homology(h) for h in {h for row in translations for h in row}}
            return [tuple(classes[h] for h in row) for row in translations]
        ids = np.asarray(translations, dtype=np.int64)
        used, where = np.unique(ids, return_inverse=True)  # a few hundred ids for any mesh
        table = np.array([self.translation_homology(int(h)) for h in used], dtype=np.int32).reshape(
            len(used), 2 * self.genus)
        return table[where.reshape(ids.shape)]

    # ---- adjacency, edges, corners, the Voronoi diagram ----

    def _list(self, what, function, outputs, count):
        """Calls a two-call-pattern function of the library with buffers of
        count rows: outputs is a list of (ctype, columns) or None (a NULL
        output); returns the owners (call with the lock held)."""
        pointers, owners = [], []
        for output in outputs:
            if output is None:
                pointers.append(None)
                owners.append(None)
                continue
            pointer, owner = _arrays.output(output[0], count, output[1])
            pointers.append(pointer)
            owners.append(owner)
        found = ctypes.c_size_t()
        check(function(*pointers, count, ctypes.byref(found)))
        if found.value != count:
            raise InternalError(f"{what}: the library listed {found.value}, expected {count}")
        return owners

    def neighbours(self) -> Neighbours:
        """The adjacency of the faces as a :class:`Neighbours` named tuple
        (faces, translations), two arrays of shape (F, 3) (lists of 3-tuples
        without NumPy): for face i and corner c, the face across the edge
        opposite c and the translation id placing its canonical copy beside
        face i's canonical copy."""
        with self._lock:
            handle = self._live("neighbours")
            count = lib.hdt_face_count(handle)
            faces, translations = self._list(
                "neighbours", lambda *a: lib.hdt_face_neighbours(handle, *a),
                [(ctypes.c_uint32, 3), (ctypes.c_int32, 3)], count)
        return Neighbours(_arrays.result(faces, 3), _arrays.result(translations, 3))

    def star(self, vertex: int) -> Star:
        """The faces around a live vertex, counterclockwise, as a
        :class:`Star` named tuple (faces, corners, translations) of arrays of
        shape (k,) (lists without NumPy). :class:`hdt.InvalidArgument` when
        vertex is not a live vertex id."""
        vertex = c_vertex(vertex)
        with self._lock:
            handle = self._live("star")
            count = ctypes.c_size_t()
            check(lib.hdt_vertex_star(handle, vertex, None, None, None, 0, ctypes.byref(count)))
            faces, corners, translations = self._list(
                "star", lambda *a: lib.hdt_vertex_star(handle, vertex, *a),
                [(ctypes.c_uint32, None), (ctypes.c_uint8, None), (ctypes.c_int32, None)], count.value)
        return Star(_arrays.result(faces), _arrays.result(corners), _arrays.result(translations))

    def stars(self) -> Stars:
        """Every live vertex's star in one call, as a :class:`Stars` named
        tuple (offsets, faces, corners, translations): the star of vertex v
        is rows offsets[v] to offsets[v + 1] - 1, what :meth:`star` gives for
        v (lists without NumPy). Much faster than :meth:`star` per vertex."""
        with self._lock:
            handle = self._live("stars")
            pointer, offsets = _arrays.output(ctypes.c_size_t, lib.hdt_vertex_id_bound(handle) + 1)
            faces, corners, translations = self._list(
                "stars", lambda *a: lib.hdt_vertex_stars(handle, pointer, *a),
                [(ctypes.c_uint32, None), (ctypes.c_uint8, None), (ctypes.c_int32, None)],
                3 * lib.hdt_face_count(handle))
        return Stars(_arrays.result(offsets), _arrays.result(faces), _arrays.result(corners),
                     _arrays.result(translations))

    @property
    def edge_count(self) -> int:
        """The number of edges, E = 3 F / 2."""
        with self._lock:
            return lib.hdt_edge_count(self._live("edge_count"))

    def edges(self) -> Edges:
        """Every edge once as an :class:`Edges` named tuple (vertices,
        translations, faces, lengths): arrays of shape (E, 2), (E,), (E, 2)
        and (E,) (lists without NumPy). Edge e runs from the representative
        of vertices[e][0] to translation_matrix(translations[e]) applied to
        the representative of vertices[e][1]; faces[e] are the faces on its
        left and right; lengths[e] its hyperbolic length."""
        with self._lock:
            handle = self._live("edges")
            count = lib.hdt_edge_count(handle)
            vertices, translations, faces, lengths = self._list(
                "edges", lambda *a: lib.hdt_edges(handle, *a),
                [(ctypes.c_uint32, 2), (ctypes.c_int32, None), (ctypes.c_uint32, 2), (ctypes.c_double, None)], count)
        return Edges(_arrays.result(vertices, 2), _arrays.result(translations), _arrays.result(faces, 2),
                     _arrays.result(lengths))

    def face_points(self) -> PointRows:
        """The three corners of each face's canonical copy in the disk, in
        the order of faces(): a float64 array of shape (F, 3, 2) (without
        NumPy, a list of three (x, y) tuples per face)."""
        with self._lock:
            handle = self._live("face_points")
            count = lib.hdt_face_count(handle)
            (xy,) = self._list("face_points", lambda *a: lib.hdt_face_points(handle, *a), [(ctypes.c_double, 6)],
                               count)
        return _pairs(xy, count, 3)

    def voronoi(self) -> Voronoi:
        """The Voronoi diagram as a :class:`Voronoi` named tuple (centres,
        radii, edges): the hyperbolic circumcentre (F, 2) and circumradius
        (F,) of each face's canonical copy, and per edge of :meth:`edges` the
        Voronoi edge (E, 2, 2) from the left face's centre to the right
        face's centre placed beside it (lists without NumPy). The cell of a
        vertex: :meth:`voronoi_cell`."""
        with self._lock:
            handle = self._live("voronoi")
            faces, edges = lib.hdt_face_count(handle), lib.hdt_edge_count(handle)
            centres, radii = self._list("voronoi", lambda *a: lib.hdt_voronoi_vertices(handle, *a),
                                        [(ctypes.c_double, 2), (ctypes.c_double, None)], faces)
            (segments,) = self._list("voronoi", lambda *a: lib.hdt_voronoi_edges(handle, *a), [(ctypes.c_double, 4)],
                                     edges)
        return Voronoi(_arrays.result(centres, 2), _arrays.result(radii), _pairs(segments, edges, 2))

    def voronoi_cell(self, vertex: int) -> Points:
        """The Voronoi cell of a live vertex: the circumcentres of the faces
        of its :meth:`star` (same order), placed around its representative,
        a counterclockwise polygon with geodesic sides; a float64 array of
        shape (k, 2) (a list of (x, y) without NumPy).
        :class:`hdt.InvalidArgument` when vertex is not a live vertex id."""
        vertex = c_vertex(vertex)
        with self._lock:
            handle = self._live("voronoi_cell")
            count = ctypes.c_size_t()
            check(lib.hdt_voronoi_cell(handle, vertex, None, 0, ctypes.byref(count)))
            (xy,) = self._list("voronoi_cell", lambda *a: lib.hdt_voronoi_cell(handle, vertex, *a),
                               [(ctypes.c_double, 2)], count.value)
        return _arrays.result(xy, 2)

    def voronoi_cells(self) -> Cells:
        """Every live vertex's Voronoi cell in one call, as a :class:`Cells`
        named tuple (offsets, points): points[offsets[v]:offsets[v + 1]] is
        what :meth:`voronoi_cell` gives for v, the same bits (a float64 array
        of shape (3F, 2); lists without NumPy)."""
        with self._lock:
            handle = self._live("voronoi_cells")
            pointer, offsets = _arrays.output(ctypes.c_size_t, lib.hdt_vertex_id_bound(handle) + 1)
            (xy,) = self._list("voronoi_cells", lambda *a: lib.hdt_voronoi_cells(handle, pointer, *a),
                               [(ctypes.c_double, 2)], 3 * lib.hdt_face_count(handle))
        return Cells(_arrays.result(offsets), _arrays.result(xy, 2))

    # ---- queries ----

    def locate(self, x: float, y: float) -> Location:
        """The face whose copy contains the disk point (x, y), as a
        :class:`Location` (face, translation): (x, y) lies in the closed
        triangle h(canonical copy of faces()[face]) for h the translation id.
        A point on an edge or a vertex gets one of the faces around it.
        :class:`hdt.OutOfDomain` (a ValueError) outside the open unit disk."""
        x, y = c_coordinate(x, "x"), c_coordinate(y, "y")
        face, translation = ctypes.c_size_t(), ctypes.c_int32()
        with self._lock:
            check(lib.hdt_locate(self._live("locate"), x, y, ctypes.byref(face), ctypes.byref(translation)))
        return Location(face.value, translation.value)

    def nearest_vertex(self, x: float, y: float) -> int:
        """The id of the vertex nearest to the disk point (x, y) on M_g
        (hyperbolic distance, decided exactly; ties go to the smaller id),
        dummies included. :class:`hdt.OutOfDomain` outside the open disk."""
        x, y = c_coordinate(x, "x"), c_coordinate(y, "y")
        vertex = ctypes.c_uint32()
        with self._lock:
            check(lib.hdt_nearest_vertex(self._live("nearest_vertex"), x, y, ctypes.byref(vertex)))
        return vertex.value

    def validate(self) -> None:
        """Checks every invariant with exact predicates (combinatorics,
        orientation, empty circles, the simplicial condition, the
        circumdiameter guarantee); returns None, or raises
        :class:`hdt.InternalError` naming the broken invariant."""
        with self._lock:
            check(lib.hdt_validate(self._live("validate")))

    # ---- pictures ----

    def to_svg(self, path: Union[str, os.PathLike, None] = None, *, size: float = 800, dummies: bool = True,
               neighbours: bool = False, title: Optional[str] = None, voronoi: bool = False,
               side_labels: bool = False) -> str:
        """The picture of the triangulation as SVG text, drawn by libhdt
        (hdt_svg, as hdt-triangulate's --svg), also written to path (a file
        name) when given; needs no third-party package.

        M_g is shown as F_g in the Poincare disk with its sides paired: every
        copy of a face that meets F_g, with geodesic edges, cut at F_g's
        sides; F_g outlined, user vertices dark dots and (when dummies is
        true) dummy vertices red and larger. neighbours also draws the 4g
        tiles across F_g's sides, lighter, with their faces, vertices and
        Voronoi edges. The caption wraps at spaces to fit the width. size is the width in pixels
        (0 < size <= 100000, else :class:`hdt.InvalidArgument`); title
        replaces the caption's first line (plain text; the library escapes
        it), by default "Delaunay triangulation of N points on M_g". voronoi
        also draws the Voronoi diagram (green), cut at the sides like the
        faces. side_labels labels the sides of F_g: s_k with g_k (which maps
        s_{k+2g} onto it) and s_{k+2g} with g_k^-1, k < 2g (libhdt 0.6.0 on).
        See :mod:`hdt.picture`.
        """
        size = float(size)
        flags = ((0 if dummies else _SVG_HIDE_DUMMIES) | (_SVG_NEIGHBOURS if neighbours else 0)
                 | (_SVG_VORONOI if voronoi else 0) | (_SVG_SIDE_LABELS if side_labels else 0))
        c_title = None
        if title is not None:
            # A NUL would end the C string: shown as '?', as the library shows
            # control characters; lone surrogates likewise.
            c_title = str(title).replace("\0", "?").encode("utf-8", "replace")
        length = ctypes.c_size_t()
        with self._lock:
            handle = self._live("to_svg")
            # A guess (about 200 bytes a face, in F_g and in each tile), so
            # that one call usually does (each call draws the whole picture);
            # the exact size when it is too small.
            copies = 4 * self._genus + 1 if neighbours else 1
            capacity = 4096 + 256 * copies * lib.hdt_face_count(handle) + 64 * lib.hdt_vertex_count(handle)
            for _ in range(2):
                buffer = ctypes.create_string_buffer(capacity)
                status = lib.hdt_svg(handle, size, c_title, flags, buffer, capacity, ctypes.byref(length))
                if status != Status.EBUFS:
                    break
                capacity = length.value + 1
            check(status)
        data = buffer.raw[: length.value]
        if path is not None:
            with open(path, "wb") as file:
                file.write(data)
        return data.decode("utf-8")

    def plot(self, ax: Optional[matplotlib.axes.Axes] = None, *, dummies: bool = True, neighbours: bool = False,
             voronoi: bool = False, side_labels: bool = False) -> matplotlib.axes.Axes:
        """Draws the triangulation on a matplotlib Axes (a new figure's when
        ax is None) and returns the Axes; the picture of :meth:`to_svg`.
        Raises ImportError when matplotlib is not installed."""
        return picture.plot(self, ax, dummies=dummies, neighbours=neighbours, voronoi=voronoi,
                            side_labels=side_labels)

    def to_meshio(self, layout: str = "representatives") -> meshio.Mesh:
        """The triangulation as a ``meshio.Mesh`` (needs meshio and NumPy;
        Debian: python3-meshio), for any format meshio writes:
        ``t.to_meshio("unfolded").write("mesh.vtu")``. layout
        "representatives": one node per vertex, at its representative in
        F_g, each triangle's corner translations as cell data
        ``translation``; "unfolded": each face in its canonical copy, nodes
        repeated across the sides, point data ``vertex`` the node-to-vertex
        map (the identification list of periodic finite elements). Both
        carry point data ``vertex`` and ``dummy``, cell data ``face`` and
        field data ``genus`` (:mod:`hdt.mesh`)."""
        return mesh.to_meshio(self, layout)

    def to_html(self, path: Union[str, os.PathLike, None] = None, *, title: Optional[str] = None,
                voronoi: bool = False) -> str:
        """The interactive viewer of the triangulation as the text of one
        self-contained HTML page (inline script and style, no network
        access; as hdt-triangulate's --html), also written to path (a file
        name, UTF-8) when given.

        The page draws F_g and the faces in the Poincare disk with geodesic
        edges, the dummy vertices marked and the copies around F_g; dragging
        moves the view by an isometry of the disk, hovering shows ids,
        points and translation words. voronoi puts the Voronoi diagram into
        the page (a switch there; about 120 bytes a face more than the 50 of
        the faces). title (plain text) replaces the heading, by default
        "Delaunay triangulation of N points on M_g". The page and its JSON
        data: docs/viewer.md and :mod:`hdt.viewer`.
        """
        return viewer.html(self, path, title=title, voronoi=voronoi)

    #: Faces above which a notebook shows the plain repr instead of the
    #: viewer (the page holds about 50 bytes a face, and each browser frame
    #: draws them all); up to VORONOI_REPR_MAX_FACES it holds the Voronoi
    #: diagram too.
    HTML_REPR_MAX_FACES = 100000
    VORONOI_REPR_MAX_FACES = 20000

    def _repr_html_(self) -> Optional[str]:
        """The viewer inline in a Jupyter notebook (an iframe holding
        :meth:`to_html`'s page, with the Voronoi diagram up to
        VORONOI_REPR_MAX_FACES faces); None (the plain repr) for a closed
        triangulation or one of more than HTML_REPR_MAX_FACES faces."""
        if self.closed or self.face_count > self.HTML_REPR_MAX_FACES:
            return None
        return viewer.iframe(self.to_html(voronoi=self.face_count <= self.VORONOI_REPR_MAX_FACES))
