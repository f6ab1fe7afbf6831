#!/usr/bin/python3
"""Cook's membrane: the tip deflection of every element family against mesh size, and CalculiX.

Usage: cooks_membrane.py CONTESSA [--sizes 2,4,8,16,32] [--calculix] [--families ...]

Makes every mesh with Gmsh from cooks_membrane.geo (the structured n x n grid, plane or a one-layer slab
in plane strain), runs Contessa's deck cooks_membrane.xml (2D) or cooks_membrane_3d.xml (3D) on it with
`--set` for the mesh file and the element, and prints the vertical displacement of the corner C (48, 60)
(history column tip_y) per family and size. With --calculix, CalculiX (`ccx`, Debian's calculix-ccx)
solves the identical 2D QUAD8 meshes with CPE8 elements (full integration) and consistent nodal forces
of the shear traction (1/6, 4/6, 1/6 of each edge's share): its finest answer is the reference of the
table (docs/verification.md, "Cook's membrane"). Needs gmsh and, for --calculix, ccx on PATH.
"""
import argparse
import csv
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
GEO = os.path.join(HERE, "cooks_membrane.geo")

# family: (dim, cells, order, incomplete)
FAMILIES = {
    "Q4": (2, 1, 1, 1), "Q4 Enhanced": (2, 1, 1, 1), "Tri3": (2, 0, 1, 1), "Tri6": (2, 0, 2, 1),
    "Q8": (2, 1, 2, 1), "Q9": (2, 1, 2, 0),
    "Hex8": (3, 1, 1, 1), "Hex8 Enhanced": (3, 1, 1, 1), "Hex20": (3, 1, 2, 1), "Hex27": (3, 1, 2, 0),
    "Tet4": (3, 0, 1, 1), "Tet10": (3, 0, 2, 1), "Wedge6": (3, 2, 1, 1), "Wedge15": (3, 2, 2, 1),
}


def mesh(workdir, n, dim, cells, order, incomplete, fmt="msh41"):
    name = os.path.join(workdir, f"cook_d{dim}_c{cells}_o{order}_i{incomplete}_n{n}.{fmt[:3]}")
    if not os.path.exists(name):
        args = ["gmsh", "-v", "0", f"-{dim}", "-setnumber", "n", str(n), "-setnumber", "dim", str(dim),
                "-setnumber", "cells", str(cells), "-setnumber", "order", str(order),
                "-setnumber", "incomplete", str(incomplete)]
        if fmt == "inp":
            args += ["-setnumber", "Mesh.SaveGroupsOfNodes", "1"]
        subprocess.run(args + ["-format", fmt, GEO, "-o", name], check=True)
    return name


def contessa_tip(contessa, workdir, family, n):
    dim, cells, order, incomplete = FAMILIES[family]
    msh = mesh(workdir, n, dim, cells, order, incomplete)
    deck = os.path.join(HERE, "cooks_membrane.xml" if dim == 2 else "cooks_membrane_3d.xml")
    out = os.path.join(workdir, "out")
    os.makedirs(out, exist_ok=True)
    run = subprocess.run([contessa, deck, "--quiet", "--output-dir", out, "--set", f"Problem/Mesh/File Name={msh}",
                          "--set", f"Problem/Blocks/body/Element={family}"], capture_output=True, text=True)
    if run.returncode != 0:
        return None, (run.stderr.strip().splitlines() or ["exit %d" % run.returncode])[-1]
    stem = os.path.splitext(os.path.basename(deck))[0]
    with open(os.path.join(out, stem + ".history.csv")) as f:
        rows = list(csv.DictReader(f))
    return float(rows[-1]["tip_y"]), None


