"""xvfb-run -a pvbatch paraview_rigid_surface.py EXO --quads N --bounds=XMIN,XMAX,YMIN,YMAX,ZMIN,ZMAX

What ParaView shows of a 3D rigid contact surface (docs/user-guide.md, "Output files"): with each of its two
Exodus readers, at the last time step, the file's only quadrilateral cells (VTK_QUAD: the SHELL4 block of the
rigid surface, drawn as a surface; the mesh is hexahedra) are N and span the given bounds (the deck's points
moved by lambda * Motion). Exit 0 when both readers show it; 77 when ParaView's Python modules are missing."""
import argparse
import sys

try:
    import paraview.simple as pvs
    from paraview import servermanager
except ImportError as e:  # pvbatch without its Python modules (Debian: python3-paraview)
    print(f"skipped: {e}")
    sys.exit(77)

VTK_QUAD, VTK_HEXAHEDRON = 9, 12
parser = argparse.ArgumentParser()
parser.add_argument("exo")
parser.add_argument("--quads", type=int, required=True)
parser.add_argument("--bounds", required=True, help="XMIN,XMAX,YMIN,YMAX,ZMIN,ZMAX (with =: they may be negative)")
args = parser.parse_args()
args.bounds = [float(v) for v in args.bounds.split(",")]
if len(args.bounds) != 6:
    sys.exit("--bounds: expected 6 comma-separated values")
problems = []
for kind in ("ExodusIIReader", "IOSSReader"):
    reader = getattr(pvs, kind)(FileName=[args.exo])
    merged = pvs.MergeBlocks(Input=reader)
    merged.UpdatePipeline(list(reader.TimestepValues)[-1])
    data = servermanager.Fetch(merged)
    quads = [c for c in range(data.GetNumberOfCells()) if data.GetCellType(c) == VTK_QUAD]
    others = {data.GetCellType(c) for c in range(data.GetNumberOfCells())} - {VTK_QUAD, VTK_HEXAHEDRON}
    bounds = [float("inf"), float("-inf")] * 3
    for c in quads:
        b = data.GetCell(c).GetBounds()
        for k in range(3):
            bounds[2 * k] = min(bounds[2 * k], b[2 * k])
            bounds[2 * k + 1] = max(bounds[2 * k + 1], b[2 * k + 1])
    if len(quads) != args.quads:
        problems.append(f"{kind}: {len(quads)} quadrilateral cells, expected {args.quads}")
    if others:
        problems.append(f"{kind}: cells of VTK types {sorted(others)} besides hexahedra and quadrilaterals")
    if any(abs(a - b) > 1e-6 * max(1.0, abs(b)) for a, b in zip(bounds, args.bounds)):
        problems.append(f"{kind}: the quadrilaterals span {bounds}, expected {args.bounds}")
    print(f"{kind}: {len(quads)} quadrilateral(s) spanning {[round(v, 9) for v in bounds]} at the last step")
    pvs.Delete(merged)
    pvs.Delete(reader)
for p in problems:
    print("FAIL:", p)
sys.exit(1 if problems else 0)
