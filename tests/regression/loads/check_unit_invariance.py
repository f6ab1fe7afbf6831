#!/usr/bin/python3
"""check_unit_invariance.py REFERENCE.csv OTHER.csv FORCE_FACTOR [RTOL]

The same problem in two units of force (every stress and load of OTHER is FORCE_FACTOR times REFERENCE's):
the runs must take the same increments (step, lambda, dlambda, attempts, i.e. no extra cut-back) with the
same Newton iterations, and every reaction_* column of OTHER must be FORCE_FACTOR times REFERENCE's to RTOL
(default 1e-6) of the largest reaction. Prints the totals; exit 0 when they agree."""
import csv
import sys

reference = list(csv.DictReader(open(sys.argv[1])))
other = list(csv.DictReader(open(sys.argv[2])))
factor = float(sys.argv[3])
rtol = float(sys.argv[4]) if len(sys.argv) > 4 else 1e-6
if len(reference) != len(other):
    sys.exit(f"FAIL: {len(reference)} increments in {sys.argv[1]}, {len(other)} in {sys.argv[2]}")
reactions = [c for c in reference[0] if c.startswith("reaction_")]
scale = max(abs(float(r[c])) for r in reference for c in reactions) if reactions else 1.0
failures = []
for a, b in zip(reference, other):
    for c in ("step", "attempts", "newton_iterations"):
        if int(float(a[c])) != int(float(b[c])):
            failures.append(f"step {a['step']}: {c} {a[c]} vs {b[c]}")
    for c in ("lambda", "dlambda"):
        if abs(float(a[c]) - float(b[c])) > 1e-12:
            failures.append(f"step {a['step']}: {c} {a[c]} vs {b[c]}")
    for c in reactions:
        if abs(float(b[c]) / factor - float(a[c])) > rtol * scale:
            failures.append(f"step {a['step']}: {c} {float(b[c]) / factor:.9e} (scaled back) vs {float(a[c]):.9e}")
newton = [sum(int(float(r["newton_iterations"])) for r in rows) for rows in (reference, other)]
attempts = [sum(int(float(r["attempts"])) for r in rows[1:]) for rows in (reference, other)]
print(f"{len(reference) - 1} increments; Newton iterations {newton[0]} and {newton[1]}; attempts {attempts[0]} and "
      f"{attempts[1]} (force factor {factor:g})")
for f in failures[:20]:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
