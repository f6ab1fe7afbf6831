#!/usr/bin/python3
"""check_uniform_pressure.py EXO --slave SET --pressure P [--rtol R]

The nodal contact_pressure of every node of the slave node set at the last step equals P (relative
tolerance R): the 3D contact patch test. Exit 0 when it holds."""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact"))
import contact_results as cr  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("exo")
parser.add_argument("--slave", required=True)
parser.add_argument("--pressure", type=float, required=True)
parser.add_argument("--rtol", type=float, default=1e-6)
args = parser.parse_args()

res = cr.Results(args.exo)
nodes = res.node_set(args.slave)
p = res.nodal("contact_pressure")[nodes]
dev = p / args.pressure - 1.0
print(f"{args.slave}: {len(nodes)} nodes, pressure {p.min():.12g} .. {p.max():.12g}; "
      f"deviation from {args.pressure:.12g}: {dev.min():+.2e} .. {dev.max():+.2e}")
if len(nodes) == 0 or np.max(np.abs(dev)) > args.rtol:
    print(f"FAIL: the pressure deviates by {np.max(np.abs(dev)) if len(nodes) else float('nan'):.2e} > {args.rtol:g}")
    sys.exit(1)
