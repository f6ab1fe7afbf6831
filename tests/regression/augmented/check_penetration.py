#!/usr/bin/python3
"""check_penetration.py HISTORY --interface NAME --tolerance T --facet-length L

The augmented Lagrangian's promise on an interface (docs/theory-contact.md §15): at every converged
increment of HISTORY (a contessa history CSV), the largest penetration max_penetration_NAME is at most
T x L (Penetration Tolerance x the slave facet length). Prints the largest ratio; exit 1 when a row
exceeds it, or when the column is missing."""
import argparse
import csv
import sys

parser = argparse.ArgumentParser()
parser.add_argument("history")
parser.add_argument("--interface", required=True)
parser.add_argument("--tolerance", type=float, required=True)
parser.add_argument("--facet-length", type=float, required=True)
args = parser.parse_args()

column = "max_penetration_" + args.interface
with open(args.history) as f:
    rows = list(csv.DictReader(f))
if not rows or column not in rows[0]:
    sys.exit(f"{args.history}: no column {column}")
bound = args.tolerance * args.facet_length
worst = max(rows, key=lambda r: float(r[column]))
print(f"largest penetration {float(worst[column]):.4g} at step {worst['step']} (bound {bound:.4g}, "
      f"{len(rows)} rows)")
bad = [r["step"] for r in rows if float(r[column]) > bound]
if bad:
    sys.exit(f"penetration above {bound:.4g} at steps {', '.join(bad)}")
