"""Checks shared by the output tests: what a results directory holds after a run, however it ended.

The contract (docs/user-guide.md, "Output files"): the history CSV has one row per completed
increment, and every one of them is in the Exodus file, readable, with the same load factor; the
Exodus file may hold one more step, the increment whose history row was not written yet when the
run died. Only numpy and netCDF4 (Debian's /usr/bin/python3)."""
import csv
import os
import subprocess

import netCDF4
import numpy as np


def history_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def rows_written(path):
    """Data rows in a history that may be being written (0 before the header is there)."""
    try:
        with open(path) as f:
            return max(0, sum(1 for line in f if line.endswith("\n")) - 1)
    except FileNotFoundError:
        return 0


def check_results(exo, history, allow_in_flight=False):
    """Problems found (an empty list when the files agree). With allow_in_flight, the Exodus file may
    hold one step more than the history (killed between the two writes); that step is reported, not
    failed, if it cannot be read (HDF5 updates are not atomic; see the user guide)."""
    problems, notes = [], []
    rows = history_rows(history)
    try:
        ds = netCDF4.Dataset(exo)
    except OSError as e:
        return [f"{exo}: netCDF4 cannot open it: {e}"], notes
    with ds:
        times = np.asarray(ds.variables["time_whole"][:], dtype=float) if "time_whole" in ds.variables else []
        n, r = len(times), len(rows)
        if n != r and not (allow_in_flight and n == r + 1):
            problems.append(f"{exo}: {n} steps, but {history} has {r} rows")
        complete = min(n, r)
        lam = np.array([float(row["lambda"]) for row in rows[:complete]])
        # The history prints 12 significant digits.
        if complete and not np.allclose(times[:complete], lam, rtol=1e-11, atol=1e-14):
            problems.append(f"{exo}: step times differ from the history's lambda column")
        for name, var in ds.variables.items():
            if not name.startswith("vals_"):
                continue
            try:
                values = np.ma.filled(var[:complete], np.nan)
            except RuntimeError as e:
                problems.append(f"{exo}: {name} cannot be read in steps 0..{complete - 1}: {e}")
                continue
            if not np.all(np.isfinite(values)):
                problems.append(f"{exo}: {name} has non-finite or missing values in steps 0..{complete - 1}")
        if n == r + 1:
            try:
                for name, var in ds.variables.items():
                    if name.startswith("vals_"):
                        var[n - 1]
                notes.append(f"the in-flight step {n - 1} is readable")
            except RuntimeError:
                notes.append(f"the in-flight step {n - 1} cannot be read")
    return problems, notes


def contessa_lines(stderr):
    """Contessa's own lines of a (possibly mpiexec) stderr."""
    return [line for line in stderr.splitlines() if line.startswith("contessa")]


def small_steps(increments):
    """--set options that make the uniaxial tension deck run `increments` equal increments: an
    output-bound run (about 100 increments per second) for the tests that act while it writes."""
    step = 1.0 / increments
    return ["--set", f"Piro/LOCA/Step Size/Initial Step Size={step}", "--set", f"Piro/LOCA/Step Size/Max Step Size={step}",
            "--set", f"Piro/LOCA/Stepper/Max Steps={increments + 10}"]


def fresh_directory(path):
    subprocess.run(["rm", "-rf", path], check=True)
    os.makedirs(path)
