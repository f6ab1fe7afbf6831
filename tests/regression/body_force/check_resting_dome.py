#!/usr/bin/python3
"""check_resting_dome.py RESULTS RHOG VOLUME_TOLERANCE

A body under its own weight resting on a frictionless rigid flat (resting_dome_tet10.xml): equilibrium in y,
    contact_force_flat_y = rho g V_h,
V_h the volume of the run's TETRA10 mesh (RESULTS.exo), integrated here on every tetrahedron's isoparametric
map (Exodus TETRA10 shape functions) with a 125-point collapsed Gauss rule (exact to degree 7 in the parent
tetrahedron; det J of a curved Tet10 is of degree 3), independent of the kernel's 4-point rule. Checks the
contact force (RESULTS.history.csv, last row) against rho g V_h within VOLUME_TOLERANCE (relative: the kernel's
4-point rule is exact for det J on straight-sided cells only; its difference on the curved ones is printed),
and V_h against the octant of the unit ball, pi / 6, within 1e-2 (the mesh's geometric error)."""
import csv
import sys

import netCDF4
import numpy as np

EDGES = [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)]


def shape(xi):
    """TETRA10 shape functions and their gradients at parent points xi (n x 3): N (n x 10), dN (n x 10 x 3)."""
    n = xi.shape[0]
    L = np.column_stack([1.0 - xi.sum(axis=1), xi])
    dL = np.array([[-1.0, -1.0, -1.0], [1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]])
    N = np.zeros((n, 10))
    dN = np.zeros((n, 10, 3))
    for a in range(4):
        N[:, a] = L[:, a] * (2 * L[:, a] - 1)
        dN[:, a, :] = np.outer(4 * L[:, a] - 1, dL[a])
    for e, (a, b) in enumerate(EDGES):
        N[:, 4 + e] = 4 * L[:, a] * L[:, b]
        dN[:, 4 + e, :] = 4 * (np.outer(L[:, b], dL[a]) + np.outer(L[:, a], dL[b]))
    return N, dN


def collapsed_rule(m):
    """m^3 points on the unit tetrahedron: Gauss-Legendre on the cube mapped by xi = u, eta = v (1 - u),
    zeta = w (1 - u)(1 - v), Jacobian (1 - u)^2 (1 - v)."""
    g, w = np.polynomial.legendre.leggauss(m)
    g, w = 0.5 * (g + 1), 0.5 * w
    pts, wts = [], []
    for i in range(m):
        for j in range(m):
            for k in range(m):
                u, v, s = g[i], g[j], g[k]
                pts.append([u, v * (1 - u), s * (1 - u) * (1 - v)])
                wts.append(w[i] * w[j] * w[k] * (1 - u) ** 2 * (1 - v))
    return np.array(pts), np.array(wts)


def four_point_rule():
    a, b = (5 + 3 * np.sqrt(5)) / 20, (5 - np.sqrt(5)) / 20
    return np.array([[b, b, b], [a, b, b], [b, a, b], [b, b, a]]), np.full(4, 1 / 24)


def volume(X, conn, rule):
    pts, wts = rule
    _, dN = shape(pts)
    total = 0.0
    for cell in conn:
        J = np.einsum("qam,ia->qim", dN, X[:, cell])  # dX_i/dxi_m at every point
        total += np.sum(wts * np.linalg.det(J))
    return total


results = sys.argv[1]
rhog, tolerance = float(sys.argv[2]), float(sys.argv[3])
ds = netCDF4.Dataset(results + ".exo")
X = np.array([ds.variables["coord" + c][:] for c in "xyz"])
conn = np.asarray(ds.variables["connect1"][:]) - 1
assert ds.variables["connect1"].getncattr("elem_type").upper().startswith("TETRA") and conn.shape[1] == 10
V = volume(X, conn, collapsed_rule(5))
V4 = volume(X, conn, four_point_rule())
with open(results + ".history.csv") as f:
    force = float(list(csv.DictReader(f))[-1]["contact_force_flat_y"])
rel = abs(force - rhog * V) / (rhog * V)
geometric = abs(V - np.pi / 6) / (np.pi / 6)
print(f"{results}.exo: {len(conn)} TETRA10; V_h = {V:.12f} (125 points), {V4:.12f} (4 points: relative "
      f"{abs(V4 - V) / V:.2e}); pi/6 = {np.pi / 6:.12f}: relative {geometric:.2e} (tolerance 1e-2)")
print(f"contact_force_flat_y = {force:.12e}, rho g V_h = {rhog * V:.12e}: relative {rel:.2e} (tolerance {tolerance:g}); "
      f"rho g V_h(4 points) = {rhog * V4:.12e}: relative {abs(force - rhog * V4) / (rhog * V4):.2e}")
ok = rel <= tolerance and geometric <= 1e-2
print("passed" if ok else "FAIL")
sys.exit(0 if ok else 1)
