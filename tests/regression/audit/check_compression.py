#!/usr/bin/python3
"""check_compression.py RESULTS E NU STRETCH [--rtol R]

neo_hookean_compression.xml and neo_hookean_compression_3d.xml: a Neo-Hookean block (reference width W along x,
height H along y, depth D along z in 3D) on a frictionless rigid plate that compresses it, its top held in y, its
left side in x (3D: its back in z). RESULTS is the run's output without extension (RESULTS.exo, RESULTS.history.csv).
The state is homogeneous, F = diag(l1, l2, l3), l3 = 1 in plane strain, l3 = l1 in 3D, sigma_11 = 0.
At every increment, from the Exodus file:
  - homogeneity: every bottom node at the same u_y, every right node at the same u_x (1e-9 of H);
  - l2 = 1 - u_y(bottom) / H; the exact l1 solves sigma_11 = mu/J (l1^2 - 1) + lambda ln J / J = 0
    (Bonet & Wood's compressible Neo-Hookean, J = l1 l2 l3); the computed l1 = 1 + u_x(right) / W against it;
  - the plate force (contact_force_plate_y of the history) against P_22 A, P_22 = J sigma_22 / l2 the first
    Piola-Kirchhoff stress, A = W (per unit thickness) or W D; the top's reaction against the same, opposite.
The run must reach l2 <= 1 - STRETCH (the prescribed compression, less the penalty's penetration).
Relative tolerance R (default 1e-8): a homogeneous state is exact on every element, so what is left is the
Newton tolerance (1e-9 of forces of 100)."""
import argparse
import csv
import math

import netCDF4
import numpy as np

parser = argparse.ArgumentParser()
parser.add_argument("results")
parser.add_argument("E", type=float)
parser.add_argument("nu", type=float)
parser.add_argument("stretch", type=float)
parser.add_argument("--rtol", type=float, default=1e-8)
args = parser.parse_args()
mu = args.E / (2 * (1 + args.nu))
lam = args.E * args.nu / ((1 + args.nu) * (1 - 2 * args.nu))


def names(ds, var):
    return ["".join(c.decode() for c in row if c not in (b"", b"\x00")).strip() for row in ds.variables[var][:].data]


ds = netCDF4.Dataset(args.results + ".exo")
nodal = names(ds, "name_nod_var")
three_d = "coordz" in ds.variables
blocks = names(ds, "eb_names")
body = np.unique(ds.variables[f"connect{blocks.index('block') + 1}"][:]) - 1  # not the rigid plate's nodes
x, y = ds.variables["coordx"][:][body], ds.variables["coordy"][:][body]
z = ds.variables["coordz"][:][body] if three_d else np.zeros_like(x)
W, H, D = x.max() - x.min(), y.max() - y.min(), z.max() - z.min()
tol = 1e-9 * H
bottom, top = np.abs(y - y.min()) < tol, np.abs(y - y.max()) < tol
right, front = np.abs(x - x.max()) < tol, np.abs(z - z.max()) < tol


def disp(c, k):
    return ds.variables[f"vals_nod_var{nodal.index('displ_' + c) + 1}"][k, :][body]


def sigma(l1, l2):
    l3 = l1 if three_d else 1.0
    J = l1 * l2 * l3
    s11 = mu / J * (l1 * l1 - 1) + lam * math.log(J) / J
    s22 = mu / J * (l2 * l2 - 1) + lam * math.log(J) / J
    return s11, s22, J


def exact_l1(l2):
    lo, hi = 1.0, 3.0  # compression along y: the block widens, sigma_11 < 0 at l1 = 1 and > 0 at 3
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if sigma(mid, l2)[0] < 0:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


history = list(csv.DictReader(open(args.results + ".history.csv")))
area = W * D if three_d else W
ok, worst, least_l2 = True, 0.0, 1.0
steps = ds.variables["vals_nod_var1"].shape[0]
if steps != len(history):
    print(f"FAIL: {steps} Exodus steps against {len(history)} history rows")
    ok = False
print(" step  l2          l1 (FE)      l1 (exact)   force (FE)      force (exact)   rel. differences")
for k in range(1, min(steps, len(history))):
    uy, ux = disp("y", k), disp("x", k)
    spread = max(np.ptp(uy[bottom]), np.ptp(ux[right]), np.abs(uy[top]).max())
    if three_d:
        spread = max(spread, np.ptp(disp("z", k)[front]))
    l2 = 1 - uy[bottom].mean() / H
    l1 = 1 + ux[right].mean() / W
    if three_d:
        l3 = 1 + disp("z", k)[front].mean() / D
        spread = max(spread, abs(l3 - l1) * H)
    l1_exact = exact_l1(l2)
    _, s22, J = sigma(l1_exact, l2)
    force_exact = -J * s22 / l2 * area
    force = float(history[k]["contact_force_plate_y"])
    reaction = float(history[k]["reaction_top_y"])
    d = [abs(l1 / l1_exact - 1), abs(force / force_exact - 1), abs(-reaction / force_exact - 1)]
    worst = max(worst, *d)
    least_l2 = min(least_l2, l2)
    print(f"{k:5d}  {l2:.8f}  {l1:.9f}  {l1_exact:.9f}  {force:.9e}  {force_exact:.9e}  "
          f"{d[0]:.1e} {d[1]:.1e} {d[2]:.1e}; spread {spread:.1e}")
    if spread > tol or max(d) > args.rtol:
        ok = False
print(f"largest relative difference {worst:.2e} (<= {args.rtol:g}); l2 reached {least_l2:.6f} (<= {1 - args.stretch:.6f})")
ok &= least_l2 <= 1 - args.stretch + 1e-12
print("passed" if ok else "FAIL")
raise SystemExit(0 if ok else 1)
