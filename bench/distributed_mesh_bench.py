#!/usr/bin/python3
"""Memory per rank of the mesh, replicated against distributed (build/bin/distributed_mesh_bench).

Writes a box of N^3 Hex8 ((N+1)^3 nodes, 10^6 for the default N = 99) as an Exodus file once, then
for 1, 2 and 4 ranks runs each path in its own mpiexec and prints one Markdown table:
  replicated-box      every rank generates the whole box and partitions it (METIS), as runs do today
  generated-box       every rank generates only its part (contiguous element ranges)
  replicated-exodus   every rank reads the whole file and partitions it, as runs do today
  distributed-exodus  rank 0 reads the file, partitions it (METIS) and sends each rank its part
  decomposed-exodus   each rank reads its own file of a pre-split set (written beforehand by the ranks,
                      one file each: contiguous element ranges)
Columns: peak resident memory (VmHWM) of the largest rank, the same above the process's start (MPI
and libraries loaded: what the mesh path itself took) for rank 0 and the largest other rank, the mesh containers each rank keeps for the
run (largest rank), the replicated contact surfaces gathered from the parts (the box's top face, and
all six faces) and the wall time of the mesh path.

  /usr/bin/python3 bench/distributed_mesh_bench.py [--n 99] [--ranks 1 2 4] [--build build]
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

MODES = ["replicated-box", "generated-box", "replicated-exodus", "distributed-exodus", "decomposed-exodus"]
LINE = re.compile(r"^(\S+)\s+ranks (\d+)\s+nodes (\d+)\s+peak/rank max ([\d.]+) MiB \(sum ([\d.]+)\)\s+"
                  r"above start max ([\d.]+) MiB \(sum ([\d.]+), rank 0 ([\d.]+), others max ([\d.]+)\)\s+held/rank max ([\d.]+) MiB\s+part max ([\d.]+) MiB\s+"
                  r"surface top ([\d.]+) MiB, all ([\d.]+) MiB\s+time ([\d.]+) s")


def mpiexec(ranks):
    command = ["mpiexec", "--oversubscribe", "-n", str(ranks)]
    if os.geteuid() == 0:
        command.insert(1, "--allow-run-as-root")
    return command


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--n", type=int, default=99, help="elements along each edge of the box (default 99)")
    parser.add_argument("--ranks", type=int, nargs="+", default=[1, 2, 4])
    parser.add_argument("--build", default=os.path.join(os.path.dirname(__file__), "..", "build"))
    args = parser.parse_args()
    program = os.path.join(args.build, "bin", "distributed_mesh_bench")
    if not os.path.exists(program):
        sys.exit(f"distributed_mesh_bench: {program} not found: build first (scripts/build.sh)")

    with tempfile.TemporaryDirectory() as work:
        path = os.path.join(work, f"box{args.n}.exo")
        subprocess.run(mpiexec(1) + [program, "write", str(args.n), path], check=True)
        print(f"box of {args.n}^3 Hex8, {(args.n + 1) ** 3} nodes; file {os.path.getsize(path) / 2**20:.1f} MiB\n")
        print("| path | ranks | peak/rank (MiB) | above start: rank 0 / other ranks (MiB) | mesh kept/rank (MiB) "
              "| surface top / all faces (MiB) | time (s) |")
        print("|---|---|---|---|---|---|---|")
        for ranks in args.ranks:
            for mode in MODES:
                arg = path if mode.endswith("exodus") else str(args.n)
                if mode == "decomposed-exodus":
                    arg = os.path.join(work, f"split{args.n}.exo")
                    subprocess.run(mpiexec(ranks) + [program, "split", str(args.n), arg], check=True)
                run = subprocess.run(mpiexec(ranks) + [program, mode, arg], capture_output=True, text=True)
                match = LINE.search(run.stdout)
                if run.returncode != 0 or not match:
                    print(f"| {mode} | {ranks} | FAILED: {(run.stderr or run.stdout).strip().splitlines()[:1]} |")
                    continue
                g = match.groups()
                others = f"{float(g[8]):.0f}" if ranks > 1 else "-"
                print(f"| {mode} | {ranks} | {float(g[3]):.0f} | {float(g[7]):.0f} / {others} | {float(g[9]):.1f} "
                      f"| {float(g[11]):.2f} / {float(g[12]):.2f} | {float(g[13]):.2f} |", flush=True)


if __name__ == "__main__":
    main()
