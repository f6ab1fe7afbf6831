#!/usr/bin/python3
"""3D contact at 10^5–10^6 unknowns: a block pressed by a rigid punch (inputs/punch_3d.xml).

    /usr/bin/python3 bench/contact3d_bench.py [--sizes 40 58 86] [--ranks 1 2] [--work DIR] [--contessa PATH]
        [--forcing "Newton Target" Constant] [--muelu "implicit R=transpose: use implicit=true" ...] [--repeat 3]

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
  a refused re-set-up, a row changed by more than kept coarse levels allow; the first set-up not counted) /
  reused (aggregates and P kept; with "reuse: type = RAP" the coarse levels too) / skipped (values unchanged);
- the 2-rank answer against one rank's (compare_history.py, 1e-8 relative on every history column but
  the solver counts);
- with --forcing, one row set per Krylov forcing term (Piro/NOX/Direction/Forcing Term: "Newton Target",
  the default, or "Constant", the deck's tolerance for every solve); with --muelu, one row set per MueLu
  variant "LABEL=PARAMETER=VALUE[;PARAMETER=VALUE...]" (parameters of the deck's MueLu sublist,
  Piro/Stratimikos/Preconditioner Types/MueLu; "LABEL=" alone is the deck as it is); with --repeat R each
  run R times
  (interleaved) with the CPU time (user + system of every rank, getrusage of the children) as the median
  and the range; the wall and phase columns are the first run's.

Tools: /usr/bin/python3 (standard library), mpiexec. Times depend on the machine's load (printed).
The global contact search alone, for 10^4–10^6 slave nodes, is build/bin/contact_search_bench.
"""
import os
import resource
import statistics
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


MUELU = "Piro/Stratimikos/Preconditioner Types/MueLu/"


def variants(args):
    """(label, --set list) per variant: the forcing terms times the MueLu variants."""
    muelu = []
    for text in args.muelu or [""]:
        label, _, given = text.partition("=")
        muelu.append((label, [MUELU + s.strip() for s in given.split(";") if s.strip()]))
    out = []
    for forcing in args.forcing:
        for label, sets in muelu:
            forcing_sets = [f"Piro/NOX/Direction/Forcing Term={forcing}"] if forcing else []
            out.append(("; ".join(x for x in (forcing, label) if x) or None, forcing_sets + sets))
    return out


def run(contessa, n, ranks, work, variant=(None, []), repeat=0):
    """One timed run; its "cpu" is the user + system time of contessa on every rank (the children's rusage)."""
    label, extra = variant
    sets = [f"Problem/Mesh/Elements {axis}={count}" for axis, count in (("X", n), ("Y", n), ("Z", n // 2))] + extra
    name = f"n{n}_np{ranks}"
    if label:
        name += "_" + "".join(c for c in label if c.isalnum())
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    r = timed_run(contessa, DECK, ranks, os.path.join(work, f"{name}_{repeat}"), sets)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    r["cpu"] = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return r


def setups(summary):
    """MueLu's set-ups of the run: started over / reused / skipped (the summary's counts)."""
    restarts = sum(summary.get(f"preconditioner_{k}", 0) for k in
                   ("new_graph_setups", "pattern_restarts", "coarse_zero_restarts", "refused_reuses",
                                                               "large_change_restarts"))
    return f"{restarts} / {summary.get('preconditioner_reused_setups', 0)} / {summary.get('preconditioner_unchanged_setups', 0)}"


def last_row(history):
    lines = open(history).read().splitlines()
    header = lines[0].split(",")
    return dict(zip(header, lines[-1].split(",")))


def main():
    parser = bench_arguments(__doc__)
    parser.add_argument("--sizes", type=int, nargs="+", default=[40, 58, 86])
    parser.add_argument("--ranks", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--forcing", nargs="+", default=[None], help='Forcing Term values, e.g. "Newton Target" Constant')
    parser.add_argument("--muelu", nargs="+", help='MueLu variants, "LABEL=PARAMETER=VALUE[;PARAMETER=VALUE...]"')
    parser.add_argument("--repeat", type=int, default=1)
    args = parser.parse_args()
    work = work_directory(args, "contact3d_bench_")
    print_table_header(["n", "unknowns", "ranks", "variant", "CPU [s] median (range)", "slave / contact nodes", "punch force [N]", "Newton it.", "Krylov it./solve (total)",
                        "wall [s]", "per Newton it. [s]", "preconditioner set-up [s]", "Krylov [s]", "contact [s]",
                        "elements + assembly [s]", "set-up [s]", "peak memory: largest rank / sum [MiB]",
                        "MueLu set-ups started over / reused / skipped", "answer vs 1 rank"])
    for n in args.sizes:
        cases = [(ranks, variant) for variant in range(len(variants(args))) for ranks in args.ranks]
        runs = {case: [] for case in cases}
        for repeat in range(args.repeat):  # interleaved, so that the machine's load falls on every case alike
            for ranks, variant in cases:
                runs[(ranks, variant)].append(run(args.contessa, n, ranks, work, variants(args)[variant], repeat))
        references = {}
        for ranks, variant in cases:
            print_row(n, ranks, variants(args)[variant][0], runs[(ranks, variant)], references)


def print_row(n, ranks, variant, runs, references):
    r = runs[0]
    s = r.get("summary")
    label = variant or "deck default"
    if any(x["status"] != 0 or x.get("summary") is None for x in runs):
        print(f"| {n} | {unknowns(n)} | {ranks} | {label} | FAILED (exit {r['status']}: {' '.join(r['stderr'])}) ||||||||||||||")
        return
    cpus = [x["cpu"] for x in runs]
    cpu = f"{statistics.median(cpus):.1f} ({min(cpus):.1f}-{max(cpus):.1f})" if len(cpus) > 1 else f"{cpus[0]:.1f}"
    history = os.path.join(r["out"], "punch_3d.history.csv")
    reference = references.setdefault(variant, history)
    answer = "reference" if reference == history else history_difference(reference, history)
    phase = {k: sum(r["phases"].get(p, 0.0) for p in v) for k, v in PHASES.items()}
    krylov = s["linear_iterations"] / max(s["linear_solves"], 1)
    memory = s["peak_memory_bytes"]
    slaves = (n + 1) ** 2
    contacts = int(float(last_row(history)["active_contacts"]))
    force = -float(last_row(history)["contact_force_punch_z"])
    print(f"| {n} | {unknowns(n)} | {ranks} | {label} | {cpu} | {slaves} / {contacts} | {force:.1f} | {s['newton_iterations']} | "
          f"{krylov:.1f} ({s['linear_iterations']}) | "
          f"{s['wall_seconds']:.1f} | {s['wall_seconds'] / max(s['newton_iterations'], 1):.2f} | "
          f"{phase['preconditioner set-up']:.1f} | {phase['Krylov iterations']:.1f} | {phase['contact']:.2f} | {phase['elements + assembly']:.1f} | "
          f"{phase['set-up']:.1f} | {memory['max'] / 2**20:.0f} / {sum(memory['per_rank']) / 2**20:.0f} | "
          f"{setups(s)} | {answer} |",
          flush=True)

if __name__ == "__main__":
    main()
