#!/usr/bin/python3
"""make_block_msh.py OUT NX NY [NZ] [--angle DEG] [--axis AX AY AZ] [--translate TX TY [TZ]]

Writes the block [0, 1] x [0, 0.5] (x [0, 1] with NZ) as a structured Gmsh MSH 2.2 mesh of NX x NY (x NZ) QUAD4
(HEX8), physical groups "block", "bottom" (y = 0) and "top" (y = 0.5), rotated by DEG degrees about the axis
(AX, AY, AZ) through the origin (2D: about z) and then translated: the same mesh, node for node, in another
frame, for the objectivity decks (objectivity_2d.xml, objectivity_3d.xml). Prints the rotation matrix."""
import argparse

import numpy as np

from msh_frames import rotation, write_msh

parser = argparse.ArgumentParser()
parser.add_argument("out")
parser.add_argument("n", type=int, nargs="+")
parser.add_argument("--angle", type=float, default=0.0)
parser.add_argument("--axis", type=float, nargs=3, default=[0.0, 0.0, 1.0])
parser.add_argument("--translate", type=float, nargs="+", default=[0.0, 0.0, 0.0])
args = parser.parse_args()
three_d = len(args.n) == 3
nx, ny = args.n[0], args.n[1]
nz = args.n[2] if three_d else 0
R = rotation(args.angle, args.axis)
shift = np.array((list(args.translate) + [0.0, 0.0])[:3])


def node(i, j, k=0):
    return 1 + i + (nx + 1) * (j + (ny + 1) * k)


nodes = []
for k in range(nz + 1):
    for j in range(ny + 1):
        for i in range(nx + 1):
            p = np.array([i / nx, 0.5 * j / ny, k / nz if three_d else 0.0])
            nodes.append(R @ p + shift)
elements = []  # (type, physical tag, nodes)
if three_d:
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                elements.append((5, 1, [node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                                        node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1),
                                        node(i, j + 1, k + 1)]))
    for j, tag in ((0, 2), (ny, 3)):
        for k in range(nz):
            for i in range(nx):
                elements.append((3, tag, [node(i, j, k), node(i + 1, j, k), node(i + 1, j, k + 1), node(i, j, k + 1)]))
    names = [(3, 1, "block"), (2, 2, "bottom"), (2, 3, "top")]
else:
    for j in range(ny):
        for i in range(nx):
            elements.append((3, 1, [node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)]))
    for j, tag in ((0, 2), (ny, 3)):
        for i in range(nx):
            elements.append((1, tag, [node(i, j), node(i + 1, j)]))
    names = [(2, 1, "block"), (1, 2, "bottom"), (1, 3, "top")]
write_msh(args.out, names, nodes, elements)
print("R =", np.array2string(R, precision=17, separator=", "))
