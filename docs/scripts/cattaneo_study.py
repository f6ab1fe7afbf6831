#!/usr/bin/python3
"""The Cattaneo-Mindlin study of docs/verification-contact.md, section 4.

  /usr/bin/python3 docs/scripts/cattaneo_study.py --points      # the rigid cylinder's polyline of the deck
  /usr/bin/python3 docs/scripts/cattaneo_study.py [--build build] [--out /tmp/cattaneo_study]

Runs inputs/verification/cattaneo_mindlin.xml as it stands (Slip Tolerance 0.001, nu = 0.49), with the default
slip tolerance (0.005) and with nu = 0.3 (Dundurs' beta = 0.29), and prints for each the stick half-width
against sqrt(1 - Q / (mu P)) at every increment (tests/regression/friction/check_cattaneo.py, whose exit
status says whether the 5 % check holds). A few minutes on two cores."""
import argparse
import os
import subprocess
import sys

import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
DECK = os.path.join(ROOT, "inputs", "verification", "cattaneo_mindlin.xml")
CHECK = os.path.join(ROOT, "tests", "regression", "friction", "check_cattaneo.py")


def polyline(radius=10.0, overlap=0.03):
    """The lowest arc of the cylinder, left to right (the cylinder lies above): 0.0025 mm on [-0.6, 0.6],
    0.05 mm out to +-1.8; lowest point at y = -overlap."""
    x = np.concatenate([np.linspace(-1.8, -0.6, 25)[:-1], np.linspace(-0.6, 0.6, 481), np.linspace(0.6, 1.8, 25)[1:]])
    y = radius - overlap - np.sqrt(radius * radius - x * x)
    return "{" + ", ".join(f"{a:.6g}, {b:.9g}" for a, b in zip(x, y)) + "}"


parser = argparse.ArgumentParser()
parser.add_argument("--points", action="store_true", help="print the deck's Rigid Surface/Points and stop")
parser.add_argument("--build", default=os.path.join(ROOT, "build"))
parser.add_argument("--out", default="/tmp/cattaneo_study")
args = parser.parse_args()
if args.points:
    print(polyline())
    sys.exit(0)

contessa = os.path.join(args.build, "bin", "contessa")
cases = [
    ("deck: slip tolerance 0.001, nu = 0.49", [], 0.49),
    ("default slip tolerance 0.005, nu = 0.49", ["Problem/Contact/cylinder/Slip Tolerance=0.005"], 0.49),
    ("slip tolerance 0.001, nu = 0.3 (beta = 0.29)", ["Problem/Materials/elastic/Poisson's Ratio=0.3"], 0.3),
]
for i, (name, sets, nu) in enumerate(cases):
    out = os.path.join(args.out, f"case{i}")
    command = [contessa, DECK, "--quiet", "--output-dir", out]
    for s in sets:
        command += ["--set", s]
    run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    summary = [line for line in run.stdout.splitlines() if "finished" in line or "stopped" in line]
    print(f"== {name}: exit {run.returncode}; {summary[0] if summary else ''}")
    check = subprocess.run([sys.executable, CHECK, os.path.join(out, "cattaneo_mindlin.exo"),
                            os.path.join(out, "cattaneo_mindlin.history.csv"), "--mu", "0.3", "--radius", "10",
                            "--young", "1000", "--poisson", str(nu)], stdout=subprocess.PIPE, text=True)
    print(check.stdout, end="")
    print(f"   check_cattaneo.py exit status {check.returncode}")
