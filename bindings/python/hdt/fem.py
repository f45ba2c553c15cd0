"""P1 finite elements of the hyperbolic metric on a triangulation of M_g.

:func:`p1_matrices` assembles the stiffness matrix K (K[i, j] = integral of
grad phi_i . grad phi_j) and the mass matrix M (integral of phi_i phi_j) of
the hat functions phi_i of the vertices, for the metric of curvature -1, as
SciPy sparse matrices. K u = lambda M u then approximates the spectrum of the
Laplace-Beltrami operator of M_g (see docs/spectrum.md of the source tree).
NumPy and SciPy are needed here only; importing :mod:`hdt` works without them.

Each face is taken in its canonical copy in the disk (Triangulation.
face_points()) and made a straight-sided triangle in one of two charts; the
hat functions are affine in that chart:

* ``"klein"`` (the default): geodesics of the Klein disk are straight lines,
  so the straight triangle IS the geodesic face and the triangles tile M_g
  exactly. The chart is not conformal: with r = |x| the metric has
  sqrt(det g) = (1 - r^2)^(-3/2) and sqrt(det g) g^-1 = (1 - r^2)^(-1/2)
  (I - x x^T); both are integrated over each triangle with a degree-5 rule
  (7 points; grad phi is constant on a triangle).
* ``"poincare"``: the Dirichlet energy integral of |grad u|^2 dA is invariant
  under a conformal change of metric in 2D, and the Poincare chart is
  conformal, so K is exactly the Euclidean cotangent matrix of the triangles
  in the chart; M integrates phi_i phi_j lambda^2, lambda = 2 / (1 - |z|^2),
  with the same rule. The straight triangles miss the geodesic ones (circle
  arcs) by O(h^2) near the sides of the copies, h the mesh size.

In both charts a face's neighbour may sit in another copy (the two differ by
an isometry, projective in Klein's chart and Moebius in Poincare's), so the
hat functions of the two sides of such an edge agree at its ends but not
quite in between: a nonconformity of order h^2, the order of the P1 error
itself. Eigenvalues converge as O(h^2), that is O(1/V) for V vertices on
quasi-uniform meshes (measured in docs/spectrum.md).

``lumped=True`` replaces M by the diagonal of its row sums (same total mass,
same O(h^2) order for eigenvalues, usually with the opposite sign of error).
"""

import collections

__all__ = ["P1Matrices", "p1_matrices"]

P1Matrices = collections.namedtuple("P1Matrices", "stiffness mass vertices")
P1Matrices.__doc__ = """The P1 matrices of a triangulation: stiffness and mass, SciPy
sparse (CSR, symmetric) of order V, row i for the vertex id vertices[i]."""

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

CHARTS = ("klein", "poincare")


def _modules():
    try:
        import numpy
        import scipy.sparse
    except ImportError as error:
        raise ImportError(
            "hdt.fem needs NumPy and SciPy (Debian: apt install python3-numpy python3-scipy; "
            f"or pip install numpy scipy): {error}") from error
    return numpy, scipy.sparse


def p1_matrices(triangulation, chart="klein", lumped=False):
    """The P1 stiffness and mass matrices of the hyperbolic metric on the
    triangulation (dummy vertices included: they are vertices of the mesh)
    as a :class:`P1Matrices` (stiffness, mass, vertices). chart is "klein"
    or "poincare" (see the module's documentation); lumped=True gives the
    diagonal (row-sum) mass matrix. ImportError without NumPy or SciPy;
    ValueError for an unknown chart."""
    if chart not in CHARTS:
        raise ValueError(f"p1_matrices: chart must be one of {CHARTS}, not {chart!r}")
    np, sparse = _modules()
    ids = np.asarray(triangulation.vertices().ids, dtype=np.int64)
    faces = np.asarray(triangulation.faces().vertices, dtype=np.int64)
    z = np.asarray(triangulation.face_points(), dtype=np.float64)  # (F, 3, 2), Poincare
    row_of = np.full(int(ids.max()) + 1 if ids.size else 0, -1, dtype=np.int64)
    row_of[ids] = np.arange(ids.size)
    rows = row_of[faces]

    if chart == "klein":
        p = 2 * z / (1 + (z * z).sum(axis=2))[..., None]
    else:
        p = z
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
        if chart == "klein":
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

    n = ids.size
    i_index = np.repeat(rows, 3, axis=1).ravel()
    j_index = np.tile(rows, (1, 3)).ravel()
    stiffness = sparse.coo_matrix((local_k.ravel(), (i_index, j_index)), shape=(n, n)).tocsr()
    if lumped:
        diagonal = np.bincount(rows.ravel(), weights=mass.sum(axis=2).ravel(), minlength=n)
        mass_matrix = sparse.diags(diagonal).tocsr()
    else:
        mass_matrix = sparse.coo_matrix((mass.ravel(), (i_index, j_index)), shape=(n, n)).tocsr()
    # Symmetric by construction up to rounding in the sums; make it exact.
    stiffness = (stiffness + stiffness.T) * 0.5
    mass_matrix = (mass_matrix + mass_matrix.T) * 0.5
    return P1Matrices(stiffness.tocsr(), mass_matrix.tocsr(), ids)
