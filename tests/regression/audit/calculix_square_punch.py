#!/usr/bin/python3
"""calculix_square_punch.py RESULTS A D E NU WORKDIR [--rtol R] [--ccx PATH]

square_punch_tet10.xml against CalculiX (ccx 2.20) on the identical mesh. RESULTS is the run's <name>
(RESULTS.exo, RESULTS.history.csv). The TETRA10 block of the results file is written as C3D10 elements (the
Exodus TETRA10 order is C3D10's), linear elastic E, NU; u_x = 0 on x = 0, u_z = 0 on z = 0, u_y = 0 on the
bottom, and the frictionless square punch [0, A]^2 as Boussinesq's mixed problem: u_y = -D on the top nodes with
x <= A and z <= A, the rest of the top free. CalculiX's force on those nodes is compared with the run's punch
force; exit 1 when they differ by more than R (default 1e-3), 77 (skipped) without ccx."""
import csv
import os
import re
import shutil
import subprocess
import sys

import netCDF4
import numpy as np

results, a, d, E, nu, work = sys.argv[1], *map(float, sys.argv[2:6]), sys.argv[6]
rtol = float(sys.argv[sys.argv.index("--rtol") + 1]) if "--rtol" in sys.argv else 1e-3
ccx = sys.argv[sys.argv.index("--ccx") + 1] if "--ccx" in sys.argv else shutil.which("ccx")
if not ccx:
    print("ccx not found (apt-get install calculix-ccx): the comparison with CalculiX is skipped")
    sys.exit(77)
ds = netCDF4.Dataset(results + ".exo")
X = [np.asarray(ds.variables["coord" + c][:]) for c in "xyz"]
cells = None
for b in range(1, len(ds.dimensions["num_el_blk"]) + 1):
    conn = ds.variables[f"connect{b}"]
    if conn.getncattr("elem_type").upper().startswith("TETRA10"):
        cells = np.asarray(conn[:])
ids = np.unique(cells)
x, y, z = (c[ids - 1] for c in X)
on = lambda v, value: np.isclose(v, value, rtol=0, atol=1e-12)  # noqa: E731
top = ids[on(y, y.max())]
punch = top[(X[0][top - 1] <= a + 1e-12) & (X[2][top - 1] <= a + 1e-12)]


def node_set(name, nodes):
    return "\n".join([f"*NSET, NSET={name}"] + [", ".join(map(str, nodes[i:i + 8])) for i in range(0, len(nodes), 8)])


text = ["*NODE"] + [f"{n}, {X[0][n - 1]:.17g}, {X[1][n - 1]:.17g}, {X[2][n - 1]:.17g}" for n in ids]
text += ["*ELEMENT, TYPE=C3D10, ELSET=EALL"] + [f"{e + 1}, " + ", ".join(map(str, c)) for e, c in enumerate(cells)]
text += [node_set("XSYM", ids[on(x, 0.0)]), node_set("ZSYM", ids[on(z, 0.0)]), node_set("BOTTOM", ids[on(y, y.min())]),
         node_set("PUNCH", punch), "*MATERIAL, NAME=M", "*ELASTIC", f"{E:.17g}, {nu:.17g}",
         "*SOLID SECTION, ELSET=EALL, MATERIAL=M", "*STEP", "*STATIC", "*BOUNDARY", "XSYM, 1, 1", "ZSYM, 3, 3",
         "BOTTOM, 2, 2", f"PUNCH, 2, 2, {-d:.17g}", "*NODE PRINT, NSET=PUNCH, TOTALS=ONLY", "RF", "*END STEP"]
os.makedirs(work, exist_ok=True)
with open(os.path.join(work, "punch.inp"), "w") as f:
    f.write("\n".join(text) + "\n")
subprocess.run([ccx, "-i", "punch"], cwd=work, stdout=subprocess.DEVNULL, env=dict(os.environ, OMP_NUM_THREADS="1"))
totals = re.findall(r"total force.*\n\s*\n\s*(\S+)\s+(\S+)\s+(\S+)", open(os.path.join(work, "punch.dat")).read())
reference = -float(totals[-1][1])
row = list(csv.DictReader(open(results + ".history.csv")))[-1]
force = -float(row["contact_force_punch_y"])
rel = force / reference - 1
print(f"CalculiX C3D10: {len(cells)} cells, {len(punch)} top nodes under the punch pushed by {d:g}: force "
      f"{reference:.9g}; Contessa: {force:.9g} ({row['active_contacts']} nodes in contact): {rel:+.2e} (|.| <= {rtol:g})")
sys.exit(0 if abs(rel) <= rtol else 1)
