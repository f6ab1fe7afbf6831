#!/usr/bin/python3
"""check_uniform_pressure.py EXO --slave SET --pressure P [--rtol R]
                             [--history CSV --force COLUMN --area A --force-rtol F]

The nodal contact_pressure of every node of the slave node set at the last step equals P (relative
tolerance R): the 3D contact patch test. On non-matching faces, where node-to-face does not pass the
patch test, R bounds the measured deviation instead. With --history, the total contact force at the last
row (|COLUMN|) also equals P x A (relative tolerance F). Exit 0 when it holds."""
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
parser.add_argument("--history")
parser.add_argument("--force", default="contact_force_interface_y")
parser.add_argument("--area", type=float, default=1.0)
parser.add_argument("--force-rtol", type=float, default=1e-6)
args = parser.parse_args()

failed = False
res = cr.Results(args.exo)
nodes = res.node_set(args.slave)
p = res.nodal("contact_pressure")[nodes]
dev = p / args.pressure - 1.0
print(f"{args.slave}: {len(nodes)} nodes, pressure {p.min():.12g} .. {p.max():.12g}; "
      f"deviation from {args.pressure:.12g}: {dev.min():+.2e} .. {dev.max():+.2e}")
if len(nodes) == 0 or np.max(np.abs(dev)) > args.rtol:
    print(f"FAIL: the pressure deviates by {np.max(np.abs(dev)) if len(nodes) else float('nan'):.2e} > {args.rtol:g}")
    failed = True
if args.history:
    force = abs(cr.read_history(args.history)[-1][args.force])
    error = force / (args.pressure * args.area) - 1.0
    print(f"|{args.force}| = {force:.12g}, P x A = {args.pressure * args.area:.12g}: relative error {error:+.2e}")
    if abs(error) > args.force_rtol:
        print(f"FAIL: the total force is off by {abs(error):.2e} > {args.force_rtol:g}")
        failed = True
sys.exit(1 if failed else 0)
