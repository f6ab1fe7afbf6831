#!/usr/bin/python3
"""make_pair_msh.py OUT [--angle DEG] [--axis AX AY AZ] [--translate TX TY TZ]

Writes two blocks as a structured Gmsh MSH 2.2 mesh of HEX8: "lower" [0, 1] x [0, 0.5] x [0, 1] of 4 x 2 x 4 and
"upper" [0, 1] x [0.5, 1] x [0, 1] of 3 x 2 x 3 (non-matching faces at y = 0.5), side sets lower_bottom, lower_top,
upper_bottom, upper_top, rotated by DEG degrees about the axis (AX, AY, AZ) through the origin and then translated,
as make_block_msh.py does: the mortar objectivity decks (objectivity_mortar.xml). Prints the rotation matrix."""
import argparse

import numpy as np

from msh_frames import rotation, write_msh

parser = argparse.ArgumentParser()
parser.add_argument("out")
parser.add_argument("--angle", type=float, default=0.0)
parser.add_argument("--axis", type=float, nargs=3, default=[0.0, 0.0, 1.0])
parser.add_argument("--translate", type=float, nargs=3, default=[0.0, 0.0, 0.0])
args = parser.parse_args()
R = rotation(args.angle, args.axis)
shift = np.array(args.translate)
nodes, elements = [], []
names = [(3, 1, "lower"), (3, 2, "upper"), (2, 3, "lower_bottom"), (2, 4, "lower_top"), (2, 5, "upper_bottom"),
         (2, 6, "upper_top")]
for block, (n, y0, faces) in enumerate([(4, 0.0, (3, 4)), (3, 0.5, (5, 6))]):
    ny, first = 2, len(nodes) + 1

    def node(i, j, k):
        return first + i + (n + 1) * (j + (ny + 1) * k)

    for k in range(n + 1):
        for j in range(ny + 1):
            for i in range(n + 1):
                nodes.append(R @ np.array([i / n, y0 + 0.5 * j / ny, k / n]) + shift)
    for k in range(n):
        for j in range(ny):
            for i in range(n):
                elements.append((5, block + 1, [node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                                                node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1),
                                                node(i, j + 1, k + 1)]))
    for j, tag in ((0, faces[0]), (ny, faces[1])):
        for k in range(n):
            for i in range(n):
                elements.append((3, tag, [node(i, j, k), node(i + 1, j, k), node(i + 1, j, k + 1), node(i, j, k + 1)]))
write_msh(args.out, names, nodes, elements)
print("R =", np.array2string(R, precision=17, separator=", "))
