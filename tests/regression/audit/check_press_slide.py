#!/usr/bin/python3
"""check_press_slide.py HISTORY MU DX DZ

press_slide_quadratic_3d.xml (a block pressed by a rigid base in load step 1, slid by it along (DX, 0, DZ) in
step 2, Coulomb coefficient MU). Checks, from the history:
  - equilibrium at every increment: reaction_top + contact_force_base = 0, each component to 1e-8 of the
    normal force (the Newton solves stop at 1e-9 of the forces);
  - the end of the press: no resultant tangential force (the block and the press are symmetric about the
    planes x = 0.5 and z = 0.5; the tetrahedra's diagonals are not, so the friction's resultant is small,
    not zero: within 3e-3 of the normal force; measured 1.7e-3 on the Tet10 deck, 4.7e-4 on its 2x finer mesh,
    6e-15 on Hex20);
  - the end of the slide (Coulomb, eq. 19): every contact node slides, |Q| = MU P within 1e-3 below and
    1e-9 above (each node is on its own cone; the slip directions differ after the press: measured 1.6e-4 and
    2.3e-4 below on the Tet10 and Hex20 decks, 7e-6 and 6e-5 on the 2x finer meshes), and Q points along
    the base's motion (DX, DZ) within 1e-3 rad."""
import csv
import math
import sys

rows = list(csv.DictReader(open(sys.argv[1])))
mu, dx, dz = map(float, sys.argv[2:5])
ok = True
for row in rows[1:]:
    normal = float(row["contact_force_base_y"])
    worst = max(abs(float(row[f"reaction_top_{c}"]) + float(row[f"contact_force_base_{c}"])) for c in "xyz")
    if worst > 1e-8 * normal:
        print(f"FAIL: increment {row['step']}: reaction + contact force = {worst:.2e} (normal force {normal:.6g})")
        ok = False
press = [r for r in rows if r["load_step"] == "1"][-1]
normal = float(press["contact_force_base_y"])
shear = math.hypot(float(press["contact_force_base_x"]), float(press["contact_force_base_z"]))
print(f"end of the press: P = {normal:.9g}, |Q| / P = {shear / normal:.2e} (<= 3e-3)")
ok &= shear <= 3e-3 * normal
end = rows[-1]
P = float(end["contact_force_base_y"])
Qx, Qz = float(end["contact_force_base_x"]), float(end["contact_force_base_z"])
Q = math.hypot(Qx, Qz)
angle = abs(math.atan2(Qz, Qx) - math.atan2(dz, dx))
print(f"end of the slide: {end['slip']} of {end['active_contacts']} contact nodes slide; P = {P:.9g}, |Q| = {Q:.9g}, "
      f"|Q| / (mu P) - 1 = {Q / (mu * P) - 1:+.2e} (in [-1e-3, 1e-9]); direction off the motion by {angle:.1e} rad")
ok &= end["slip"] == end["active_contacts"] and int(end["active_contacts"]) > 0
ok &= -1e-3 <= Q / (mu * P) - 1 <= 1e-9 and angle <= 1e-3
ok &= end["load_step"] == "2" and float(end["lambda"]) == 1.0
print("passed" if ok else "FAIL")
sys.exit(0 if ok else 1)
