#!/usr/bin/python3
"""make_bad_meshes.py OUTDIR

Writes small Exodus II meshes the way other tools do (netCDF classic 64-bit offset, as Cubit and
most mesh generators write them), one good and each of the others broken in one realistic way, for
the bad-mesh CLI tests (tests/regression/bad_meshes/CMakeLists.txt). The good mesh is the 2 x 1
block of inputs/verification/uniaxial_tension_exodus_mesh.xml: 4 x 2 QUAD4 elements in block
'block_1', node sets left, right, bottom, side sets right, top. Numbers are Exodus' (from 1).

Written: good.exo, good_netcdf4.exo and
  nan_coordinate.exo          node 8 has y = NaN
  clockwise_element.exo       element 6 listed clockwise
  mirrored_mesh.exo           every element clockwise (a mesh mirrored without reordering)
  bow_tie.exo                 element 3 with its last two nodes swapped (self-intersecting)
  repeated_node.exo           element 2 lists one node twice (a collapsed quadrilateral)
  connectivity_out_of_range.exo  element 3 refers to node 99 of 15
  interior_side_set.exo       side set 'right' holds the side between elements 2 and 3
  side_out_of_range.exo       side set 'top' refers to side 7 of a QUAD4
  node_set_out_of_range.exo   node set 'left' refers to node 40 of 15
  quad8_mid_edge_off.exo      the good mesh as QUAD8, the mid-edge node of element 3's bottom edge moved
                              along it by 40 % of its length
  tri6_inverted.exo           the good mesh's quadrilaterals split into TRI6, element 5 listed clockwise
  tri3_interior_side_set.exo  the quadrilaterals split into TRI3, side set 'right' holding the diagonal
                              of the first quadrilateral (side 3 of element 1, shared with element 2)
  tet10_inverted.exo          a 3D mesh of two TETRA10 (the unit cube's corner tetrahedra at the origin and
                              at (1, 1, 1)), the second listed with its nodes 2 and 3 swapped (and their
                              mid-edge nodes with them)
  empty.exo, random_bytes.exo, truncated_classic.exo (good.exo cut to 2/3), truncated_classic_tail.exo
  (good.exo without its last 16 bytes), truncated_netcdf4.exo
  (good_netcdf4.exo cut in half), not_exodus.nc (a netCDF file of another kind), directory.exo/
"""
import os
import random
import shutil
import sys

import netCDF4
import numpy as np

NX, NY = 4, 2


def node(i, j):
    return j * (NX + 1) + i + 1


def good_mesh():
    """Coordinates, connectivity (1-based), node sets and side sets of the good mesh."""
    x = np.array([2.0 * i / NX for j in range(NY + 1) for i in range(NX + 1)])
    y = np.array([1.0 * j / NY for j in range(NY + 1) for i in range(NX + 1)])
    connect = np.array([[node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)]
                        for j in range(NY) for i in range(NX)], dtype=np.int32)
    node_sets = {"left": [node(0, j) for j in range(NY + 1)],
                 "right": [node(NX, j) for j in range(NY + 1)],
                 "bottom": [node(i, 0) for i in range(NX + 1)]}
    element = lambda i, j: j * NX + i + 1  # noqa: E731
    side_sets = {"right": ([element(NX - 1, j) for j in range(NY)], [2] * NY),
                 "top": ([element(i, NY - 1) for i in range(NX)], [3] * NX)}
    return {"x": x, "y": y, "connect": connect, "node_sets": node_sets, "side_sets": side_sets}


def split_into_triangles(mesh):
    """Each quadrilateral (a, b, c, d) as the triangles (a, b, c) and (a, c, d); the side sets of the
    quadrilaterals' sides 2 (b, c) and 3 (c, d) become sides 2 of the first and second triangles."""
    quads = mesh["connect"]
    mesh["connect"] = np.array([t for q in quads for t in ([q[0], q[1], q[2]], [q[0], q[2], q[3]])], dtype=np.int32)
    mesh["type"] = "TRI3"
    for name, (elements, sides) in mesh["side_sets"].items():
        mesh["side_sets"][name] = ([2 * e - (1 if s == 2 else 0) for e, s in zip(elements, sides)], [2] * len(sides))
    return mesh


def with_mid_edge_nodes(mesh, corners_per_cell, edges, name):
    """The cells made quadratic: one node at the middle of each edge (numbered after the corners, in the
    order of first use), appended to each cell in the Exodus order of `edges` (pairs of local corners)."""
    middle = {}
    x, y = list(mesh["x"]), list(mesh["y"])
    cells = []
    for cell in mesh["connect"]:
        extra = []
        for a, b in edges:
            key = tuple(sorted((cell[a], cell[b])))
            if key not in middle:
                x.append((x[key[0] - 1] + x[key[1] - 1]) / 2)
                y.append((y[key[0] - 1] + y[key[1] - 1]) / 2)
                middle[key] = len(x)
            extra.append(middle[key])
        cells.append(list(cell[:corners_per_cell]) + extra)
    mesh.update({"x": np.array(x), "y": np.array(y), "connect": np.array(cells, dtype=np.int32), "type": name})
    return mesh


