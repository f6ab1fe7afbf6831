#!/usr/bin/python3
"""check_patch.py EXO HISTORY --interface NAME --slave SET [SET ...] [--uniform P --rtol R]

Contact patch test checks on the last step of a run:
- consistency of the output: the nodal contact_pressure of the slave nodes (of every pass) times their
  tributary lengths adds up to |contact_force_<NAME>_y| (rtol 1e-7: the force is the sum of p A n_y,
  and where the pressure is not uniform the master segments tilt by theta ~ 1e-4 rad, so n_y = 1 - O(1e-8);
  measured 3e-12 for uniform states, 1.2e-8 for the 4 against 3 meshes), and that force equals the top
  reaction (reaction_upper_top_y, rtol 1e-9: global equilibrium);
- with --uniform P: every slave node of every pass carries the pressure P (relative tolerance --rtol).
Prints the pressure distribution. Exit 0 when every check holds."""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import contact_results as cr  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("exo")
parser.add_argument("history")
parser.add_argument("--interface", default="interface")
parser.add_argument("--slave", nargs="+", required=True, help="slave side/node sets (two for two-pass)")
parser.add_argument("--uniform", type=float, help="expected uniform pressure at every slave node")
parser.add_argument("--rtol", type=float, default=1e-9)
args = parser.parse_args()

res = cr.Results(args.exo)
last = cr.read_history(args.history)[-1]
force = last[f"contact_force_{args.interface}_y"]
pressure = res.nodal("contact_pressure")
failures = []
total = 0.0
for name in args.slave:
    nodes, length = cr.surface_nodes(res, name)
    p = pressure[nodes]
    total += float(np.sum(p * length))
    line = " ".join(f"{v:.6f}" for v in p)
    if args.uniform is not None:
        dev = p / args.uniform - 1.0
        print(f"{name}: pressure {line}; deviation from {args.uniform:.10g}: {dev.min():+.2e} .. {dev.max():+.2e}")
        if np.max(np.abs(dev)) > args.rtol:
            failures.append(f"{name}: pressure deviates by {np.max(np.abs(dev)):.2e} > {args.rtol:g}")
    else:
        print(f"{name}: pressure {line}")
rel = abs(total - abs(force)) / abs(force)
print(f"sum of pressure x tributary length {total:.12g}, |contact_force_{args.interface}_y| {abs(force):.12g} "
      f"(rel. diff {rel:.1e}); reaction_upper_top_y {last['reaction_upper_top_y']:.12g}")
if rel > 1e-7:
    failures.append(f"nodal pressures do not add up to the contact force (rel. diff {rel:.2e} > 1e-7)")
if abs(last["reaction_upper_top_y"] - (-abs(force))) > 1e-9 * abs(force):
    failures.append("the top reaction differs from the contact force")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
