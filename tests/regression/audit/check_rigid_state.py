#!/usr/bin/python3
"""check_rigid_state.py EXODUS UX UY [UZ] [--atol A]

The last step of EXODUS is a rigid translation: every node of the block 'block' has its displacement is (UX, UY[, UZ]) within A (default
1e-10: the Newton tolerance 1e-9 on forces over stiffnesses of 1e3). press_slide_release.xml: a block released
from its base after sliding, held only at its top edge."""
import argparse

import netCDF4
import numpy as np

parser = argparse.ArgumentParser()
parser.add_argument("exodus")
parser.add_argument("u", type=float, nargs="+")
parser.add_argument("--atol", type=float, default=1e-10)
args = parser.parse_args()
ds = netCDF4.Dataset(args.exodus)
nodal = ["".join(c.decode() for c in row if c not in (b"", b"\x00")).strip() for row in ds.variables["name_nod_var"][:].data]
blocks = ["".join(c.decode() for c in row if c not in (b"", b"\x00")).strip() for row in ds.variables["eb_names"][:].data]
body = np.unique(ds.variables[f"connect{blocks.index('block') + 1}"][:]) - 1  # not the rigid base's nodes
worst = 0.0
for c, value in zip("xyz", args.u):
    u = ds.variables[f"vals_nod_var{nodal.index('displ_' + c) + 1}"][-1, :][body]
    worst = max(worst, float(np.abs(u - value).max()))
    print(f"u_{c}: from {float(u.min()):.12g} to {float(u.max()):.12g} (expected {value:g})")
print(f"largest difference {worst:.2e} (<= {args.atol:g})")
print("passed" if worst <= args.atol else "FAIL")
raise SystemExit(0 if worst <= args.atol else 1)
