#!/usr/bin/env python3
"""The first eigenvalue of the Laplacian on the Bolza surface M_2, by P1
finite elements on Delaunay refinements of M_2.

Strohmaier and Uski (Comm. Math. Phys. 317, 2013) give lambda_1 =
3.8388872588421995 with multiplicity 3. This meshes M_2 from the dummy
points with Triangulation.refine (circumradius <= r, radius-edge ratio <=
1), assembles the stiffness and (lumped) mass matrices (hdt.fem.p1_matrices,
Klein chart), solves
K u = lambda M u for the lowest eigenvalues with SciPy's shift-invert
Lanczos (sigma below 0, as lambda_0 = 0), and prints per mesh: vertices,
lambda_0, the cluster near lambda_1 and its multiplicity, the error, the time.
The observed order p (error ~ V^(-p/2), h ~ V^(-1/2)) and a Richardson
extrapolation of the last meshes follow.

  python3 examples/bolza_spectrum.py            the table (about 10 s)
  python3 examples/bolza_spectrum.py --quick    one mesh of about 800 vertices: lambda_0 ~ 0,
                                                multiplicity 3, lambda_1 within 2% (CI)
  python3 examples/bolza_spectrum.py --svg FILE an eigenfunction of lambda_1 drawn on the
                                                faces of the mesh of circumradius 0.07

Needs NumPy and SciPy; finds libhdt as the hdt package does (HDT_LIBRARY).
"""

import argparse
import math
import sys
import time

import numpy as np
from scipy.sparse.linalg import eigsh

import hdt
from hdt.fem import p1_matrices

REFERENCE = 3.8388872588421995  # Strohmaier and Uski 2013
MULTIPLICITY = 3
SVG_RADIUS = 0.07  # the mesh drawn by --svg: about 1,700 vertices, 100 kB of SVG


def mesh(max_radius, max_ratio=1.0):
    t = hdt.Triangulation(2)
    t.refine(max_radius=max_radius, max_ratio=max_ratio)
    return t


def lowest(triangulation, count=6, chart="klein", lumped=False):
    """The count lowest eigenvalues of K u = lambda M u, increasing."""
    k, m, _ = p1_matrices(triangulation, chart=chart, lumped=lumped)
    values = eigsh(k, k=count, M=m, sigma=-0.1, which="LM", return_eigenvectors=False)
    return np.sort(values)


def cluster(values, tolerance=0.05):
    """The eigenvalues within a relative tolerance of the first above
    lambda_0: the discrete copies of lambda_1, split by the mesh's
    asymmetry (their mean is the one compared)."""
    first = values[1]
    return [v for v in values[1:] if abs(v - first) <= tolerance * max(abs(first), 1.0)]


def first_eigenfunction(triangulation, chart="klein", lumped=True):
    """lambda_1's lowest discrete copy and its eigenvector as a dict vertex
    id -> value, scaled to max |u| = 1 with its largest entry positive (an
    eigenvector is only defined up to a factor). The start vector is fixed,
    so that ARPACK's result does not depend on a random draw."""
    k, m, ids = p1_matrices(triangulation, chart=chart, lumped=lumped)
    values, vectors = eigsh(k, k=2, M=m, sigma=-0.1, which="LM", v0=np.ones(k.shape[0]))
    order = np.argsort(values)
    u = vectors[:, order[1]]
    u = u / u[np.argmax(np.abs(u))]
    return float(values[order[1]]), {int(v): float(x) for v, x in zip(ids, u)}


def colour(value, levels=8):
    """Blue (-1), white (0), red (+1) in 2 levels + 1 steps: coarse, so
    that rounding noise in the eigenvector does not change the picture."""
    step = round(max(-1.0, min(1.0, value)) * levels) / levels
    fade = int(round(255 * (1 - abs(step))))
    return f"#ff{fade:02x}{fade:02x}" if step > 0 else f"#{fade:02x}{fade:02x}ff"


