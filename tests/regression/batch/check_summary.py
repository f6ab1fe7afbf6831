#!/usr/bin/python3
"""check_summary.py RANKS EXPECTED_STATUS OUTDIR DECK -- COMMAND...

Runs COMMAND (a contessa run writing into OUTDIR) and checks the run's summary (docs/user-guide.md,
"Batch runs"): the log line `contessa: summary: ...` on stdout and `<name>.summary.json` beside the
history agree with each other and with the history: increments, Newton iterations, linear iterations
(at least those of the history's converged solves), the exit status, and one memory high-water mark per
rank, each plausible (more than the 20 MiB any MPI process needs, less than the machine's memory); and the
mesh parts: every element in exactly one rank's part, and on several ranks no rank holding the whole mesh."""
import csv
import json
import os
import re
import subprocess
import sys

ranks, expected_status, outdir, deck = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3], sys.argv[4]
command = sys.argv[sys.argv.index("--") + 1:]
name = os.path.splitext(os.path.basename(deck))[0]
summary_path = os.path.join(outdir, f"{name}.summary.json")
if os.path.exists(summary_path):
    os.remove(summary_path)
run = subprocess.run(command, capture_output=True, text=True, timeout=300)
problems = []


def check(ok, what):
    if not ok:
        problems.append(what)


check(run.returncode == expected_status, f"exit status {run.returncode}, expected {expected_status}: {run.stderr.strip()}")
check(os.path.exists(summary_path), f"no {summary_path}")
if not problems:
    s = json.load(open(summary_path))
    rows = list(csv.DictReader(open(os.path.join(outdir, f"{name}.history.csv"))))
    increments = len(rows) - 1
    newton = sum(int(r["newton_iterations"]) for r in rows)
    linear = sum(int(r["linear_iterations"]) for r in rows)
    check(s["ranks"] == ranks, f"ranks {s['ranks']}, expected {ranks}")
    check(s["exit_status"] == expected_status, f"exit_status {s['exit_status']}, expected {expected_status}")
    check(s["finished"] == (expected_status in (0, 3)), f"finished {s['finished']} with exit status {expected_status}")
    check(s["finished"] or s["stop_reason"] != "", "a stopped run without a stop_reason")
    check(s["increments"] == increments, f"increments {s['increments']}, the history has {increments}")
    # The history counts the converged solve of each increment; the summary every solve (failed
    # attempts too), so it is at least as large.
    check(s["newton_iterations"] >= newton, f"newton_iterations {s['newton_iterations']} < {newton} in the history")
    check(s["linear_iterations"] >= linear, f"linear_iterations {s['linear_iterations']} < {linear} in the history")
    check(s["wall_seconds"] > 0, f"wall_seconds {s['wall_seconds']}")
    # A new run: this job is the whole run (a continued one: tests/regression/batch/slurm_batch.py).
    job, whole = s["this_job"], s["whole_run"]
    check(job == {"first_step": 1, "increments": s["increments"], "newton_iterations": s["newton_iterations"],
                  "wall_seconds": s["wall_seconds"]}, f"this_job {job} of a new run")
    check(whole == {"continued": False, "increments": s["increments"], "newton_iterations": s["newton_iterations"],
                    "wall_seconds": s["wall_seconds"]}, f"whole_run {whole} of a new run")
    memory = s["peak_memory_bytes"]
    per_rank = memory["per_rank"]
    total = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    check(len(per_rank) == ranks, f"{len(per_rank)} memory figures for {ranks} ranks")
    check(all(20 * 2**20 < m < total for m in per_rank), f"implausible peak memory per rank: {per_rank}")
    check(memory["min"] == min(per_rank) and memory["max"] == max(per_rank), f"min/max {memory} disagree with per_rank")
    # The mesh in parts (issue 11): each element in one part; on several ranks no part is the whole mesh.
    mesh = s["mesh"]
    for key in ("part_elements", "part_nodes", "part_bytes"):
        check(len(mesh[key]) == ranks, f"{len(mesh[key])} {key} for {ranks} ranks")
    check(sum(mesh["part_elements"]) == mesh["elements"], f"parts hold {mesh['part_elements']} elements of {mesh['elements']}")
    check(all(0 < n <= mesh["nodes"] for n in mesh["part_nodes"]), f"part nodes {mesh['part_nodes']} of {mesh['nodes']}")
    check(all(b > 0 for b in mesh["part_bytes"]), f"part bytes {mesh['part_bytes']}")
    if ranks > 1:
        check(max(mesh["part_elements"]) < mesh["elements"] and max(mesh["part_nodes"]) < mesh["nodes"],
              f"a rank holds the whole mesh: {mesh}")
    # The log line says the same.
    line = [l for l in run.stdout.splitlines() if l.startswith("contessa: summary:")]
    check(len(line) == 1, f"{len(line)} 'contessa: summary:' lines on stdout")
    if line:
        m = re.match(r"contessa: summary: (\d+) increments, (\d+) failed attempts, (\d+) Newton iterations, "
                     r"(\d+) linear iterations, wall ([0-9.e+-]+) s, peak memory per rank ([0-9.e+-]+) to "
                     r"([0-9.e+-]+) MiB \((\d+) rank\(s\)\)$", line[0])
        check(m is not None, f"log line not in the documented form: {line[0]!r}")
        if m:
            check(int(m[1]) == s["increments"] and int(m[3]) == s["newton_iterations"] and
                  int(m[4]) == s["linear_iterations"] and int(m[8]) == ranks, f"log line {line[0]!r} disagrees with {s}")
            check(abs(float(m[6]) - memory["min"] / 2**20) <= 0.01 * float(m[6]) + 0.01 and
                  abs(float(m[7]) - memory["max"] / 2**20) <= 0.01 * float(m[7]) + 0.01,
                  f"log line memory {m[6]}..{m[7]} MiB, file {memory}")
    print(json.dumps(s))
for p in problems:
    print("FAIL:", p)
sys.exit(1 if problems else 0)
