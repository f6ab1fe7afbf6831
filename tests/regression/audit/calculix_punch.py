#!/usr/bin/python3
"""calculix_punch.py RESULTS.exo A D E NU WORKDIR [--ccx PATH] [--plane-strain]

CalculiX's answer (ccx 2.20, Debian's calculix-ccx) to the rigid flat punch of flat_punch_axisymmetric.xml
on the identical mesh: the QUAD8 block of the Contessa results file RESULTS.exo (its nodes and cells; the
Exodus QUAD8 order is CalculiX's CAX8 order) as CAX8 elements of a linear elastic E, NU; u_x = 0 on the axis
(x = 0), u_y = 0 on the bottom; on the top Boussinesq's mixed boundary value problem: u_y = -D on the top
nodes with x <= A (frictionless: u_x free), the rest of the top free. Prints the punch force P (the sum of
those nodes' reactions over the full circumference).

CalculiX's axisymmetric reactions are not per full circumference; the script does not assume its convention:
a second run on the same mesh pushes the whole top by D (uniaxial stress, exact: F = E D / H pi R^2 on the
whole circumference) and scales the punch's reactions by that run's exact over computed force (printed).
With --plane-strain the section is a plane-strain body of unit thickness instead: CPE8 elements, the exact
uniaxial force E / (1 - NU^2) D / H R per unit thickness."""
import os
import re
import subprocess
import sys

import netCDF4
import numpy as np

exo, a, d, E, nu, work = sys.argv[1], *map(float, sys.argv[2:6]), sys.argv[6]
ccx = sys.argv[sys.argv.index("--ccx") + 1] if "--ccx" in sys.argv else "ccx"
plane_strain = "--plane-strain" in sys.argv
element = "CPE8" if plane_strain else "CAX8"
ds = netCDF4.Dataset(exo)
x = np.asarray(ds.variables["coordx"][:])
y = np.asarray(ds.variables["coordy"][:])
cells = None
for b in range(1, len(ds.dimensions["num_el_blk"]) + 1):
    conn = ds.variables[f"connect{b}"]
    if conn.getncattr("elem_type").upper().startswith("QUAD8"):
        cells = np.asarray(conn[:])  # 1-based node ids
ids = np.unique(cells)
ytop, ybottom = y[ids - 1].max(), y[ids - 1].min()
top = ids[np.isclose(y[ids - 1], ytop, rtol=0, atol=1e-12)]
bottom = ids[np.isclose(y[ids - 1], ybottom, rtol=0, atol=1e-12)]
axis = ids[np.isclose(x[ids - 1], 0.0, rtol=0, atol=1e-12)]
punch = top[x[top - 1] <= a + 1e-12]


def node_set(name, nodes):
    lines = [f"*NSET, NSET={name}"]
    lines += [", ".join(str(n) for n in nodes[i:i + 8]) for i in range(0, len(nodes), 8)]
    return "\n".join(lines)


def deck(pushed):
    text = ["*NODE"]
    text += [f"{n}, {x[n - 1]:.17g}, {y[n - 1]:.17g}" for n in ids]
    text.append(f"*ELEMENT, TYPE={element}, ELSET=EALL")
    text += [f"{e + 1}, " + ", ".join(str(n) for n in c) for e, c in enumerate(cells)]
    text += [node_set("AXIS", axis), node_set("BOTTOM", bottom), node_set("PUSHED", pushed)]
    text += ["*MATERIAL, NAME=M", "*ELASTIC", f"{E:.17g}, {nu:.17g}", "*SOLID SECTION, ELSET=EALL, MATERIAL=M",
             "*STEP", "*STATIC", "*BOUNDARY", "AXIS, 1, 1", "BOTTOM, 2, 2", f"PUSHED, 2, 2, {-d:.17g}",
             "*NODE PRINT, NSET=PUSHED, TOTALS=ONLY", "RF", "*END STEP"]
    return "\n".join(text) + "\n"


def total_force(job, pushed):
    os.makedirs(work, exist_ok=True)
    with open(os.path.join(work, job + ".inp"), "w") as f:
        f.write(deck(pushed))
    subprocess.run([ccx, "-i", job], cwd=work, check=True, stdout=subprocess.DEVNULL,
                   env=dict(os.environ, OMP_NUM_THREADS="1"))
    text = open(os.path.join(work, job + ".dat")).read()
    totals = re.findall(r"total force.*\n\s*\n\s*(\S+)\s+(\S+)\s+(\S+)", text)
    return float(totals[-1][1])


R, H = x[ids - 1].max(), ytop - ybottom
exact_uniaxial = E / (1 - nu * nu) * d / H * R if plane_strain else E * d / H * np.pi * R * R
scale = exact_uniaxial / total_force("uniaxial", top)
force = total_force("punch", punch) * scale
print(f"CalculiX {element}: {len(cells)} cells, {len(ids)} nodes, {len(punch)} top nodes at x <= {a:g} pushed by {d:g}")
print(f"scale to the full circumference {scale:.9g} (2 pi = {2 * np.pi:.9g})" if not plane_strain else
      f"scale to unit thickness {scale:.9g}")
print(f"punch force {force:.9g}")