def write_svg(triangulation, values, path, size=600, lam=None):
    """The faces' canonical copies in the Poincare disk as straight
    triangles, each filled with the colour of the mean of u at its corners;
    F_g outlined (its sides as geodesic arcs), a title above, and a colour
    bar of the levels on the right."""
    faces = triangulation.faces()
    corners = triangulation.face_points()
    top, bar = 44, 90  # the title band above the disk, the colour bar's band on the right
    half = size / 2
    scale = half - 4
    cx, cy = half, top + half

    def place(x, y):
        return cx + scale * x, cy - scale * y

    width, height = size + bar, size + top
    title = "An eigenfunction of lambda_1 on the Bolza surface M_2"
    detail = (f"lambda = {lam:.6f}, " if lam is not None else "") + f"{triangulation.vertex_count:,} vertices; F_2 outlined"
    lines = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
             f'viewBox="0 0 {width} {height}" font-family="DejaVu Sans, sans-serif">',
             '<rect width="100%" height="100%" fill="white"/>',
             f'<text x="{cx:g}" y="20" text-anchor="middle" font-size="15">{title}</text>',
             f'<text x="{cx:g}" y="37" text-anchor="middle" font-size="11" fill="#444">{detail}</text>',
             f'<circle cx="{cx:g}" cy="{cy:g}" r="{scale:g}" fill="none" stroke="#333" stroke-width="1"/>']
    # One path per colour: a few kilobytes per thousand faces.
    paths = {}
    for face, points in zip(faces.vertices, corners):
        fill = colour(sum(values[int(v)] for v in face) / 3)
        (a, b, c) = (place(float(x), float(y)) for x, y in points)
        paths.setdefault(fill, []).append(f"M{a[0]:.1f} {a[1]:.1f}L{b[0]:.1f} {b[1]:.1f}L{c[0]:.1f} {c[1]:.1f}Z")
    for fill in sorted(paths):
        lines.append(f'<path fill="{fill}" stroke="{fill}" stroke-width="0.4" d="{"".join(paths[fill])}"/>')
    # F_g: each side the arc of the circle through its ends orthogonal to
    # the unit circle (centre c with |c|^2 = 1 + r^2), drawn as an SVG arc.
    n = 4 * triangulation.genus
    vertex = [place(*hdt.polygon_vertex(triangulation.genus, k)) for k in range(n)]
    outline = [f"M{vertex[-1][0]:.2f} {vertex[-1][1]:.2f}"]
    for k in range(n):  # side s_k joins v_{k-1} and v_k
        mx, my = hdt.polygon_side_midpoint(triangulation.genus, k)
        m = math.hypot(mx, my)
        radius = (1 / m - m) / 2 * scale  # its circle's centre lies at (m + 1/m) / 2 beyond the midpoint
        # counterclockwise in the disk, clockwise on the page (y down): the arc bends towards O
        outline.append(f"A{radius:.2f} {radius:.2f} 0 0 1 {vertex[k][0]:.2f} {vertex[k][1]:.2f}")
    lines.append(f'<path fill="none" stroke="#b5651d" stroke-width="1.6" d="{"".join(outline)}Z"/>')
    # The colour bar: the 2 levels + 1 colours from +1 (top) to -1.
    levels = 8
    x0, y0, h = size + 24, top + 40, (size - 80) / (2 * levels + 1)
    for i in range(2 * levels + 1):
        value = 1 - i / levels
        lines.append(f'<rect x="{x0}" y="{y0 + i * h:.2f}" width="18" height="{h + 0.3:.2f}" fill="{colour(value)}"/>')
    lines.append(f'<rect x="{x0}" y="{y0}" width="18" height="{(2 * levels + 1) * h:.2f}" fill="none" stroke="#333"/>')
    for label, y in (("+1", y0 + h / 2), ("0", y0 + (levels + 0.5) * h), ("-1", y0 + (2 * levels + 0.5) * h)):
        lines.append(f'<text x="{x0 + 24}" y="{y + 4:.2f}" font-size="11">{label}</text>')
    lines.append(f'<text x="{x0 + 9}" y="{y0 - 12}" text-anchor="middle" font-size="11">u / max |u|</text>')
    lines.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def run(radii, chart, lumped, out=sys.stdout):
    rows = []
    print(f"chart {chart}, {'lumped' if lumped else 'consistent'} mass; reference lambda_1 = {REFERENCE}", file=out)
    print(f"{'r_max':>6} {'V':>7} {'lambda_0':>10} {'lambda_1 (cluster)':>38} {'mult':>4} "
          f"{'rel. error':>10} {'order':>6} {'time s':>7}", file=out)
    for r in radii:
        start = time.perf_counter()
        t = mesh(r)
        values = lowest(t, chart=chart, lumped=lumped)
        elapsed = time.perf_counter() - start
        near = cluster(values)
        lam = float(np.mean(near))
        n = t.vertex_count
        error = (lam - REFERENCE) / REFERENCE
        order = ""
        if rows:
            n0, lam0 = rows[-1][0], rows[-1][1]
            order = f"{2 * math.log(abs(lam0 - REFERENCE) / abs(lam - REFERENCE)) / math.log(n / n0):6.2f}"
        rows.append((n, lam))
        shown = " ".join(f"{v:.6f}" for v in near)
        print(f"{r:6.4f} {n:7d} {values[0]:10.1e} {shown:>38} {len(near):4d} {error:10.2e} {order:>6} "
              f"{elapsed:7.2f}", file=out)
    return rows


