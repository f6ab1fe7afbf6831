#!/usr/bin/python3
"""check_hydrostatic.py RESULT.exo E NU P X0 Y0 Z0 TOL

Every node's displacement at the last step against the exact field of a body under the uniform
pressure P on its whole boundary: u = -P (1 - 2 NU) / E (X - X0). Exit 0 when the largest error is
below TOL times the largest exact displacement."""
import sys

import netCDF4
import numpy as np

exo, E, nu, p, x0, y0, z0, tol = sys.argv[1], *map(float, sys.argv[2:])
with netCDF4.Dataset(exo) as d:
    X = np.column_stack([d.variables[c][:] for c in ("coordx", "coordy", "coordz")])
    names = ["".join(c.decode() for c in row if c not in (b"", b"\x00")).strip()
             for row in d.variables["name_nod_var"][:].data]
    u = np.column_stack([d.variables["vals_nod_var%d" % (names.index(c) + 1)][-1, :]
                         for c in ("displ_x", "displ_y", "displ_z")])
exact = -p * (1.0 - 2.0 * nu) / E * (X - np.array([x0, y0, z0]))
error = np.abs(u - exact).max() / np.abs(exact).max()
print(f"{len(X)} nodes: largest displacement error {error:.2e} of the largest exact displacement")
sys.exit(0 if error < tol else f"FAIL: above {tol}")
