#!/usr/bin/python3
"""calculix_hertz_sphere.py MSH WORKDIR [--contact surface|node] [--run] [--slope 1e7]

The peer-code check of the Tet10 Hertz sphere (docs/verification-contact.md, "Hertz sphere on tetrahedra"):
writes a CalculiX deck of the same Gmsh TETRA10 mesh (hertz_sphere_tet10.msh) as C3D10 elements, with the
deck's data (E = 20 000 MPa, nu = 0.3, symmetry on x = 0 and y = 0, the equator pushed 2 mm in two
increments) against the plane z = -50 made of a fixed block of C3D8 (every node fixed: rigid), the contact
linear penalty with the deck's slope (1e7 MPa/mm), surface-to-surface (mortar-like, the TRI6 faces as
integration surface) or node-to-surface; with --run, runs `ccx` in WORKDIR and prints, from its .frd
contact output (CPRESS at the slave nodes) and the .dat totals of the equator's reaction, the force, the
pressure at the pole node and the fitted contact radius against Hertz for that force (the same fit as
check_hertz_sphere.py: p^2 = p0^2 (1 - r^2/a^2) over r <= 0.8 a_H). Not a regression test (ccx is not a
build dependency); the figures are in the verification note."""
import argparse
import math
import os
import subprocess
import sys

import numpy as np


def read_msh41(path):
    """Nodes (tag -> xyz), TETRA10 cells, TRI6 faces per physical surface name, from a Gmsh 4.1 ASCII file."""
    lines = open(path).read().split("\n")
    i = 0
    names, surface_phys, nodes, tets, faces = {}, {}, {}, [], {}
    while i < len(lines):
        head = lines[i].strip()
        if head == "$PhysicalNames":
            for k in range(int(lines[i + 1])):
                dim, tag, name = lines[i + 2 + k].split(maxsplit=2)
                names[(int(dim), int(tag))] = name.strip('"')
        elif head == "$Entities":
            counts = [int(v) for v in lines[i + 1].split()]
            j = i + 2 + counts[0] + counts[1]
            for k in range(counts[2]):
                v = lines[j + k].split()
                nphys = int(v[7])
                surface_phys[int(v[0])] = [names[(2, int(t))] for t in v[8:8 + nphys]]
        elif head == "$Nodes":
            blocks = int(lines[i + 1].split()[0])
            j = i + 2
            for _ in range(blocks):
                n = int(lines[j].split()[3])
                tags = [int(lines[j + 1 + k]) for k in range(n)]
                for k, t in enumerate(tags):
                    nodes[t] = [float(v) for v in lines[j + 1 + n + k].split()]
                j += 1 + 2 * n
        elif head == "$Elements":
            blocks = int(lines[i + 1].split()[0])
            j = i + 2
            for _ in range(blocks):
                dim, entity, etype, n = (int(v) for v in lines[j].split())
                rows = [[int(v) for v in lines[j + 1 + k].split()[1:]] for k in range(n)]
                if etype == 11:
                    tets += rows
                elif etype == 9:
                    for name in surface_phys.get(entity, []):
                        faces.setdefault(name, []).extend(rows)
                j += 1 + n
        i += 1
    return nodes, tets, faces


def abaqus_tet10(cell, nodes):
    """The cell in C3D10's order (corners, then the mid-edge nodes of 1-2, 2-3, 3-1, 1-4, 2-4, 3-4), each
    mid-edge node found as the one nearest its edge's middle (independent of Gmsh's own edge order)."""
    corners, mids = cell[:4], cell[4:]
    out = list(corners)
    for a, b in [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)]:
        centre = 0.5 * (np.array(nodes[corners[a]]) + np.array(nodes[corners[b]]))
        out.append(min(mids, key=lambda m: np.linalg.norm(np.array(nodes[m]) - centre)))
    return out


# C3D10 (and C3D4) faces by their corners (1-based in the element): S1 1-2-3, S2 1-4-2, S3 2-4-3, S4 3-4-1.
TET_FACES = {1: (0, 1, 2), 2: (0, 3, 1), 3: (1, 3, 2), 4: (2, 3, 0)}


