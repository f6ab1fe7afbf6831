#!/usr/bin/python3
"""MUMPS against Belos GMRES + MueLu (smoothed aggregation, rigid-body near-null space) on the 3D box.

    /usr/bin/python3 bench/linear_solver_bench.py [--sizes 14 31 46] [--ranks 1 2] [--solvers mumps muelu]
                                                  [--skip-mumps-above N] [--work DIR] [--contessa PATH]

The deck is inputs/verification/uniaxial_tension_3d.xml (finite-strain tension of a cube of Hex8
Enhanced, exact force 264) with a uniform n x n x n box (Bias 1) in two increments of λ = 0.5, so each
run is a few Newton iterations of the same nonlinear problem. n = 14, 31, 46 give 3 (n+1)^3 = 10 125,
98 304 and 311 469 unknowns. For each size, rank count and solver it prints one Markdown row:

- Newton iterations and linear solves; Krylov iterations per linear solve (Belos);
- wall time of the run (the summary's wall_seconds: deck to end, without MPI start-up) and the time
  per Newton iteration (the continuation's wall time, `NOX/LOCA and everything else` included, divided
  by the Newton iterations);
- linear solver time (`contessa --timers`, the maximum over ranks per phase): MUMPS input + analysis +
  factorisation + solve, or the preconditioner set-up + Krylov iterations;
- peak memory per rank (the summary's VmHWM high-water marks: largest rank, and the sum over ranks);
- the largest relative difference of the history's reactions from the MUMPS run of the same size on one
  rank (compare_history.py, solver counts left out): the iterative answer must agree to 1e-8.

Tools: /usr/bin/python3 (standard library), mpiexec. Timings depend on the machine's load (the header
prints the load average). The largest size with MUMPS needs several GiB; --skip-mumps-above N leaves
MUMPS out above N unknowns.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from speed_bench import (ROOT, bench_arguments, history_difference, print_table_header, timed_run,  # noqa: E402
                         work_directory)

DECK = os.path.join(ROOT, "inputs", "verification", "uniaxial_tension_3d.xml")
STRAT = "Piro/Stratimikos/"
SOLVERS = {
    "mumps": [],
    "muelu": [STRAT + "Linear Solver Type=Belos", STRAT + "Preconditioner Type=MueLu"],
    "ifpack2": [STRAT + "Linear Solver Type=Belos", STRAT + "Preconditioner Type=Ifpack2"],
}
LINEAR_PHASES = {
    "mumps": ["MUMPS input (pattern, values)", "MUMPS analysis (JOB=1)", "MUMPS factorisation (JOB=2)",
              "MUMPS solve (JOB=3, rhs to/from host)"],
    "muelu": ["iterative: preconditioner set-up", "iterative: Krylov iterations"],
    "ifpack2": ["iterative: preconditioner set-up", "iterative: Krylov iterations"],
}


def overrides(n):
    mesh = "Problem/Mesh/"
    sets = [mesh + f"Elements {a}={n}" for a in "XYZ"] + [mesh + f"Bias {a}=1.0" for a in "XYZ"]
    sets += ["Piro/LOCA/Step Size/Initial Step Size=0.5", "Piro/LOCA/Step Size/Max Step Size=0.5"]
    return sets


def run(contessa, n, solver, ranks, work):
    return timed_run(contessa, DECK, ranks, os.path.join(work, f"n{n}_{solver}_np{ranks}"), overrides(n) + SOLVERS[solver])


def main():
    parser = bench_arguments(__doc__)
    parser.add_argument("--sizes", type=int, nargs="+", default=[14, 31, 46])
    parser.add_argument("--ranks", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--solvers", nargs="+", default=["mumps", "muelu"], choices=sorted(SOLVERS))
    parser.add_argument("--skip-mumps-above", type=int, default=400000)
    args = parser.parse_args()
    work = work_directory(args, "linear_solver_bench_")
    print_table_header(["n", "unknowns", "solver", "ranks", "Newton it.", "linear solves", "Krylov it./solve", "wall [s]",
                        "per Newton it. [s]", "linear solver [s]", "peak memory: largest rank / sum [MiB]",
                        "answer vs MUMPS np1"])
    for n in args.sizes:
        unknowns = 3 * (n + 1) ** 3
        reference = None
        for solver in args.solvers:
            if solver == "mumps" and unknowns > args.skip_mumps_above:
                print(f"| {n} | {unknowns} | {solver} | - | skipped (--skip-mumps-above {args.skip_mumps_above}) |||||||")
                continue
            for ranks in args.ranks:
                r = run(args.contessa, n, solver, ranks, work)
                s = r.get("summary")
                if r["status"] != 0 or s is None:
                    print(f"| {n} | {unknowns} | {solver} | {ranks} | FAILED (exit {r['status']}: {' '.join(r['stderr'])}) |||||||")
                    continue
                history = os.path.join(r["out"], "uniaxial_tension_3d.history.csv")
                if solver == "mumps" and ranks == 1:
                    reference = history
                answer = "reference" if history == reference else (history_difference(reference, history) if reference else "-")
                linear = sum(r["phases"].get(p, 0.0) for p in LINEAR_PHASES[solver])
                continuation = s["wall_seconds"]
                per_newton = continuation / max(s["newton_iterations"], 1)
                krylov = f"{s['linear_iterations'] / s['linear_solves']:.1f}" if solver != "mumps" and s["linear_solves"] else "-"
                memory = s["peak_memory_bytes"]
                print(f"| {n} | {unknowns} | {solver} | {ranks} | {s['newton_iterations']} | {s['linear_solves']} | {krylov} | "
                      f"{continuation:.1f} | {per_newton:.2f} | {linear:.1f} | {memory['max'] / 2**20:.0f} / "
                      f"{sum(memory['per_rank']) / 2**20:.0f} | {answer} |", flush=True)


if __name__ == "__main__":
    main()
