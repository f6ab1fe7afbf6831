"""Runs contessa with --check-jacobian and checks its lines: one per requested increment, each with a
worst relative error below the bound. Usage: check_jacobian.py BOUND INCREMENTS [EXIT] -- COMMAND...
(INCREMENTS: the comma-separated increment numbers expected, e.g. 1,10,20; EXIT: the exit status
expected, 0 by default: 3 when --set changes the answer the deck's own regression checks expect)."""
import re
import subprocess
import sys

sep = sys.argv.index("--")
bound = float(sys.argv[1])
expected = [int(n) for n in sys.argv[2].split(",")]
proc = subprocess.run(sys.argv[sep + 1:], capture_output=True, text=True)
sys.stdout.write(proc.stdout)
sys.stderr.write(proc.stderr)
if proc.returncode != (int(sys.argv[3]) if sep > 3 else 0):
    sys.exit(f"contessa exited with {proc.returncode}")
pattern = re.compile(r"^jacobian check, increment (\d+) \(load factor \S+\): worst relative error (\S+) at row node "
                     r"\d+ [xyz], column node \d+ [xyz] \(.+\), W = \S+, FD = \S+; norm-wise \|\|W - W_FD\|\|/\|\|W\|\| = (\S+) "
                     r"\((\d+) residuals, \S+ s\)$")
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
if found != expected:
    sys.exit(f"checked increments {found}, expected {expected}")
print(f"jacobian check: increments {found} below {bound:g}")
