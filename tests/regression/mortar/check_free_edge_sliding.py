"""Sliding past a master's free edge (verification-contact.md §9.4): the history of a 3D run whose slave face
slides off a rigid base's edge. Checks, at every increment from --from-step on where every closed node slips
(slip == active_contacts > 0), that the interface's contact force has |F_t| = mu |F_y| (F_t = (F_x, F_z)) to
the relative tolerance --rtol, and that the run did slide past the edge: |F_y| fell below --below times its
value at step 0 (the pressed state) at some such increment, so the check saw the overlap shrink. Usage:
  check_free_edge_sliding.py HISTORY.csv --interface NAME --mu MU --rtol R --below FRACTION [--from-step S]"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact"))
import contact_results as cr  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("history")
parser.add_argument("--interface", required=True)
parser.add_argument("--mu", type=float, required=True)
parser.add_argument("--rtol", type=float, required=True)
parser.add_argument("--below", type=float, required=True)
parser.add_argument("--from-step", type=int, default=1)
args = parser.parse_args()

rows = cr.read_history(args.history)
pressed = abs(rows[0][f"contact_force_{args.interface}_y"])
checked, worst, lowest, failures = 0, 0.0, math.inf, []
for row in rows:
    if row["step"] < args.from_step:
        continue
    active, slip = int(row["active_contacts"]), int(row["slip"])
    if active == 0 or slip != active:
        continue
    fx, fy, fz = (row[f"contact_force_{args.interface}_{c}"] for c in "xyz")
    ratio = math.hypot(fx, fz) / abs(fy)
    deviation = abs(ratio - args.mu) / args.mu
    checked += 1
    worst = max(worst, deviation)
    lowest = min(lowest, abs(fy) / pressed)
    if deviation > args.rtol:
        failures.append(f"step {row['step']:g} (lambda {row['lambda']:.6g}): |F_t|/F_y = {ratio:.12g}, "
                        f"{active} nodes closed, all slipping")
print(f"{checked} all-slipping increments from step {args.from_step}: |F_t|/F_y within {worst:.3g} of mu = "
      f"{args.mu:g} (bound {args.rtol:g}); F_y down to {lowest:.6g} of the pressed {pressed:.12g} N")
for f in failures:
    print(f)
if checked == 0 or failures:
    sys.exit("free-edge sliding: |F_t| is not mu F_N at every all-slipping increment")
if not lowest < args.below:
    sys.exit(f"free-edge sliding: F_y never fell below {args.below:g} of the pressed force: the slave did not "
             "slide past the edge")
print("ok")
