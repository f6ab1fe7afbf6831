#!/usr/bin/python3
"""check_quadratic_patch.py EXO --slave SET --pressure P --grid H --corner-max C --mid-ratio R --rtol T

The matching contact patch test on TRI6 slave faces (Tet10 blocks): in the limit of a stiff penalty the
two bodies act as one, so the contact forces tend to the consistent nodal loads of the uniform pressure,
which are 0 at the faces' corners and A/3 at their mid-edge nodes, whatever the slave weights
(docs/verification-contact.md §11). With the sub-facet weights (A/12, A/4) the nodal contact pressure is
then ~0 at a corner node and (A/3)/(A/4) = 4/3 P at a mid-edge node. Checked at the last step: every
corner node (x and z multiples of the grid size H) below C x P, every mid-edge node within T of R x P.
Exit 0 when it holds."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact"))
import contact_results as cr  # noqa: E402

args = cr.required_options("exo", texts=["--slave"],
                           numbers=["--pressure", "--grid", "--corner-max", "--mid-ratio", "--rtol"])

res = cr.Results(args.exo)
nodes = res.node_set(args.slave)
p = res.nodal("contact_pressure")[nodes] / args.pressure
on_grid = lambda v: np.abs(v / args.grid - np.round(v / args.grid)) < 1e-9  # noqa: E731
corner = on_grid(res.x[nodes]) & on_grid(res.z[nodes])
print(f"{args.slave}: {corner.sum()} corner nodes, p/P {p[corner].min():.4g} .. {p[corner].max():.4g}; "
      f"{(~corner).sum()} mid-edge nodes, p/P {p[~corner].min():.6g} .. {p[~corner].max():.6g}")
failed = False
if corner.sum() == 0 or p[corner].max() > args.corner_max:
    print(f"FAIL: a corner node carries more than {args.corner_max:g} P")
    failed = True
if (~corner).sum() == 0 or np.max(np.abs(p[~corner] / args.mid_ratio - 1.0)) > args.rtol:
    print(f"FAIL: a mid-edge node is off {args.mid_ratio:g} P by more than {args.rtol:g}")
    failed = True
sys.exit(1 if failed else 0)
