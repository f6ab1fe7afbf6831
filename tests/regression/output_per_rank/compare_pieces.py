#!/usr/bin/python3
"""compare_pieces.py SINGLE.exo PIECE_0 [PIECE_1 ...]

A per-rank Exodus set (Problem/Output/Exodus Layout = Per Rank: name.exo.N.r) against the single file
of the same run on the same ranks: put together through each piece's global node and element ids, it
must hold the single file's steps exactly and its nodal, element and global values at every step to
1e-9 of the largest magnitude of the variable's group (stresses; displ_*; contact_*; globals) (two runs on 2 ranks differ in round-off: the ranks' sums
arrive in varying order; on 1 rank they are identical);
and its Nemesis records must describe the decomposition (each node in the pieces that use it, a border
node listed in the communication map of every other piece that holds it, the global sizes). Exit 0
when everything agrees; the differences are printed otherwise."""
import sys

import netCDF4
import numpy as np

problems = []
TOL = 1e-9


def same(a, b, scale=0.0):
    """Equal up to TOL times the larger magnitude of the two arrays or `scale` (the magnitude of the
    variable's group: a stress component that is zero up to round-off, e.g. sigma_xx of the patch test,
    is measured against the other stresses)."""
    if a.shape != b.shape:
        return False
    scale = max(scale, np.max(np.abs(a), initial=0.0), np.max(np.abs(b), initial=0.0))
    return bool(np.all(np.abs(a - b) <= TOL * scale))


def group_scale(ds, prefix, count, name_of):
    """Largest magnitude of each group of variables (named alike up to the last '_')."""
    scales = {}
    for v in range(1, count + 1):
        group = name_of(v).rsplit("_", 1)[0]
        for n in ds.variables:
            if n == f"{prefix}{v}" or n.startswith(f"{prefix}{v}eb"):
                scales[group] = max(scales.get(group, 0.0), float(np.max(np.abs(np.asarray(ds.variables[n][:], dtype=float)), initial=0.0)))
    return scales


def expect(condition, message):
    if not condition:
        problems.append(message)


def names(ds, var):
    if var not in ds.variables:
        return []
    return ["".join(c.decode() for c in row if c not in (b"", b"\x00")).strip() for row in ds.variables[var][:].data]


def block_values(ds, v, numbered):
    """Element variable v over the file's mesh blocks (those with the variable), in file element order."""
    out = []
    for b in range(1, len(ds.dimensions["num_el_blk"]) + 1):
        name = f"vals_elem_var{v}eb{b}"
        if name in ds.variables:
            out.append(np.asarray(ds.variables[name][:], dtype=float))
        elif f"num_el_in_blk{b}" in ds.dimensions and numbered[b - 1]:
            out.append(None)
    return out


single = netCDF4.Dataset(sys.argv[1])
pieces = [netCDF4.Dataset(p) for p in sys.argv[2:]]
steps = np.asarray(single.variables["time_whole"][:])
nodal = names(single, "name_nod_var")
element = names(single, "name_elem_var")
num_nodes = len(single.dimensions["num_nodes"])
num_elems = len(single.dimensions["num_elem"])
ranks = len(pieces)
# Stresses share one scale (all element variables are stresses); nodal variables by group (displ_*,
# contact_*); globals by the largest global.
element_scale = max(group_scale(single, "vals_elem_var", len(element), lambda v: element[v - 1]).values(), default=0.0)
nodal_scale = group_scale(single, "vals_nod_var", len(nodal), lambda v: nodal[v - 1])
global_scale = float(np.max(np.abs(np.asarray(single.variables["vals_glo_var"][:], dtype=float)), initial=0.0))

