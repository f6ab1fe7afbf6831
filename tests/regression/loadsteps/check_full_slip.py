#!/usr/bin/python3
"""check_full_slip.py HISTORY.csv --interface NAME --mu MU [--rtol R]

Coulomb's law at full sliding (eq. 19 of the reference paper): when every node of the interface slides
at the end of the run (history: slip = active_contacts > 0), the tangential contact force is mu times the
normal force: |contact_force_NAME_x| = mu * |contact_force_NAME_y| (2D; in 3D the tangential force is
the norm of x and z). Exit 0 when that holds within --rtol."""
import argparse
import csv
import math
import sys

parser = argparse.ArgumentParser()
parser.add_argument("history")
parser.add_argument("--interface", required=True)
parser.add_argument("--mu", type=float, required=True)
parser.add_argument("--rtol", type=float, default=1e-9)
args = parser.parse_args()

last = list(csv.DictReader(open(args.history)))[-1]
active, slip = int(float(last["active_contacts"])), int(float(last["slip"]))
if active == 0 or slip != active:
    sys.exit(f"FAIL: {slip} of {active} contact nodes slide at the end; full sliding expected")
prefix = f"contact_force_{args.interface}_"
normal = abs(float(last[prefix + "y"]))
tangential = math.hypot(float(last[prefix + "x"]), float(last.get(prefix + "z", 0.0)))
ratio = tangential / normal
error = abs(ratio - args.mu) / args.mu
print(f"{slip} of {active} nodes slide: tangential {tangential:.12g}, normal {normal:.12g}, ratio {ratio:.12g} "
      f"against mu = {args.mu:g} (rel. error {error:.3e}, tolerance {args.rtol:g})")
sys.exit(0 if error <= args.rtol else 1)