def write_deck(msh, path, contact, slope, reach=16.0):
    nodes, tets, faces = read_msh41(msh)
    cells = [abaqus_tet10(c, nodes) for c in tets]
    # The slave faces: the TRI6 faces of "surface" within `reach` of the pole (the contact is ~10 mm wide).
    by_corners = {}
    for e, c in enumerate(cells):
        for side, (a, b, d) in TET_FACES.items():
            by_corners[frozenset((c[a], c[b], c[d]))] = (e + 1, side)
    slave = []
    for f in faces["surface"]:
        centre = np.mean([nodes[n] for n in f[:3]], axis=0)
        if math.hypot(centre[0], centre[1]) <= reach:
            slave.append(by_corners[frozenset(f[:3])])
    slave_nodes = sorted({n for f in faces["surface"] for n in f
                          if math.hypot(nodes[n][0], nodes[n][1]) <= reach})
    first = max(nodes) + 1
    out = ["*HEADING", "Hertz sphere on Tet10 (hertz_sphere_tet10.msh) against a rigid plane, Contessa's peer check",
           "*NODE, NSET=NALL"]
    out += [f"{t}, {x[0]:.15g}, {x[1]:.15g}, {x[2]:.15g}" for t, x in sorted(nodes.items())]
    # The plane: a fixed block x, y in [-4, 24] (2 mm cells), z in [-52, -50].
    n_cells, h = 14, 2.0
    plate = {}
    for k, z in enumerate((-52.0, -50.0)):
        for j in range(n_cells + 1):
            for i in range(n_cells + 1):
                tag = first + k * (n_cells + 1) ** 2 + j * (n_cells + 1) + i
                plate[(i, j, k)] = tag
                out.append(f"{tag}, {-4.0 + h * i:.15g}, {-4.0 + h * j:.15g}, {z:.15g}")
    out.append("*ELEMENT, TYPE=C3D10, ELSET=SPHERE")
    out += [f"{e + 1}, " + ", ".join(str(n) for n in c) for e, c in enumerate(cells)]
    out.append("*ELEMENT, TYPE=C3D8, ELSET=PLATE")
    plate_first = len(cells) + 1
    top = []
    for j in range(n_cells):
        for i in range(n_cells):
            e = plate_first + j * n_cells + i
            q = [plate[(i, j, 0)], plate[(i + 1, j, 0)], plate[(i + 1, j + 1, 0)], plate[(i, j + 1, 0)]]
            t = [plate[(i, j, 1)], plate[(i + 1, j, 1)], plate[(i + 1, j + 1, 1)], plate[(i, j + 1, 1)]]
            out.append(f"{e}, " + ", ".join(str(n) for n in q + t))
            top.append(e)
    node_sets = {name: sorted({n for f in faces[name] for n in f}) for name in ("symmetry_x", "symmetry_y", "equator")}
    for name, members in node_sets.items():
        out.append(f"*NSET, NSET={name.upper()}")
        out += [", ".join(str(n) for n in members[k:k + 12]) for k in range(0, len(members), 12)]
    out.append("*NSET, NSET=PLATENODES")
    tags = sorted(plate.values())
    out += [", ".join(str(n) for n in tags[k:k + 12]) for k in range(0, len(tags), 12)]
    if contact == "node":
        out.append("*SURFACE, NAME=SLAVE, TYPE=NODE")
        out += [str(n) for n in slave_nodes]
    else:
        out.append("*SURFACE, NAME=SLAVE, TYPE=ELEMENT")
        out += [f"{e}, S{s}" for e, s in slave]
    out.append("*SURFACE, NAME=MASTER, TYPE=ELEMENT")
    out += [f"{e}, S2" for e in top]  # C3D8 S2: the face of nodes 5-8, z = -50
    out += ["*MATERIAL, NAME=ELASTIC", "*ELASTIC", "20000.0, 0.3", "*SOLID SECTION, ELSET=SPHERE, MATERIAL=ELASTIC",
            "*MATERIAL, NAME=STIFF", "*ELASTIC", "2.0e9, 0.3", "*SOLID SECTION, ELSET=PLATE, MATERIAL=STIFF",
            "*SURFACE INTERACTION, NAME=PENALTY", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR",
            # slope (pressure per overclosure), tension at large clearance (node-to-surface), c0
            f"{slope:.6g}, 1e-3, 1e-3",
            "*CONTACT PAIR, INTERACTION=PENALTY, TYPE=" + ("NODE TO SURFACE" if contact == "node" else "SURFACE TO SURFACE"),
            "SLAVE, MASTER",
            "*BOUNDARY", "SYMMETRY_X, 1, 1", "SYMMETRY_Y, 2, 2", "PLATENODES, 1, 3",
            "*STEP, NLGEOM=NO, INC=200", "*STATIC", "0.5, 1.0, 1e-4, 0.5",
            "*BOUNDARY", "EQUATOR, 3, 3, -2.0",
            "*NODE FILE", "U", "*CONTACT FILE", "CSTR, CDIS",
            "*NODE PRINT, NSET=EQUATOR, TOTALS=ONLY", "RF", "*END STEP"]
    open(path, "w").write("\n".join(out) + "\n")
    return nodes, slave_nodes


