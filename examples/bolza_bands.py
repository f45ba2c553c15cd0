#!/usr/bin/env python3
"""The lowest bands of the Bolza surface M_2: hyperbolic band theory
(Maciejko and Rayan, Science Advances 7, 2021; PNAS 119, 2022) by P1 finite
elements.

A point k of the Brillouin torus (R / 2 pi Z)^4 is a character chi_k(gamma)
= exp(i k . [gamma]) of Gamma_2, [gamma] in Z^4 the class of gamma over the
generators g_0..g_3 (Triangulation.translation_homology). The Laplacian on
sections u(gamma z) = chi_k(gamma) u(z) has eigenvalues lambda_n(k): the
bands. k = 0 is the spectrum of M_2 (lambda_0 = 0, lambda_1 = 3.8388872588
with multiplicity 3, Strohmaier and Uski 2013). This meshes M_2 from the
dummy points (Triangulation.refine, circumradius <= r, radius-edge ratio <=
1), assembles the twisted Hermitian matrices (hdt.fem.p1_matrices(t, k=k),
Klein chart per face, consistent mass) and solves for the lowest
eigenvalues along the path Gamma -> X -> M -> R -> Gamma,
Gamma = 0, X = (pi, 0, 0, 0), M = (pi, pi, 0, 0), R = (pi, pi, pi, pi).

  python3 examples/bolza_bands.py               the bands at r = 0.1 (885 vertices, about 2 s)
  python3 examples/bolza_bands.py --quick       r = 0.3 (99 vertices), 4 points a segment,
                                                and the checks below (CI, under 1 s)
  python3 examples/bolza_bands.py --png FILE    also the plot (matplotlib)

Checks (every run): lambda_0(Gamma) ~ 0, three eigenvalues near lambda_1 at
Gamma (within 2% at r = 0.1, 20% at r = 0.3), lambda_0 > 0 away from Gamma,
lambda_n(k) = lambda_n(-k). Needs NumPy and SciPy; finds libhdt as the hdt
package does (HDT_LIBRARY).
"""

import argparse
import math
import sys
import time

import numpy as np
import scipy.linalg
from scipy.sparse.linalg import eigsh

import hdt
from hdt.fem import p1_matrices

REFERENCE = 3.8388872588421995  # lambda_1 of M_2, Strohmaier and Uski 2013
CORNERS = [("Gamma", (0, 0, 0, 0)), ("X", (math.pi, 0, 0, 0)), ("M", (math.pi, math.pi, 0, 0)),
           ("R", (math.pi, math.pi, math.pi, math.pi)), ("Gamma", (0, 0, 0, 0))]


def mesh(max_radius):
    t = hdt.Triangulation(2)
    t.refine(max_radius=max_radius, max_ratio=1.0)
    return t


def bands_at(t, k, count):
    """The count lowest eigenvalues of the twisted problem at k, increasing."""
    stiffness, mass, _ = p1_matrices(t, k=np.asarray(k, dtype=float))
    if stiffness.shape[0] <= 400:  # dense is faster and sure for small meshes
        return scipy.linalg.eigh(stiffness.toarray(), mass.toarray(), eigvals_only=True)[:count]
    values = eigsh(stiffness, k=count, M=mass, sigma=-0.1, which="LM", return_eigenvectors=False)
    return np.sort(values.real)


def path(points_per_segment):
    """(distance along the path, k) pairs and the corners' distances."""
    out, ticks, s = [], [0.0], 0.0
    for (_, a), (_, b) in zip(CORNERS, CORNERS[1:]):
        a, b = np.asarray(a, float), np.asarray(b, float)
        length = float(np.linalg.norm(b - a))
        for i in range(points_per_segment):
            out.append((s + length * i / points_per_segment, a + (b - a) * i / points_per_segment))
        s += length
        ticks.append(s)
    out.append((s, np.asarray(CORNERS[-1][1], float)))
    return out, ticks


