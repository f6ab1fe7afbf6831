#!/usr/bin/python3
"""check_applied_balance.py HISTORY.csv --applied NAME --reactions SET[,SET...] [--rtol R]

The Applied Force point history of a body whose every load acts on the request's node set (loads on sets:
pressure, traction, body force; and nodal forces) against the body's equilibrium: the reactions of its
supported node sets (summed internal forces minus loads, theory-solids §7) balance it, at every converged
increment: NAME_c + sum of reaction_SET_c = 0 within rtol x max |NAME_c| for every component c. Exit 0
when it holds at every row (and the applied force is not zero at the last)."""
import argparse
import csv
import sys

parser = argparse.ArgumentParser()
parser.add_argument("history")
parser.add_argument("--applied", required=True)
parser.add_argument("--reactions", required=True)
parser.add_argument("--rtol", type=float, default=1e-8)
args = parser.parse_args()

rows = list(csv.DictReader(open(args.history)))
sets = args.reactions.split(",")
axes = [a for a in ("x", "y", "z") if f"{args.applied}_{a}" in rows[0]]
scale = max(abs(float(r[f"{args.applied}_{a}"])) for r in rows for a in axes)
if scale == 0.0:
    sys.exit(f"FAIL: {args.applied} is zero throughout")
worst = 0.0
for r in rows:
    for a in axes:
        balance = float(r[f"{args.applied}_{a}"]) + sum(float(r[f"reaction_{s}_{a}"]) for s in sets)
        worst = max(worst, abs(balance) / scale)
last = rows[-1]
print(f"{args.applied} at the end: " + ", ".join(f"{a} {float(last[f'{args.applied}_{a}']):.10g}" for a in axes) +
      f"; max |applied + reactions| / max |applied| = {worst:.3e} (tolerance {args.rtol:g})")
sys.exit(0 if worst <= args.rtol else 1)
