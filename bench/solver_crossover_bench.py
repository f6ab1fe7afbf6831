#!/usr/bin/python3
"""Where MUMPS and Belos GMRES + MueLu cross over, in 3D (the punch) and 2D (the tube); issue 23.

    /usr/bin/python3 bench/solver_crossover_bench.py [--punch 16 18 20 22 24] [--tube 2 4 8] [--repeat 2]
                                                     [--penalty 1e8] [--solvers MUMPS "Belos + MueLu"]

3D: inputs/punch_3d.xml (a block pressed by a rigid punch, frictionless penalty contact; N x N x N/2 Hex8,
linear elastic, or each model of --materials with the same E and ν), the whole run (two increments of
0.5 mm), for each contact penalty of --penalty (the
deck's 1e8 N/mm^3 is about 100 times the stiffness E/h of the block's surface elements at N = 20; 1e5 is
soft, 0.1 E/h). 2D: inputs/tube_bending.xml refined K times in each direction (13K x 101K Q4 Enhanced),
--tube-steps fixed increments of 0.1 (the plate reaches the tube in the first). Each case with MUMPS and
with Belos GMRES + MueLu (Contessa's defaults for both), the variants interleaved over --repeat rounds.
Prints per case the median CPU seconds (user + system, /usr/bin/time: the whole process, start-up and
set-up included), the Newton iterations, the CPU per Newton iteration, the Krylov iterations per linear
solve, the factorisations (MUMPS) or MueLu set-ups skipped, and per case the ratio MUMPS / Belos of the
CPU (above 1: Belos + MueLu is the cheaper); then per case the ratios per run and per Newton iteration and
which solver is the cheaper by each.

The punch's Jacobian changes only with its contact set (a linear solid and a flat rigid punch): Jacobians
equal to the last one reuse MUMPS' factors or MueLu's set-up, which a nonlinear solid (the tube) does not
allow; the two decks bracket what the automatic choice meets.
"""
import json
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from speed_bench import ROOT, print_host, punch_arguments, run  # noqa: E402

PUNCH = os.path.join(ROOT, "inputs", "punch_3d.xml")
TUBE = os.path.join(ROOT, "inputs", "tube_bending.xml")
SOLVERS = {"MUMPS": ["Piro/Stratimikos/Linear Solver Type=MUMPS"],
           "Belos + MueLu": ["Piro/Stratimikos/Linear Solver Type=Belos", "Piro/Stratimikos/Preconditioner Type=MueLu"]}


