#!/usr/bin/python3
"""3D contact at 10^5–10^6 unknowns: a block pressed by a rigid punch (inputs/punch_3d.xml).

    /usr/bin/python3 bench/contact3d_bench.py [--sizes 40 58 86] [--ranks 1 2] [--work DIR] [--contessa PATH]

The deck is a quarter block of Hex8 (n x n x n/2 elements, 3 (n+1)^2 (n/2+1) unknowns: n = 40, 58, 86
give 1.06e5, 3.13e5 and 9.99e5) pressed by a rigid square punch covering part of its top face,
frictionless penalty contact, two increments of λ = 0.5, Belos GMRES + MueLu (rigid-body modes as
near-null space). For each size and rank count it prints one Markdown row:

- slave nodes of the contact surface and contact nodes at the end, the punch force at the end
  (contact_force_punch_z); Newton iterations; Krylov iterations per linear solve;
- wall time of the run (the summary's wall_seconds) and per Newton iteration;
- linear solver time (MueLu's set-up and the Krylov iterations, apart), contact time (search, contact
  elements and their scatter), element kernels + assembly, set-up (deck, mesh, partition, graph):
  `contessa --timers`, the largest rank per phase;
- peak memory per rank (the summary's VmHWM: largest rank and the sum over ranks);
- MueLu's set-ups from the summary: started over (on a new graph, a filled-in entry, a coarse matrix's zeros,
  a refused re-set-up; the first set-up not counted) / reused (aggregates and P kept) / skipped (values
  unchanged);
- the 2-rank answer against one rank's (compare_history.py, 1e-8 relative on every history column but
  the solver counts).

Tools: /usr/bin/python3 (standard library), mpiexec. Times depend on the machine's load (printed).
The global contact search alone, for 10^4–10^6 slave nodes, is build/bin/contact_search_bench.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from speed_bench import (ROOT, bench_arguments, history_difference, print_table_header, timed_run,  # noqa: E402
                         work_directory)

DECK = os.path.join(ROOT, "inputs", "punch_3d.xml")
PHASES = {
    "preconditioner set-up": ["iterative: preconditioner set-up"],
    "Krylov iterations": ["iterative: Krylov iterations"],
    "contact": ["contact: search, elements, scatter"],
    "elements + assembly": ["element kernels, residual passes", "element kernels, Jacobian passes",
                            "assembly: scatter, Dirichlet, Export"],
    "set-up": ["set-up: deck, mesh, partition, graph"],
}


def unknowns(n):
    return 3 * (n + 1) ** 2 * (n // 2 + 1)


def run(contessa, n, ranks, work):
    sets = [f"Problem/Mesh/Elements {axis}={count}" for axis, count in (("X", n), ("Y", n), ("Z", n // 2))]
    return timed_run(contessa, DECK, ranks, os.path.join(work, f"n{n}_np{ranks}"), sets)


def setups(summary):
    """MueLu's set-ups of the run: started over / reused / skipped (the summary's counts)."""
    restarts = sum(summary.get(f"preconditioner_{k}", 0) for k in
                   ("new_graph_setups", "pattern_restarts", "coarse_zero_restarts", "refused_reuses"))
    return f"{restarts} / {summary.get('preconditioner_reused_setups', 0)} / {summary.get('preconditioner_unchanged_setups', 0)}"


def last_row(history):
    lines = open(history).read().splitlines()
    header = lines[0].split(",")
    return dict(zip(header, lines[-1].split(",")))


def main():
    parser = bench_arguments(__doc__)
    parser.add_argument("--sizes", type=int, nargs="+", default=[40, 58, 86])
    parser.add_argument("--ranks", type=int, nargs="+", default=[1, 2])
    args = parser.parse_args()
    work = work_directory(args, "contact3d_bench_")
    print_table_header(["n", "unknowns", "ranks", "slave / contact nodes", "punch force [N]", "Newton it.", "Krylov it./solve",
                        "wall [s]", "per Newton it. [s]", "preconditioner set-up [s]", "Krylov [s]", "contact [s]",
                        "elements + assembly [s]", "set-up [s]", "peak memory: largest rank / sum [MiB]",
                        "MueLu set-ups started over / reused / skipped", "answer vs 1 rank"])
    for n in args.sizes:
        reference = None
        for ranks in args.ranks:
            r = run(args.contessa, n, ranks, work)
            s = r.get("summary")
            if r["status"] != 0 or s is None:
                print(f"| {n} | {unknowns(n)} | {ranks} | FAILED (exit {r['status']}: {' '.join(r['stderr'])}) ||||||||||||||")
                continue
            history = os.path.join(r["out"], "punch_3d.history.csv")
            answer = "reference" if reference is None else history_difference(reference, history)
            reference = reference or history
            phase = {k: sum(r["phases"].get(p, 0.0) for p in v) for k, v in PHASES.items()}
            krylov = s["linear_iterations"] / max(s["linear_solves"], 1)
            memory = s["peak_memory_bytes"]
            slaves = (n + 1) ** 2
            contacts = int(float(last_row(history)["active_contacts"]))
            force = -float(last_row(history)["contact_force_punch_z"])
            print(f"| {n} | {unknowns(n)} | {ranks} | {slaves} / {contacts} | {force:.1f} | {s['newton_iterations']} | {krylov:.1f} | "
                  f"{s['wall_seconds']:.1f} | {s['wall_seconds'] / max(s['newton_iterations'], 1):.2f} | "
                  f"{phase['preconditioner set-up']:.1f} | {phase['Krylov iterations']:.1f} | {phase['contact']:.2f} | {phase['elements + assembly']:.1f} | "
                  f"{phase['set-up']:.1f} | {memory['max'] / 2**20:.0f} / {sum(memory['per_rank']) / 2**20:.0f} | "
                  f"{setups(s)} | {answer} |",
                  flush=True)


if __name__ == "__main__":
    main()
