"""Full oblique sliding at the end of a 3D run: the contact force of one interface in the last row of its
history has |F_t| = mu F_y, F_t = (F_x, F_z) (Coulomb, eq. 18-19 of the reference paper), and F_t points
against the load's direction (DX, DZ), each to a relative tolerance. Usage:
  check_oblique_sliding.py HISTORY.csv --interface NAME --mu MU --dx DX --dz DZ --rtol R"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact"))
import contact_results as cr  # noqa: E402

args = cr.required_options("history", texts=["--interface"], numbers=["--mu", "--dx", "--dz", "--rtol"])
last = cr.read_history(args.history)[-1]
fx, fy, fz = (last[f"contact_force_{args.interface}_{c}"] for c in "xyz")
ratio = math.hypot(fx, fz) / abs(fy)
# The sine of the angle between F_t and -(DX, DZ): 0 when they are parallel.
length = math.hypot(args.dx, args.dz)
across = (fx * args.dz - fz * args.dx) / (math.hypot(fx, fz) * length)
along = -(fx * args.dx + fz * args.dz) / (math.hypot(fx, fz) * length)
print(f"step {last['step']:g}: F = ({fx:.12g}, {fy:.12g}, {fz:.12g}), |F_t|/F_y = {ratio:.15g} (mu {args.mu:g}), "
      f"F_t against the load: cos {along:.15g}, sin {across:.3g}")
if not abs(ratio - args.mu) <= args.rtol * args.mu:
    sys.exit(f"|F_t|/|F_y| = {ratio:.15g} is not mu = {args.mu:g} to {args.rtol:g}")
if not (along > 0 and abs(across) <= args.rtol):
    sys.exit(f"F_t is not against the load's direction ({args.dx:g}, {args.dz:g}) to {args.rtol:g}: sin {across:.3g}")
print("ok")
