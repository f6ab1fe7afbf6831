#!/usr/bin/python3
"""check_cattaneo.py EXO HISTORY --mu MU --radius R --young E --poisson NU [--slave top] [--interface cylinder]
                    [--min-load 0.15] [--tolerance 0.05] [--hertz-tolerance 0.02]

Cattaneo-Mindlin on every converged increment of a rigid cylinder pressed on an elastic half-space (normal
load P first, then a tangential load Q), from the Exodus field contact_status (0 open, 1 stick, 2 slip) of
the slave surface and the history's contact force:
- contact half-width a: half the distance between the midpoints from the outermost contact nodes to their
  open neighbours; it must match Hertz, a_H = sqrt(4 P R / (pi E*)), E* = E / (1 - nu^2), within
  --hertz-tolerance (the edge is resolved to one node spacing h: h / (2 a) = 1.3 % here);
- stick half-width c: the same with the central run of sticking nodes and their slipping neighbours (a node
  that closes at the contact edge during an increment is a first contact, reported as stick: the longest
  run of consecutive stick nodes is the stick zone);
- for every increment with Q / (mu P) >= --min-load (the slip zones are then a few nodes wide):
  |(c / a) / sqrt(1 - Q / (mu P)) - 1| <= --tolerance;
- the stick zone is centred in the contact zone (offset below 2 h), and the slip zones only grow.
Exit 0 when every check holds; prints one line per increment."""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact"))
import contact_results as cr  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("exo")
parser.add_argument("history")
parser.add_argument("--mu", type=float, required=True)
parser.add_argument("--radius", type=float, required=True)
parser.add_argument("--young", type=float, required=True)
parser.add_argument("--poisson", type=float, required=True)
parser.add_argument("--slave", default="top")
parser.add_argument("--interface", default="cylinder")
parser.add_argument("--min-load", type=float, default=0.15)
parser.add_argument("--tolerance", type=float, default=0.05)
parser.add_argument("--hertz-tolerance", type=float, default=0.02)
args = parser.parse_args()

res = cr.Results(args.exo)
rows = cr.read_history(args.history)
nodes = res.node_set(args.slave)
e_star = args.young / (1.0 - args.poisson ** 2)
failures = []
checked = 0
previous_slip = 0
if len(rows) != len(res.times):
    failures.append(f"{len(rows)} history rows but {len(res.times)} Exodus steps")


def half_width(x, inside):
    """Half the distance between the midpoints from the ends of the run [first, last] to their neighbours."""
    first, last = inside
    if first == 0 or last == len(x) - 1:
        return float("nan"), float("nan")
    left, right = 0.5 * (x[first] + x[first - 1]), 0.5 * (x[last] + x[last + 1])
    return 0.5 * (right - left), 0.5 * (right + left)


for step, row in enumerate(rows):
    status = res.nodal("contact_status", step)[nodes]
    x = res.x[nodes] + res.nodal("displ_x", step)[nodes]
    order = np.argsort(x)
    x, status = x[order], status[order]
    contact = np.where(status > 0)[0]
    if len(contact) == 0:
        failures.append(f"step {step}: no contact")
        continue
    a, centre = half_width(x, (contact[0], contact[-1]))
    runs, start = [], None
    for i, s in enumerate(status):
        if s == 1 and start is None:
            start = i
        if s != 1 and start is not None:
            runs.append((start, i - 1))
            start = None
    if start is not None:
        runs.append((start, len(status) - 1))
    p = abs(row[f"contact_force_{args.interface}_y"])
    q = abs(row[f"contact_force_{args.interface}_x"])
    load = q / (args.mu * p)
    a_hertz = math.sqrt(4.0 * p * args.radius / (math.pi * e_star))
    h = float(np.median(np.diff(x[contact[0]:contact[-1] + 1])))
    slip = int(np.sum(status == 2))
    line = f"step {step}: P {p:.4f} Q {q:.4f} Q/(mu P) {load:.4f} a {a:.4f} (Hertz {a_hertz:.4f})"
    if abs(a / a_hertz - 1.0) > args.hertz_tolerance:
        failures.append(f"step {step}: a = {a:.5f} differs from Hertz {a_hertz:.5f} by more than "
                        f"{100 * args.hertz_tolerance:.1f} %")
    if slip < previous_slip:
        failures.append(f"step {step}: fewer slipping nodes ({slip}) than before ({previous_slip})")
    previous_slip = slip
    if runs:
        c, stick_centre = half_width(x, max(runs, key=lambda r: r[1] - r[0]))
        theory = math.sqrt(max(0.0, 1.0 - load))
        line += f" c {c:.4f} c/a {c / a:.4f} theory {theory:.4f} ({100 * ((c / a) / theory - 1):+.2f} %) slip nodes {slip}"
        if load >= args.min_load:
            checked += 1
            if not abs((c / a) / theory - 1.0) <= args.tolerance:
                failures.append(f"step {step}: c/a = {c / a:.4f}, Cattaneo-Mindlin {theory:.4f} "
                                f"(more than {100 * args.tolerance:.1f} % apart)")
            if abs(stick_centre - centre) > 2 * h:
                failures.append(f"step {step}: stick zone centred at {stick_centre:.4f}, contact at {centre:.4f}")
    print(line)
if checked == 0:
    failures.append(f"no increment with Q/(mu P) >= {args.min_load}")
for f in failures:
    print("FAIL:", f)
print(f"{checked} increments checked against Cattaneo-Mindlin, {len(failures)} failures")
sys.exit(1 if failures else 0)
