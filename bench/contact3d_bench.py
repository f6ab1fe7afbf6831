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
- the 2-rank answer against one rank's (compare_history.py, 1e-8 relative on every history column but
  the solver counts).

Tools: /usr/bin/python3 (standard library), mpiexec. Times depend on the machine's load (printed).
The global contact search alone, for 10^4–10^6 slave nodes, is build/bin/contact_search_bench.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from linear_solver_bench import MPIEXEC, ROW, difference  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
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
    out = os.path.join(work, f"n{n}_np{ranks}")
    os.makedirs(out, exist_ok=True)
    command = ([] if ranks == 1 else MPIEXEC + [str(ranks)]) + [contessa, DECK, "--quiet", "--timers", "--output-dir", out]
    for axis, count in (("X", n), ("Y", n), ("Z", n // 2)):
        command += ["--set", f"Problem/Mesh/Elements {axis}={count}"]
    p = subprocess.run(command, capture_output=True, text=True)
    with open(os.path.join(out, "log.txt"), "w") as log:
        log.write(p.stdout + p.stderr)
    result = {"status": p.returncode, "out": out, "stderr": p.stderr.strip().splitlines()[-1:], "phases": {}}
    for line in p.stdout.splitlines():
        m = ROW.match(line)
        if m:
            result["phases"][m[1].strip()] = float(m[2])
    summary = os.path.join(out, "punch_3d.summary.json")
    if os.path.exists(summary):
        result["summary"] = json.load(open(summary))
    return result


def last_row(history):
    lines = open(history).read().splitlines()
    header = lines[0].split(",")
    return dict(zip(header, lines[-1].split(",")))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sizes", type=int, nargs="+", default=[40, 58, 86])
    parser.add_argument("--ranks", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--work", default=None)
    parser.add_argument("--contessa", default=os.path.join(ROOT, "build", "bin", "contessa"))
    args = parser.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="contact3d_bench_")
    print(f"load average {os.getloadavg()[0]:.2f} {os.getloadavg()[1]:.2f}; work directory {work}\n")
    print("| n | unknowns | ranks | slave / contact nodes | punch force [N] | Newton it. | Krylov it./solve | wall [s] | per Newton it. [s] | "
          "preconditioner set-up [s] | Krylov [s] | contact [s] | elements + assembly [s] | set-up [s] | peak memory: largest rank / sum [MiB] | "
          "answer vs 1 rank |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for n in args.sizes:
        reference = None
        for ranks in args.ranks:
            r = run(args.contessa, n, ranks, work)
            s = r.get("summary")
            if r["status"] != 0 or s is None:
                print(f"| {n} | {unknowns(n)} | {ranks} | FAILED (exit {r['status']}: {' '.join(r['stderr'])}) |||||||||||||")
                continue
            history = os.path.join(r["out"], "punch_3d.history.csv")
            answer = "reference" if reference is None else difference(reference, history)
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
                  f"{phase['set-up']:.1f} | {memory['max'] / 2**20:.0f} / {sum(memory['per_rank']) / 2**20:.0f} | {answer} |",
                  flush=True)


if __name__ == "__main__":
    main()