def tet10_pair(swap_second):
    """Two TETRA10 of the unit cube: (0,0,0) (1,0,0) (0,1,0) (0,0,1) and (1,1,1) (1,0,1) (0,1,1) (1,1,0)
    (both right-handed), mid-edge nodes in the Exodus order (1-2, 2-3, 3-1, 1-4, 2-4, 3-4)."""
    corners = [[(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)], [(1, 1, 1), (1, 0, 1), (0, 1, 1), (1, 1, 0)]]
    edges = [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)]
    points, cells = [], []
    for c in corners:
        cell = []
        for p in c + [tuple((c[a][i] + c[b][i]) / 2 for i in range(3)) for a, b in edges]:
            cell.append(len(points) + 1)
            points.append(p)
        cells.append(cell)
    if swap_second:  # nodes 2 and 3, so edges 1-2 and 3-1 swap too, and 2-4 with 3-4
        cells[1] = [cells[1][k] for k in [0, 2, 1, 3, 6, 5, 4, 7, 9, 8]]
    x, y, z = (np.array([p[i] for p in points], dtype=float) for i in range(3))
    return {"x": x, "y": y, "z": z, "connect": np.array(cells, dtype=np.int32), "type": "TETRA10",
            "node_sets": {"origin": [1]}, "side_sets": {"base": ([1], [4])}}


def quad8_mesh():
    return with_mid_edge_nodes(good_mesh(), 4, [(0, 1), (1, 2), (2, 3), (3, 0)], "QUAD8")


def tri6_mesh():
    return with_mid_edge_nodes(split_into_triangles(good_mesh()), 3, [(0, 1), (1, 2), (2, 0)], "TRI6")


def names_array(names):
    out = np.zeros((len(names), 33), dtype="S1")
    for k, name in enumerate(names):
        out[k, :len(name)] = [c.encode() for c in name]
    return out


def write_exodus(path, mesh, fmt="NETCDF3_64BIT_OFFSET"):
    """The Exodus II (API 6) layout: dimensions, attributes and variables as the library writes them."""
    ds = netCDF4.Dataset(path, "w", format=fmt)
    ds.setncatts({"api_version": np.float32(6.02), "version": np.float32(6.02),
                  "floating_point_word_size": np.int32(8), "file_size": np.int32(1),
                  "maximum_name_length": np.int32(32), "int64_status": np.int32(0),
                  "title": "bad mesh corpus"})
    connect = mesh["connect"]
    node_sets, side_sets = mesh["node_sets"], mesh["side_sets"]
    for name, size in [("len_string", 33), ("len_line", 81), ("four", 4), ("len_name", 33), ("time_step", None),
                       ("num_dim", 3 if "z" in mesh else 2), ("num_nodes", len(mesh["x"])), ("num_elem", len(connect)),
                       ("num_el_blk", 1), ("num_node_sets", len(node_sets)), ("num_side_sets", len(side_sets)),
                       ("num_el_in_blk1", len(connect)), ("num_nod_per_el1", connect.shape[1])]:
        ds.createDimension(name, size)
    for k, nodes in enumerate(node_sets.values(), 1):
        ds.createDimension(f"num_nod_ns{k}", len(nodes))
    for k, (elements, _) in enumerate(side_sets.values(), 1):
        ds.createDimension(f"num_side_ss{k}", len(elements))
    ds.createVariable("time_whole", "f8", ("time_step",))
    for prefix, count, dim in [("eb", 1, "num_el_blk"), ("ns", len(node_sets), "num_node_sets"),
                               ("ss", len(side_sets), "num_side_sets")]:
        ds.createVariable(f"{prefix}_status", "i4", (dim,))[:] = np.ones(count, dtype=np.int32)
        prop = ds.createVariable(f"{prefix}_prop1", "i4", (dim,))
        prop.setncattr("name", "ID")
        prop[:] = np.arange(1, count + 1, dtype=np.int32)
    ds.createVariable("coordx", "f8", ("num_nodes",))[:] = mesh["x"]
    ds.createVariable("coordy", "f8", ("num_nodes",))[:] = mesh["y"]
    if "z" in mesh:
        ds.createVariable("coordz", "f8", ("num_nodes",))[:] = mesh["z"]
    ds.createVariable("eb_names", "S1", ("num_el_blk", "len_name"))[:] = names_array(["block_1"])
    ds.createVariable("ns_names", "S1", ("num_node_sets", "len_name"))[:] = names_array(list(node_sets))
    ds.createVariable("ss_names", "S1", ("num_side_sets", "len_name"))[:] = names_array(list(side_sets))
    ds.createVariable("coor_names", "S1", ("num_dim", "len_name"))[:] = names_array(["x", "y", "z"][:3 if "z" in mesh else 2])
    conn = ds.createVariable("connect1", "i4", ("num_el_in_blk1", "num_nod_per_el1"))
    conn.setncattr("elem_type", mesh.get("type", "QUAD4"))
    conn[:] = connect
    for k, nodes in enumerate(node_sets.values(), 1):
        ds.createVariable(f"node_ns{k}", "i4", (f"num_nod_ns{k}",))[:] = np.array(nodes, dtype=np.int32)
    for k, (elements, sides) in enumerate(side_sets.values(), 1):
        ds.createVariable(f"elem_ss{k}", "i4", (f"num_side_ss{k}",))[:] = np.array(elements, dtype=np.int32)
        ds.createVariable(f"side_ss{k}", "i4", (f"num_side_ss{k}",))[:] = np.array(sides, dtype=np.int32)
    ds.close()