def calculix_tip(workdir, n):
    """CPE8 on the identical QUAD8 mesh: E = 1, nu = 1/3, clamped edge, consistent shear forces."""
    inp = mesh(workdir, n, 2, 1, 2, 1, fmt="inp")
    text = open(inp).read()
    nodes = {}
    block = re.search(r"\*NODE\n(.*?)\n\*", text, re.S).group(1)
    for line in block.splitlines():
        v = line.split(",")
        nodes[int(v[0])] = (float(v[1]), float(v[2]))
    elements = re.search(r"\*ELEMENT, type=CPS8, ELSET=\w+\n(.*?)\n\*", text, re.S).group(1)
    nsets = {m.group(1): [int(t) for t in re.split(r"[,\s]+", m.group(2)) if t]
             for m in re.finditer(r"\*NSET,NSET=(\w+)\n(.*?)(?=\n\*|\Z)", text, re.S)}
    loaded = sorted(nsets["loaded"], key=lambda k: nodes[k][1])  # along x = 48, bottom to top
    force = {k: 0.0 for k in loaded}
    traction = 1.0 / 16.0
    for e in range(0, len(loaded) - 1, 2):  # quadratic edges: corner, middle, corner
        a, m, b = loaded[e], loaded[e + 1], loaded[e + 2]
        length = nodes[b][1] - nodes[a][1]
        force[a] += traction * length / 6.0
        force[m] += traction * length * 4.0 / 6.0
        force[b] += traction * length / 6.0
    corner = nsets["corner"][0]
    with open(os.path.join(workdir, "cook_ccx.inp"), "w") as f:
        f.write("*NODE, NSET=NALL\n" + block + "\n")
        f.write("*ELEMENT, TYPE=CPE8, ELSET=EALL\n" + elements + "\n")
        f.write("*NSET, NSET=CLAMPED\n" + ",\n".join(str(k) for k in nsets["clamped"]) + "\n")
        f.write("*NSET, NSET=CORNER\n%d\n" % corner)
        f.write("*MATERIAL, NAME=M\n*ELASTIC\n1.0, 0.333333333333333333\n*SOLID SECTION, ELSET=EALL, MATERIAL=M\n1.0\n")
        f.write("*BOUNDARY\nCLAMPED, 1, 2\n*STEP\n*STATIC\n*CLOAD\n")
        for k, v in force.items():
            f.write("%d, 2, %.17g\n" % (k, v))
        f.write("*NODE PRINT, NSET=CORNER\nU\n*END STEP\n")
    subprocess.run(["ccx", "cook_ccx"], cwd=workdir, check=True, capture_output=True)
    dat = open(os.path.join(workdir, "cook_ccx.dat")).read()
    values = re.search(r"^\s*%d\s+(\S+)\s+(\S+)" % corner, dat, re.M)
    return float(values.group(2))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("contessa")
    parser.add_argument("--sizes", default="2,4,8,16,32")
    parser.add_argument("--calculix", action="store_true")
    parser.add_argument("--families", default=",".join(FAMILIES))
    args = parser.parse_args()
    sizes = [int(s) for s in args.sizes.split(",")]
    with tempfile.TemporaryDirectory() as workdir:
        reference = None
        if args.calculix:
            for n in sizes + [64]:
                print(f"CalculiX CPE8 n = {n}: tip_y = {calculix_tip(workdir, n):.5f}")
                sys.stdout.flush()
            reference = calculix_tip(workdir, 64)
        print("| element | " + " | ".join(f"n = {n}" for n in sizes) + " |")
        print("|---|" + "---|" * len(sizes))
        for family in args.families.split(","):
            cells = []
            for n in sizes:
                tip, error = contessa_tip(args.contessa, workdir, family, n)
                if tip is None:
                    cells.append("error: " + error[:60])
                elif reference:
                    cells.append(f"{tip:.4f} ({100 * (tip / reference - 1):+.2f} %)")
                else:
                    cells.append(f"{tip:.4f}")
            print(f"| `{family}` | " + " | ".join(cells) + " |")
            sys.stdout.flush()


if __name__ == "__main__":
    main()
