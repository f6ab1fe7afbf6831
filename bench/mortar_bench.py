#!/usr/bin/python3
"""Mortar against node-to-segment on the tube (inputs/tube_bending.xml, 102 slave nodes on the outer arc
against the rigid plate): the contact phase's wall time per evaluation and per slave node.

Runs the fixed-step tube (Method=Constant, 47 increments) with `--timers`, frictionless and with
Friction Coefficient = 0.2, once with Discretization = Node To Segment and once with Mortar, --repeat
times each (interleaved, so that a change of machine load hits every variant alike), and prints one
Markdown table: Newton iterations, contact evaluations (the timer's count: residual and Jacobian passes),
the median contact-phase time ("contact: search, elements, scatter": search, every slave node's term,
scatter into the matrix), that time per evaluation and per slave node and evaluation, mortar over
node-to-segment per evaluation, and the median total wall time.

    /usr/bin/python3 bench/mortar_bench.py [--repeat 3] [--contessa PATH] [--work DIR]
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
DECK = os.path.join(ROOT, "inputs", "tube_bending.xml")
SLAVE_NODES = 102  # the outer arc: 101 elements around it
FIXED = ["--set", "Piro/LOCA/Step Size/Method=Constant", "--set", "Problem/Regression/increments/Expected=47"]
CONTACT = re.compile(r"^\s*contact: search, elements, scatter\s+(\S+)\s+\S+\s+(\d+)\s*$")
TOTAL = re.compile(r"^\s*total\s+(\S+)")
NEWTON = re.compile(r"(\d+) Newton iterations")


def run(contessa, work, discretization, mu, index):
    out = os.path.join(work, f"{discretization.replace(' ', '')}_mu{mu}_{index}")
    cmd = [contessa, DECK, "--quiet", "--timers", "--output-dir", out, *FIXED,
           "--set", f"Problem/Contact/plate/Discretization={discretization}",
           "--set", f"Problem/Contact/plate/Friction Coefficient={mu}",
           # the runs' own answers differ from the deck's frictionless node-to-segment baselines
           "--set", "Problem/Regression/plate force/Relative Tolerance=1",
           "--set", "Problem/Regression/contact nodes/Absolute Tolerance=100"]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"{' '.join(cmd)} exited with {p.returncode}:\n{p.stderr[-2000:]}")
    contact = total = newton = None
    for line in (p.stdout + p.stderr).splitlines():
        if (m := CONTACT.match(line)):
            contact = (float(m.group(1)), int(m.group(2)))
        elif (m := TOTAL.match(line)):
            total = float(m.group(1))
        elif (m := NEWTON.search(line)) and "finished after" in line:
            newton = int(m.group(1))
    if contact is None or total is None:
        sys.exit(f"no timer table in the output of {' '.join(cmd)}")
    return contact[0], contact[1], total, newton


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--contessa", default=os.path.join(ROOT, "build", "bin", "contessa"))
    parser.add_argument("--work", default=None)
    args = parser.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="mortar_bench_")
    variants = [(d, mu) for mu in (0.0, 0.2) for d in ("Node To Segment", "Mortar")]
    results = {v: [] for v in variants}
    for i in range(args.repeat):
        for v in variants:
            results[v].append(run(args.contessa, work, *v, i))
    print(f"tube, fixed steps, 1 rank, median of {args.repeat}; contact phase = search, every slave node's term, scatter\n")
    print("| friction | discretisation | Newton | contact evaluations | contact s | ms / evaluation "
          "| µs / (slave node · evaluation) | mortar / node-to-segment | total s |")
    print("|---|---|---|---|---|---|---|---|---|")
    per_eval = {}
    for v in variants:
        rows = results[v]
        contact = statistics.median(r[0] for r in rows)
        evaluations = rows[0][1]
        total = statistics.median(r[2] for r in rows)
        per_eval[v] = contact / evaluations
        ratio = per_eval[v] / per_eval[("Node To Segment", v[1])]
        print(f"| {v[1]:g} | {v[0]} | {rows[0][3]} | {evaluations} | {contact:.4f} | {1e3 * per_eval[v]:.3f} "
              f"| {1e6 * per_eval[v] / SLAVE_NODES:.2f} | {ratio:.2f} | {total:.2f} |")


if __name__ == "__main__":
    main()
