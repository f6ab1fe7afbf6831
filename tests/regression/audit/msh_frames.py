"""The rigid frame change and the MSH 2.2 writer shared by the objectivity scripts (make_block_msh.py,
make_pair_msh.py, rotate_deck.py, check_objectivity.py)."""
import math

import numpy as np


def rotation(angle_degrees, axis):
    """The rotation by angle_degrees about axis through the origin (Rodrigues' formula), a 3 x 3 matrix."""
    a = np.array(axis, dtype=float) / np.linalg.norm(axis)
    t = math.radians(angle_degrees)
    K = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + math.sin(t) * K + (1 - math.cos(t)) * K @ K


def write_msh(path, names, nodes, elements):
    """A Gmsh MSH 2.2 file: names (dim, tag, name) physical groups, nodes 3-vectors numbered from 1, elements
    (Gmsh type, physical tag, node numbers)."""
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n%d\n" % len(names))
        for dim, tag, name in names:
            f.write(f'{dim} {tag} "{name}"\n')
        f.write("$EndPhysicalNames\n$Nodes\n%d\n" % len(nodes))
        for n, p in enumerate(nodes, 1):
            f.write(f"{n} {float(p[0])!r} {float(p[1])!r} {float(p[2])!r}\n")
        f.write("$EndNodes\n$Elements\n%d\n" % len(elements))
        for e, (kind, tag, conn) in enumerate(elements, 1):
            f.write(f"{e} {kind} 2 {tag} {tag} " + " ".join(map(str, conn)) + "\n")
        f.write("$EndElements\n")
