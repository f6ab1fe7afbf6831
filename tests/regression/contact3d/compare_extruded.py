#!/usr/bin/python3
"""compare_extruded.py HISTORY_2D HISTORY_3D --thickness T --node-layers L [--force-rtol R] [--reaction-rtol R]

A 2D plane-strain run against its extrusion into 3D (L layers of nodes, thickness T, u_z = 0): at every
increment the same load factor, the same contact nodes (L times as many in 3D), the plate force per unit
thickness (contact_force_plate_y / T) and the support reaction per unit thickness (reaction_start_y / T)
within the given relative tolerances. Prints the worst differences. Exit 0 when every check holds.

Why two tolerances: the plate force is a sum of penalty forces eps_N g_N A; with eps_N = 1e9 one unit
in the last place of a nodal position (1.4e-14 at 100 mm) moves it by about 1e-4 N, so it carries
round-off of that size in ANY run (the 2D run's own plate force and support reaction differ by up to
1.1e-5 relative). The reaction is a sum of internal forces, with no such amplification: it compares the
two discretisations to round-off."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact"))
import contact_results as cr  # noqa: E402

args, a, b = cr.two_histories("two", "three", required=[("--thickness", float), ("--node-layers", int)],
                              defaults=[("--force-rtol", float, 1e-4), ("--reaction-rtol", float, 1e-9)])
failures = []
if len(a) != len(b):
    failures.append(f"{len(a)} rows in 2D, {len(b)} in 3D")
worst = {"force": (0.0, None), "reaction": (0.0, None), "lambda": (0.0, None)}


def note(key, value, step):
    if value > worst[key][0]:
        worst[key] = (value, step)


for ra, rb in zip(a, b):
    step = ra["step"]
    note("lambda", abs(float(ra["lambda"]) - float(rb["lambda"])), step)
    if args.node_layers * int(ra["active_contacts"]) != int(rb["active_contacts"]):
        failures.append(f"step {step}: {ra['active_contacts']} contact nodes in 2D, {rb['active_contacts']} in 3D")
    for key, column in (("force", "contact_force_plate_y"), ("reaction", "reaction_start_y")):
        f2, f3 = float(ra[column]), float(rb[column]) / args.thickness
        if f2 != 0.0:
            note(key, abs(f3 - f2) / abs(f2), step)
        elif f3 != 0.0:
            failures.append(f"step {step}: {column} 0 in 2D, {f3} in 3D")
print(f"{min(len(a), len(b))} rows; largest |lambda difference| {worst['lambda'][0]:.3e} (step {worst['lambda'][1]}); "
      f"plate force per unit thickness: largest rel. difference {worst['force'][0]:.3e} (step {worst['force'][1]}); "
      f"support reaction: {worst['reaction'][0]:.3e} (step {worst['reaction'][1]})")
if worst["lambda"][0] > 1e-12:
    failures.append("different load factors")
if worst["force"][0] > args.force_rtol:
    failures.append(f"plate force differs by {worst['force'][0]:.3e} > {args.force_rtol:g}")
if worst["reaction"][0] > args.reaction_rtol:
    failures.append(f"support reaction differs by {worst['reaction'][0]:.3e} > {args.reaction_rtol:g}")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
