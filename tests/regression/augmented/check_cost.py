#!/usr/bin/python3
"""check_cost.py AUGMENTED_SUMMARY PENALTY_SUMMARY --at-most R

Issue 21's cost target (docs/theory-contact.md §15, docs/verification-contact.md §12): the Newton iterations
of every attempt of an augmented Lagrangian run (its <name>.summary.json) at most R times those of the
penalty law's run of the same deck. Prints both counts and the ratio; exit 1 above R, or when a run did
not finish."""
import json
import sys

args = sys.argv[1:]
if len(args) != 4 or args[2] != "--at-most":
    sys.exit(__doc__.split("\n")[0])
runs = [json.load(open(path)) for path in args[:2]]
bound = float(args[3])
for path, run in zip(args[:2], runs):
    if not run.get("finished") or run.get("final_load_factor") != 1:
        sys.exit(f"{path}: the run did not reach its final load")
augmented, penalty = (run["newton_iterations"] for run in runs)
ratio = augmented / penalty
print(f"Newton iterations: augmented {augmented}, penalty {penalty}, ratio {ratio:.3f} (at most {bound:g})")
if ratio > bound:
    sys.exit(f"the augmented Lagrangian takes {ratio:.3f} times the penalty law's Newton iterations, more than {bound:g}")
