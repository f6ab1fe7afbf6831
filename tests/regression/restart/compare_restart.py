#!/usr/bin/python3
"""compare_restart.py FULL_DIR RESTARTED_DIR NAME [--rtol R] [--pieces N]

A restarted run against the uninterrupted one (docs/user-guide.md, "Checkpoint and restart"): the history
CSV row by row (every column but wall_s; the CSV prints 12 significant digits), and the Exodus files at
full precision: the same time steps, every global variable (the history's columns: load factor, step size,
beta, contact counts, reactions, contact forces) and every nodal and element variable at every step.
Prints the largest relative difference |a - b| / max(|a|, |b|) (0 for exact agreement) and exits 1 when it
exceeds the tolerance (default 1e-12) or the files differ in shape. With --pieces N, the Exodus output is the
per-rank set NAME.exo.N.r of both runs (the same rank count, so the same parts), compared piece by piece."""
import argparse
import csv
import sys

import netCDF4
import numpy as np

parser = argparse.ArgumentParser()
parser.add_argument("full")
parser.add_argument("restarted")
parser.add_argument("name")
parser.add_argument("--rtol", type=float, default=1e-12)
parser.add_argument("--atol", type=float, default=0.0,
                    help="absolute tolerance besides the relative one: |a - b| <= atol + rtol max(|a|, |b|) (for runs "
                         "that are not reproducible bit for bit, e.g. on several ranks)")
parser.add_argument("--pieces", type=int, default=0, help="per-rank Exodus output of N ranks (NAME.exo.N.r)")
parser.add_argument("--residual-rtol", type=float, default=None,
                    help="tolerance of residual_norm (the Newton residual at convergence, round-off noise of the "
                         "penalty; on several ranks MUMPS' parallel factorisation makes it vary from run to run)")
args = parser.parse_args()


def fail(message):
    sys.exit(f"FAIL: {message}")


def relative(a, b):
    """The largest |a - b| / max(|a|, |b|) over the entries beyond atol (0 where within atol)."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    scale = np.maximum(np.abs(a), np.abs(b))
    diff = np.abs(a - b)
    diff = np.where(diff <= args.atol, 0.0, diff)
    with np.errstate(invalid="ignore", divide="ignore"):
        r = np.where(scale > 0, diff / np.where(scale > 0, scale, 1), 0.0)
    both_nan = np.isnan(a) & np.isnan(b)
    r = np.where(both_nan, 0.0, r)
    return float(np.nanmax(r)) if r.size else 0.0


worst = {"history": 0.0, "exodus": 0.0}
rows_a = list(csv.DictReader(open(f"{args.full}/{args.name}.history.csv")))
rows_b = list(csv.DictReader(open(f"{args.restarted}/{args.name}.history.csv")))
if len(rows_a) != len(rows_b):
    fail(f"{len(rows_a)} history rows uninterrupted, {len(rows_b)} restarted")
if list(rows_a[0]) != list(rows_b[0]):
    fail("different history columns")
for i, (ra, rb) in enumerate(zip(rows_a, rows_b)):
    for c in ra:
        if c == "wall_s":
            continue
        r = relative(float(ra[c]), float(rb[c]))
        if c == "residual_norm" and args.residual_rtol is not None:
            worst["residual"] = max(worst.get("residual", 0.0), r)
            if r <= args.residual_rtol:
                continue
        worst["history"] = max(worst["history"], r)
        if r > args.rtol:
            fail(f"history row {i} column {c}: {ra[c]} uninterrupted, {rb[c]} restarted")

def compare_exodus(path_a, path_b):
    a = netCDF4.Dataset(path_a)
    b = netCDF4.Dataset(path_b)
    for ds in (a, b):
        ds.set_auto_mask(False)
    ta, tb = a.variables["time_whole"][:], b.variables["time_whole"][:]
    if len(ta) != len(tb):
        fail(f"{path_b}: {len(ta)} Exodus steps uninterrupted, {len(tb)} restarted")
    worst["exodus"] = max(worst["exodus"], relative(ta, tb))
    names = sorted(v for v in a.variables if v.startswith("vals_"))
    globals_a = [n.tobytes().decode().strip("\x00 ") for n in a.variables["name_glo_var"][:]] if "name_glo_var" in a.variables else []
    if names != sorted(v for v in b.variables if v.startswith("vals_")):
        fail(f"{path_b}: different Exodus variables")
    for v in names:
        va, vb = a.variables[v][:], b.variables[v][:]
        if v == "vals_glo_var" and args.residual_rtol is not None and "residual_norm" in globals_a:
            keep = [i for i, n in enumerate(globals_a) if n != "residual_norm"]
            va, vb = va[:, keep], vb[:, keep]
        r = relative(va, vb)
        worst["exodus"] = max(worst["exodus"], r)
        if r > args.rtol:
            fail(f"{path_b}: Exodus {v}: relative difference {r:.3e}")
    return len(ta)


files = [f"{args.name}.exo"] if args.pieces == 0 else [f"{args.name}.exo.{args.pieces}.{r}" for r in range(args.pieces)]
for f in files:
    steps = compare_exodus(f"{args.full}/{f}", f"{args.restarted}/{f}")
residual = f", residual_norm {worst['residual']:.3e}" if "residual" in worst else ""
print(f"max relative difference: history {worst['history']:.3e}, Exodus {worst['exodus']:.3e}{residual} "
      f"({len(rows_a)} rows, {steps} steps, {len(files)} Exodus file(s))")
if max(worst["history"], worst["exodus"]) > args.rtol:
    fail("above the tolerance")
