"""xvfb-run -a pvbatch paraview_check.py EXO HISTORY

What ParaView 5.11 shows of the tube's results file, with each of its two Exodus readers, as
docs/user-guide.md ("Viewing results in ParaView") states it: the time steps (one per history row,
the load factor as time), the names under which each reader lists the variables, the blocks (the
tube and the rigid plate), and values that must agree with the history CSV and the file itself:
the plate's position at the last step (the readers apply displ_x/displ_y to the coordinates), the
plate force, and the range of the vertical displacement. Exit status 0 when everything is as
documented; the differences are printed otherwise (77: ParaView's Python modules are missing)."""
import csv
import sys

import netCDF4
import numpy as np

try:
    import paraview.simple as pvs
except ImportError as e:  # pvbatch without its Python modules (Debian: python3-paraview)
    print(f"skipped: {e}")
    sys.exit(77)

exo, history = sys.argv[1], sys.argv[2]
with open(history, newline="") as f:
    rows = list(csv.DictReader(f))
with netCDF4.Dataset(exo) as ds:
    displ_y_last = np.asarray(ds.variables["vals_nod_var2"][-1])  # displ_y (the second nodal variable)
problems = []


def expect(condition, message):
    if not condition:
        problems.append(message)


def close(a, b, tol=1e-9):
    return abs(a - b) <= tol * max(1.0, abs(b))


# What each reader lists, by the user guide: (point arrays, cell arrays, field arrays).
LISTED = {
    "ExodusIIReader": ({"displ_": 3, "contact_pressure": 1, "contact_gap": 1, "contact_status": 1, "contact_slip": 1},
                       {"stress_xx": 1, "stress_yy": 1, "stress_zz": 1, "stress_xy": 1, "von_mises": 1},
                       {"load_factor": 1, "step_size": 1, "beta": 1, "active_contacts": 1, "newton_iterations": 1,
                        "reaction_start_": 2, "reaction_end_": 2, "contact_force_plate_": 2, "QA_Records": None,
                        "Info_Records": None}),
    "IOSSReader": ({"displ": 2, "contact_pressure": 1, "contact_gap": 1, "contact_status": 1, "contact_slip": 1},
                   {"stress": 4, "von_mises": 1},
                   {"load_factor": 1, "step_size": 1, "beta": 1, "active_contacts": 1, "newton_iterations": 1,
                    "reaction_start": 2, "reaction_end": 2, "contact_force_plate": 2, "QA Records": 4,
                    "Information Records": 1}),
}
plate_y, motion_y = 120.0, -75.2  # inputs/tube_bending.xml: Rigid Surface Points and Motion
force = [float(r["contact_force_plate_y"]) for r in rows]

for kind, (point, cell, field) in LISTED.items():
    reader = getattr(pvs, kind)(FileName=[exo])
    blocks = list(reader.ElementBlocks)
    expect(blocks == ["tube", "plate"], f"{kind}: element blocks {blocks}, expected ['tube', 'plate']")
    times = list(reader.TimestepValues)
    expect(len(times) == len(rows), f"{kind}: {len(times)} time steps, the history has {len(rows)} rows")
    expect(all(close(t, float(r["lambda"]), 1e-11) for t, r in zip(times, rows)),
           f"{kind}: the time steps are not the history's load factors")

    reader.UpdatePipeline(times[0])
    top0 = reader.GetDataInformation().GetBounds()[3]
    reader.UpdatePipeline(times[-1])
    info = reader.GetDataInformation()
    top = info.GetBounds()[3]
    expect(close(top0, plate_y) and close(top, plate_y + motion_y * times[-1], 1e-7),
           f"{kind}: the plate's top is at y = {top0} then {top}, expected {plate_y} then {plate_y + motion_y}")
    for data, listed, where in ((reader.PointData, point, "point"), (reader.CellData, cell, "cell"),
                                (reader.FieldData, field, "field")):
        for name, components in listed.items():
            if name not in data.keys():
                problems.append(f"{kind}: no {where} array '{name}' (has {list(data.keys())})")
            elif components is not None and data[name].GetNumberOfComponents() != components:
                problems.append(f"{kind}: {where} array '{name}' has {data[name].GetNumberOfComponents()} "
                                f"components, expected {components}")
    displ = reader.PointData["displ_" if kind == "ExodusIIReader" else "displ"]
    low, high = displ.GetRange(1)
    expect(close(low, displ_y_last.min()) and close(high, displ_y_last.max()),
           f"{kind}: displ Y ranges over [{low}, {high}] at the last step, the file has "
           f"[{displ_y_last.min()}, {displ_y_last.max()}]")
    plate = reader.FieldData["contact_force_plate_" if kind == "ExodusIIReader" else "contact_force_plate"].GetRange(1)
    # The legacy reader gives a global variable's whole history, IOSS its value at the current time.
    expected = (min(force), max(force)) if kind == "ExodusIIReader" else (force[-1], force[-1])
    expect(close(plate[0], expected[0]) and close(plate[1], expected[1]),
           f"{kind}: contact_force_plate Y ranges over {plate}, the history gives {expected}")
    print(f"{kind}: {len(times)} steps, blocks {blocks}, plate top {top0:g} -> {top:g}, displ Y [{low:.6g}, {high:.6g}], "
          f"plate force {plate[0]:.7g}; point {sorted(reader.PointData.keys())}; cell {sorted(reader.CellData.keys())}")
    pvs.Delete(reader)

for p in problems:
    print("FAIL:", p)
sys.exit(1 if problems else 0)
