#!/usr/bin/python3
"""compare_units.py A.csv B.csv --length L --force F [--rtol R] [--floor Q]

Issue 21, point 2: the same deck in two unit systems, B's lengths L times A's and its forces per unit
thickness (2D) F times A's (mm, MPa -> m, Pa: L = 1e-3, F = 1e3 N/m per N/mm), both without a Normal
Penalty. With the automatic penalty (docs/theory-contact.md §5.3) the answers must be the same up to the
units: every row's reaction_* and contact_force_* columns scaled by F, max_penetration_* and *slip_* by L,
the counts (active_contacts, stick, slip, new_contacts) and lambda equal; |a s - b| <= rtol max(|a s|, |b|)
+ Q (default 1e-10) of the largest value of any column of that kind (the round-off of entries that are 0 in exact
arithmetic, e.g. a symmetry cut's tangential reaction: the solves stop at 1e-9 of the forces)."""
import sys

import contact_results as cr

args, rows_a, rows_b = cr.two_histories("a", "b", required=[("--length", float), ("--force", float)],
                                        defaults=[("--rtol", float, 1e-8), ("--floor", float, 1e-10)])
if len(rows_a) != len(rows_b) or not rows_a:
    sys.exit(f"FAIL: {len(rows_a)} rows against {len(rows_b)}")


def scale(column):
    if column.startswith(("reaction_", "contact_force_")):
        return args.force
    if column.startswith(("max_penetration_", "max_elastic_slip_", "max_slip_", "mean_slip_")):
        return args.length
    if column in ("lambda", "active_contacts", "new_contacts", "stick", "slip", "step"):
        return 1.0
    return None  # solver figures (residual, iterations, time) are not compared


largest = {}
for column in rows_b[0]:
    if scale(column) is not None:
        largest[scale(column)] = max(largest.get(scale(column), 0.0), max(abs(float(r[column])) for r in rows_b))
failures, compared = [], 0
for column in rows_a[0]:
    s = scale(column)
    if s is None:
        continue
    a = [float(r[column]) * s for r in rows_a]
    b = [float(r[column]) for r in rows_b]
    floor = args.floor * largest[s]
    for i, (x, y) in enumerate(zip(a, b)):
        compared += 1
        if abs(x - y) > args.rtol * max(abs(x), abs(y)) + floor:
            failures.append(f"row {i} {column}: {x!r} (scaled) against {y!r}")
print(f"{compared} values compared, {len(failures)} differ")
if failures:
    print("FAIL:\n  " + "\n  ".join(failures[:20]))
    sys.exit(1)
print("ok")
