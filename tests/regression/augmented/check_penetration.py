#!/usr/bin/python3
"""check_penetration.py HISTORY --interface NAME --tolerance T --facet-length L

The augmented Lagrangian's promise on an interface (docs/theory-contact.md §15): at every converged
increment of HISTORY (a contessa history CSV), the largest penetration max_penetration_NAME is at most
T x L (Penetration Tolerance x the slave facet length). Prints the largest ratio; exit 1 when a row
exceeds it, or when the column is missing."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact"))
import contact_results as cr  # noqa: E402

args = cr.required_options("history", texts=["--interface"], numbers=["--tolerance", "--facet-length"])
column = "max_penetration_" + args.interface
rows = cr.read_history(args.history)
if not rows or column not in rows[0]:
    sys.exit(f"{args.history}: no column {column}")
bound = args.tolerance * args.facet_length
worst = max(rows, key=lambda r: r[column])
print(f"largest penetration {worst[column]:.4g} at step {worst['step']:g} (bound {bound:.4g}, "
      f"{len(rows)} rows)")
bad = [f"{r['step']:g}" for r in rows if r[column] > bound]
if bad:
    sys.exit(f"penetration above {bound:.4g} at steps {', '.join(bad)}")