seen_nodes = np.zeros(num_nodes, dtype=int)
seen_elems = np.zeros(num_elems, dtype=int)
holders = {}
for r, ds in enumerate(pieces):
    name = sys.argv[2 + r]
    expect(np.array_equal(np.asarray(ds.variables["time_whole"][:]), steps), f"{name}: other time steps")
    expect(names(ds, "name_nod_var") == nodal and names(ds, "name_elem_var") == element,
           f"{name}: other variable names")
    ga, gb = np.asarray(ds.variables["vals_glo_var"][:]), np.asarray(single.variables["vals_glo_var"][:])
    expect(ga.shape == gb.shape and all(same(ga[:, k], gb[:, k], global_scale) for k in range(ga.shape[1])),
           f"{name}: other global values")
    node_ids = np.asarray(ds.variables["node_num_map"][:], dtype=np.int64) - 1
    elem_ids = np.asarray(ds.variables["elem_num_map"][:], dtype=np.int64) - 1
    seen_nodes[node_ids] += 1
    seen_elems[elem_ids] += 1
    for local, g in enumerate(node_ids):
        holders.setdefault(int(g), []).append((r, local + 1))
    for v in range(1, len(nodal) + 1):
        a = np.asarray(ds.variables[f"vals_nod_var{v}"][:], dtype=float)
        b = np.asarray(single.variables[f"vals_nod_var{v}"][:], dtype=float)[:, node_ids]
        expect(same(a, b, nodal_scale[nodal[v - 1].rsplit("_", 1)[0]]), f"{name}: nodal variable {nodal[v - 1]} differs from the single file "
                                     f"(max {np.max(np.abs(a - b)) if a.shape == b.shape else 'shape'})")
    # Element values: the pieces number their elements block by block, as the single file does.
    for v in range(1, len(element) + 1):
        mine = np.concatenate([np.asarray(ds.variables[n][:], dtype=float) for n in sorted(
            (n for n in ds.variables if n.startswith(f"vals_elem_var{v}eb")), key=lambda n: int(n.split("eb")[1]))]
            , axis=1)
        whole = np.concatenate([np.asarray(single.variables[n][:], dtype=float) for n in sorted(
            (n for n in single.variables if n.startswith(f"vals_elem_var{v}eb")), key=lambda n: int(n.split("eb")[1]))]
            , axis=1)
        mesh_elems = mine.shape[1]
        expect(same(mine, whole[:, elem_ids[:mesh_elems]], element_scale),
               f"{name}: element variable {element[v - 1]} differs from the single file")
    # Nemesis: global sizes, and the border nodes as the communication maps list them.
    expect(len(ds.dimensions["num_nodes_global"]) == num_nodes and len(ds.dimensions["num_elems_global"]) == num_elems,
           f"{name}: global sizes {len(ds.dimensions['num_nodes_global'])}, {len(ds.dimensions['num_elems_global'])}")
    expect("nem_ftype" in ds.variables and int(ds.variables["nem_ftype"][...]) == 0, f"{name}: not marked a parallel (per-processor) file")

expect(np.all(seen_elems == 1), f"elements held by no piece or by two: {np.flatnonzero(seen_elems != 1)[:10]}")
expect(np.all(seen_nodes >= 1), f"nodes held by no piece: {np.flatnonzero(seen_nodes < 1)[:10]}")
# Every node held by several pieces is in each of their communication maps, pointing at the others.
for r, ds in enumerate(pieces):
    listed = set()
    if "n_comm_nids" in ds.variables:
        nodes = np.asarray(ds.variables["n_comm_nids"][:], dtype=np.int64)
        procs = np.asarray(ds.variables["n_comm_proc"][:], dtype=np.int64)
        listed = {(int(n), int(p)) for n, p in zip(nodes, procs)}
    wanted = set()
    node_ids = np.asarray(ds.variables["node_num_map"][:], dtype=np.int64) - 1
    for local, g in enumerate(node_ids):
        for other, _ in holders[int(g)]:
            if other != r:
                wanted.add((local + 1, other))
    expect(listed == wanted, f"{sys.argv[2 + r]}: communication maps list {len(listed)} (node, rank) pairs, "
                             f"expected {len(wanted)}")
shared = int(np.sum(seen_nodes > 1))
if problems:
    print("\n".join(problems))
    sys.exit(1)
print(f"{ranks} piece(s) = the single file: {len(steps)} steps, {num_nodes} nodes ({shared} on borders), "
      f"{num_elems} elements, {len(nodal)} nodal and {len(element)} element variables")
