"""xvfb-run -a pvbatch paraview_quadratic.py DIR [RESULTS.exo ...]

What ParaView 5.11 makes of quadratic cells in Exodus files Contessa's ExodusWriter wrote (DIR/tet10.exo,
DIR/hex20.exo, DIR/hex20_wedge15.exo, from tests/unit/mesh/WriteFamilyExodus.cpp): with each of its two
Exodus readers, every cell is the VTK quadratic cell of its Exodus type (TETRA10: VTK_QUADRATIC_TETRA,
HEX20: VTK_QUADRATIC_HEXAHEDRON, WEDGE15: VTK_QUADRATIC_WEDGE), as many as the file's blocks hold
(netCDF4), with all its nodes: the points are the file's nodes, and the nodal field x*y*z agrees with the
coordinates at every point (a reader that linearised the cells would drop the mid-edge points). Exit
status 0 when so; the differences are printed otherwise (77: ParaView's Python modules are missing).
RESULTS.exo: a solver's results files (the Tet10 and Hex20 runs of uniaxial_tension_3d.xml), checked the
same way but for the field (their cell types and counts, and their points)."""
import sys

import netCDF4
import numpy as np

try:
    import paraview.simple as pvs
    from paraview import servermanager
    from vtkmodules.numpy_interface import dataset_adapter as dsa
except ImportError as e:
    print(f"skipped: {e}")
    sys.exit(77)

VTK_TYPE = {"TETRA10": (24, 10), "HEX20": (25, 20), "WEDGE15": (26, 15)}
directory = sys.argv[1]
problems = []


def expect(condition, message):
    if not condition:
        problems.append(message)


def file_blocks(path):
    """(topology, element count, nodes per element) of each block, and the node count, as stored."""
    with netCDF4.Dataset(path) as ds:
        blocks = []
        for b in range(1, ds.dimensions["num_el_blk"].size + 1):
            conn = ds.variables[f"connect{b}"]
            blocks.append((conn.getncattr("elem_type"), conn.shape[0], conn.shape[1]))
        return blocks, ds.dimensions["num_nodes"].size


files = [(f"{directory}/{stem}.exo", stem, True) for stem in ["tet10", "hex20", "hex20_wedge15"]]
files += [(path, path, False) for path in sys.argv[2:]]
for path, stem, has_field in files:
    blocks, num_nodes = file_blocks(path)
    expected = {}
    for topology, count, nodes in blocks:
        expect(topology in VTK_TYPE and VTK_TYPE[topology][1] == nodes,
               f"{stem}: block of type {topology} with {nodes} nodes per element")
        vtk_type = VTK_TYPE.get(topology, (None, None))[0]
        expected[vtk_type] = expected.get(vtk_type, 0) + count
    for kind in ["ExodusIIReader", "IOSSReader"]:
        reader = getattr(pvs, kind)(FileName=[path])
        if kind == "ExodusIIReader" and has_field:
            reader.PointVariables = ["xyz"]
        merged = pvs.MergeBlocks(Input=reader)
        merged.UpdatePipeline(0.0)
        data = dsa.WrapDataObject(servermanager.Fetch(merged))
        types, counts = np.unique(np.asarray(data.CellTypes), return_counts=True)
        got = dict(zip(types.tolist(), counts.tolist()))
        expect(got == expected, f"{stem}, {kind}: cell types {got}, the file holds {expected}")
        points = np.asarray(data.Points)
        expect(points.shape[0] == num_nodes, f"{stem}, {kind}: {points.shape[0]} points, the file has {num_nodes} nodes")
        if not has_field:
            print(f"{stem}, {kind}: {got} cells, {points.shape[0]} points")
            continue
        field = np.asarray(data.PointData["xyz"])
        deviation = np.max(np.abs(field - points[:, 0] * points[:, 1] * points[:, 2]))
        # ExodusIIReader hands out single-precision points (1e-7 measured); a value put on the wrong point
        # is off by the field's variation between nodes, 0.01 or more on these meshes.
        expect(deviation < 1e-5, f"{stem}, {kind}: x*y*z differs from the field by {deviation}")
        print(f"{stem}, {kind}: {got} cells, {points.shape[0]} points")

for p in problems:
    print("FAIL:", p)
sys.exit(1 if problems else 0)
