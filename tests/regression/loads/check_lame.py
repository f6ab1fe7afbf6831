#!/usr/bin/python3
"""check_lame.py FILE A B E NU P TOLERANCE [axisymmetric]

Lame's thick-walled cylinder under internal pressure P in plane strain: every node's radial displacement
in the last step of the Exodus file FILE (2D, or 3D with plane-strain ends: z is ignored) against
u_r(r) = (1 + nu)/E ((1 - 2 nu) C1 r + C2/r), C1 = P A^2/(B^2 - A^2), C2 = P A^2 B^2/(B^2 - A^2).
With "axisymmetric" the mesh is the revolved section (r = x, u_r = u_x). Prints the largest relative error (over all nodes, and at r = A and r = B) and fails above TOLERANCE."""
import sys

import netCDF4
import numpy as np


def names(ds, var):
    return ["".join(c.decode() for c in row if c not in (b"", b"\x00")).strip() for row in ds.variables[var][:].data]


path = sys.argv[1]
a, b, E, nu, p, tolerance = map(float, sys.argv[2:8])
ds = netCDF4.Dataset(path)
nodal = names(ds, "name_nod_var")
x = ds.variables["coordx"][:]
y = ds.variables["coordy"][:]
ux = ds.variables[f"vals_nod_var{nodal.index('displ_x') + 1}"][-1, :]
uy = ds.variables[f"vals_nod_var{nodal.index('displ_y') + 1}"][-1, :]
revolved = len(sys.argv) > 8 and sys.argv[8] == "axisymmetric"
r = x if revolved else np.hypot(x, y)
ur = ux if revolved else (ux * x + uy * y) / r
c1 = p * a * a / (b * b - a * a)
c2 = p * a * a * b * b / (b * b - a * a)
exact = (1 + nu) / E * ((1 - 2 * nu) * c1 * r + c2 / r)
error = np.abs(ur - exact) / exact
inner = np.isclose(r, a, rtol=1e-9)
outer = np.isclose(r, b, rtol=1e-9)
print(f"{path}: {len(r)} nodes; u_r(a) = {ur[inner].mean():.7e} (exact {exact[inner][0]:.7e}), "
      f"u_r(b) = {ur[outer].mean():.7e} (exact {exact[outer][0]:.7e})")
print(f"largest relative error of u_r: {error.max():.3e} (at r = {r[error.argmax()]:.4f}); "
      f"at r = a: {error[inner].max():.3e}, at r = b: {error[outer].max():.3e}; tolerance {tolerance:g}")
if not inner.any() or not outer.any():
    print("FAIL: no nodes on the inner or outer radius")
    sys.exit(1)
sys.exit(0 if error.max() <= tolerance else 1)
