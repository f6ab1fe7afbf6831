#!/usr/bin/python3
"""check_ranks_iterations.py ONE_RANK.history.csv TWO_RANKS.history.csv --max-ratio R

The Krylov iterations per Newton iteration of a run on two ranks are at most R times those on one rank
(issue 23: within 20 %, R = 1.2). Before MueLu's coarsest level was gathered onto one rank
(LinearSolverFactory.cpp, completeCoarseRepartition), the 3D punch needed about twice as many on two."""
import csv
import sys


def per_newton(path):
    rows = list(csv.DictReader(open(path)))
    newton = sum(int(r["newton_iterations"]) for r in rows)
    linear = sum(int(r["linear_iterations"]) for r in rows)
    if newton == 0:
        sys.exit(f"FAIL: {path} has no Newton iterations")
    return linear / newton


one, two = per_newton(sys.argv[1]), per_newton(sys.argv[2])
ratio = float(sys.argv[sys.argv.index("--max-ratio") + 1])
print(f"Krylov iterations per Newton iteration: {one:.2f} on one rank, {two:.2f} on two ({two / one:.2f}x; at most {ratio})")
sys.exit(0 if two <= ratio * one else 1)
