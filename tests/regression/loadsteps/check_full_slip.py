#!/usr/bin/python3
"""check_full_slip.py HISTORY.csv --interface NAME --mu MU [--rtol R] [--spread S]

Coulomb's law at full sliding (eq. 19 of the reference paper): when every node of the interface slides
at the end of the run (history: slip = active_contacts > 0), every node's tangential traction is mu times
its normal one. In 2D (one tangent) the resultants follow: |contact_force_NAME_x| = mu |contact_force_NAME_y|
within --rtol. In 3D each node slides along its own direction, so the resultant tangential force (the norm
of x and z) is at most mu P, and equal only when every node slides the same way: with --spread S it must
lie in [mu (1 - S), mu (1 + rtol)] P. Exit 0 when that holds."""
import argparse
import csv
import math
import sys

parser = argparse.ArgumentParser()
parser.add_argument("history")
parser.add_argument("--interface", required=True)
parser.add_argument("--mu", type=float, required=True)
parser.add_argument("--rtol", type=float, default=1e-9)
parser.add_argument("--spread", type=float, default=0.0,
                    help="3D: how far below mu P the resultant may lie (the nodes' slip directions differ)")
args = parser.parse_args()

last = list(csv.DictReader(open(args.history)))[-1]
active, slip = int(float(last["active_contacts"])), int(float(last["slip"]))
if active == 0 or slip != active:
    sys.exit(f"FAIL: {slip} of {active} contact nodes slide at the end; full sliding expected")
prefix = f"contact_force_{args.interface}_"
normal = abs(float(last[prefix + "y"]))
tangential = math.hypot(float(last[prefix + "x"]), float(last.get(prefix + "z", 0.0)))
ratio = tangential / normal
error = (ratio - args.mu) / args.mu
ok = -(args.rtol + args.spread) <= error <= args.rtol
print(f"{slip} of {active} nodes slide: tangential {tangential:.12g}, normal {normal:.12g}, ratio {ratio:.12g} "
      f"against mu = {args.mu:g} (rel. difference {error:.3e}, allowed [-{args.rtol + args.spread:g}, {args.rtol:g}])")
sys.exit(0 if ok else 1)
