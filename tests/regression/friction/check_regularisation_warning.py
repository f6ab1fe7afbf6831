#!/usr/bin/python3
"""check_regularisation_warning.py --interface NAME --expect warn|clean|penetration --exit N --history CSV
                                   [--elastic-slip S] -- COMMAND...

Issue 21, point 3: the run says when the penalty regularisation spoils the answer. Runs COMMAND (a contessa
run that writes CSV) and checks
- its exit status is N;
- with --expect warn, stderr holds exactly one "contessa: warning: contact interface 'NAME': the elastic
  slip ..." line naming the deck parameter Problem/Contact/NAME/Slip Tolerance; with --expect clean, no
  "contessa: warning:" line at all;
- the history's last row agrees with that verdict: max_elastic_slip_NAME > 0.1 * mean_slip_NAME exactly
  when a warning is expected (the criterion of docs/theory-contact.md §14), and no penetration warning
  unless max_penetration_NAME exceeds a tenth of the slave displacements (not measured here: it must stay
  silent);
- with --expect penetration, stderr holds exactly one "contessa: warning: contact interface 'NAME': the
  penetration P exceeds a tenth of the largest slave displacement ..." line naming Problem/Contact/NAME/Normal
  Penalty, and P is the history's last max_penetration_NAME (3 digits);
- with --elastic-slip S, the largest elastic slip of every increment with a slipping node is S (relative
  1e-9): a slipping node's elastic slip is Slip Tolerance x L exactly (theory-contact.md §5.1).
"""
import argparse
import csv
import re
import subprocess
import sys

parser = argparse.ArgumentParser()
parser.add_argument("--interface", required=True)
parser.add_argument("--expect", choices=["warn", "clean", "penetration"], required=True)
parser.add_argument("--exit", type=int, default=0)
parser.add_argument("--history", required=True)
parser.add_argument("--elastic-slip", type=float)
parser.add_argument("command", nargs=argparse.REMAINDER)
args = parser.parse_args()
command = args.command[1:] if args.command and args.command[0] == "--" else args.command

run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
failures = []
if run.returncode != args.exit:
    failures.append(f"exit status {run.returncode}, expected {args.exit}")
warnings = [l for l in run.stderr.splitlines() if l.startswith("contessa: warning:")]
name = args.interface
if args.expect == "clean" and warnings:
    failures.append(f"unexpected warnings: {warnings}")
if args.expect == "warn":
    pattern = (rf"^contessa: warning: contact interface '{re.escape(name)}': the elastic slip \S+ exceeds a tenth "
               rf"of the mean slip \S+ of its \d+ slipping nodes at step \d+ .*lower Problem/Contact/{re.escape(name)}/Slip Tolerance$")
    if len(warnings) != 1 or not re.match(pattern, warnings[0]):
        failures.append(f"expected one elastic-slip warning for '{name}', got {warnings}")

rows = list(csv.DictReader(open(args.history)))
last = rows[-1]
if args.expect == "penetration":
    pattern = (rf"^contessa: warning: contact interface '{re.escape(name)}': the penetration (\S+) exceeds a tenth of "
               rf"the largest slave displacement \S+ at step \d+ .*raise Problem/Contact/{re.escape(name)}/Normal Penalty$")
    match = re.match(pattern, warnings[0]) if len(warnings) == 1 else None
    if not match:
        failures.append(f"expected one penetration warning for '{name}', got {warnings}")
    elif abs(float(match.group(1)) / float(last[f"max_penetration_{name}"]) - 1) > 1e-2:
        failures.append(f"warning's penetration {match.group(1)} is not the history's {last[f'max_penetration_{name}']}")
    print(f"penetration {last[f'max_penetration_{name}']}; warnings: {warnings}")
    if failures:
        print("FAIL:\n  " + "\n  ".join(failures))
        sys.exit(1)
    print("ok")
    sys.exit(0)
elastic, mean = float(last[f"max_elastic_slip_{name}"]), float(last[f"mean_slip_{name}"])
slipping = int(float(last["slip"]))
spoils = slipping > 0 and elastic > 0.1 * mean
print(f"last step {last['step']}: elastic slip {elastic:.4g}, mean slip of {slipping} slipping nodes {mean:.4g}, "
      f"ratio {elastic / mean if mean else float('nan'):.3f}; warnings: {warnings}")
if spoils != (args.expect == "warn"):
    failures.append(f"history's last row says spoils={spoils}, expected {args.expect}")
if args.elastic_slip is not None:
    for r in rows:
        if int(float(r["slip"])) > 0:
            got = float(r[f"max_elastic_slip_{name}"])
            if abs(got - args.elastic_slip) > 1e-9 * args.elastic_slip:
                failures.append(f"step {r['step']}: largest elastic slip {got}, expected {args.elastic_slip}")
if failures:
    print("FAIL:\n  " + "\n  ".join(failures))
    print("stderr:\n" + run.stderr)
    sys.exit(1)
print("ok")
