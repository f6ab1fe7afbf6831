"""Full sliding at the end of a run: |F_x| = mu F_y for the contact force of one interface in the last row of
its history (Coulomb, eq. 19 of the reference paper), to a relative tolerance. Usage:
  check_sliding_ratio.py HISTORY.csv --interface NAME --mu MU --rtol R"""
import argparse
import csv
import sys

parser = argparse.ArgumentParser()
parser.add_argument("history")
parser.add_argument("--interface", required=True)
parser.add_argument("--mu", type=float, required=True)
parser.add_argument("--rtol", type=float, required=True)
args = parser.parse_args()
last = list(csv.DictReader(open(args.history)))[-1]
fx = float(last[f"contact_force_{args.interface}_x"])
fy = float(last[f"contact_force_{args.interface}_y"])
ratio = abs(fx) / abs(fy)
print(f"step {last['step']}: F_x {fx:.10g}, F_y {fy:.10g}, |F_x|/|F_y| = {ratio:.15g} (mu {args.mu:g})")
if not abs(ratio - args.mu) <= args.rtol * args.mu:
    sys.exit(f"|F_x|/|F_y| = {ratio:.15g} is not mu = {args.mu:g} to {args.rtol:g}")
print("ok")
