#!/usr/bin/python3
"""MueLu's set-up reused across Newton iterations and increments (solvers/PreconditionerReuse.hpp).

    /usr/bin/python3 bench/muelu_reuse_bench.py [--punch 12 20] [--reuse none tP RP] [--repeat 3] [--ranks 1]

Runs inputs/punch_3d.xml (Belos GMRES + MueLu, N x N x N/2 Hex8, two increments) with each MueLu
"reuse: type" in turn, the variants interleaved over --repeat rounds so that a change of the machine's
load hits them alike, and the sliding block of tests/regression/contact_graph (Search Reach 0: five
rebuilds of the matrix graph, 23 increments) with --sliding, on --ranks ranks. Prints per variant the
median CPU seconds (user + system, /usr/bin/time), the Newton and Krylov iterations, the set-ups reused
(under "none" MueLu turns every re-set-up the wrapper asks for into a full set-up: they are printed as
"0 (N full)"), those skipped because the Jacobian's values were those of the last set-up, those started
over on a new graph, on an entry that filled in since the set-up and on exact zeros of a coarse matrix
(two or more ranks), and those MueLu refused to redo (then started over), and the plate or punch force of
the last history row against the variant "none" (a fresh hierarchy for every Jacobian, Contessa's
behaviour before the reuse).
"""
import csv
import json
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from speed_bench import ROOT, print_host, punch_arguments, run  # noqa: E402

MUELU = "Piro/Stratimikos/Preconditioner Types/MueLu"
SLIDING = ["Problem/Contact/strip/Search Reach=0", "Piro/LOCA/Step Size/Initial Step Size=0.05",
           "Piro/LOCA/Step Size/Max Step Size=0.05", "Piro/Stratimikos/Linear Solver Type=Belos",
           "Piro/Stratimikos/Preconditioner Type=MueLu", f"{MUELU}/coarse: max size=100"]


def cases(a):
    out = []
    for n in a.punch:
        mesh = [f"Problem/Mesh/Elements X={n}", f"Problem/Mesh/Elements Y={n}", f"Problem/Mesh/Elements Z={max(n // 2, 1)}"]
        out.append((f"punch {n}x{n}x{max(n // 2, 1)} ({3 * (n + 1) ** 2 * (max(n // 2, 1) + 1)} unknowns)",
                    os.path.join(ROOT, "inputs", "punch_3d.xml"), "punch_3d", mesh))
    if a.sliding:
        out.append(("sliding block, 5 graph rebuilds", os.path.join(ROOT, "tests", "regression", "contact_graph",
                                                                     "sliding_block.xml"), "sliding_block", SLIDING))
    return out


def last_force(history):
    rows = list(csv.DictReader(open(history)))
    forces = [k for k in rows[-1] if k.startswith("contact_force") or k.startswith("reaction")]
    return {k: float(rows[-1][k]) for k in forces}


def main():
    p = punch_arguments(__doc__, [12, 20], 3, "/tmp/contessa-muelu-reuse-bench", 1800)
    p.add_argument("--sliding", action="store_true", help="also the sliding block (graph rebuilds)")
    p.add_argument("--reuse", nargs="+", default=["none", "tP", "RP"])
    p.add_argument("--ranks", type=int, default=1)
    a = p.parse_args()
    print_host()
    results = {}
    for rep in range(a.repeat):
        for label, deck, stem, sets in cases(a):
            for reuse in a.reuse:
                out = os.path.join(a.work, f"{stem}_{reuse}")
                cmd = ([] if a.ranks == 1 else ["mpiexec", "--oversubscribe"] + (["--allow-run-as-root"] if os.geteuid() == 0 else []) + ["-n", str(a.ranks)]) + [a.contessa, deck, "--quiet", "--output-dir", out]
                for s in sets + [f"{MUELU}/reuse: type={reuse}"]:
                    cmd += ["--set", s]
                r = run(cmd, out, a.timeout, accept=(0, 1, 3))
                summary = json.load(open(os.path.join(out, stem + ".summary.json")))
                r["summary"] = summary
                r["forces"] = last_force(os.path.join(out, stem + ".history.csv"))
                results.setdefault((label, reuse), []).append(r)
            print(f"[{rep + 1}/{a.repeat}] {label} done", file=sys.stderr, flush=True)
    print(f"{a.ranks} rank(s); CPU = user + system seconds, median of {a.repeat} interleaved runs\n")
    print("| case | reuse: type | CPU s | min–max | vs none | Newton it. | Krylov it. | reused set-ups | unchanged, skipped | "
          "new-graph set-ups | filled-in restarts | coarse-zero restarts | refused reuses | "
          "largest force difference to none (relative) |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for label, _, _, _ in cases(a):
        base = statistics.median(r["cpu"] for r in results[(label, a.reuse[0])])
        ref = results[(label, a.reuse[0])][-1]["forces"]
        scale = max(abs(v) for v in ref.values()) or 1.0
        for reuse in a.reuse:
            rs = results[(label, reuse)]
            cpu = [r["cpu"] for r in rs]
            s = rs[-1]["summary"]
            diff = max(abs(rs[-1]["forces"][k] - ref[k]) for k in ref) / scale
            flag = "" if s["finished"] else " (did not finish)"
            reused = s.get("preconditioner_reused_setups", "–")
            if reuse == "none" and reused != "–":
                reused = f"0 ({reused} full)"  # the wrapper's re-set-ups, each a full set-up under "none"
            print(f"| {label}{flag} | {reuse} | {statistics.median(cpu):.2f} | {min(cpu):.2f}–{max(cpu):.2f} | "
                  f"{statistics.median(cpu) / base:.2f} | {s['newton_iterations']} | {s['linear_iterations']} | "
                  f"{reused} | {s.get('preconditioner_unchanged_setups', '–')} | {s['preconditioner_new_graph_setups']} | "
                  f"{s.get('preconditioner_pattern_restarts', '–')} | {s.get('preconditioner_coarse_zero_restarts', '–')} | "
                  f"{s['preconditioner_refused_reuses']} | {diff:.1e} |")


if __name__ == "__main__":
    main()
