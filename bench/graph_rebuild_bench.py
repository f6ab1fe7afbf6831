#!/usr/bin/python3
"""Cost of the matrix graph's rebuilds (the contact leaving its reserved couplings) on a large 3D case.

    /usr/bin/python3 bench/graph_rebuild_bench.py [--reach 0 0.5 2.5] [--ranks 1] [--work DIR] [--contessa PATH]

The 3D sliding block of tests/regression/contact_graph/sliding_block_3d.xml refined 4x (base 64 x 2 x 24,
block 16 x 4 x 16 Hex8 Enhanced: 6320 nodes, 18 960 unknowns; master faces h = 0.088 mm, the block slides
2 mm over them in 20 increments), run once per Search Reach with --timers and MUMPS
(named: the automatic choice takes Belos + MueLu above 15 000 unknowns). Prints one Markdown table:
Search Reach, the graph's entries at the first rebuild (or none), rebuilds, the mean seconds of one
rebuild (reservation around the current configuration, graph, scatter positions: the log line), MUMPS
analyses, the mean seconds of one factorisation and of one Jacobian element pass (for scale), Newton
iterations, wall seconds and peak memory (summary.json). A rebuild also costs one more element pass with
the tangent and one MUMPS analysis (the new pattern), counted in their columns. Needs scripts/build.sh
first; about 2 minutes per run on the 2-core CI machine.
"""
import json
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from speed_bench import ROOT, bench_arguments, print_table_header, work_directory  # noqa: E402

DECK = os.path.join(ROOT, "tests", "regression", "contact_graph", "sliding_block_3d.xml")
REFINED = ["Problem/Mesh/base/Elements X=64", "Problem/Mesh/base/Elements Y=2", "Problem/Mesh/base/Elements Z=24",
           "Problem/Mesh/block/Elements X=16", "Problem/Mesh/block/Elements Y=4",
           "Problem/Mesh/block/Elements Z=16", "Piro/LOCA/Step Size/Initial Step Size=0.05",
           "Piro/LOCA/Step Size/Max Step Size=0.05",
           # MUMPS by name: at 18 960 unknowns the automatic choice takes Belos + MueLu, whose runs have no
           # analyses or factorisations, so the MUMPS columns would read 0.
           "Piro/Stratimikos/Linear Solver Type=MUMPS"]
REBUILD = re.compile(r"^contessa: matrix graph rebuilt \(\d+\): .*, (\d+) entries, (\S+) s$")


def phase(log, name):
    """(seconds, count) of a row of the --timers table."""
    m = re.search(r"^  " + re.escape(name) + r"\s+(\S+)\s+\S+\s+(\d+)$", log, re.M)
    return (float(m.group(1)), int(m.group(2))) if m else (0.0, 0)


def main():
    parser = bench_arguments(__doc__)
    parser.add_argument("--reach", type=float, nargs="+", default=[0.0, 0.5, 2.5])
    parser.add_argument("--ranks", type=int, default=1)
    args = parser.parse_args()
    work = work_directory(args, "graph_rebuild_bench_")
    print_table_header(["Search Reach", "graph entries", "rebuilds", "s per rebuild", "MUMPS analyses", "s per factorisation",
                        "s per Jacobian element pass", "Newton iterations", "wall s", "peak MiB"], align="---:")
    for reach in args.reach:
        out = os.path.join(work, f"reach_{reach:g}")
        command = ([] if args.ranks == 1 else ["mpiexec", "-n", str(args.ranks), "--oversubscribe"]) + [
            args.contessa, DECK, "--timers", "--output-dir", out]
        for s in REFINED + [f"Problem/Contact/base/Search Reach={reach:g}"]:
            command += ["--set", s]
        run = subprocess.run(command, capture_output=True, text=True)
        log = run.stdout
        with open(os.path.join(work, f"reach_{reach:g}.log"), "w") as f:
            f.write(log + run.stderr)
        if run.returncode != 0:
            print(f"| {reach:g} | FAILED (exit {run.returncode}): {run.stderr.strip()[:200]} |")
            continue
        rebuilds = [REBUILD.match(l) for l in log.splitlines() if l.startswith("contessa: matrix graph rebuilt")]
        summary = json.load(open(os.path.join(out, "sliding_block_3d.summary.json")))
        entries = rebuilds[0].group(1) if rebuilds else "(none)"
        per_rebuild = sum(float(m.group(2)) for m in rebuilds) / len(rebuilds) if rebuilds else 0.0
        analyses = phase(log, "MUMPS analysis (JOB=1)")[1]
        fact_s, fact_n = phase(log, "MUMPS factorisation (JOB=2)")
        jac_s, jac_n = phase(log, "element kernels, Jacobian passes")
        print(f"| {reach:g} | {entries} | {summary['graph_rebuilds']} | {per_rebuild:.3f} | {analyses} | "
              f"{fact_s / max(fact_n, 1):.3f} | {jac_s / max(jac_n, 1):.3f} | {summary['newton_iterations']} | "
              f"{summary['wall_seconds']:.1f} | {summary['peak_memory_bytes']['max'] / 2**20:.0f} |", flush=True)


if __name__ == "__main__":
    sys.exit(main())
