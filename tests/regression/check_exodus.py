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


def present_and_finite(kind, wanted, name_var, values_var=None):
    """The file's `kind` variable names (from `name_var`), with a problem for each of `wanted` that is
    missing or, where `values_var(k)` names the k-th one's values (1-based), has a non-finite value."""
    have = names(ds, name_var) if wanted else []
    for n in wanted:
        if n not in have:
            problems.append(f"{kind} variable {n} missing (have {have})")
        elif values_var and not np.all(np.isfinite(ds.variables[values_var(have.index(n) + 1)][:])):
            problems.append(f"{kind} variable {n} has non-finite values")
    return have


nodal = present_and_finite("nodal", args.nodal, "name_nod_var", lambda k: f"vals_nod_var{k}")
element = present_and_finite("element", args.element, "name_elem_var", lambda k: f"vals_elem_var{k}eb1")
globals_ = present_and_finite("global", args.globals, "name_glo_var")
for p in problems:
    print("FAIL:", p)
print(f"{args.file}: {len(times)} steps, nodal {nodal}, element {element}, global {globals_}")
sys.exit(1 if problems else 0)
