#!/usr/bin/python3
"""compare_history.py A.csv B.csv [--rtol R] [--atol A] [--ignore COLUMN[,COLUMN...] ...]

Compares two Contessa history files row by row (every numeric column but wall_s and the --ignore
ones, e.g. the solver's own counts when two linear solvers are compared; a test that ignores a
column says why) with |a - b| <= atol + rtol * max(|a|, |b|), as exodiff does. Exit 0 when they agree."""
import argparse
import csv
import sys

parser = argparse.ArgumentParser()
parser.add_argument("a")
parser.add_argument("b")
parser.add_argument("--rtol", type=float, default=1e-8)
parser.add_argument("--atol", type=float, default=1e-10)
parser.add_argument("--ignore", nargs="*", default=[],
                    help="columns left out besides wall_s (separate arguments or comma-separated)")
args = parser.parse_args()

rows_a = list(csv.DictReader(open(args.a)))
rows_b = list(csv.DictReader(open(args.b)))
if len(rows_a) != len(rows_b):
    sys.exit(f"FAIL: {len(rows_a)} rows in {args.a}, {len(rows_b)} in {args.b}")
if not rows_a:
    sys.exit("FAIL: empty histories")
skipped = {"wall_s"} | {c for arg in args.ignore for c in arg.split(",") if c}
columns = [c for c in rows_a[0] if c not in skipped]
if set(columns) != set(c for c in rows_b[0] if c not in skipped):
    sys.exit("FAIL: different columns")
worst = (0.0, None)
failures = 0
for i, (ra, rb) in enumerate(zip(rows_a, rows_b)):
    for c in columns:
        a, b = float(ra[c]), float(rb[c])
        diff = abs(a - b)
        bound = args.atol + args.rtol * max(abs(a), abs(b))
        if c == "residual_norm":  # round-off level by construction: compare only its magnitude
            bound = max(bound, 1e-6 + 10 * max(abs(a), abs(b)))
        if diff > bound:
            failures += 1
            print(f"row {i} {c}: {a!r} vs {b!r} (diff {diff:.3e} > {bound:.3e})")
        if c != "residual_norm" and diff > worst[0]:
            worst = (diff, f"row {i} {c}")
print(f"{len(rows_a)} rows, {len(columns)} columns compared; largest difference {worst[0]:.3e} at {worst[1]}")
sys.exit(1 if failures else 0)