def cases(a):
    """(label, unknowns, deck, stem, --set list) per case."""
    out = []
    for n in a.punch:
        nz = max(n // 2, 1)
        for material in a.materials:
            for penalty in a.penalty:
                out.append((f"punch {n}x{n}x{nz}, {material}, penalty {penalty}", 3 * (n + 1) ** 2 * (nz + 1), PUNCH,
                            "punch_3d",
                            [f"Problem/Mesh/Elements X={n}", f"Problem/Mesh/Elements Y={n}", f"Problem/Mesh/Elements Z={nz}",
                             f"Problem/Contact/punch/Normal Penalty={penalty}", f"Problem/Materials/steel/Model={material}"]))
    for k in a.tube:
        nr, nt = 13 * k, 101 * k
        out.append((f"tube 2D refined {k}x ({nr}x{nt}), {a.tube_steps} increments", 2 * (nr + 1) * (nt + 1), TUBE,
                    "tube_bending",
                    ["Piro/LOCA/Step Size/Method=Constant", "Piro/LOCA/Step Size/Initial Step Size=0.1",
                     f"Piro/LOCA/Stepper/Max Steps={a.tube_steps}", f"Problem/Mesh/Elements Through Thickness={nr}",
                     f"Problem/Mesh/Elements Around Arc={nt}"]))
    return out


def main():
    p = punch_arguments(__doc__, [16, 18, 20, 22, 24], 2, "/tmp/contessa-crossover-bench", 3600)
    p.add_argument("--tube", type=int, nargs="*", default=[], help="2D tube refinement factors (e.g. 4 8)")
    p.add_argument("--tube-steps", type=int, default=3, help="fixed increments of the tube runs (default 3)")
    p.add_argument("--penalty", nargs="+", default=["1e8"])
    p.add_argument("--materials", nargs="+", default=["Linear Elastic"],
                   help="the punch's material models (Neo-Hookean: a Jacobian that changes at every iteration)")
    p.add_argument("--solvers", nargs="+", default=list(SOLVERS))
    a = p.parse_args()
    print_host()
    results = {}
    for rep in range(a.repeat):
        for label, unknowns, deck, stem, sets in cases(a):
            for solver in a.solvers:
                out = os.path.join(a.work, f"{stem}_{len(results)}_{solver.split()[0]}")
                cmd = [a.contessa, deck, "--quiet", "--output-dir", out]
                for s in sets + SOLVERS[solver]:
                    cmd += ["--set", s]
                r = run(cmd, out, a.timeout, accept=(0, 1, 3))
                s = json.load(open(os.path.join(out, stem + ".summary.json")))
                results.setdefault((label, unknowns, solver), []).append((r["cpu"], s))
            print(f"[{rep + 1}/{a.repeat}] {label} done", file=sys.stderr, flush=True)
    print(f"CPU = user + system seconds of the whole process, median of {a.repeat} interleaved runs\n")
    print("| case | unknowns | solver | Newton it. | CPU s | CPU s per Newton it. | Krylov it. per solve | "
          "factorisations (reused) / MueLu set-ups skipped | MUMPS / Belos CPU |")
    print("|---|---:|---|---:|---:|---:|---:|---:|---:|")
    medians = {key: statistics.median(c for c, _ in runs) for key, runs in results.items()}
    for (label, unknowns, solver), runs in results.items():
        cpu = medians[(label, unknowns, solver)]
        s = runs[-1][1]
        newton, solves = s["newton_iterations"], s["linear_solves"]
        flag = "" if s["finished"] else " (did not finish)"
        if solver == "MUMPS":
            krylov, reuse = "–", f"{s['direct_factorizations']} ({s.get('reused_factorizations', '–')})"
        else:
            krylov, reuse = (f"{s['linear_iterations'] / solves:.1f}" if solves else "–"), str(s.get("preconditioner_unchanged_setups", "–"))
        pair = [medians.get((label, unknowns, x)) for x in SOLVERS]
        ratio = f"{pair[0] / pair[1]:.2f}" if None not in pair and solver != "MUMPS" else ""
        print(f"| {label}{flag} | {unknowns} | {solver} | {newton} | {cpu:.2f} | {cpu / max(newton, 1):.3f} | {krylov} | "
              f"{reuse} | {ratio} |")
    print_crossover(results, medians)


def print_crossover(results, medians):
    """Per case, which solver is the cheaper per run and per Newton iteration (the two measures an automatic
    choice can serve: a deck's whole run, or the cost of one iteration whatever the iteration counts)."""
    print("\n| case | unknowns | MUMPS / Belos CPU per run | MUMPS / Belos CPU per Newton it. | cheaper per run | "
          "cheaper per Newton it. |")
    print("|---|---:|---:|---:|---|---|")
    for label, unknowns in dict.fromkeys((lab, n) for lab, n, _ in results):
        runs = [results.get((label, unknowns, x)) for x in SOLVERS]
        if None in runs:
            continue
        cpu = [medians[(label, unknowns, x)] for x in SOLVERS]
        per_it = [c / max(r[-1][1]["newton_iterations"], 1) for c, r in zip(cpu, runs)]
        names = list(SOLVERS)
        print(f"| {label} | {unknowns} | {cpu[0] / cpu[1]:.2f} | {per_it[0] / per_it[1]:.2f} | "
              f"{names[0] if cpu[0] <= cpu[1] else names[1]} | {names[0] if per_it[0] <= per_it[1] else names[1]} |")


if __name__ == "__main__":
    main()
