#!/usr/bin/python3
"""calculix_press.py RESULTS D E NU WORKDIR [--rtol R] [--ccx PATH]

The frictionless press of press_slide_quadratic_3d.xml (Friction Coefficient 0) against CalculiX on the identical
mesh. RESULTS is the run's <name> (RESULTS.exo, RESULTS.history.csv). The TETRA10 or HEX20 block of the results
file is written as CalculiX C3D10 or C3D20 elements (Exodus TETRA10 is C3D10's order; HEX20's mid-edge nodes
13-16 (vertical edges) and 17-20 (top edges) are C3D20's 17-20 and 13-16), linear elastic E, NU, the top held
(u = 0) and the bottom pushed up by D in y, free in x and z: the frictionless contact of a flat rigid base with
the whole bottom in contact, as a Dirichlet condition. CalculiX's total reaction of the bottom is compared with
the contact force at the end of load step 1 (the press; the last row of a deck without steps); exit 1 when they differ by more than R (default 1e-4),
77 (skipped) without ccx."""
import csv
import os
import re
import shutil
import subprocess
import sys

import netCDF4
import numpy as np

results, d, E, nu, work = sys.argv[1], *map(float, sys.argv[2:5]), sys.argv[5]
rtol = float(sys.argv[sys.argv.index("--rtol") + 1]) if "--rtol" in sys.argv else 1e-4
ccx = sys.argv[sys.argv.index("--ccx") + 1] if "--ccx" in sys.argv else shutil.which("ccx")
if not ccx:
    print("ccx not found (apt-get install calculix-ccx): the comparison with CalculiX is skipped")
    sys.exit(77)
ds = netCDF4.Dataset(results + ".exo")
X = [np.asarray(ds.variables["coord" + c][:]) for c in "xyz"]
cells, kind = None, None
for b in range(1, len(ds.dimensions["num_el_blk"]) + 1):
    conn = ds.variables[f"connect{b}"]
    name = conn.getncattr("elem_type").upper()
    if name.startswith(("HEX20", "TETRA10")):
        cells, kind = np.asarray(conn[:]), name
if kind.startswith("HEX20"):
    cells, element = np.concatenate([cells[:, :12], cells[:, 16:20], cells[:, 12:16]], axis=1), "C3D20"
else:
    element = "C3D10"
ids = np.unique(cells)
y = X[1][ids - 1]
top, bottom = ids[np.isclose(y, y.max(), rtol=0, atol=1e-12)], ids[np.isclose(y, y.min(), rtol=0, atol=1e-12)]


def node_set(name, nodes):
    return "\n".join([f"*NSET, NSET={name}"] + [", ".join(map(str, nodes[i:i + 8])) for i in range(0, len(nodes), 8)])


def element_line(e, c):  # CalculiX takes at most 16 entries a line
    head = f"{e + 1}, " + ", ".join(map(str, c[:15]))
    return head + (",\n" + ", ".join(map(str, c[15:])) if len(c) > 15 else "")


text = ["*NODE"] + [f"{n}, {X[0][n - 1]:.17g}, {X[1][n - 1]:.17g}, {X[2][n - 1]:.17g}" for n in ids]
text += [f"*ELEMENT, TYPE={element}, ELSET=EALL"] + [element_line(e, c) for e, c in enumerate(cells)]
text += [node_set("TOP", top), node_set("BOTTOM", bottom), "*MATERIAL, NAME=M", "*ELASTIC", f"{E:.17g}, {nu:.17g}",
         "*SOLID SECTION, ELSET=EALL, MATERIAL=M", "*STEP", "*STATIC", "*BOUNDARY", "TOP, 1, 3",
         f"BOTTOM, 2, 2, {d:.17g}", "*NODE PRINT, NSET=BOTTOM, TOTALS=ONLY", "RF", "*END STEP"]
os.makedirs(work, exist_ok=True)
with open(os.path.join(work, "press.inp"), "w") as f:
    f.write("\n".join(text) + "\n")
subprocess.run([ccx, "-i", "press"], cwd=work, stdout=subprocess.DEVNULL, env=dict(os.environ, OMP_NUM_THREADS="1"))
totals = re.findall(r"total force.*\n\s*\n\s*(\S+)\s+(\S+)\s+(\S+)", open(os.path.join(work, "press.dat")).read())
reference = float(totals[-1][1])
press = [row for row in csv.DictReader(open(results + ".history.csv")) if row.get("load_step", "1") == "1"][-1]
force = float(press["contact_force_base_y"])
rel = force / reference - 1
print(f"CalculiX {element}: {len(cells)} cells, {len(bottom)} bottom nodes pushed by {d:g}: force {reference:.9g}; "
      f"Contessa's press: {force:.9g} ({press['active_contacts']} of them in contact): {rel:+.2e} (|.| <= {rtol:g})")
sys.exit(0 if abs(rel) <= rtol else 1)
