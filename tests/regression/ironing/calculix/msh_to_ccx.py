#!/usr/bin/python3
"""Writes the shallow ironing mesh (Gmsh 4.1 ASCII, 2D quadrilaterals) as a one-layer CalculiX mesh.

    msh_to_ccx.py MESH.msh OUTPUT.inp

The same nodes and elements as Contessa's run, extruded by 1 mm along z into C3D8 (one layer; the deck
fixes u_z everywhere, so the run is plane strain and its reactions are per mm of thickness, the unit of
docs/verification-contact.md §8). Writes *NODE (node n of the mesh at z = 0 is n, at z = 1 is n + N),
*ELEMENT per physical surface (ELSET named after it), an NSET per physical curve (both layers) and, for
every physical curve, an element-face *SURFACE named after it (the faces of the C3D8 over the curve's
line elements: S3 to S6 for the quadrilateral's edges 1-2, 2-3, 3-4, 4-1). No meshio on Debian's python,
so the reader is here (the mesh files are the ones make_shallow_ironing_meshes.sh writes).
"""
import sys


def sections(path):
    """{section name: [lines]} of a Gmsh ASCII file."""
    result, name = {}, None
    with open(path) as stream:
        for line in stream:
            line = line.strip()
            if line.startswith('$End'):
                name = None
            elif line.startswith('$'):
                name = line[1:]
                result[name] = []
            elif name is not None:
                result[name].append(line)
    return result


def physical_names(lines):
    """{(dim, tag): name}."""
    names = {}
    for line in lines[1:]:
        dim, tag, name = line.split(maxsplit=2)
        names[(int(dim), int(tag))] = name.strip('"')
    return names


def entity_groups(lines):
    """{(dim, entity tag): [physical tags]} from $Entities (format 4.1)."""
    counts = [int(c) for c in lines[0].split()[:4]]
    groups, row = {}, 1
    for dim, count in enumerate(counts):
        for _ in range(count):
            fields = lines[row].split()
            row += 1
            tag = int(fields[0])
            n_box = 3 if dim == 0 else 6
            n_phys = int(fields[1 + n_box])
            groups[(dim, tag)] = [int(p) for p in fields[2 + n_box:2 + n_box + n_phys]]
    return groups


def nodes(lines):
    """{node tag: (x, y)}."""
    n_blocks = int(lines[0].split()[0])
    coords, row = {}, 1
    for _ in range(n_blocks):
        n_in_block = int(lines[row].split()[3])
        tags = [int(lines[row + 1 + i]) for i in range(n_in_block)]
        for i, tag in enumerate(tags):
            x, y, _ = (float(v) for v in lines[row + 1 + n_in_block + i].split())
            coords[tag] = (x, y)
        row += 1 + 2 * n_in_block
    return coords


def elements(lines):
    """[(dim, entity tag, [node tags])] of the 2-node lines and 4-node quadrilaterals."""
    n_blocks = int(lines[0].split()[0])
    result, row = [], 1
    for _ in range(n_blocks):
        dim, entity, etype, count = (int(v) for v in lines[row].split())
        for i in range(count):
            if etype in (1, 3):  # line, quadrilateral
                result.append((dim, entity, [int(v) for v in lines[row + 1 + i].split()[1:]]))
        row += 1 + count
    return result


def counterclockwise(quad, coords):
    """The quadrilateral with positive area in the xy plane (C3D8: bottom face 1-4 anticlockwise seen
    from +z, where the top face 5-8 lies)."""
    area = 0.0
    for a, b in zip(quad, quad[1:] + quad[:1]):
        area += coords[a][0] * coords[b][1] - coords[b][0] * coords[a][1]
    return quad if area > 0 else quad[::-1]


def write(path, coords, quads, lines, names):
    shift = max(coords)
    face_of_edge = {}
    with open(path, 'w') as out:
        out.write('** written by tests/regression/ironing/calculix/msh_to_ccx.py\n*NODE, NSET=NALL\n')
        for z, offset in ((0.0, 0), (1.0, shift)):
            for tag in sorted(coords):
                out.write('%d, %.15g, %.15g, %g\n' % (tag + offset, coords[tag][0], coords[tag][1], z))
        number = 0
        for group, members in quads.items():
            out.write('*ELEMENT, TYPE=C3D8, ELSET=%s\n' % group)
            for quad in members:
                number += 1
                out.write('%d, %s\n' % (number, ', '.join(str(n) for n in quad + [q + shift for q in quad])))
                for k in range(4):
                    edge = frozenset((quad[k], quad[(k + 1) % 4]))
                    face_of_edge[edge] = (number, 'S%d' % (k + 3))
        for group, members in lines.items():
            tags = sorted({n for line in members for n in line})
            out.write('*NSET, NSET=%s\n' % group)
            for tag in tags:
                out.write('%d,\n%d,\n' % (tag, tag + shift))
            out.write('*SURFACE, NAME=S_%s, TYPE=ELEMENT\n' % group)
            for line in members:
                element, face = face_of_edge[frozenset(line)]
                out.write('%d, %s\n' % (element, face))


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    parts = sections(sys.argv[1])
    names = physical_names(parts['PhysicalNames'])
    groups = entity_groups(parts['Entities'])
    coords = nodes(parts['Nodes'])
    quads, lines = {}, {}
    for dim, entity, conn in elements(parts['Elements']):
        for physical in groups.get((dim, entity), []):
            name = names[(dim, physical)]
            if dim == 2:
                quads.setdefault(name, []).append(counterclockwise(conn, coords))
            else:
                lines.setdefault(name, []).append(conn)
    write(sys.argv[2], coords, quads, lines, names)
    return 0


if __name__ == '__main__':
    sys.exit(main())
