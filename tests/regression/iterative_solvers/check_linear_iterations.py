#!/usr/bin/python3
"""check_linear_iterations.py HISTORY.csv iterative|direct [--max-per-newton X]

iterative: every row with Newton iterations reports at least one Krylov iteration per Newton iteration
in linear_iterations (a Newton direction cannot come from zero Krylov iterations), and a row without
Newton iterations (the predictor alone converged; it is not counted) reports none. direct: the column
is 0 in every row. --max-per-newton X: the run's Krylov iterations per Newton iteration are at most X (a
preconditioner that lost its set-up, e.g. MueLu without the rigid-body modes, needs about three times as
many on the punch deck)."""
import csv
import sys

path, kind = sys.argv[1], sys.argv[2]
max_per_newton = float(sys.argv[sys.argv.index("--max-per-newton") + 1]) if "--max-per-newton" in sys.argv else None
rows = list(csv.DictReader(open(path)))
if not rows or "linear_iterations" not in rows[0]:
    sys.exit(f"FAIL: {path} has no linear_iterations column")
failures = []
for row in rows:
    step, newton, linear = int(row["step"]), int(row["newton_iterations"]), int(row["linear_iterations"])
    if kind == "direct" and linear != 0:
        failures.append(f"step {step}: {linear} linear iterations with a direct solver")
    if kind == "iterative":
        if newton == 0 and linear != 0:
            failures.append(f"step {step}: {linear} linear iterations without a Newton iteration")
        if linear < newton:
            failures.append(f"step {step}: {linear} linear iterations for {newton} Newton iterations")
for f in failures:
    print("FAIL:", f)
total = sum(int(r["linear_iterations"]) for r in rows)
newton = sum(int(r["newton_iterations"]) for r in rows)
print(f"{len(rows)} rows: {total} linear iterations over {newton} Newton iterations"
      + (f" ({total / newton:.1f} per Newton iteration)" if newton else ""))
if max_per_newton is not None and newton and total / newton > max_per_newton:
    print(f"FAIL: {total / newton:.1f} linear iterations per Newton iteration, more than {max_per_newton}")
    failures.append("per Newton")
sys.exit(1 if failures else 0)
