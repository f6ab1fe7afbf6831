#!/usr/bin/python3
"""msh_to_exodus.py MESH.msh OUT.exo

Converts a Gmsh 4.1 ASCII mesh of 8-node hexahedra into an Exodus II file as other tools write it
(netCDF classic 64-bit offset, 32-bit integers, Exodus API 6 layout; netCDF4 only, no Contessa code),
so that a deck on the Exodus file tests Contessa's Exodus reader on a file it did not write itself:
  - each physical volume is an element block (HEX8) named after the group;
  - each physical surface is a side set (every quadrilateral matched to the hexahedron face it is, in
    the Exodus side numbering) and a node set of the same name; node set 'all' holds every node
    (the sets the Box generator defines);
  - nodes keep Gmsh's order (by tag, only those of hexahedra), elements Gmsh's: not the Box's numbering.
Gmsh's hexahedron node order is Exodus' (bottom face counter-clockwise, then the top face).
"""
import sys

import netCDF4
import numpy as np

# Exodus HEX8 sides (1-based side number -> 0-based local nodes).
HEX8_SIDES = {1: (0, 1, 5, 4), 2: (1, 2, 6, 5), 3: (2, 3, 7, 6), 4: (0, 4, 7, 3), 5: (0, 3, 2, 1), 6: (4, 5, 6, 7)}
GMSH_QUAD4, GMSH_HEX8 = 3, 5


def sections(path):
    """Each $Section's lines, split into words."""
    out, name = {}, None
    with open(path) as f:
        for line in f:
            line = line.strip()
            if line.startswith("$End"):
                name = None
            elif line.startswith("$"):
                name = line[1:]
                out[name] = []
            elif name is not None:
                out[name].append(line.split())
    return out


def read_msh(path):
    s = sections(path)
    if s["MeshFormat"][0][0] != "4.1" or s["MeshFormat"][0][1] != "0":
        sys.exit(f"{path}: expected a Gmsh 4.1 ASCII file")
    names = {(int(dim), int(tag)): name.strip('"') for dim, tag, name in s["PhysicalNames"][1:]}
    # $Entities: per (dim, entity tag) its physical tags.
    ent = s["Entities"]
    counts = [int(c) for c in ent[0]]
    physical, row = {}, 1
    for dim in range(4):
        for _ in range(counts[dim]):
            words = ent[row]
            row += 1
            first = 4 if dim == 0 else 7  # a point: tag x y z; others: tag and a bounding box
            n = int(words[first])
            physical[(dim, int(words[0]))] = [abs(int(t)) for t in words[first + 1:first + 1 + n]]
    # $Nodes: blocks of tags then coordinates.
    nodes, lines, row = {}, s["Nodes"], 1
    while row < len(lines):
        count = int(lines[row][3])
        tags = [int(lines[row + 1 + k][0]) for k in range(count)]
        for k, tag in enumerate(tags):
            nodes[tag] = [float(v) for v in lines[row + 1 + count + k]]
        row += 1 + 2 * count
    # $Elements: blocks of one type on one entity.
    hexes, quads, lines, row = {}, {}, s["Elements"], 1
    while row < len(lines):
        dim, entity, kind, count = (int(v) for v in lines[row])
        for k in range(count):
            conn = [int(v) for v in lines[row + 1 + k][1:]]
            for group in physical.get((dim, entity), []):
                if kind == GMSH_HEX8 and dim == 3:
                    hexes.setdefault(names[(3, group)], []).append(conn)
                elif kind == GMSH_QUAD4 and dim == 2:
                    quads.setdefault(names[(2, group)], []).append(conn)
                else:
                    sys.exit(f"{path}: element type {kind} in group {names.get((dim, group))} is not converted")
        row += 1 + count
    return nodes, hexes, quads


def names_array(names, length):
    out = np.zeros((len(names), length), dtype="S1")
    for k, name in enumerate(names):
        out[k, :len(name)] = [c.encode() for c in name]
    return out


