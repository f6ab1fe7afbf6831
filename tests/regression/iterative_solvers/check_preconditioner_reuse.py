#!/usr/bin/python3
"""check_preconditioner_reuse.py SUMMARY.json [--min-reused N] [--min-restarts N] [--max-restarts N]

MueLu's set-up reused (solvers/PreconditionerReuse.hpp): the run's summary counts at least N Jacobians
that kept the hierarchy, re-set-up (preconditioner_reused_setups) or kept as it was because their values
were those of the last set-up (preconditioner_unchanged_setups); default 1; none that MueLu refused
(preconditioner_refused_reuses: the reuse decision is taken before MueLu runs, on every rank alike), and,
with --min-restarts, at least N hierarchies started over because an entry that was zero at the set-up
(a contact coupling reserved in the graph) is nonzero now (preconditioner_pattern_restarts), and with
--max-restarts at most N (a row whose values changed before has its zeros in MueLu's product patterns:
its fill-in keeps the hierarchy)."""
import json
import sys

path = sys.argv[1]
args = sys.argv[2:]
min_reused = int(args[args.index("--min-reused") + 1]) if "--min-reused" in args else 1
min_restarts = int(args[args.index("--min-restarts") + 1]) if "--min-restarts" in args else 0
max_restarts = int(args[args.index("--max-restarts") + 1]) if "--max-restarts" in args else None
s = json.load(open(path))
failures = []
kept = s["preconditioner_reused_setups"] + s["preconditioner_unchanged_setups"]
if kept < min_reused:
    failures.append(f"{kept} Jacobians kept the hierarchy, expected at least {min_reused}")
if s["preconditioner_refused_reuses"] != 0:
    failures.append(f"{s['preconditioner_refused_reuses']} re-set-ups refused by MueLu, expected none")
if s["preconditioner_pattern_restarts"] < min_restarts:
    failures.append(f"{s['preconditioner_pattern_restarts']} restarts on a filled-in entry, expected at least {min_restarts}")
if max_restarts is not None and s["preconditioner_pattern_restarts"] > max_restarts:
    failures.append(f"{s['preconditioner_pattern_restarts']} restarts on a filled-in entry, expected at most {max_restarts}")
for f in failures:
    print("FAIL:", f)
print(f"{path}: reused {s['preconditioner_reused_setups']}, unchanged {s['preconditioner_unchanged_setups']}, new graph {s['preconditioner_new_graph_setups']}, "
      f"filled-in entries {s['preconditioner_pattern_restarts']}, coarse zeros {s['preconditioner_coarse_zero_restarts']}, "
      f"refused {s['preconditioner_refused_reuses']}; {s['ranks']} rank(s)")
sys.exit(1 if failures else 0)