def plot(samples, values, ticks, path_png, title):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 4.5))
    for n in range(values.shape[1]):
        ax.plot(samples, values[:, n], color="C0", lw=1.5)
    ax.axhline(REFERENCE, color="0.6", lw=0.8, ls="--")
    ax.text(ticks[-1], REFERENCE, " $\\lambda_1$", va="center", color="0.4")
    ax.set_xticks(ticks, [r"$\Gamma$", "X", "M", "R", r"$\Gamma$"])
    for x in ticks:
        ax.axvline(x, color="0.85", lw=0.8)
    ax.set_xlim(ticks[0], ticks[-1])
    ax.set_ylim(bottom=0)
    ax.set_ylabel(r"$\lambda_n(k)$")
    ax.set_title(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path_png, dpi=120)
    plt.close(fig)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="a small mesh, 4 points a segment (CI)")
    parser.add_argument("--radius", type=float, default=None, help="max circumradius of the mesh (0.1; quick 0.3)")
    parser.add_argument("--points", type=int, default=None, help="k points per segment (12; quick 4)")
    parser.add_argument("--bands", type=int, default=6, help="how many bands (6)")
    parser.add_argument("--png", metavar="FILE", help="write the plot there (matplotlib)")
    args = parser.parse_args(argv)
    radius = args.radius or (0.3 if args.quick else 0.1)
    points = args.points or (4 if args.quick else 12)

    start = time.perf_counter()
    t = mesh(radius)
    samples, ticks = path(points)
    values = np.array([bands_at(t, k, args.bands) for _, k in samples])
    elapsed = time.perf_counter() - start

    print(f"Bolza surface, r_max {radius}: {t.vertex_count} vertices, {t.face_count} faces; "
          f"{len(samples)} points of the path, {args.bands} bands, {elapsed:.1f} s")
    names = iter(name for name, _ in CORNERS)
    corner_at = {round(x, 12): next(names) for x in ticks}
    print("     s  k                                   " + "  ".join(f"lambda_{n}" for n in range(args.bands)))
    for (s, k), row in zip(samples, values):
        label = corner_at.get(round(s, 12), "")
        print(f"{s:6.3f}  {label:5s} ({', '.join(f'{x:5.3f}' for x in k)})  " + "  ".join(f"{v:8.4f}" for v in row))

    failures = []
    gamma = values[0]
    tolerance = 0.02 if radius <= 0.1 else 0.2
    if abs(gamma[0]) > 1e-9:
        failures.append(f"lambda_0(Gamma) = {gamma[0]:.3g}, not 0")
    if not all(abs(v - REFERENCE) < tolerance * REFERENCE for v in gamma[1:4]) or abs(gamma[4] - REFERENCE) < 0.2:
        failures.append(f"at Gamma: {gamma[1:5]} is not lambda_1 = {REFERENCE:.6f} with multiplicity 3")
    away = values[1:-1, 0]
    if away.min() <= 0:
        failures.append(f"lambda_0 = {away.min():.3g} away from Gamma")
    k = np.array([0.7, -1.3, 2.1, 0.4])
    if np.abs(bands_at(t, k, args.bands) - bands_at(t, -k, args.bands)).max() > 1e-8:
        failures.append("lambda_n(k) != lambda_n(-k)")
    x, m, r = (values[ticks.index(tick) * points if tick != ticks[-1] else -1] for tick in ticks[1:4])
    print(f"lowest band: {values[:, 0].min():.4f} at Gamma, X {x[0]:.4f}, M {m[0]:.4f}, R {r[0]:.4f} "
          f"(top of band 0 along the path {values[:, 0].max():.4f}; band 1 from {values[:, 1].min():.4f})")
    if args.png:
        plot([s for s, _ in samples], values, ticks, args.png,
             f"Bolza surface: lowest {args.bands} bands, P1 on {t.vertex_count} vertices (r = {radius})")
        print(f"plot written to {args.png}")
    for failure in failures:
        print("FAILED:", failure)
    if not failures:
        print("checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
