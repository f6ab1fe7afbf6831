#!/usr/bin/python3
"""check_flat_punch.py RESULTS A D E NU [--calculix WORKDIR [--ccx PATH]] [--plane-strain]

The rigid flat punch of flat_punch_axisymmetric.xml (radius A pressed D, frictionless, axisymmetric; RESULTS is
the run's <name>: RESULTS.exo and RESULTS.history.csv). Checks at the last step:
  - equilibrium: the bottom's axial reaction balances the punch's force, to 1e-8 relative;
  - Boussinesq's pressure away from the singular edge: p(r) = F / (2 pi A sqrt(A^2 - r^2)) (Johnson, Contact
    Mechanics, eq. 3.34 with the force of §5.2), F the run's punch force, at every top node 0 <= r <= A/2, within
    3 % (measured: 2.1-2.6 % on the deck's 40 x 40 mesh, 1.0-1.2 % on 80 x 80: the edge's singularity spoils
    the discrete pressure at O(h), and the finite cylinder adds its own); the node on the axis, which a revolved
    3-node edge weighs by 0, shows its edge's pressure (contact::valueOnAxis; measured 2.1 % below, it read 0,
    open, before), and is checked on its own too;
  - with --calculix: the force against CalculiX's solution of the mixed problem on the identical mesh
    (calculix_punch.py; exit 77, skipped, without ccx), within 1e-5 (measured 2.0e-7: the augmented
    Lagrangian leaves a penetration of 1.4e-9 against D = 0.01, and CalculiX's axisymmetric elements, expanded
    into a 2-degree wedge, miss the exact uniaxial force by 2.6e-7).
With --plane-strain (the deck's section as a plane-strain body, Element = Q8) only the comparison with CalculiX
(CPE8; measured 2.6e-8) and the equilibrium are checked: Boussinesq's axisymmetric profile does not apply."""
import csv
import os
import shutil
import subprocess
import sys

import netCDF4
import numpy as np


def names(ds, var):
    return ["".join(c.decode() for c in row if c not in (b"", b"\x00")).strip() for row in ds.variables[var][:].data]


results = sys.argv[1]
a, d, E, nu = map(float, sys.argv[2:6])
row = list(csv.DictReader(open(results + ".history.csv")))[-1]
force = -float(row["contact_force_punch_y"])
reaction = float(row["reaction_bottom_y"])
ok = True
rel = abs(reaction - force) / force
half_space = "" if "--plane-strain" in sys.argv else f" (2 a E* d on a half-space: {2 * a * E / (1 - nu * nu) * d:.6g})"
print(f"punch force {force:.9g}{half_space}, bottom reaction {reaction:.9g}: relative {rel:.1e} (<= 1e-8)")
ok &= rel <= 1e-8

plane_strain = "--plane-strain" in sys.argv
ds = netCDF4.Dataset(results + ".exo")
nodal = names(ds, "name_nod_var")
x = np.asarray(ds.variables["coordx"][:])
y = np.asarray(ds.variables["coordy"][:])
p = np.asarray(ds.variables[f"vals_nod_var{nodal.index('contact_pressure') + 1}"][-1, :])
body = ds.dimensions["num_nodes"].size
inner = np.where((np.abs(y) < 1e-12) & (x > -1e-12) & (x <= 0.5 * a))[0]
exact = force / (2 * np.pi * a * np.sqrt(a * a - x[inner] ** 2))
ratio = p[inner] / exact
on_axis = ratio[np.abs(x[inner]) <= 1e-12]
print(("(not checked in plane strain) " if plane_strain else "") + f"p / Boussinesq at {len(inner)} top nodes 0 <= r <= a/2: {ratio.min():.4f} to {ratio.max():.4f} (within 3 %), on the axis {on_axis[0] if len(on_axis) else float('nan'):.4f}")
if not plane_strain:
    ok &= len(inner) >= 6 and len(on_axis) == 1 and np.all(np.abs(ratio - 1) <= 0.03)

if "--calculix" in sys.argv:
    work = sys.argv[sys.argv.index("--calculix") + 1]
    ccx = sys.argv[sys.argv.index("--ccx") + 1] if "--ccx" in sys.argv else shutil.which("ccx")
    if not ccx:
        print("ccx not found (apt-get install calculix-ccx): the comparison with CalculiX is skipped")
        sys.exit(77)
    here = os.path.dirname(os.path.abspath(__file__))
    out = subprocess.run([sys.executable, os.path.join(here, "calculix_punch.py"), results + ".exo", str(a), str(d),
                          str(E), str(nu), work, "--ccx", ccx] + (["--plane-strain"] if plane_strain else []), check=True, capture_output=True, text=True).stdout
    print(out, end="")
    reference = float(out.split("punch force")[-1])
    rel = abs(force - reference) / reference
    print(f"Contessa against CalculiX on the identical mesh: relative {rel:.2e} (<= 1e-5)")
    ok &= rel <= 1e-5
print("passed" if ok else "FAIL")
sys.exit(0 if ok else 1)
