#!/usr/bin/python3
"""check_same_newton_count.py A.history.csv B.history.csv

The two runs (the same deck on 1 and on 2 ranks) take the same Newton iterations in every increment. With
an iterative linear solver the rank count changes where GMRES stops within its tolerance; the Krylov
forcing term (solvers/KrylovForcing.hpp) keeps the linear residual a Newton step leaves below a tenth of the
Newton target, so that this does not decide whether an iterate passes. Before it, the 3D punch at
20 x 20 x 10 took 3 Newton iterations in its first increment on one rank and 4 on two (the residual after
the third, 4.96 N and 18.4 N, on either side of the target 15.3 N)."""
import csv
import sys


def counts(path):
    return [int(r["newton_iterations"]) for r in csv.DictReader(open(path))]


a, b = counts(sys.argv[1]), counts(sys.argv[2])
print(f"Newton iterations per increment: {a} (sum {sum(a)}) and {b} (sum {sum(b)})")
sys.exit(0 if a == b else 1)
