"""xvfb-run -a pvbatch paraview_pieces.py SINGLE.exo PIECE_0

ParaView 5.11 opens a per-rank Exodus set (name.exo.N.r) from its first file, with both of its Exodus
readers, as the single file of the same run: the same time steps, blocks and cells; the points of the
border between pieces appear once per piece (so the point count is the single file's plus the shared
ones, from the file's own Nemesis count); the displacement ranges the same to 1e-9. Exit 0 when so (77:
ParaView's Python modules are missing)."""
import sys

import netCDF4

try:
    import paraview.simple as pvs
except ImportError as e:
    print(f"skipped: {e}")
    sys.exit(77)

single, first = sys.argv[1], sys.argv[2]
with netCDF4.Dataset(first) as ds:
    processors = len(ds.dimensions["num_processors"]) if "num_processors" in ds.dimensions else 1
border = 0
for r in range(processors):
    suffix = str(r).zfill(len(str(processors)))
    with netCDF4.Dataset(first[: first.rfind(".") + 1] + suffix) as ds:
        border += len(ds.dimensions["num_bor_node"]) if "num_bor_node" in ds.dimensions else 0
problems = []
for kind, displ in (("ExodusIIReader", "displ_"), ("IOSSReader", "displ")):
    whole = getattr(pvs, kind)(FileName=[single])
    pieces = getattr(pvs, kind)(FileName=[first])
    times = list(whole.TimestepValues)
    if list(pieces.TimestepValues) != times:
        problems.append(f"{kind}: time steps {list(pieces.TimestepValues)}, expected {times}")
    if list(pieces.ElementBlocks) != list(whole.ElementBlocks):
        problems.append(f"{kind}: blocks {list(pieces.ElementBlocks)}, expected {list(whole.ElementBlocks)}")
    whole.UpdatePipeline(times[-1])
    pieces.UpdatePipeline(times[-1])
    a, b = pieces.GetDataInformation(), whole.GetDataInformation()
    # A border node is counted once in each piece that holds it: the extra copies are the border
    # nodes counted over all pieces minus one copy of each (2 pieces: half of them).
    if a.GetNumberOfCells() != b.GetNumberOfCells():
        problems.append(f"{kind}: {a.GetNumberOfCells()} cells, the single file {b.GetNumberOfCells()}")
    if processors == 2 and a.GetNumberOfPoints() != b.GetNumberOfPoints() + border // 2:
        problems.append(f"{kind}: {a.GetNumberOfPoints()} points, expected {b.GetNumberOfPoints()} + {border // 2}")
    for c in range(pieces.PointData[displ].GetNumberOfComponents()):
        ra, rb = pieces.PointData[displ].GetRange(c), whole.PointData[displ].GetRange(c)
        # Two runs on 2 ranks differ in round-off (sums in arrival order).
        if any(abs(x - y) > 1e-9 * max(abs(rb[0]), abs(rb[1]), 1e-300) for x, y in zip(ra, rb)):
            problems.append(f"{kind}: {displ} component {c} range {ra}, the single file {rb}")
    print(f"{kind}: {a.GetNumberOfPoints()} points, {a.GetNumberOfCells()} cells, {len(times)} steps")
if problems:
    print("\n".join(problems))
    sys.exit(1)
