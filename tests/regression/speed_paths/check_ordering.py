#!/usr/bin/python3
"""check_ordering.py AMD|METIS -- COMMAND [ARGS...]

Runs COMMAND (contessa with Piro/Stratimikos/Linear Solver Types/MUMPS/Verbose=true) and passes when it
exits with status 0 (the deck's own checks passed) and MUMPS' last analysis ordered with the expected
method: INFOG(7), "Ordering option effectively used", is 0 for AMD and 1 for the order Contessa gives
(METIS' nested dissection). With Ordering = Fewest Operations the last analysis is the one kept
(docs/user-guide.md, "Fill-reducing ordering")."""
import re
import subprocess
import sys

expected = {"AMD": 0, "METIS": 1}[sys.argv[1]]
command = sys.argv[3:] if sys.argv[2] == "--" else sys.argv[2:]
done = subprocess.run(command, capture_output=True, text=True)
used = re.findall(r"Ordering option effectively used\s*=\s*(\d+)", done.stdout)
operations = re.findall(r"RINFOG\(1\) Operations during elimination \(estim\)=\s*(\S+)", done.stdout)
print(f"exit {done.returncode}; analyses ordered with {used}, estimated operations {operations}")
if done.returncode != 0:
    sys.exit("FAIL: exit status %d:\n%s%s" % (done.returncode, done.stdout[-2000:], done.stderr[-2000:]))
if not used or int(used[-1]) != expected:
    sys.exit(f"FAIL: expected the last analysis ordered with {sys.argv[1]} (INFOG(7) = {expected})")
