#!/usr/bin/python3
"""compare_step_end.py STEPPED_DIR/NAME REFERENCE_DIR/NAME --load-step N [--rtol R] [--columns C,C,...]

Load steps (issue 19 §2; docs/verification-loads.md, "Load steps"): the state a stepped run reaches at the
end of its load step N (the last history row and Exodus step with load_step = N) must equal the last
state of a reference run of other values (a one-step run of the values the steps combine to). Each
argument is a results path without its extension (NAME.exo and NAME.history.csv are read). Compared:
every nodal displacement component, relative to the reference's largest |u| (the mesh and its node
numbering must be the same), and each named history column, relative to the reference's value (with an
absolute floor of rtol times the largest |value| among the named columns). Exit 0 when all agree."""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact"))
from contact_results import Results, read_history  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("stepped")
parser.add_argument("reference")
parser.add_argument("--load-step", type=int, required=True)
parser.add_argument("--rtol", type=float, default=1e-8)
parser.add_argument("--columns", default="")
parser.add_argument("--shift", default="",
                    help="a rigid translation added to the stepped run's displacements (x,y[,z]), e.g. when its "
                         "loading differs from the reference's by a frame moving at constant velocity")
args = parser.parse_args()

stepped_rows = read_history(args.stepped + ".history.csv")
reference_rows = read_history(args.reference + ".history.csv")
in_step = [i for i, r in enumerate(stepped_rows) if int(r["load_step"]) == args.load_step]
if not in_step:
    sys.exit(f"FAIL: {args.stepped}.history.csv has no row of load step {args.load_step}")
row = in_step[-1]
if abs(stepped_rows[row]["lambda"] - 1.0) > 1e-12:
    sys.exit(f"FAIL: load step {args.load_step} ends at lambda {stepped_rows[row]['lambda']}, not 1")
stepped = Results(args.stepped + ".exo")
reference = Results(args.reference + ".exo")
if len(stepped.times) != len(stepped_rows):
    sys.exit(f"FAIL: {len(stepped.times)} Exodus steps, {len(stepped_rows)} history rows")
failed = False
components = [c for c in ("displ_x", "displ_y", "displ_z") if c in reference.nodal_names]
u_ref = np.stack([reference.nodal(c) for c in components])
u = np.stack([stepped.nodal(c, row) for c in components])
if args.shift:
    u += np.array([float(v) for v in args.shift.split(",")])[:len(components), None]
if u.shape != u_ref.shape:
    sys.exit(f"FAIL: {u.shape} displacements, the reference has {u_ref.shape}")
scale = np.max(np.abs(u_ref))
difference = np.max(np.abs(u - u_ref)) / scale
print(f"displacements at the end of load step {args.load_step} (row {row}): max |u - u_ref| / max |u_ref| = "
      f"{difference:.3e} (max |u_ref| = {scale:.6e}, tolerance {args.rtol:g})")
failed |= not difference <= args.rtol
columns = [c for c in args.columns.split(",") if c]
floor = args.rtol * max([abs(reference_rows[-1][c]) for c in columns] + [0.0])
for c in columns:
    a, b = stepped_rows[row][c], reference_rows[-1][c]
    ok = abs(a - b) <= args.rtol * abs(b) + floor
    print(f"{c}: {a:.12g} against {b:.12g} (rel. {abs(a - b) / max(abs(b), 1e-300):.3e}) {'ok' if ok else 'FAILED'}")
    failed |= not ok
sys.exit(1 if failed else 0)