def richardson(rows):
    """Extrapolates the last three meshes: fits lambda(V) = L + C V^(-q) by
    solving for q from three values, then L; also L with q = 1 (order 2)
    from the last two."""
    (n1, l1), (n2, l2), (n3, l3) = rows[-3:]

    def mismatch(q):
        a = (l1 - l2) / (n1 ** -q - n2 ** -q)
        b = (l2 - l3) / (n2 ** -q - n3 ** -q)
        return a - b

    lo, hi = 0.3, 3.0
    q = None
    if mismatch(lo) * mismatch(hi) < 0:
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if mismatch(lo) * mismatch(mid) <= 0:
                hi = mid
            else:
                lo = mid
        q = 0.5 * (lo + hi)
    fixed = (l3 * n3 - l2 * n2) / (n3 - n2)  # q = 1
    fitted = None
    if q is not None:
        c = (l2 - l3) / (n2 ** -q - n3 ** -q)
        fitted = l3 - c * n3 ** -q
    return q, fitted, fixed


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="one small mesh, loose check (CI)")
    parser.add_argument("--chart", choices=hdt.fem.CHARTS, default="klein")
    parser.add_argument("--mass", choices=("lumped", "consistent"), default="lumped",
                        help="the mass matrix: diagonal row sums (smaller error here) or the full one")
    parser.add_argument("--svg", metavar="FILE",
                        help="draw an eigenfunction of lambda_1 on the mesh of circumradius 0.07 and stop")
    parser.add_argument("--radii", type=float, nargs="+", default=[0.1, 0.05, 0.025, 0.0125],
                        help="the meshes' largest circumradius, one per row")
    args = parser.parse_args(argv)
    lumped = args.mass == "lumped"

    if args.svg:
        t = mesh(SVG_RADIUS)
        lam, u = first_eigenfunction(t, chart=args.chart, lumped=lumped)
        write_svg(t, u, args.svg, lam=lam)
        print(f"V = {t.vertex_count}, lambda = {lam:.6f}: {args.svg}")
        return 0

    if args.quick:
        t = mesh(0.1)
        values = lowest(t, chart=args.chart, lumped=lumped)
        near = cluster(values)
        lam = float(np.mean(near))
        print(f"V = {t.vertex_count}, eigenvalues {np.array2string(values, precision=5)}")
        print(f"lambda_1 ~ {lam:.6f} (multiplicity {len(near)}), reference {REFERENCE}, "
              f"relative error {(lam - REFERENCE) / REFERENCE:.2e}")
        assert abs(values[0]) < 1e-8, f"lambda_0 = {values[0]} is not ~0"
        assert len(near) == MULTIPLICITY, f"multiplicity {len(near)}, expected {MULTIPLICITY}"
        assert abs(lam - REFERENCE) < 0.02 * REFERENCE, f"lambda_1 = {lam}, not within 2% of {REFERENCE}"
        return 0

    start = time.perf_counter()
    rows = run(args.radii, args.chart, lumped)
    if len(rows) >= 3:
        q, fitted, fixed = richardson(rows)
        print(f"Richardson, order 2 assumed (last two meshes): {fixed:.10f}  "
              f"rel. error {(fixed - REFERENCE) / REFERENCE:.1e}")
        if fitted is not None:
            print(f"Richardson, order fitted to the last three ({2 * q:.2f}): {fitted:.10f}  "
                  f"rel. error {(fitted - REFERENCE) / REFERENCE:.1e}")
    print(f"total {time.perf_counter() - start:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
