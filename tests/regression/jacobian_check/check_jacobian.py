"""Runs contessa with --check-jacobian and checks its lines: one per requested increment, each with a
worst relative error below the bound and at most MAX_NOT_COMPARED columns left out (a contact status
changing within the difference step on both sides). Usage:
  check_jacobian.py BOUND INCREMENTS [EXIT [MAX_NOT_COMPARED]] -- COMMAND...
(INCREMENTS: the comma-separated increment numbers expected, e.g. 1,10,20; EXIT: the exit status
expected, 0 by default: 3 when --set changes the answer the deck's own regression checks expect;
MAX_NOT_COMPARED: 0 by default)."""
import re
import subprocess
import sys

sep = sys.argv.index("--")
bound = float(sys.argv[1])
expected = [int(n) for n in sys.argv[2].split(",")]
proc = subprocess.run(sys.argv[sep + 1:], capture_output=True, text=True)
sys.stdout.write(proc.stdout)
sys.stderr.write(proc.stderr)
max_not_compared = int(sys.argv[4]) if sep > 4 else 0
if proc.returncode != (int(sys.argv[3]) if sep > 3 else 0):
    sys.exit(f"contessa exited with {proc.returncode}")
pattern = re.compile(r"^jacobian check, increment (\d+) \(load factor \S+\): worst relative error (\S+) at row node "
                     r"\d+ [xyz], column node \d+ [xyz] \(.+\), W = \S+, FD = \S+; norm-wise \|\|W - W_FD\|\|/\|\|W\|\| = ([^;\s]+)"
                     r"(?:; (\d+) column\(s\) not compared \(a contact status changes within ±h on both sides, first: "
                     r"node \d+ [xyz]; status \d+, facet \d+, contact point \d+\))?"
                     r"(?:; \d+ column\(s\) differenced on one side \(a contact status changes on the other: "
                     r"status \d+, facet \d+, contact point \d+\))?"
                     r"(?:; \d+ column\(s\) differenced with a shorter step \(the residual bends "
                     r"within h\))?"
                     r"(?:; \d+ slave node\(s\) with a secant slip tangent in Newton's W \(slip reversed; checked: "
                     r"the consistent one\))? \((\d+) residuals, \S+ s\)$")
found = []
for line in proc.stdout.splitlines():
    if line.startswith("jacobian check"):
        m = pattern.match(line)
        if not m:
            sys.exit(f"malformed line: {line}")
        found.append(int(m.group(1)))
        worst, normwise = float(m.group(2)), float(m.group(3))
        if not worst < bound or not normwise < bound:
            sys.exit(f"increment {m.group(1)}: worst {worst:g} or norm-wise {normwise:g} not below {bound:g}")
        not_compared = int(m.group(4) or 0)
        if not_compared > max_not_compared:
            sys.exit(f"increment {m.group(1)}: {not_compared} columns not compared, more than {max_not_compared}")
if found != expected:
    sys.exit(f"checked increments {found}, expected {expected}")
print(f"jacobian check: increments {found} below {bound:g}")
