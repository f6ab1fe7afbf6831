#!/usr/bin/python3
"""check_exodus.py FILE --steps N --nodal NAMES --element NAMES --global NAMES

Checks that an Exodus II results file is what ParaView needs: netCDF-4 readable, the expected number
of time steps with increasing times, and the named nodal/element/global variables with finite values."""
import argparse
import sys

import netCDF4
import numpy as np

parser = argparse.ArgumentParser()
parser.add_argument("file")
parser.add_argument("--steps", type=int, required=True)
parser.add_argument("--nodal", nargs="*", default=[])
parser.add_argument("--element", nargs="*", default=[])
parser.add_argument("--global", dest="globals", nargs="*", default=[])
args = parser.parse_args()


def names(ds, var):
    return ["".join(c.decode() for c in row if c not in (b"", b"\x00")).strip() for row in ds.variables[var][:].data]


ds = netCDF4.Dataset(args.file)
problems = []
if ds.data_model != "NETCDF4_CLASSIC" and ds.data_model != "NETCDF4":
    problems.append(f"data model {ds.data_model}, expected netCDF-4")
times = ds.variables["time_whole"][:]
if len(times) != args.steps:
    problems.append(f"{len(times)} time steps, expected {args.steps}")
if np.any(np.diff(times) <= 0):
    problems.append("times are not increasing")
nodal = names(ds, "name_nod_var") if args.nodal else []
for n in args.nodal:
    if n not in nodal:
        problems.append(f"nodal variable {n} missing (have {nodal})")
    elif not np.all(np.isfinite(ds.variables[f"vals_nod_var{nodal.index(n) + 1}"][:])):
        problems.append(f"nodal variable {n} has non-finite values")
element = names(ds, "name_elem_var") if args.element else []
for n in args.element:
    if n not in element:
        problems.append(f"element variable {n} missing (have {element})")
    elif not np.all(np.isfinite(ds.variables[f"vals_elem_var{element.index(n) + 1}eb1"][:])):
        problems.append(f"element variable {n} has non-finite values")
globals_ = names(ds, "name_glo_var") if args.globals else []
for n in args.globals:
    if n not in globals_:
        problems.append(f"global variable {n} missing (have {globals_})")
for p in problems:
    print("FAIL:", p)
print(f"{args.file}: {len(times)} steps, nodal {nodal}, element {element}, global {globals_}")
sys.exit(1 if problems else 0)
