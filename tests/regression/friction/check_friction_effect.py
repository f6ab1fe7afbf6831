#!/usr/bin/python3
"""check_friction_effect.py FRICTIONAL.csv FRICTIONLESS.csv --mu MU --motion D [--up-to D1] [--max-change R]
                           [--interface NAME]

Compares the plate force of a frictional run with the frictionless run of the same deck (history CSVs of a
rigid plate moving by D x load factor): for every converged increment of the frictional run with a plate
displacement in (0, D1], the frictionless force is interpolated linearly at that displacement, and
|F_y / F_y,0 - 1| <= R must hold (friction changes the force by a fraction of a percent there; the
interpolation error of a 1.6 mm step on this curve is below 4e-4 relative). Every row must also satisfy the
Coulomb bound of a flat rigid plate, |F_x| <= mu |F_y| (1 + 1e-9): each node carries |t_T| <= mu |t_N|.
Prints the table; exit 0 when both hold."""
import argparse
import csv
import sys

import numpy as np

parser = argparse.ArgumentParser()
parser.add_argument("frictional")
parser.add_argument("frictionless")
parser.add_argument("--mu", type=float, required=True)
parser.add_argument("--motion", type=float, required=True, help="plate displacement at load factor 1")
parser.add_argument("--up-to", type=float, default=51.2, help="compare up to this plate displacement")
parser.add_argument("--max-change", type=float, default=0.01)
parser.add_argument("--interface", default="plate")
args = parser.parse_args()


def read(path):
    rows = list(csv.DictReader(open(path)))
    d = np.array([float(r["lambda"]) * abs(args.motion) for r in rows])
    fx = np.array([float(r[f"contact_force_{args.interface}_x"]) for r in rows])
    fy = np.array([float(r[f"contact_force_{args.interface}_y"]) for r in rows])
    return d, fx, fy


d, fx, fy = read(args.frictional)
d0, _, fy0 = read(args.frictionless)
failures = []
compared = 0
worst = 0.0
print(f"{'d (mm)':>8} {'F_y':>12} {'F_y,0':>12} {'change':>9} {'|F_x|/|F_y|':>12}")
for di, fxi, fyi in zip(d, fx, fy):
    ratio = abs(fxi) / abs(fyi) if fyi != 0 else 0.0
    if abs(fxi) > args.mu * abs(fyi) * (1 + 1e-9):
        failures.append(f"d = {di:.3f}: |F_x| = {abs(fxi):.6g} exceeds mu |F_y| = {args.mu * abs(fyi):.6g}")
    if di <= 0 or di > args.up_to * (1 + 1e-12):
        continue
    if di > d0[-1] * (1 + 1e-12):
        failures.append(f"d = {di:.3f} beyond the frictionless run (ends at {d0[-1]:.3f})")
        continue
    f0 = float(np.interp(di, d0, fy0))
    change = fyi / f0 - 1.0
    compared += 1
    worst = max(worst, abs(change))
    print(f"{di:8.3f} {fyi:12.6f} {f0:12.6f} {100 * change:8.3f}% {ratio:12.5f}")
    if abs(change) > args.max_change:
        failures.append(f"d = {di:.3f}: plate force {fyi:.6f} differs from the frictionless {f0:.6f} by "
                        f"{100 * change:.3f} % (at most {100 * args.max_change:.3f} %)")
if compared == 0:
    failures.append("no common displacement compared")
print(f"{compared} displacements compared up to {args.up_to} mm, largest change {100 * worst:.3f} %")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
