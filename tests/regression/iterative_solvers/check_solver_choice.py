#!/usr/bin/python3
"""check_solver_choice.py SOLVER automatic|given SUMMARY.json -- COMMAND [ARGS...]

Runs COMMAND (a contessa run without --quiet) and passes when it exits with status 0, its log names the
linear solver exactly once, as "contessa: linear solver SOLVER (REASON)" with REASON the automatic
choice's ("automatic: 3D, N unknowns <= LIMIT; ...") or the deck's ("given by Piro/Stratimikos/Linear
Solver Type"), and the run's summary (SUMMARY.json) records the same solver and whether it was automatic
(issue 23: the linear solver chosen by the problem's size and dimension)."""
import json
import re
import subprocess
import sys

solver, kind, summary_path = sys.argv[1], sys.argv[2], sys.argv[3]
command = sys.argv[sys.argv.index("--") + 1:]
run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
failures = []
if run.returncode != 0:
    failures.append(f"exit status {run.returncode}, expected 0")
lines = [l for l in run.stdout.splitlines() if l.startswith("contessa: linear solver ")]
if len(lines) != 1:
    failures.append(f"{len(lines)} 'contessa: linear solver' lines in the log, expected 1: {lines}")
else:
    m = re.fullmatch(r"contessa: linear solver (.+) \((.+)\)", lines[0])
    reason = (r"automatic: [23]D, \d+ unknowns (<=|>) \d+; Piro/Stratimikos/Linear Solver Type = MUMPS or Belos forces one"
              if kind == "automatic" else r"given by Piro/Stratimikos/Linear Solver Type")
    if not m or m.group(1) != solver or not re.fullmatch(reason, m.group(2)):
        failures.append(f"log line '{lines[0]}': expected solver '{solver}' and reason /{reason}/")
if not failures:
    summary = json.load(open(summary_path))
    if summary.get("linear_solver") != solver:
        failures.append(f"{summary_path}: linear_solver {summary.get('linear_solver')!r}, expected {solver!r}")
    if summary.get("linear_solver_automatic") != (kind == "automatic"):
        failures.append(f"{summary_path}: linear_solver_automatic {summary.get('linear_solver_automatic')}, "
                        f"expected {kind == 'automatic'}")
for f in failures:
    print("FAIL:", f)
if failures:
    print("log (end):\n" + "\n".join(run.stdout.splitlines()[-15:]))
    sys.exit(1)
print(f"ok: {lines[0]}")
