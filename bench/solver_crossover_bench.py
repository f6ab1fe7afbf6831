#!/usr/bin/python3
"""Where penalty contact moves the 3D crossover of MUMPS and Belos GMRES + MueLu (issue 23, third round).

    /usr/bin/python3 bench/solver_crossover_bench.py [--punch 20 24 28] [--penalty 1e8 1e5] [--repeat 2]

Runs inputs/punch_3d.xml (a block pressed by a rigid punch, frictionless penalty contact; N x N x N/2
Hex8) with MUMPS and with Belos GMRES + MueLu, for each contact penalty (the deck's 1e8 N/mm^3, about
100 times the stiffness E/h of the block's surface elements at N = 20, and a soft 1e5, 0.1 E/h, which
leaves the matrix about as well conditioned as without contact), stopped after the first attempt of
the first increment and at most --newton Newton iterations (the punch does not converge on these
coarse meshes, issue 22; every iteration is a full Jacobian and linear solve all the same). The
variants are interleaved over --repeat rounds. Prints per variant: the median CPU seconds (user +
system, /usr/bin/time) per Newton iteration (the whole process' CPU, set-up included, over the Newton
iterations) and the Krylov iterations per linear solve (Belos; from the run's summary.json).
"""
import json
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from speed_bench import ROOT, print_host, punch_arguments, run  # noqa: E402

DECK = os.path.join(ROOT, "inputs", "punch_3d.xml")
SOLVERS = {"MUMPS": ["Piro/Stratimikos/Linear Solver Type=MUMPS"],
           "Belos + MueLu": ["Piro/Stratimikos/Linear Solver Type=Belos", "Piro/Stratimikos/Preconditioner Type=MueLu"]}


def main():
    p = punch_arguments(__doc__, [20, 24, 28], 2, "/tmp/contessa-crossover-bench", 3600)
    p.add_argument("--penalty", nargs="+", default=["1e8", "1e5"])
    p.add_argument("--solvers", nargs="+", default=list(SOLVERS))
    p.add_argument("--newton", type=int, default=8, help="Newton iterations at most (default 8)")
    a = p.parse_args()
    print_host()
    results = {}
    for rep in range(a.repeat):
        for n in a.punch:
            nz = max(n // 2, 1)
            mesh = [f"Problem/Mesh/Elements X={n}", f"Problem/Mesh/Elements Y={n}", f"Problem/Mesh/Elements Z={nz}"]
            for penalty in a.penalty:
                for solver in a.solvers:
                    out = os.path.join(a.work, f"punch{n}_{penalty}_{solver.split()[0]}")
                    cmd = [a.contessa, DECK, "--quiet", "--output-dir", out]
                    sets = mesh + SOLVERS[solver] + ["Piro/LOCA/Stepper/Max Steps=1",
                                                      f"Piro/NOX/Status Tests/Maximum Iterations={a.newton}",
                                                      f"Problem/Contact/punch/Normal Penalty={penalty}"]
                    for s in sets:
                        cmd += ["--set", s]
                    r = run(cmd, out, a.timeout, accept=(0, 1, 3))
                    s = json.load(open(os.path.join(out, "punch_3d.summary.json")))
                    key = (n, 3 * (n + 1) ** 2 * (nz + 1), penalty, solver)
                    results.setdefault(key, []).append((r["cpu"], s["newton_iterations"], s["linear_solves"],
                                                        s["linear_iterations"]))
            print(f"[{rep + 1}/{a.repeat}] punch {n} done", file=sys.stderr, flush=True)
    print(f"CPU = user + system seconds of the whole process over its Newton iterations, median of {a.repeat} runs\n")
    print("| mesh | unknowns | penalty | solver | Newton it. | CPU s per Newton it. | Krylov it. per solve |")
    print("|---|---:|---:|---|---:|---:|---:|")
    for (n, unknowns, penalty, solver), runs in results.items():
        cpu = statistics.median(c / max(newton, 1) for c, newton, _, _ in runs)
        _, newton, solves, krylov = runs[0]
        per_solve = f"{krylov / solves:.1f}" if solver != "MUMPS" and solves else "–"
        print(f"| {n}x{n}x{max(n // 2, 1)} | {unknowns} | {penalty} | {solver} | {newton} | {cpu:.3f} | {per_solve} |")


if __name__ == "__main__":
    main()
