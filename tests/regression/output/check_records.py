#!/usr/bin/python3
"""check_records.py EXO HISTORY DECK --version TEXT [--set PATH=VALUE ...]

What the tube's results file holds besides the fields (docs/user-guide.md, "Output files"), read
back with netCDF4 only:
- every reaction and contact force column of the history is an Exodus global variable of the same
  name with the same values at every step (the history prints 12 significant digits), and the
  load_factor global is the step time;
- each rigid contact surface is a block of its own (named after its interface): BAR2 in 2D, SHELL4 in 3D,
  whose points are the deck's Rigid Surface/Points, whose elements are its Facets (in 2D without Facets,
  the chain of consecutive points) and whose displacement at every step is lambda * Motion;
- a QA record ("contessa", the version `contessa --version` prints, the date, the time);
- information records with the command line and the deck as run: every parameter of DECK is there
  with the same value, except those given with --set, which have the overriding value."""
import argparse
import re
import sys
import xml.etree.ElementTree as ET

import netCDF4
import numpy as np

from output_files import history_rows

parser = argparse.ArgumentParser()
parser.add_argument("exo")
parser.add_argument("history")
parser.add_argument("deck")
parser.add_argument("--version", required=True, help="the output of contessa --version")
parser.add_argument("--set", dest="sets", action="append", default=[])
args = parser.parse_args()
problems = []


def text(row):
    return "".join(c.decode() for c in row if c not in (b"", b"\x00"))


def names(ds, var):
    return [text(row) for row in ds.variables[var][:].data] if var in ds.variables else []


def parameters(root):
    """{path: value} of every Parameter under an XML ParameterList element."""
    found = {}

    def walk(element, path):
        for child in element:
            if child.tag == "ParameterList":
                walk(child, path + [child.get("name")])
            elif child.tag == "Parameter":
                found["/".join(path + [child.get("name")])] = child.get("value")

    walk(root, [])
    return found


def same_value(a, b):
    """Deck values compare as numbers (or lists of numbers) when they are numbers: 100.0 is 100."""
    numbers = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
    if re.fullmatch(r"\s*\{?\s*" + numbers + r"(\s*,\s*" + numbers + r")*\s*\}?\s*", a or ""):
        x, y = [float(v) for v in re.findall(numbers, a)], [float(v) for v in re.findall(numbers, b or "")]
        return x == y
    return a == b