def convert(msh, exo):
    nodes, hexes, quads = read_msh(msh)
    used = sorted({n for conns in hexes.values() for conn in conns for n in conn})
    number = {tag: k + 1 for k, tag in enumerate(used)}  # Exodus node numbers, from 1
    blocks = [(name, np.array([[number[n] for n in conn] for conn in conns], dtype=np.int32))
              for name, conns in hexes.items()]
    # Every hexahedron face (as a node set) -> (element number from 1, side).
    faces, element = {}, 0
    for _, conns in blocks:
        for conn in conns:
            element += 1
            for side, local in HEX8_SIDES.items():
                faces[frozenset(int(conn[i]) for i in local)] = (element, side)
    side_sets, node_sets = {}, {}
    for name, conns in quads.items():
        entries = []
        for conn in conns:
            key = frozenset(number[n] for n in conn)
            if key not in faces:
                sys.exit(f"{msh}: a quadrilateral of '{name}' is no hexahedron's face")
            entries.append(faces[key])
        entries.sort()
        side_sets[name] = entries
        node_sets[name] = sorted({number[n] for conn in conns for n in conn})
    node_sets["all"] = list(range(1, len(used) + 1))

    ds = netCDF4.Dataset(exo, "w", format="NETCDF3_64BIT_OFFSET")
    name_length = 33
    ds.setncatts({"api_version": np.float32(6.02), "version": np.float32(6.02),
                  "floating_point_word_size": np.int32(8), "file_size": np.int32(1),
                  "maximum_name_length": np.int32(name_length - 1), "int64_status": np.int32(0),
                  "title": f"converted from {msh.rsplit('/', 1)[-1]} by msh_to_exodus.py"})
    dims = [("len_string", 33), ("len_line", 81), ("four", 4), ("len_name", name_length), ("time_step", None),
            ("num_dim", 3), ("num_nodes", len(used)), ("num_elem", element), ("num_el_blk", len(blocks)),
            ("num_node_sets", len(node_sets)), ("num_side_sets", len(side_sets))]
    dims += [(f"num_el_in_blk{k}", len(conn)) for k, (_, conn) in enumerate(blocks, 1)]
    dims += [(f"num_nod_per_el{k}", 8) for k in range(1, len(blocks) + 1)]
    dims += [(f"num_nod_ns{k}", len(v)) for k, v in enumerate(node_sets.values(), 1)]
    dims += [(f"num_side_ss{k}", len(v)) for k, v in enumerate(side_sets.values(), 1)]
    for name, size in dims:
        ds.createDimension(name, size)
    ds.createVariable("time_whole", "f8", ("time_step",))
    for prefix, count, dim in [("eb", len(blocks), "num_el_blk"), ("ns", len(node_sets), "num_node_sets"),
                               ("ss", len(side_sets), "num_side_sets")]:
        ds.createVariable(f"{prefix}_status", "i4", (dim,))[:] = np.ones(count, dtype=np.int32)
        prop = ds.createVariable(f"{prefix}_prop1", "i4", (dim,))
        prop.setncattr("name", "ID")
        prop[:] = np.arange(1, count + 1, dtype=np.int32)
    xyz = np.array([nodes[tag] for tag in used])
    for axis, name in enumerate("xyz"):
        ds.createVariable(f"coord{name}", "f8", ("num_nodes",))[:] = xyz[:, axis]
    ds.createVariable("coor_names", "S1", ("num_dim", "len_name"))[:] = names_array(["x", "y", "z"], name_length)
    ds.createVariable("eb_names", "S1", ("num_el_blk", "len_name"))[:] = names_array([b[0] for b in blocks],
                                                                                    name_length)
    ds.createVariable("ns_names", "S1", ("num_node_sets", "len_name"))[:] = names_array(list(node_sets), name_length)
    ds.createVariable("ss_names", "S1", ("num_side_sets", "len_name"))[:] = names_array(list(side_sets), name_length)
    for k, (_, conn) in enumerate(blocks, 1):
        var = ds.createVariable(f"connect{k}", "i4", (f"num_el_in_blk{k}", f"num_nod_per_el{k}"))
        var.setncattr("elem_type", "HEX8")
        var[:] = conn
    for k, members in enumerate(node_sets.values(), 1):
        ds.createVariable(f"node_ns{k}", "i4", (f"num_nod_ns{k}",))[:] = np.array(members, dtype=np.int32)
    for k, entries in enumerate(side_sets.values(), 1):
        ds.createVariable(f"elem_ss{k}", "i4", (f"num_side_ss{k}",))[:] = np.array([e for e, _ in entries], np.int32)
        ds.createVariable(f"side_ss{k}", "i4", (f"num_side_ss{k}",))[:] = np.array([s for _, s in entries], np.int32)
    ds.close()
    print(f"{exo}: {len(used)} nodes, {element} HEX8 in {len(blocks)} block(s), side sets {', '.join(side_sets)}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    convert(sys.argv[1], sys.argv[2])