def truncated_copy(source, target, fraction):
    with open(source, "rb") as f:
        data = f.read()
    with open(target, "wb") as f:
        f.write(data[:int(len(data) * fraction)])


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    write_exodus(os.path.join(out, "good.exo"), good_mesh())
    write_exodus(os.path.join(out, "good_netcdf4.exo"), good_mesh(), fmt="NETCDF4")

    def variant(name, change):
        mesh = good_mesh()
        change(mesh)
        write_exodus(os.path.join(out, name + ".exo"), mesh)

    variant("nan_coordinate", lambda m: m["y"].__setitem__(7, np.nan))
    variant("clockwise_element", lambda m: m["connect"].__setitem__(5, m["connect"][5][::-1]))
    variant("mirrored_mesh", lambda m: m.__setitem__("connect", np.ascontiguousarray(m["connect"][:, ::-1])))
    variant("bow_tie", lambda m: m["connect"].__setitem__(2, m["connect"][2][[0, 1, 3, 2]]))
    variant("repeated_node", lambda m: m["connect"].__setitem__((1, 1), m["connect"][1][0]))
    variant("connectivity_out_of_range", lambda m: m["connect"].__setitem__((2, 1), 99))
    variant("interior_side_set", lambda m: m["side_sets"].__setitem__("right", ([2], [2])))
    variant("side_out_of_range", lambda m: m["side_sets"]["top"][1].__setitem__(0, 7))
    variant("node_set_out_of_range", lambda m: m["node_sets"]["left"].append(40))

    def moved_mid_edge_node(m):  # element 3's side 1 (y = 0): its mid-edge node, 5th of the cell
        m["x"][m["connect"][2][4] - 1] -= 0.4 * 0.5
        return m

    write_exodus(os.path.join(out, "quad8_mid_edge_off.exo"), moved_mid_edge_node(quad8_mesh()))
    tri6 = tri6_mesh()
    tri6["connect"][4] = tri6["connect"][4][[0, 2, 1, 5, 4, 3]]
    write_exodus(os.path.join(out, "tri6_inverted.exo"), tri6)
    tri3 = split_into_triangles(good_mesh())
    tri3["side_sets"]["right"] = ([1], [3])  # triangle 1 (a, b, c): side 3 (c, a) is the diagonal
    write_exodus(os.path.join(out, "tri3_interior_side_set.exo"), tri3)
    write_exodus(os.path.join(out, "tet10_good.exo"), tet10_pair(False))
    write_exodus(os.path.join(out, "tet10_inverted.exo"), tet10_pair(True))

    open(os.path.join(out, "empty.exo"), "wb").close()
    with open(os.path.join(out, "random_bytes.exo"), "wb") as f:
        f.write(random.Random(7).randbytes(4096))
    truncated_copy(os.path.join(out, "good.exo"), os.path.join(out, "truncated_classic.exo"), 2 / 3)
    with open(os.path.join(out, "good.exo"), "rb") as f:  # the last 16 bytes lost: netCDF alone reads zeros
        data = f.read()
    with open(os.path.join(out, "truncated_classic_tail.exo"), "wb") as f:
        f.write(data[:-16])
    truncated_copy(os.path.join(out, "good_netcdf4.exo"), os.path.join(out, "truncated_netcdf4.exo"), 1 / 2)
    with netCDF4.Dataset(os.path.join(out, "not_exodus.nc"), "w") as ds:
        ds.createDimension("time", 3)
        ds.createVariable("temperature", "f8", ("time",))[:] = [280.0, 281.5, 283.0]
    directory = os.path.join(out, "directory.exo")
    shutil.rmtree(directory, ignore_errors=True)
    os.makedirs(directory)


if __name__ == "__main__":
    main()
