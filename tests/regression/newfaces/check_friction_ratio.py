#!/usr/bin/python3
"""check_friction_ratio.py CSV --interface NAME --mu MU --direction DX DZ --rtol R

A block sliding on a plane y = const: at the last row of the history, the friction force of interface NAME
(contact_force_NAME_x, _z) is MU times its normal force (contact_force_NAME_y) and points along
(DX, 0, DZ) (a unit vector), each to R. What holds on faces whose total normal force carries a penalty
error (TRI6, QUAD8: docs/verification-contact.md §11): Coulomb's law on the force the interface does carry.
Exit 0 when it holds."""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact"))
import contact_results as cr  # noqa: E402

args = cr.required_options("csv", texts=["--interface"], numbers=["--mu", "--rtol"], pairs=["--direction"])

row = cr.read_history(args.csv)[-1]
fx, fy, fz = (row[f"contact_force_{args.interface}_{c}"] for c in "xyz")
ft = math.hypot(fx, fz)
ratio_error = ft / (args.mu * abs(fy)) - 1.0
direction_error = math.hypot(fx / ft - args.direction[0], fz / ft - args.direction[1])
print(f"|F_t| = {ft:.12g}, mu |F_N| = {args.mu * abs(fy):.12g}: relative error {ratio_error:+.2e}; "
      f"direction ({fx / ft:.12g}, {fz / ft:.12g}) off ({args.direction[0]:g}, {args.direction[1]:g}) by {direction_error:.2e}")
sys.exit(0 if abs(ratio_error) <= args.rtol and direction_error <= args.rtol else 1)
