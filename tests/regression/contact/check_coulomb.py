#!/usr/bin/python3
"""check_coulomb.py EXO HISTORY --mu MU --eps-t EPS_T [--slip-tolerance S] [--shear-direction {1,-1}]
                   [--interface base] [--slave bottom] [--reaction top]

Coulomb friction checks on every converged step of a block pressed on a flat rigid base and sheared
along x (monotonically), from the history and the Exodus file:
- normal force = sum of contact_pressure x tributary length (rtol 1e-9; flat rigid base: n = e_y exactly);
- tangential contact force = - reaction_<top>_x (global equilibrium, to 1e-9 x normal force);
- every node sticks (slip = 0): |F_x| < mu F_y, and the stick traction is the tangential penalty times the
  elastic slip: sum of eps_T x tributary length x contact_slip = |F_x| (rtol 1e-8; monotone loading);
  with --slip-tolerance S > 0 the penalty of node k is eps_T,k = mu p_k / (S L_k) (L_k: mean length of the
  slave sides at the node), capped by --eps-t when that is > 0 (docs/theory-contact.md, slip tolerance),
  and since p_k changes from step to step the stick traction is summed as eq. (20) does:
  t_k = sum over steps of eps_T,k(p_k) x (increment of contact_slip);
- every node slips (stick = 0, slip = active): |F_x| / F_y = mu (rtol 1e-9);
- the friction force opposes the shear: F_x has the sign of -(--shear-direction) once it is non-zero;
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
parser.add_argument("--eps-t", type=float, required=True, help="constant eps_T, or its cap with --slip-tolerance")
parser.add_argument("--slip-tolerance", type=float, default=0.0)
parser.add_argument("--shear-direction", type=float, default=1.0, choices=[1.0, -1.0])
parser.add_argument("--interface", default="base")
parser.add_argument("--slave", default="bottom")
parser.add_argument("--reaction", default="top")
parser.add_argument("--require-stick-steps", type=int, default=1, help="at least this many all-stick steps")
parser.add_argument("--require-slide-steps", type=int, default=1, help="at least this many all-slip steps")
args = parser.parse_args()

res = cr.Results(args.exo)
rows = cr.read_history(args.history)
nodes, length = cr.surface_nodes(res, args.slave)
# Facet length of each node: the mean of its adjacent sides (the end nodes have one side).
facet = 2.0 * length / np.array([1.0 if i in (0, len(nodes) - 1) else 2.0 for i in range(len(nodes))])
failures = []
stick_traction = np.zeros(len(nodes))  # eq. (20) in stick: t_{n+1} = t_n + eps_T(p_{n+1}) (g_T,n+1 - g_T,n)
previous_g_t = np.zeros(len(nodes))
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
    eps_t = np.full(len(nodes), args.eps_t)
    if args.slip_tolerance > 0:
        eps_t = args.mu * p / (args.slip_tolerance * facet)
        if args.eps_t > 0:
            eps_t = np.minimum(eps_t, args.eps_t)
    stick_traction += eps_t * (g_t - previous_g_t)
    previous_g_t = g_t
    penalty_force = float(np.sum(stick_traction * length))
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
    if fx != 0 and np.sign(fx) != -args.shear_direction:
        failures.append(f"step {step}: friction force {fx!r} does not oppose the shear direction {args.shear_direction}")
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
