"""hdt.fem: the P1 stiffness and mass matrices of the hyperbolic metric,
checked against what does not depend on the assembly: the area of M_g
(Gauss-Bonnet, 4 pi (g - 1)), constants in the kernel of K, the cotangent
formula recomputed from the corners' angles, and the Bolza surface's first
eigenvalue (Strohmaier and Uski 2013) through the example's quick run."""

import math
import os
import pathlib
import subprocess
import sys

import pytest

np = pytest.importorskip("numpy")
pytest.importorskip("scipy.sparse")

import hdt  # noqa: E402
from hdt.fem import p1_matrices  # noqa: E402

LAMBDA_1 = 3.8388872588421995  # Strohmaier and Uski, Comm. Math. Phys. 317 (2013)
EXAMPLE = pathlib.Path(__file__).resolve().parents[3] / "examples" / "bolza_spectrum.py"


def refined(genus, radius):
    t = hdt.Triangulation(genus)
    t.refine(max_radius=radius, max_ratio=1.0)
    return t


@pytest.fixture(scope="module")
def bolza():
    return refined(2, 0.3)


def mass_error(genus, radius, chart, lumped=False):
    area = 4 * math.pi * (genus - 1)
    return (p1_matrices(refined(genus, radius), chart=chart, lumped=lumped).mass.sum() - area) / area


@pytest.mark.parametrize("genus", [2, 3])
def test_klein_mass_is_the_area(genus):
    # The Klein triangles are the geodesic faces: they tile M_g exactly, so
    # only the degree-5 quadrature errs, by O(h^6): 64x less when h halves
    # (measured 57x from r = 0.2 to 0.1; 1.3e-7 at r = 0.1, genus 2).
    coarse, fine = (mass_error(genus, r, "klein") for r in (0.2, 0.1))
    assert abs(fine) < 1e-6
    assert abs(coarse) > 30 * abs(fine)
    assert mass_error(genus, 0.1, "klein", lumped=True) == pytest.approx(fine, abs=1e-12)


@pytest.mark.parametrize("genus", [2, 3])
def test_poincare_mass_converges_to_the_area(genus):
    # Straight triangles in the Poincare chart cover more than the geodesic
    # ones (arcs bulge toward the origin) along the copies' borders: an
    # O(h^2) excess, 4x less when h halves (0.8% and 0.17% at genus 2).
    coarse, fine = (mass_error(genus, r, "poincare") for r in (0.2, 0.1))
    assert 0 < fine < 0.005
    assert 3 < coarse / fine < 6


@pytest.mark.parametrize("chart", ["klein", "poincare"])
def test_stiffness_rows_sum_to_zero_and_kernel_is_the_constants(bolza, chart):
    k, m, ids = p1_matrices(bolza, chart=chart)
    n = bolza.vertex_count
    assert k.shape == m.shape == (n, n)
    assert sorted(ids.tolist()) == sorted(bolza.vertices().ids.tolist())
    dense = k.toarray()
    scale = np.abs(dense).max()
    assert np.abs(dense.sum(axis=1)).max() < 1e-12 * scale
    assert np.array_equal(dense, dense.T)
    values = np.linalg.eigvalsh(dense)
    assert abs(values[0]) < 1e-10 * scale  # PSD with the constants in the kernel
    assert values[1] > 1e-3 * scale  # and nothing else: M_g is connected
    masses = np.linalg.eigvalsh(m.toarray())
    assert masses[0] > 0


def test_poincare_stiffness_is_the_cotangent_matrix(bolza):
    # Recomputed per face from its three angles: K_ij = -(cot of the angle
    # opposite ij) / 2, summed over the two faces of the edge.
    k, _, ids = p1_matrices(bolza, chart="poincare")
    row = {int(v): i for i, v in enumerate(ids)}
    expected = np.zeros(k.shape)
    for corners, points in zip(bolza.faces().vertices, bolza.face_points()):
        for c in range(3):
            a, b, o = (c + 1) % 3, (c + 2) % 3, c
            u = points[a] - points[o]
            w = points[b] - points[o]
            angle = math.atan2(abs(u[0] * w[1] - u[1] * w[0]), u[0] * w[0] + u[1] * w[1])
            i, j = row[int(corners[a])], row[int(corners[b])]
            half_cot = 0.5 / math.tan(angle)
            expected[i, j] -= half_cot
            expected[j, i] -= half_cot
            expected[i, i] += half_cot
            expected[j, j] += half_cot
    assert np.abs(k.toarray() - expected).max() < 1e-9 * np.abs(expected).max()


@pytest.mark.parametrize("chart", ["klein", "poincare"])
@pytest.mark.parametrize("lumped", [False, True])
def test_first_eigenvalue_converges_with_order_two(chart, lumped):
    # Against the published lambda_1 of the Bolza surface: three discrete
    # copies near it, and the error of their mean 4x smaller when the radius
    # halves (4.1x measured, Klein chart, consistent mass).
    from scipy.sparse.linalg import eigsh

    errors = []
    for radius in (0.1, 0.05):
        k, m, _ = p1_matrices(refined(2, radius), chart=chart, lumped=lumped)
        values = np.sort(eigsh(k, k=5, M=m, sigma=-0.1, return_eigenvectors=False))
        assert abs(values[0]) < 1e-9
        assert values[3] / values[1] < 1.01 and values[4] > 1.3 * values[3]
        errors.append(abs(values[1:4].mean() - LAMBDA_1))
    assert errors[0] < 0.01 * LAMBDA_1
    assert 3 < errors[0] / errors[1] < 5.5


def test_bad_chart(bolza):
    with pytest.raises(ValueError, match="chart"):
        p1_matrices(bolza, chart="upper half-plane")


def test_bolza_example_quick():
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(pathlib.Path(hdt.__file__).parents[1]),
                                                      env.get("PYTHONPATH")]))
    done = subprocess.run([sys.executable, str(EXAMPLE), "--quick"], env=env, capture_output=True, text=True,
                          timeout=60)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "multiplicity 3" in done.stdout
