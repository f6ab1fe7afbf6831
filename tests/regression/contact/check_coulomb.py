#!/usr/bin/python3
"""check_coulomb.py EXO HISTORY --mu MU --eps-t EPS_T [--interface base] [--slave bottom] [--reaction top]

Coulomb friction checks on every converged step of a block pressed on a flat rigid base and sheared
along x (monotonically), from the history and the Exodus file:
- normal force = sum of contact_pressure x tributary length (rtol 1e-9; flat rigid base: n = e_y exactly);
- tangential contact force = - reaction_<top>_x (global equilibrium, to 1e-9 x normal force);
- every node sticks (slip = 0): |F_x| < mu F_y, and the stick traction is the tangential penalty times the
  elastic slip: sum of eps_T x tributary length x contact_slip = |F_x| (rtol 1e-8; monotone loading);
- every node slips (stick = 0, slip = active): |F_x| / F_y = mu (rtol 1e-9);
- the number of slipping nodes never decreases (monotone shear).
Exit 0 when every check holds; prints one line per step."""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import contact_results as cr  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("exo")
parser.add_argument("history")
parser.add_argument("--mu", type=float, required=True)
parser.add_argument("--eps-t", type=float, required=True)
parser.add_argument("--interface", default="base")
parser.add_argument("--slave", default="bottom")
parser.add_argument("--reaction", default="top")
parser.add_argument("--require-stick-steps", type=int, default=1, help="at least this many all-stick steps")
parser.add_argument("--require-slide-steps", type=int, default=1, help="at least this many all-slip steps")
args = parser.parse_args()

res = cr.Results(args.exo)
rows = cr.read_history(args.history)
nodes, length = cr.surface_nodes(res, args.slave)
failures = []
stick_steps = slide_steps = 0
previous_slip = 0
if len(rows) != len(res.times):
    failures.append(f"{len(rows)} history rows but {len(res.times)} Exodus steps")
for step, row in enumerate(rows):
    fx = row[f"contact_force_{args.interface}_x"]
    fy = row[f"contact_force_{args.interface}_y"]
    active, stick, slip = int(row["active_contacts"]), int(row["stick"]), int(row["slip"])
    p = res.nodal("contact_pressure", step)[nodes]
    g_t = res.nodal("contact_slip", step)[nodes]
    normal = float(np.sum(p * length))
    penalty_force = args.eps_t * float(np.sum(g_t * length))
    ratio = abs(fx) / fy if fy > 0 else float("nan")
    state = "open"
    if active > 0 and slip == 0:
        state = "stick"
    elif active > 0 and stick == 0:
        state = "slide"
    elif active > 0:
        state = "partial"
    print(f"step {step}: lambda {row['lambda']:.3f} active {active} stick {stick} slip {slip} "
          f"Fx {fx:+.10f} Fy {fy:.10f} |Fx|/Fy {ratio:.10f} [{state}] "
          f"eps_T sum(A g_T) {penalty_force:.10f}")
    if fy > 0 and abs(normal - fy) > 1e-9 * fy:
        failures.append(f"step {step}: sum p A = {normal!r} differs from contact_force_y = {fy!r}")
    react = row[f"reaction_{args.reaction}_x"]
    if abs(fx + react) > 1e-9 * max(fy, 1e-300):
        failures.append(f"step {step}: contact force x {fx!r} is not minus the reaction {react!r}")
    if slip < previous_slip:
        failures.append(f"step {step}: fewer slipping nodes ({slip}) than before ({previous_slip})")
    previous_slip = slip
    if state == "stick":
        stick_steps += 1
        if not abs(fx) < args.mu * fy:
            failures.append(f"step {step}: all nodes stick but |Fx|/Fy = {ratio} >= mu = {args.mu}")
        if abs(penalty_force - abs(fx)) > 1e-8 * max(abs(fx), 1e-8 * fy):
            failures.append(f"step {step}: eps_T sum(A g_T) = {penalty_force!r} differs from |Fx| = {abs(fx)!r}")
    if state == "slide":
        slide_steps += 1
        if abs(ratio / args.mu - 1.0) > 1e-9:
            failures.append(f"step {step}: all nodes slip but |Fx|/Fy = {ratio!r}, mu = {args.mu}")
if stick_steps < args.require_stick_steps:
    failures.append(f"only {stick_steps} all-stick steps, expected >= {args.require_stick_steps}")
if slide_steps < args.require_slide_steps:
    failures.append(f"only {slide_steps} all-slip steps, expected >= {args.require_slide_steps}")
for f in failures:
    print("FAIL:", f)
print(f"{stick_steps} all-stick steps, {slide_steps} all-slip steps, {len(failures)} failures")
sys.exit(1 if failures else 0)
