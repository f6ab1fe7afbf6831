#!/usr/bin/python3
"""check_inflation.py FILE A B E NU P TOLERANCE [MIN_STRETCH]

The finite-strain inflation of a Neo-Hookean thick-walled cylinder (plane strain) by a follower pressure
P at load factor 1: at every converged increment of the Exodus file FILE, the applied pressure
lambda P against the exact pressure at the computed inner stretch l_a = (A + u_x(A, 0)) / A
(neo_hookean_cylinder.py). Prints each increment; fails when a relative difference exceeds TOLERANCE
or the run did not reach an inner stretch of MIN_STRETCH (default 1.5)."""
import os
import sys

import netCDF4
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from neo_hookean_cylinder import pressure  # noqa: E402


def names(ds, var):
    return ["".join(c.decode() for c in row if c not in (b"", b"\x00")).strip() for row in ds.variables[var][:].data]


path = sys.argv[1]
a, b, E, nu, p, tolerance = map(float, sys.argv[2:8])
min_stretch = float(sys.argv[8]) if len(sys.argv) > 8 else 1.5
ds = netCDF4.Dataset(path)
nodal = names(ds, "name_nod_var")
glob = names(ds, "name_glo_var")
x = ds.variables["coordx"][:]
y = ds.variables["coordy"][:]
z = ds.variables["coordz"][:] if "coordz" in ds.variables else np.zeros_like(x)
node = int(np.argmin(np.abs(x - a) + np.abs(y) + np.abs(z)))  # the inner node on the x axis (z = 0)
ux = ds.variables[f"vals_nod_var{nodal.index('displ_x') + 1}"][:, node]
load = ds.variables["vals_glo_var"][:, glob.index("load_factor")]
worst, reached = 0.0, 1.0
print(" step  lambda    l_a        p (FE)       p (exact)    rel. difference")
for k in range(1, len(load)):
    la = (a + ux[k]) / a
    applied = load[k] * p
    exact = pressure(la, a, b, E, nu)
    difference = abs(applied - exact) / exact
    worst = max(worst, difference)
    reached = max(reached, la)
    print(f"{k:5d}  {load[k]:.5f}  {la:.6f}  {applied:.6e}  {exact:.6e}  {difference:.3e}")
print(f"{path}: largest relative difference {worst:.3e} (tolerance {tolerance:g}), inner stretch reached {reached:.4f}")
sys.exit(0 if worst <= tolerance and reached >= min_stretch else 1)
