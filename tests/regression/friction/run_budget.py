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
--min-pairs of them. A pair that misses the bound is excused only when it crosses a change of the active
set: the driver prints each iterate's contact states with Newton Details ("contessa: iterate k: open O,
stick S, slip P, signature H", solvers/IterateContactStates.hpp), and where the signature of r_k+1 differs
from r_k's a node opened, closed, changed stick/slip or moved to another facet, so the residual is another
smooth function on each side and no rate is owed; every slow pair within one active set fails the run.
Steps where the residual grows are counted and printed, not checked. Each pair is
printed with the convergence order estimate p = log(r_k+1 / r_k) / log(r_k / r_k-1) when r_k-1 is in the
asymptotic range too (information: with two or three iterates above the floor, p is dominated by the
first one's distance from the asymptotic range; the bounded ratio is the test).

With --history CSV (the run's <name>.history.csv; no failed attempt allowed then, so that attempt i is
increment i) every increment is classified by the contact states it converged to: stick (only sticking
nodes), slip (only slipping nodes), mixed, or none; --require-states stick,slip demands at least one
checked pair in increments of each of these kinds (a deck whose stick phase converges below the floor in
one iterate would otherwise pass on slip alone).

With --min-rebuilds N (the command run without --quiet) at least N rebuilds of the matrix graph must be
logged ("contessa: matrix graph rebuilt (k): ..."), as many as --summary JSON's graph_rebuilds when given,
and with --newton-rate at least N asymptotic pairs must be checked after a rebuild within its attempt
(Newton on the rebuilt graph).
Exit 0 when everything holds."""
import argparse
import csv
import math
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
parser.add_argument("--history")
parser.add_argument("--require-states", default="")
parser.add_argument("--min-rebuilds", type=int)
parser.add_argument("--summary")
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

rebuilds = [line for line in out.splitlines() if line.startswith("contessa: matrix graph rebuilt (")]
if args.min_rebuilds is not None:
    print(f"{len(rebuilds)} matrix graph rebuilds logged")
    if len(rebuilds) < args.min_rebuilds:
        failures.append(f"{len(rebuilds)} matrix graph rebuilds, at least {args.min_rebuilds} expected")
    if args.summary:
        import json
        counted = json.load(open(args.summary)).get("graph_rebuilds")
        if counted != len(rebuilds):
            failures.append(f"summary graph_rebuilds {counted}, {len(rebuilds)} logged")

if args.newton_rate:
    attempts = []
    signatures = []  # per attempt, the contact-state signature of each residual norm (None: not printed)
    rebuilt_after = {}  # attempt -> number of residual norms printed before its first rebuild
    pending = None  # the latest iterate's signature, printed just before its ||F||
    for line in out.splitlines():
        if "Start of Continuation Step" in line:
            attempts.append([])
            signatures.append([])
            pending = None
        if line.startswith("contessa: matrix graph rebuilt (") and attempts:
            rebuilt_after.setdefault(len(attempts) - 1, len(attempts[-1]))
        s = re.match(r"contessa: iterate \d+: .*signature (\w+)", line)
        if s:
            pending = s.group(1)
        m = re.search(r"\|\|F\|\| = (\S+)", line)
        if m and attempts:
            attempts[-1].append(float(m.group(1)))
            signatures[-1].append(pending)
            pending = None
    states = {}
    if args.history:
        if summary and failed != 0:
            failures.append(f"--history needs a run without failed attempts ({failed})")
        with open(args.history) as f:
            for row in csv.DictReader(f):
                stick, slip = int(float(row["stick"])), int(float(row["slip"]))
                kind = "mixed" if stick and slip else "stick" if stick else "slip" if slip else "none"
                states[int(float(row["step"]))] = f"{kind} ({stick} stick, {slip} slip)"
    checked = {}
    pairs = increases = after_rebuild = excused = 0
    slow = []
    for i, norms in enumerate(attempts):
        for k in range(1, len(norms)):
            a, b = norms[k - 1], norms[k]
            if a > args.asymptotic or b < args.floor:
                continue
            if b >= a:
                increases += 1
                continue
            pairs += 1
            # The step r_k-1 -> r_k solves with the Jacobian at iterate k - 1, evaluated after r_k-1 was printed.
            rebuilt = i in rebuilt_after and k >= rebuilt_after[i]
            after_rebuild += rebuilt
            state = states.get(i, "")
            kind = state.split(" ")[0]
            checked[kind] = checked.get(kind, 0) + 1
            c = b / (a * a)
            order = ""
            if k >= 2 and args.floor <= norms[k - 2] <= args.asymptotic and norms[k - 2] > a:
                order = f"  order {math.log(b / a) / math.log(a / norms[k - 2]):.2f}"
            print(f"attempt {i}{' ' + state if state else ''}: ||F|| {a:.3e} -> {b:.3e}  "
                  f"r_k+1 / r_k^2 = {c:.3e}{order}{'  (after a graph rebuild)' if rebuilt else ''}")
            before, after = signatures[i][k - 1], signatures[i][k]
            if c > args.quadratic_constant and before is not None and after is not None and before != after:
                excused += 1
                print(f"    not quadratic, across a change of the active set (signature {before} -> {after}): excused")
            elif c > args.quadratic_constant:
                slow.append(f"attempt {i}: {a:.3e} -> {b:.3e} is not quadratic (r_k+1 / r_k^2 = {c:.3e} > "
                            f"{args.quadratic_constant})")
    print(f"{len(attempts)} attempts, {pairs} asymptotic pairs checked ({excused} slow ones across an active-set "
          f"change excused), {increases} residual increases skipped")
    failures.extend(slow)
    if pairs < args.min_pairs:
        failures.append(f"only {pairs} asymptotic pairs (at least {args.min_pairs}): is Newton Details on?")
    if checked:
        print("pairs checked per kind of increment: " + ", ".join(f"{k} {n}" for k, n in sorted(checked.items())))
    if args.min_rebuilds is not None:
        print(f"{after_rebuild} asymptotic pairs after a graph rebuild in their attempt")
        if after_rebuild < args.min_rebuilds:
            failures.append(f"{after_rebuild} asymptotic pairs checked after a graph rebuild, at least "
                            f"{args.min_rebuilds} expected")
    for kind in filter(None, args.require_states.split(",")):
        if not checked.get(kind):
            failures.append(f"no asymptotic pair checked in a {kind} increment")

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
