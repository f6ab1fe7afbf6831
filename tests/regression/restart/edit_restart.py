#!/usr/bin/python3
"""edit_restart.py FILE --variable GROUP/.../NAME (--index I[,J...] --value V | --add) [--stale-checksum]

Edits one value of a restart file (netCDF-4, docs/user-guide.md "Checkpoint and restart") in place, as a
tool that knows the format would: the value is changed and the checksum attribute recomputed, so the file
is intact and only its content is wrong (e.g. a NaN displacement). --add adds the variable (a double
scalar, 1.0) instead: a field this Contessa does not know. With --stale-checksum the checksum is left as
it was: a file whose bytes changed after it was written. Prints what it changed.

The checksum is FNV-1a (64 bit) over the deck attribute's bytes, the nodes and elements attributes (int64)
and mesh_hash (uint64), then for every variable, variables before groups, each in name order, its path
("nodes/displacement") and its values' bytes (little-endian doubles and int64, text as UTF-8)."""
import argparse

import netCDF4
import numpy

MASK = (1 << 64) - 1


def fnv1a(data, h):
    for b in data:
        h = ((h ^ b) * 1099511628211) & MASK
    return h


def values_bytes(var):
    var.set_auto_mask(False)
    if var.dtype == str:
        return var[...].item().encode() if var.ndim == 0 else var[...].encode()
    data = var[...] if var.ndim > 0 else numpy.array(var.getValue())
    return numpy.ascontiguousarray(data, dtype=data.dtype.newbyteorder("<")).tobytes()


def tree_checksum(group, prefix, h):
    for name in sorted(group.variables):
        h = fnv1a((prefix + name).encode(), h)
        h = fnv1a(values_bytes(group.variables[name]), h)
    for name in sorted(group.groups):
        h = tree_checksum(group.groups[name], prefix + name + "/", h)
    return h


def checksum(ds):
    h = fnv1a(ds.getncattr("deck").encode(), 14695981039346656037)
    h = fnv1a(numpy.int64(ds.getncattr("nodes")).tobytes(), h)
    h = fnv1a(numpy.int64(ds.getncattr("elements")).tobytes(), h)
    h = fnv1a(numpy.uint64(ds.getncattr("mesh_hash")).tobytes(), h)
    return tree_checksum(ds, "", h)


parser = argparse.ArgumentParser()
parser.add_argument("file")
parser.add_argument("--variable", required=True)
parser.add_argument("--index")
parser.add_argument("--value", type=float)
parser.add_argument("--add", action="store_true")
parser.add_argument("--stale-checksum", action="store_true")
args = parser.parse_args()

with netCDF4.Dataset(args.file, "r+") as ds:
    stored = int(ds.getncattr("checksum"))
    if checksum(ds) != stored:
        raise SystemExit(f"FAIL: {args.file}: the checksum does not match before the edit (this script and "
                         "the format disagree)")
    *groups, name = args.variable.split("/")
    group = ds
    for g in groups:
        group = group.groups[g]
    if args.add:
        group.createVariable(name, "f8", ())[...] = 1.0
        change = ": added"
    else:
        var = group.variables[name]
        var.set_auto_mask(False)
        index = tuple(int(i) for i in args.index.split(","))
        old = var[index]
        var[index] = args.value
        change = f"[{args.index}]: {old!r} -> {args.value!r}"
    if not args.stale_checksum:
        ds.setncattr("checksum", numpy.uint64(checksum(ds)))
    print(args.variable + change)
