#!/usr/bin/python3
"""run_budget.py [--max-increments N] [--max-failed N] [--max-newton N] [--newton-rate] -- COMMAND [ARGS...]

Runs a Contessa command (its own deck checks included: it must exit 0) and checks the cost it reports on
stdout, "finished after N increments (F failed attempts), I Newton iterations", where I counts every
Newton iteration, those of failed attempts and Contact Beta restarts included.

With --newton-rate the command must print NOX's iterations ("Piro/NOX/Printing/Newton Details=true"):
the residual norms ||F|| of every attempt are read, and Newton must converge quadratically in the last
iterations of an increment. Checked on the asymptotic pairs (r_k, r_k+1): r_k <= --asymptotic (below the
jumps of the first iterate and of active-set changes), r_k+1 < r_k, and r_k+1 >= --floor (above the
round-off floor of the residual; on the tube a penalty of 1e9 times a tributary length of 1.9 mm times the
spacing of doubles near 120 mm quantises each nodal force by about 3e-5 N/mm, and ||F|| stalls at 3e-5 to
1.5e-4): each must satisfy r_k+1 <= C r_k^2 (--quadratic-constant C), and there must be at least
--min-pairs of them. Steps where the residual grows (a node opens, closes or changes stick/slip between
iterates) are counted and printed, not checked: they are not part of the asymptotic range.
Exit 0 when everything holds."""
import argparse
import re
import subprocess
import sys

parser = argparse.ArgumentParser()
parser.add_argument("--max-increments", type=int)
parser.add_argument("--max-failed", type=int)
parser.add_argument("--max-newton", type=int)
parser.add_argument("--newton-rate", action="store_true")
parser.add_argument("--asymptotic", type=float, default=10.0)
parser.add_argument("--floor", type=float, default=1e-3)
parser.add_argument("--quadratic-constant", type=float, default=0.1)
parser.add_argument("--min-pairs", type=int, default=20)
parser.add_argument("command", nargs=argparse.REMAINDER)
args = parser.parse_args()
command = args.command[1:] if args.command and args.command[0] == "--" else args.command
if not command:
    sys.exit("run_budget.py: no command")

run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
out = run.stdout
failures = []
if run.returncode != 0:
    print(out[-4000:])
    failures.append(f"exit status {run.returncode}, expected 0")

summary = re.search(r"finished after (\d+) increments \((\d+) failed attempts\), (\d+) Newton iterations", out)
if not summary:
    failures.append("no 'finished after ...' summary line on stdout")
else:
    increments, failed, newton = (int(g) for g in summary.groups())
    print(f"{increments} increments, {failed} failed attempts, {newton} Newton iterations")
    for name, value, bound in (("increments", increments, args.max_increments),
                               ("failed attempts", failed, args.max_failed),
                               ("Newton iterations", newton, args.max_newton)):
        if bound is not None and value > bound:
            failures.append(f"{value} {name}, at most {bound} allowed")

if args.newton_rate:
    attempts = []
    for line in out.splitlines():
        if "Start of Continuation Step" in line:
            attempts.append([])
        m = re.search(r"\|\|F\|\| = (\S+)", line)
        if m and attempts:
            attempts[-1].append(float(m.group(1)))
    pairs = increases = 0
    for i, norms in enumerate(attempts):
        for a, b in zip(norms, norms[1:]):
            if a > args.asymptotic or b < args.floor:
                continue
            if b >= a:
                increases += 1
                continue
            pairs += 1
            c = b / (a * a)
            print(f"attempt {i}: ||F|| {a:.3e} -> {b:.3e}  r_k+1 / r_k^2 = {c:.3e}")
            if c > args.quadratic_constant:
                failures.append(f"attempt {i}: {a:.3e} -> {b:.3e} is not quadratic (r_k+1 / r_k^2 = {c:.3e} > "
                                f"{args.quadratic_constant})")
    print(f"{len(attempts)} attempts, {pairs} asymptotic pairs checked, {increases} residual increases skipped")
    if pairs < args.min_pairs:
        failures.append(f"only {pairs} asymptotic pairs (at least {args.min_pairs}): is Newton Details on?")

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