def last_block(frd, name):
    """The last result block `name` of a .frd file: node tag -> values."""
    values, current = None, None
    for line in open(frd):
        if line.startswith(" -4"):
            current = {} if line.split()[1] == name else None
            if current is not None:
                values = current
        elif current is not None and line.startswith(" -1"):
            tag = int(line[3:13])
            current[tag] = [float(line[13 + 12 * k:25 + 12 * k]) for k in range((len(line.rstrip()) - 13) // 12)]
    return values or {}


def equator_force(dat):
    """The last total z reaction of the equator in the .dat file."""
    force, take = None, False
    for line in open(dat):
        if "total force" in line and "equator" in line.lower():
            take = True
            continue
        if take and line.strip():
            force = float(line.split()[2])
            take = False
    return force


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("msh")
    parser.add_argument("workdir")
    parser.add_argument("--contact", choices=["surface", "node"], default="surface")
    parser.add_argument("--slope", type=float, default=1e7)
    parser.add_argument("--run", action="store_true")
    args = parser.parse_args()
    os.makedirs(args.workdir, exist_ok=True)
    job = "sphere"
    nodes, slave_nodes = write_deck(args.msh, os.path.join(args.workdir, job + ".inp"), args.contact, args.slope)
    if not args.run:
        return 0
    subprocess.run(["ccx", "-i", job], cwd=args.workdir, check=True, stdout=subprocess.DEVNULL)
    contact = last_block(os.path.join(args.workdir, job + ".frd"), "CONTACT")
    force = 4.0 * abs(equator_force(os.path.join(args.workdir, job + ".dat")))
    E_star = 20000.0 / (1 - 0.3 ** 2)
    a_h = (3 * force * 50.0 / (4 * E_star)) ** (1 / 3)
    p0_h = 3 * force / (2 * math.pi * a_h ** 2)
    r = np.array([math.hypot(*nodes[n][:2]) for n in slave_nodes])
    # CONTACT block: COPEN, CSLIP1, CSLIP2, CPRESS, CSHEAR1, CSHEAR2 at the slave nodes.
    p = np.array([contact.get(n, [0, 0, 0, 0])[3] for n in slave_nodes])
    pole = int(np.argmin(r))
    fit = (p > 0) & (r <= 0.8 * a_h)
    slope, intercept = np.polyfit(r[fit] ** 2, p[fit] ** 2, 1)
    # No radius where the fit is not a falling line (node-to-surface: nodes open inside the contact).
    a_fit = math.sqrt(-intercept / slope) if slope < 0 < intercept else float("nan")
    print(f"ccx {args.contact}-to-surface: P = {force:.1f} N, a_H = {a_h:.4f} mm, p0_H = {p0_h:.2f} MPa")
    print(f"  pole p0 = {p[pole]:.2f} MPa ({p[pole] / p0_h - 1:+.2%}), fit peak {math.sqrt(max(intercept, 0.0)):.2f} "
          f"({math.sqrt(max(intercept, 0.0)) / p0_h - 1:+.2%}), a_fit = {a_fit:.4f} mm ({a_fit / a_h - 1:+.2%}); "
          f"{int((p > 0).sum())} nodes in contact")
    return 0


if __name__ == "__main__":
    sys.exit(main())
