"""Full sliding at the end of a run: |F_x| = mu F_y for the contact force of one interface in the last row of
its history (Coulomb, eq. 19 of the reference paper), to a relative tolerance. Usage:
  check_sliding_ratio.py HISTORY.csv --interface NAME --mu MU --rtol R"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact"))
import contact_results as cr  # noqa: E402

args = cr.required_options("history", texts=["--interface"], numbers=["--mu", "--rtol"])
last = cr.read_history(args.history)[-1]
fx = last[f"contact_force_{args.interface}_x"]
fy = last[f"contact_force_{args.interface}_y"]
ratio = abs(fx) / abs(fy)
print(f"step {last['step']:g}: F_x {fx:.10g}, F_y {fy:.10g}, |F_x|/|F_y| = {ratio:.15g} (mu {args.mu:g})")
if not abs(ratio - args.mu) <= args.rtol * args.mu:
    sys.exit(f"|F_x|/|F_y| = {ratio:.15g} is not mu = {args.mu:g} to {args.rtol:g}")
print("ok")
