"""Compares one force column of two histories of the same fixed-step run at every increment: the same load
factors, and |f_a - f_b| <= rtol |f_b| at each (f_b the reference discretisation). Prints the largest
relative difference, where, and the one at the last increment. Usage:
  compare_force_per_increment.py A.history.csv B.history.csv --column NAME --rtol R"""
import argparse
import csv
import sys

parser = argparse.ArgumentParser()
parser.add_argument("a")
parser.add_argument("b")
parser.add_argument("--column", required=True)
parser.add_argument("--rtol", type=float, required=True)
args = parser.parse_args()
rows_a = list(csv.DictReader(open(args.a)))
rows_b = list(csv.DictReader(open(args.b)))
if len(rows_a) != len(rows_b):
    sys.exit(f"{len(rows_a)} rows against {len(rows_b)}: not the same fixed-step run")
worst, worst_step, failed = 0.0, None, []
for ra, rb in zip(rows_a, rows_b):
    if abs(float(ra["lambda"]) - float(rb["lambda"])) > 1e-12:
        sys.exit(f"step {ra['step']}: load factors {ra['lambda']} and {rb['lambda']} differ")
    fa, fb = float(ra[args.column]), float(rb[args.column])
    if fb == 0.0:
        if fa != 0.0:
            failed.append(ra["step"])
        continue
    rel = abs(fa - fb) / abs(fb)
    if rel > worst:
        worst, worst_step = rel, ra["step"]
    if rel > args.rtol:
        failed.append(ra["step"])
last = rows_a[-1]
rel_last = abs(float(last[args.column]) - float(rows_b[-1][args.column])) / abs(float(rows_b[-1][args.column]))
print(f"{args.column}: {len(rows_a) - 1} increments, largest relative difference {worst:.3e} at step {worst_step}, "
      f"{rel_last:.3e} at the last (lambda {last['lambda']})")
if failed:
    sys.exit(f"relative difference above {args.rtol:g} at steps {', '.join(failed)}")
print("ok")
