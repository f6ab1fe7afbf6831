#!/usr/bin/python3
"""compare_history.py A.csv B.csv [--rtol R] [--atol A] [--ignore COLUMN[,COLUMN...] ...]

Compares two Contessa history files row by row (every numeric column but wall_s and the --ignore
ones, e.g. the solver's own counts when two linear solvers are compared; a test that ignores a
column says why) with |a - b| <= atol + rtol * max(|a|, |b|), as exodiff does. Exit 0 when they agree.

--along-load-factor: rows of an adaptive run (Contact Beta) lie at load factors the controller chose
from the state, so two runs whose states differ by round-off end an increment at load factors a little
apart (LOCA's predictor is a finite difference in the load factor, which amplifies round-off); a column
may then also differ by its rate over the increment times that distance:
    + |lambda_a - lambda_b| * |c_i - c_(i-1)| / dlambda_i   (from run a's row i and the one before it)."""
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
parser.add_argument("--along-load-factor", action="store_true",
                    help="allow each column its rate over the increment times the rows' load-factor distance")
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
        if args.along_load_factor and i > 0 and c not in ("lambda", "dlambda"):
            step = abs(float(ra["dlambda"]))
            if step > 0:
                rate = abs(a - float(rows_a[i - 1][c])) / step
                bound += rate * abs(float(ra["lambda"]) - float(rb["lambda"]))
        if c == "residual_norm":  # round-off level by construction: compare only its magnitude
            bound = max(bound, 1e-6 + 10 * max(abs(a), abs(b)))
        if diff > bound:
            failures += 1
            print(f"row {i} {c}: {a!r} vs {b!r} (diff {diff:.3e} > {bound:.3e})")
        if c != "residual_norm" and diff > worst[0]:
            worst = (diff, f"row {i} {c}")
print(f"{len(rows_a)} rows, {len(columns)} columns compared; largest difference {worst[0]:.3e} at {worst[1]}")
sys.exit(1 if failures else 0)
