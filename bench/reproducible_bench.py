#!/usr/bin/python3
"""What MUMPS' Reproducible costs on 2 ranks (docs/user-guide.md, "Parallel runs"):
    /usr/bin/python3 bench/reproducible_bench.py [--repeat 3] [--refine 1 4] [--work DIR]
The tube (inputs/tube_bending.xml) refined k times in each direction, 10 fixed increments, on 2 ranks,
with MUMPS' default parallel factorisation and with Reproducible (the matrix gathered on rank 0 and
factorised and solved there alone), the two variants interleaved so that a change of the machine's load
hits both alike. Prints one Markdown row per k and variant: median and minimum wall time, the median
MUMPS factorisation time per call (`--timers`), the peak memory of the largest rank, and whether the
repeated runs of the variant wrote identical histories (every column but wall_s)."""
import argparse
import csv
import os
import statistics
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from speed_bench import FACTORISATION, MESH, STEP, contessa_cmd, parse, run  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
REPRODUCIBLE = "Piro/Stratimikos/Linear Solver Types/MUMPS/Reproducible=true"


def history(out_dir):
    rows = list(csv.DictReader(open(os.path.join(out_dir, "tube_bending.history.csv"))))
    return [{c: v for c, v in r.items() if c != "wall_s"} for r in rows]


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--refine", type=int, nargs="+", default=[1, 4])
    p.add_argument("--contessa", default=os.path.join(ROOT, "build", "bin", "contessa"))
    p.add_argument("--work", default=None)
    p.add_argument("--timeout", type=float, default=1800)
    a = p.parse_args()
    work = a.work or tempfile.mkdtemp(prefix="contessa_reproducible_")
    print(f"load average at the start: {os.getloadavg()}", file=sys.stderr)
    print("| k | unknowns | MUMPS | wall s (median) | wall s (min) | factorisation ms per call | peak MB (largest rank) | runs identical |")
    print("|---:|---:|---|---:|---:|---:|---:|---|")
    for k in a.refine:
        nr, nt = 13 * k, 101 * k
        sets = [STEP + "Method=Constant", STEP + "Initial Step Size=0.1", MESH + f"Elements Through Thickness={nr}",
                MESH + f"Elements Around Arc={nt}"]
        results = {"parallel": [], "Reproducible": []}
        for i in range(a.repeat):
            for variant in results:
                out = os.path.join(work, f"k{k}_{variant}_{i}")
                extra = [REPRODUCIBLE] if variant == "Reproducible" else []
                # Exit 3: the deck's checks are for the standard mesh and 31 increments; the run itself finished.
                r = parse(run(contessa_cmd(a.contessa, 2, out, sets + extra, True), out, a.timeout, accept=(0, 3)))
                fact = r["phases"].get(FACTORISATION, (float("nan"), 1))
                r["fact_ms"] = 1000 * fact[0] / max(1, fact[1])
                r["history"] = history(out)
                results[variant].append(r)
                print(f"k={k} {variant} run {i}: {r['wall']:.2f} s", file=sys.stderr, flush=True)
        for variant, runs in results.items():
            identical = all(r["history"] == runs[0]["history"] for r in runs[1:])
            print(f"| {k} | {2 * (nr + 1) * (nt + 1)} | {variant} | {statistics.median(r['wall'] for r in runs):.2f} "
                  f"| {min(r['wall'] for r in runs):.2f} | {statistics.median(r['fact_ms'] for r in runs):.1f} "
                  f"| {max(r['rss_mb'] for r in runs):.0f} | {'yes' if identical else 'no'} ({len(runs)} runs) |")
    print(f"load average at the end: {os.getloadavg()}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
