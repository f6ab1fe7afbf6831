#!/usr/bin/python3
"""check_lame_sphere.py RESULTS A B E NU P TOLERANCE [--axisymmetric]

Lame's thick-walled sphere a <= r <= b under internal pressure p (Timoshenko & Goodier, Theory of
Elasticity, §141): u_r(r) = p a^3 / (E (b^3 - a^3)) ((1 - 2 nu) r + (1 + nu) b^3 / (2 r^2)).
RESULTS is the run's <name> (RESULTS.exo and RESULTS.history.csv). Checks, at the last step:
  - every node's radial displacement against u_r(r): the largest error relative to u_r(a) <= TOLERANCE;
  - the normal reaction of each symmetry cut (history columns reaction_symmetry_<a>_<a> in 3D, the octant;
    reaction_equator_y with --axisymmetric, the upper half of the section revolved) against the pressure's
    resultant on the bore it holds: -p pi a^2 / 4 on an octant's cut, -p pi a^2 on the equator of the
    revolved quarter section; within 1e-4 relative (the pressure follows the bore, whose radius grows by
    u_r(a)/a ~ 1e-5, and the curved faces are interpolated: measured 1.6e-6 and below).
With --axisymmetric the mesh is the 2D section revolved about y (r = sqrt(x^2 + y^2) in the section)."""
import csv
import sys

import netCDF4
import numpy as np


def names(ds, var):
    return ["".join(c.decode() for c in row if c not in (b"", b"\x00")).strip() for row in ds.variables[var][:].data]


results = sys.argv[1]
a, b, E, nu, p, tolerance = map(float, sys.argv[2:8])
axisymmetric = "--axisymmetric" in sys.argv[8:]
ds = netCDF4.Dataset(results + ".exo")
nodal = names(ds, "name_nod_var")
axes = "xy" if axisymmetric else "xyz"
X = np.array([ds.variables["coord" + c][:] for c in axes])
U = np.array([ds.variables[f"vals_nod_var{nodal.index('displ_' + c) + 1}"][-1, :] for c in axes])
r = np.linalg.norm(X, axis=0)
ur = np.sum(U * X, axis=0) / r
exact = p * a**3 / (E * (b**3 - a**3)) * ((1 - 2 * nu) * r + (1 + nu) * b**3 / (2 * r**2))
scale = exact.max()  # u_r(a)
error = np.abs(ur - exact) / scale
inner = np.isclose(r, a, rtol=1e-6)
outer = np.isclose(r, b, rtol=1e-6)
ok = inner.any() and outer.any()
print(f"{results}.exo: {len(r)} nodes; u_r(a) = {ur[inner].mean():.7e} (exact {exact[inner].mean():.7e}), "
      f"u_r(b) = {ur[outer].mean():.7e} (exact {exact[outer].mean():.7e})")
print(f"largest error of u_r over u_r(a): {error.max():.3e} at r = {r[error.argmax()]:.4f}; tolerance {tolerance:g}")
ok = ok and error.max() <= tolerance

with open(results + ".history.csv") as f:
    row = list(csv.DictReader(f))[-1]
if axisymmetric:
    cuts = {"reaction_equator_y": -p * np.pi * a**2}
else:
    cuts = {f"reaction_symmetry_{c}_{c}": -p * np.pi * a**2 / 4 for c in "xyz"}
for column, expected in cuts.items():
    value = float(row[column])
    rel = abs(value - expected) / abs(expected)
    print(f"{column} = {value:.9e}, -p pi a^2{'' if axisymmetric else ' / 4'} = {expected:.9e}: relative {rel:.2e}")
    ok = ok and rel <= 1e-4
print("passed" if ok else "FAIL")
sys.exit(0 if ok else 1)
