#!/usr/bin/python3
"""Runs contessa and checks its phase-timer table (contessa --timers).

    check_timers.py on  RANKS HISTORY -- COMMAND...   the table is printed once, names every phase, its
                                                      phases add up to its total, and its counts agree
                                                      with the run (solves, increments, history rows)
    check_timers.py off HISTORY -- COMMAND...         no table without --timers

The table's figures are wall seconds, so only their consistency is checked, never their size.
"""
import csv
import re
import subprocess
import sys

# Every phase of packages/common/PhaseTimers.hpp, as the table names it.
PHASES = [
    "process start, MPI_Init, Kokkos",
    "set-up: deck, mesh, partition, graph",
    "element kernels, residual passes",
    "element kernels, Jacobian passes",
    "assembly: scatter, Dirichlet, Export",
    "contact: search, elements, scatter",
    "matrix graph rebuilds (contact)",
    "MUMPS input (pattern, values)",
    "MUMPS analysis (JOB=1)",
    "MUMPS factorisation (JOB=2)",
    "MUMPS solve (JOB=3, rhs to/from host)",
    "iterative: preconditioner set-up",
    "iterative: Krylov iterations",
    "output: Exodus, CSV, stresses",
    "reactions for output",
    "NOX/LOCA and everything else",
]
FINAL = re.compile(r"finished after (\d+) increments \((\d+) failed attempts\), (\d+) Newton iterations, "
                   r"(\d+) linear solves")
ROW = re.compile(r"^  (.+?)\s+(\d+\.\d{4})\s+(\d+\.\d)\s+(\d+)$")
TOTAL = re.compile(r"^  total\s+(\d+\.\d{4})\s+100\.0$")

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


def main():
    mode = sys.argv[1]
    sep = sys.argv.index("--")
    args, command = sys.argv[2:sep], sys.argv[sep + 1:]
    run = subprocess.run(command, capture_output=True, text=True)
    out = run.stdout
    if run.returncode != 0:
        print(f"FAIL: exit status {run.returncode}\n{run.stderr}")
        return 1
    history = list(csv.DictReader(open(args[-1], newline="")))
    headers = out.count("contessa: phase timers")
    if mode == "off":
        check(headers == 0 and "MUMPS factorisation" not in out, "a timer table was printed without --timers")
    else:
        ranks = int(args[0])
        check(headers == 1, f"{headers} timer tables printed, expected 1")
        if failures:
            return report()
        lines = out.splitlines()
        start = next(i for i, l in enumerate(lines) if l.startswith("contessa: phase timers"))
        header = lines[start]
        check(("maximum over 2 ranks" in header) == (ranks == 2), f"header does not fit {ranks} rank(s): {header}")
        rows = {}
        for line in lines[start + 2:start + 2 + len(PHASES)]:
            m = ROW.match(line)
            check(m is not None, f"not a table row: {line!r}")
            if m:
                rows[m.group(1)] = (float(m.group(2)), float(m.group(3)), int(m.group(4)))
        check(list(rows) == PHASES, f"phases {list(rows)}, expected {PHASES}")
        m = TOTAL.match(lines[start + 2 + len(PHASES)])
        check(m is not None, f"no total row: {lines[start + 2 + len(PHASES)]!r}")
        final = FINAL.search(out)
        check(final is not None, "no final summary line")
        if failures:
            return report()
        total = float(m.group(1))
        seconds = {k: v[0] for k, v in rows.items()}
        count = {k: v[2] for k, v in rows.items()}
        # Exclusive phases cover the run once: on one rank they add up to the total (rounding of 14
        # figures to 0.1 ms); on several each figure is a maximum over the ranks, so the sum is at least it.
        if ranks == 1:
            check(abs(sum(seconds.values()) - total) <= 1e-3, f"phases add up to {sum(seconds.values()):.4f} s, total {total:.4f} s")
        else:
            check(sum(seconds.values()) >= total - 1e-3, f"phases add up to {sum(seconds.values()):.4f} s < total {total:.4f} s")
        check(all(s >= 0 for s in seconds.values()), "a negative time")
        for phase in ("process start, MPI_Init, Kokkos", "set-up: deck, mesh, partition, graph",
                      "NOX/LOCA and everything else"):
            check(count[phase] == 1, f"{phase}: count {count[phase]}, expected 1")
        solves = int(final.group(4))
        check(count["MUMPS solve (JOB=3, rhs to/from host)"] == solves,
              f"MUMPS solves {count['MUMPS solve (JOB=3, rhs to/from host)']}, the run reports {solves} linear solves")
        factorisations = count["MUMPS factorisation (JOB=2)"]
        check(1 <= factorisations <= solves, f"{factorisations} factorisations for {solves} solves")
        check(1 <= count["MUMPS analysis (JOB=1)"] <= factorisations, "MUMPS analyses not between 1 and the factorisations")
        check(count["MUMPS input (pattern, values)"] == factorisations, "one MUMPS input per factorisation expected")
        check(count["element kernels, Jacobian passes"] <= factorisations, "more Jacobian passes than factorisations")
        check(count["element kernels, Jacobian passes"] >= 1, "no Jacobian pass")
        check(count["element kernels, residual passes"] >= int(final.group(1)), "fewer residual passes than increments")
        # One output record per history row (the initial state and every converged increment).
        check(count["output: Exodus, CSV, stresses"] == len(history),
              f"{count['output: Exodus, CSV, stresses']} outputs for {len(history)} history rows")
    return report()


def report():
    if failures:
        print("FAIL:\n  " + "\n  ".join(failures))
        return 1
    print("ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