deck = ET.parse(args.deck).getroot()
deck_values = parameters(deck)
rows = history_rows(args.history)
with netCDF4.Dataset(args.exo) as ds:
    times = np.asarray(ds.variables["time_whole"][:])
    if len(times) != len(rows):
        problems.append(f"{len(times)} steps in the Exodus file, {len(rows)} history rows")
    steps = min(len(times), len(rows))

    # Globals: the history's reactions and contact forces under the same names, and the load factor.
    globals_ = names(ds, "name_glo_var")
    values = np.asarray(ds.variables["vals_glo_var"][:]) if globals_ else np.zeros((0, 0))
    force_columns = [c for c in rows[0] if c.startswith(("reaction_", "contact_force_"))]
    if not force_columns:
        problems.append(f"{args.history} has no reaction or contact force column")
    for column in force_columns + ["load_factor"]:
        if column not in globals_:
            problems.append(f"global variable {column} missing (have {globals_})")
            continue
        expected = np.array([float(r["lambda" if column == "load_factor" else column]) for r in rows[:steps]])
        got = values[:steps, globals_.index(column)]
        if not np.allclose(got, expected, rtol=1e-11, atol=1e-9 * max(1.0, np.max(np.abs(expected)))):
            problems.append(f"global {column} differs from the history (largest difference "
                            f"{np.max(np.abs(got - expected)):.3g})")
    if "load_factor" in globals_ and not np.array_equal(values[:, globals_.index("load_factor")], times):
        problems.append("the load_factor global is not the step time")

    # Rigid surfaces: a BAR2 (2D) or SHELL4 (3D) block each on the deck's points and facets, moving with lambda.
    dim = len(ds.dimensions["num_dim"])
    axes = "xyz"[:dim]
    blocks = names(ds, "eb_names")
    surfaces = {}
    contact = deck.find("./ParameterList[@name='Problem']/ParameterList[@name='Contact']")
    for interface in (contact if contact is not None else []):
        surface = interface.find("./ParameterList[@name='Rigid Surface']")
        if surface is None:
            continue
        get = {p.get("name"): [float(v) for v in p.get("value").strip("{} ").split(",") if v.strip()] for p in surface}
        points = np.reshape(get["Points"], (-1, dim))
        facets = get.get("Facets") or [i + a for i in range(len(points) - 1) for a in (0, 1)]  # 2D: the chain
        surfaces[interface.get("name")] = (points, np.reshape(np.array(facets, dtype=int), (-1, 2 if dim == 2 else 4)),
                                           np.array(get["Motion"]))
    if not surfaces:
        problems.append(f"{args.deck} has no rigid surface")
    displ = names(ds, "name_nod_var")
    # The surfaces' points follow the mesh nodes, surface after surface in the deck's order.
    first = len(ds.dimensions["num_nodes"]) - sum(len(points) for points, _, _ in surfaces.values())
    for name, (points, facets, motion) in surfaces.items():
        nodes = np.arange(first, first + len(points))
        first += len(points)
        if name not in blocks:
            problems.append(f"no block '{name}' for the rigid surface (blocks: {blocks})")
            continue
        b = blocks.index(name) + 1
        kind = ds.variables[f"connect{b}"].getncattr("elem_type")
        expected_kind = "BAR2" if dim == 2 else "SHELL4"
        if kind != expected_kind:
            problems.append(f"block '{name}' has elements of type {kind}, expected {expected_kind}")
        connect = np.asarray(ds.variables[f"connect{b}"][:]) - 1
        if connect.shape != facets.shape or np.any(connect - nodes[0] != facets):
            problems.append(f"block '{name}' has elements {(connect - nodes[0]).tolist()}, the deck's facets are "
                            f"{facets.tolist()}")
        coords = np.stack([np.asarray(ds.variables["coord" + a][:])[nodes] for a in axes], axis=1)
        if not np.allclose(coords, points, rtol=0, atol=1e-12):
            problems.append(f"block '{name}' lies at {coords.tolist()}, the deck's points are {points.tolist()}")
        for c, axis in enumerate(axes):
            u = np.asarray(ds.variables[f"vals_nod_var{displ.index('displ_' + axis) + 1}"][:steps][:, nodes])
            expected = np.outer(times[:steps], np.full(len(nodes), motion[c]))
            if not np.allclose(u, expected, rtol=1e-14, atol=1e-12):
                problems.append(f"block '{name}': displ_{axis} is not lambda * Motion")
        print(f"rigid block '{name}': {kind}, {len(points)} points, {len(connect)} elements, displacement at the "
              f"last step {[float(np.asarray(ds.variables['vals_nod_var' + str(displ.index('displ_' + a) + 1)][steps - 1])[nodes[0]]) for a in axes]}")

    # QA record and information records.
    qa = [[text(field) for field in record] for record in ds.variables["qa_records"][:].data]
    version = args.version.split()[1]  # "contessa 0.1.0 (abc1234)"
    if len(qa) != 1 or qa[0][0] != "contessa" or not qa[0][1].startswith(version) or \
            not re.fullmatch(r"\d{4}/\d\d/\d\d", qa[0][2]) or not re.fullmatch(r"\d\d:\d\d:\d\d", qa[0][3]):
        problems.append(f"QA records {qa}: expected one (contessa, {version}..., YYYY/MM/DD, HH:MM:SS)")
    lines, pending = [], ""
    for record in names(ds, "info_records"):  # records of 80 characters; a trailing \ continues a line
        if record.endswith("\\") and len(record) == 80:
            pending += record[:-1]
        else:
            lines.append(pending + record)
            pending = ""
    if not any(line.startswith("command: contessa ") for line in lines):
        problems.append("no information record with the command line")
    marker = "deck as run (after --set overrides):"
    if marker not in lines:
        problems.append(f"no information record '{marker}'")
    else:
        recorded = parameters(ET.fromstring("\n".join(lines[lines.index(marker) + 1:])))
        expected = dict(deck_values)
        for s in args.sets:
            path, value = s.split("=", 1)
            expected[path] = value
        for path, value in expected.items():
            if path not in recorded:
                problems.append(f"the recorded deck has no {path}")
            elif not same_value(value, recorded[path]):
                problems.append(f"the recorded deck has {path} = {recorded[path]}, expected {value}")
        print(f"recorded deck: {len(recorded)} parameters; QA {qa[0] if qa else None}")
    print(f"globals: {globals_}")

for p in problems:
    print("FAIL:", p)
sys.exit(1 if problems else 0)
