#!/usr/bin/python3
"""check_objectivity.py REFERENCE ROTATED [--angle DEG] [--axis AX AY AZ] [--rtol R] [--interface NAME]
                      [--reaction SET] [--block BLOCK]

objectivity_2d.xml, objectivity_3d.xml and objectivity_mortar.xml (--interface interface --reaction lower_bottom
--block lower) against their rotated and translated copies (rotate_deck.py,
make_block_msh.py; the rotation R as they build it). REFERENCE and ROTATED are the runs' outputs without extension
(.history.csv, .exo). Exact identities (rigid-body objectivity), at every increment:
  - the same load step and load factor, the same number of nodes in contact and sliding (but at lambda = 0, where
    the flush bottom touches the surface at round-off: 2e-13 at 1e3 from the origin);
  - the contact force and the top's reaction of the rotated run are R times the reference's;
  - every node's displacement of the rotated run is R times the reference's (the meshes are the same node for node);
and at the end of the last step (release): no contact, no force, u = 0 on BLOCK (default 'block').
Tolerance: R (default 1e-7) of the largest force of the run for forces, of the largest displacement for
displacements (round-off: the rotated body sits 1e3 from the origin, where a coordinate keeps 13 digits and the
penetrations are 1e-5)."""
import argparse
import csv

import netCDF4
import numpy as np

from msh_frames import rotation

parser = argparse.ArgumentParser()
parser.add_argument("reference")
parser.add_argument("rotated")
parser.add_argument("--angle", type=float, default=0.0)
parser.add_argument("--axis", type=float, nargs=3, default=[0.0, 0.0, 1.0])
parser.add_argument("--rtol", type=float, default=1e-7)
parser.add_argument("--interface", default="base", help="the contact interface's name")
parser.add_argument("--reaction", default="top", help="the node set whose reaction is compared")
parser.add_argument("--block", default="block", help="the block that returns to u = 0 at the release")
args = parser.parse_args()
R = rotation(args.angle, args.axis)


def names(ds, var):
    return ["".join(c.decode() for c in row if c not in (b"", b"\x00")).strip() for row in ds.variables[var][:].data]


ref = list(csv.DictReader(open(args.reference + ".history.csv")))
rot = list(csv.DictReader(open(args.rotated + ".history.csv")))
dim = 3 if f"contact_force_{args.interface}_z" in ref[0] else 2
Rd = R[:dim, :dim]
ok = True
if len(ref) != len(rot):
    print(f"FAIL: {len(ref)} increments against {len(rot)}")
    ok = False


def vec(row, name):
    return np.array([float(row[f"{name}_{c}"]) for c in "xyz"[:dim]])


fmax = max(np.linalg.norm(vec(r, f"contact_force_{args.interface}")) for r in ref)
worst_force, worst_u = 0.0, 0.0
for a, b in zip(ref, rot):
    for key in ("load_step", "active_contacts", "slip"):
        if a[key] != b[key] and float(a["lambda"]) > 0:  # at lambda = 0 flush nodes touch at round-off
            print(f"FAIL: increment {a['step']}: {key} {a[key]} against {b[key]}")
            ok = False
    if abs(float(a["lambda"]) - float(b["lambda"])) > 1e-12:
        print(f"FAIL: increment {a['step']}: lambda {a['lambda']} against {b['lambda']}")
        ok = False
    for name in (f"contact_force_{args.interface}", f"reaction_{args.reaction}"):
        worst_force = max(worst_force, np.abs(Rd @ vec(a, name) - vec(b, name)).max() / fmax)
da, db = netCDF4.Dataset(args.reference + ".exo"), netCDF4.Dataset(args.rotated + ".exo")
na, nb = names(da, "name_nod_var"), names(db, "name_nod_var")
steps = da.variables["vals_nod_var1"].shape[0]


def displacement(ds, nodal, k):
    return np.array([ds.variables[f"vals_nod_var{nodal.index('displ_' + c) + 1}"][k, :] for c in "xyz"[:dim]])


umax = max(np.abs(displacement(da, na, k)).max() for k in range(steps))
if db.variables["vals_nod_var1"].shape[0] != steps:
    print("FAIL: the Exodus files hold different numbers of steps")
    ok = False
for k in range(min(steps, db.variables["vals_nod_var1"].shape[0])):
    worst_u = max(worst_u, np.abs(Rd @ displacement(da, na, k) - displacement(db, nb, k)).max() / umax)
blocks = names(db, "eb_names")
body = np.unique(db.variables[f"connect{blocks.index(args.block) + 1}"][:]) - 1  # not the rigid surface's nodes
end = rot[-1]
residue = max(np.linalg.norm(vec(end, f"contact_force_{args.interface}")),
              np.linalg.norm(vec(end, f"reaction_{args.reaction}"))) / fmax
u_end = np.abs(displacement(db, nb, -1)[:, body]).max() / umax
print(f"{len(ref)} increments; largest force {fmax:.6g}, largest |u| {umax:.4g}")
print(f"forces: |R f_ref - f_rot| / max|f| = {worst_force:.2e}; displacements: {worst_u:.2e} (<= {args.rtol:g})")
print(f"released: {end['active_contacts']} nodes in contact, forces {residue:.1e} of the largest, |u| {u_end:.1e} of the "
      f"largest (step {end['load_step']}, lambda {end['lambda']})")
ok &= worst_force <= args.rtol and worst_u <= args.rtol
ok &= end["active_contacts"] == "0" and residue <= args.rtol and u_end <= args.rtol and float(end["lambda"]) == 1.0
print("passed" if ok else "FAIL")
raise SystemExit(0 if ok else 1)
