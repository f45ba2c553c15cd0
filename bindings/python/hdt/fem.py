"""P1 finite elements of the hyperbolic metric on a triangulation of M_g.

:func:`p1_matrices` assembles the stiffness matrix K (K[i, j] = integral of
grad phi_i . grad phi_j) and the mass matrix M (integral of phi_i phi_j) of
the hat functions phi_i of the vertices, for the metric of curvature -1, as
SciPy sparse matrices. K u = lambda M u then approximates the spectrum of the
Laplace-Beltrami operator of M_g (see docs/spectrum.md of the source tree).
NumPy and SciPy are needed here only; importing :mod:`hdt` works without them.

Each face is taken in its canonical copy in the disk (Triangulation.
face_points()) and made a straight-sided triangle in a chart; the hat
functions are affine in that chart:

* ``"klein"`` (the default): the Klein chart centred at the face's
  hyperbolic circumcentre C (the Moebius map taking C to 0, then x = 2w /
  (1 + |w|^2)). Geodesics of a Klein chart are straight lines, so the
  straight triangle IS the geodesic face and the triangles tile M_g
  exactly. The chart is not conformal: with r = |x| the metric has
  sqrt(det g) = (1 - r^2)^(-3/2) and sqrt(det g) g^-1 = (1 - r^2)^(-1/2)
  (I - x x^T); both are integrated over each triangle with a degree-5 rule
  (7 points; grad phi is constant on a triangle). Why the circumcentre: on
  the hyperboloid an affine function of the Klein chart centred at C is
  l(X) / <X, C>, l linear, and the point of an edge PQ at chart parameter s
  is the ray of (1 - s) X_P / <X_P, C> + s X_Q / <X_Q, C>. The two faces of
  the edge have centres equidistant from P and Q, so both weights are equal
  in each chart and s is the same point in both: the two faces' hat
  functions agree on the whole shared edge (a conforming, H^1 element;
  :func:`seam_mismatch` measures 4e-14 to 3e-13).
* ``"klein-copy"``: the Klein chart of each face's canonical copy, centred
  at the copy's own origin (the default before 0.6). Two faces that meet
  across a side of F_g sit in copies whose origins are a translation
  (length about 3 at genus 2) apart, so <X_P, C> / <X_Q, C> differs between
  them by O(h) and their hat functions disagree along the edge by O(h):
  seam_mismatch 0.11, 0.068, 0.036, 0.019 on the epsilon-nets 0.2 to 0.025
  of M_2 (docs/spectrum.md).
* ``"poincare"``: the Dirichlet energy integral of |grad u|^2 dA is invariant
  under a conformal change of metric in 2D, and the Poincare chart is
  conformal, so K is exactly the Euclidean cotangent matrix of the triangles
  in the chart (per canonical copy); M integrates phi_i phi_j lambda^2,
  lambda = 2 / (1 - |z|^2), with the same rule. The straight triangles miss
  the geodesic ones (circle arcs) by O(h^2) near the sides of the copies,
  and across the sides the hat functions disagree by O(h) as in
  "klein-copy" (seam_mismatch 0.074 to 0.013 on the same meshes).

Eigenvalues converge as O(h^2), that is O(1/V) for V vertices on
quasi-uniform meshes, in all three (measured in docs/spectrum.md); only
"klein" is a conforming element, and the twisted matrices (k, hyperbolic
band theory, docs/bands.md) are meant to be built on it.

``lumped=True`` replaces M by the diagonal of its row sums (same total mass,
same O(h^2) order for eigenvalues, usually with the opposite sign of error).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, NamedTuple, Sequence, Tuple, Union

if TYPE_CHECKING:  # for the annotations only: importing hdt needs neither NumPy nor SciPy
    import numpy
    import scipy.sparse

    from .triangulation import Triangulation

__all__ = ["P1Matrices", "p1_matrices", "seam_mismatch"]


class P1Matrices(NamedTuple):
    stiffness: scipy.sparse.csr_matrix
    mass: scipy.sparse.csr_matrix
    vertices: numpy.ndarray


P1Matrices.__doc__ = """The P1 matrices of a triangulation: stiffness and mass, SciPy
sparse (CSR, symmetric; complex Hermitian when twisted by k) of order V,
row i for the vertex id vertices[i]."""

# Degree-5 rule on the triangle (Dunavant 1985, 7 points): barycentric
# coordinates, weights summing to 1.
_A1, _B1 = 0.059715871789770, 0.470142064105115
_A2, _B2 = 0.797426985353087, 0.101286507323456
_W0, _W1, _W2 = 0.225, 0.132394152788506, 0.125939180544827
_RULE = [
    ((1 / 3, 1 / 3, 1 / 3), _W0),
    ((_A1, _B1, _B1), _W1), ((_B1, _A1, _B1), _W1), ((_B1, _B1, _A1), _W1),
    ((_A2, _B2, _B2), _W2), ((_B2, _A2, _B2), _W2), ((_B2, _B2, _A2), _W2),
]

CHARTS = ("klein", "klein-copy", "poincare")


def _modules() -> Tuple[Any, Any]:
    try:
        import numpy
        import scipy.sparse
    except ImportError as error:
        raise ImportError(
            "hdt.fem needs NumPy and SciPy (Debian: apt install python3-numpy python3-scipy; "
            f"or pip install numpy scipy): {error}") from error
    return numpy, scipy.sparse


def _circumcentres(np, z):
    """The hyperbolic circumcentres (F,) complex, in the Poincare disk, of
    the faces whose corners are z (F, 3, 2): on the hyperboloid the centre C
    has the same Minkowski product <C, X_i> with the three corners."""
    r2 = (z * z).sum(axis=2)
    x = np.concatenate([(1 + r2)[..., None], 2 * z], axis=2) / (1 - r2)[..., None]  # (F, 3, 3)
    n = np.linalg.solve(x * np.array([1.0, -1.0, -1.0]), np.ones(x.shape[:2]))
    n /= np.sqrt(n[:, 0] ** 2 - n[:, 1] ** 2 - n[:, 2] ** 2)[:, None] * np.sign(n[:, 0])[:, None]
    return (n[:, 1] + 1j * n[:, 2]) / (1 + n[:, 0])


def _centres(np, z, chart):
    """Per face, the disk point (complex) its chart is centred at."""
    if chart == "klein":
        return _circumcentres(np, z)
    return np.zeros(len(z), dtype=complex)


def _to_chart(np, z, centres, chart):
    """Disk points z (F, ..., 2) of the faces' canonical copies in the faces'
    charts: the Moebius map sending each face's centre to 0, then (Klein
    charts) x = 2w / (1 + |w|^2)."""
    c = centres.reshape((-1,) + (1,) * (z.ndim - 2))
    w = z[..., 0] + 1j * z[..., 1]
    w = (w - c) / (1 - np.conj(c) * w)
    if chart != "poincare":
        w = 2 * w / (1 + np.abs(w) ** 2)
    return np.stack([w.real, w.imag], axis=-1)


def _from_chart(np, p, centres, chart):
    """The inverse of :func:`_to_chart`."""
    c = centres.reshape((-1,) + (1,) * (p.ndim - 2))
    w = p[..., 0] + 1j * p[..., 1]
    if chart != "poincare":
        w = w / (1 + np.sqrt(1 - np.abs(w) ** 2))
    w = (w + c) / (1 + np.conj(c) * w)
    return np.stack([w.real, w.imag], axis=-1)


def _barycentric(np, p, q):
    """Barycentric coordinates (F, S, 3) of points q (F, S, 2) in the
    triangles p (F, 3, 2)."""
    e1, e2 = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
    det = e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0]
    d = q - p[:, None, 0]
    l1 = (d[..., 0] * e2[:, None, 1] - d[..., 1] * e2[:, None, 0]) / det[:, None]
    l2 = (e1[:, None, 0] * d[..., 1] - e1[:, None, 1] * d[..., 0]) / det[:, None]
    return np.stack([1 - l1 - l2, l1, l2], axis=-1)


def seam_mismatch(triangulation: Triangulation, chart: str = "klein",
                  samples: Union[numpy.ndarray, Sequence[float]] = (0.25, 0.5, 0.75)) -> float:
    """How far the hat functions of two faces disagree along their shared
    edge: the largest |phi_f - phi_f'| over every edge (both faces' hat
    functions of the edge's two ends) at the points of chord parameter s in
    `samples` in face f's chart, mapped into the neighbour f' placed beside
    f (hdt_face_neighbours' translation). 0 up to rounding for a conforming
    element. The P1 space of :func:`p1_matrices` is conforming (H^1) exactly
    when this is 0."""
    if chart not in CHARTS:
        raise ValueError(f"seam_mismatch: chart must be one of {CHARTS}, not {chart!r}")
    np, _ = _modules()
    faces = np.asarray(triangulation.faces().vertices, dtype=np.int64)
    z = np.asarray(triangulation.face_points(), dtype=np.float64)
    neighbours = triangulation.neighbours()
    across = np.asarray(neighbours.faces, dtype=np.int64)
    moved = np.asarray(neighbours.translations, dtype=np.int64)
    centres = _centres(np, z, chart)
    p = _to_chart(np, z, centres, chart)
    s = np.asarray(samples, dtype=np.float64)
    worst = 0.0
    matrices = {int(h): triangulation.translation_matrix(int(h)) for h in np.unique(moved)}
    for c in range(3):
        a, b = (c + 1) % 3, (c + 2) % 3
        q = p[:, a, None] * (1 - s)[None, :, None] + p[:, b, None] * s[None, :, None]  # (F, S, 2)
        y = _from_chart(np, q, centres, chart)
        w = y[..., 0] + 1j * y[..., 1]
        ha = np.array([matrices[int(h)][0] for h in moved[:, c]])[:, None]
        hb = np.array([matrices[int(h)][1] for h in moved[:, c]])[:, None]
        w = (np.conj(ha) * w - hb) / (-np.conj(hb) * w + ha)  # h^-1: into the neighbour's canonical copy
        g = across[:, c]
        q2 = _to_chart(np, np.stack([w.real, w.imag], axis=-1), centres[g], chart)
        lam = _barycentric(np, p[g], q2)
        for corner, expected in ((a, 1 - s), (b, s)):
            where = faces[g] == faces[:, corner, None]  # the same vertex's corner in the neighbour
            if not np.all(where.sum(axis=1) == 1):
                raise RuntimeError("seam_mismatch: an edge's vertex is not a corner of the face across it")
            pick = where.argmax(axis=1)[:, None, None].repeat(len(s), axis=1)
            value = np.take_along_axis(lam, pick, axis=2)[..., 0]
            worst = max(worst, float(np.abs(value - expected[None, :]).max()))
    return worst


def p1_matrices(triangulation: Triangulation, chart: str = "klein", lumped: bool = False,
                k: Union[numpy.ndarray, Sequence[float], None] = None) -> P1Matrices:
    """The P1 stiffness and mass matrices of the hyperbolic metric on the
    triangulation (dummy vertices included: they are vertices of the mesh)
    as a :class:`P1Matrices` (stiffness, mass, vertices). chart is "klein",
    "klein-copy" or "poincare" (see the module's documentation);
    lumped=True gives the diagonal (row-sum) mass matrix.

    k: None for the real matrices of functions on M_g, or a point of the
    Brillouin torus (2g reals, taken mod 2 pi) for the complex Hermitian
    matrices of the sections twisted by the character chi_k(gamma) =
    exp(i k . [gamma]), [gamma] in Z^{2g} the class of gamma
    (Triangulation.translation_homology): functions u on the disk with
    u(gamma z) = chi_k(gamma) u(z). Corner i of a face, the vertex's
    representative moved by h_i, then has the value chi_k(h_i) u(v_i), so
    the face's entry (i, j) picks up exp(i k . ([h_j] - [h_i])). k = 0
    gives the real matrices' numbers exactly, as complex matrices (other k
    of 2 pi Z^{2g} the same up to the rounding of exp). ImportError without NumPy or SciPy; ValueError for
    an unknown chart or a k of another length than 2g."""
    if chart not in CHARTS:
        raise ValueError(f"p1_matrices: chart must be one of {CHARTS}, not {chart!r}")
    np, sparse = _modules()
    phase_k = None if k is None else np.asarray(k, dtype=np.float64)
    if phase_k is not None and phase_k.shape != (2 * triangulation.genus,):
        raise ValueError(f"p1_matrices: k must have 2g = {2 * triangulation.genus} entries, not shape {phase_k.shape}")
    ids = np.asarray(triangulation.vertices().ids, dtype=np.int64)
    faces = np.asarray(triangulation.faces().vertices, dtype=np.int64)
    z = np.asarray(triangulation.face_points(), dtype=np.float64)  # (F, 3, 2), Poincare
    row_of = np.full(int(ids.max()) + 1 if ids.size else 0, -1, dtype=np.int64)
    row_of[ids] = np.arange(ids.size)
    rows = row_of[faces]

    p = _to_chart(np, z, _centres(np, z, chart), chart)
    # Edge vectors e_i opposite corner i; grad phi_i = J e_i / (2 area), J the
    # quarter turn, for counterclockwise corners.
    e = np.roll(p, -2, axis=1) - np.roll(p, -1, axis=1)  # e_i = p_{i+2} - p_{i+1}
    area = 0.5 * (e[:, 1, 0] * e[:, 2, 1] - e[:, 1, 1] * e[:, 2, 0])
    grad = np.stack([-e[..., 1], e[..., 0]], axis=2) / (2 * area)[:, None, None]

    stiffness_weight = np.zeros((len(p), 2, 2))  # integral over the face of the metric's A(x)
    mass = np.zeros((len(p), 3, 3))
    for bary, weight in _RULE:
        b = np.asarray(bary)
        x = np.einsum("i,fij->fj", b, p)
        r2 = (x * x).sum(axis=1)
        if chart != "poincare":
            density = (1 - r2) ** -1.5
            a = (1 - r2) ** -0.5
            stiffness_weight += (weight * area * a)[:, None, None] * (
                np.eye(2)[None] - x[:, :, None] * x[:, None, :])
        else:
            density = 4 / (1 - r2) ** 2
        mass += (weight * area * density)[:, None, None] * np.outer(b, b)[None]
    if chart == "poincare":
        stiffness_weight = area[:, None, None] * np.eye(2)[None]  # conformal: Euclidean cotangent matrix
    local_k = np.einsum("fia,fab,fjb->fij", grad, stiffness_weight, grad)
    local_m = mass
    if phase_k is not None:
        # The phase of the relative translation of corner j's copy to
        # corner i's; 1 exactly (exp(0)) on the diagonal, and wherever
        # k . ([h_j] - [h_i]) is 0.
        theta = np.asarray(triangulation.corner_homology(), dtype=np.float64) @ phase_k  # (F, 3)
        phase = np.exp(1j * (theta[:, None, :] - theta[:, :, None]))
        local_k = local_k * phase
        local_m = local_m * phase

    n = ids.size
    i_index = np.repeat(rows, 3, axis=1).ravel()
    j_index = np.tile(rows, (1, 3)).ravel()
    stiffness = sparse.coo_matrix((local_k.ravel(), (i_index, j_index)), shape=(n, n)).tocsr()
    if lumped:
        diagonal = np.bincount(rows.ravel(), weights=mass.sum(axis=2).ravel(), minlength=n)
        mass_matrix = sparse.diags(diagonal if phase_k is None else diagonal.astype(complex)).tocsr()
    else:
        mass_matrix = sparse.coo_matrix((local_m.ravel(), (i_index, j_index)), shape=(n, n)).tocsr()
    # Hermitian (symmetric) by construction up to rounding in the sums; make it exact.
    stiffness = (stiffness + stiffness.conj().T) * 0.5
    mass_matrix = (mass_matrix + mass_matrix.conj().T) * 0.5
    return P1Matrices(stiffness.tocsr(), mass_matrix.tocsr(), ids)
