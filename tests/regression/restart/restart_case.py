#!/usr/bin/python3
"""restart_case.py --stop HOW --out DIR --name NAME [--expect-stop STATUS] -- COMMAND...

Interrupts a run and continues it with --restart (docs/user-guide.md, "Checkpoint and restart"): COMMAND
(contessa or mpiexec ... contessa, with the deck and its options, without --output-dir) runs into DIR, is
stopped as HOW says, and runs again with --restart DIR/NAME.restart. HOW is one of
  steps:N:M       Every N Increments = N and Max Steps = M: the run stops (status 1) after M attempts, its
                  restart file is of the last multiple of N, and the files hold increments past it;
  signal:SIG:K    the signal (TERM, USR1, INT) goes to COMMAND's process (contessa, or mpiexec which
                  forwards it) once the progress table shows increment K: status 4;
  walltime:S      Max Wall Time = S seconds: status 4.
Prints the step the restart file holds and its size; exits non-zero when a status is not the expected
one or the restart file is missing. The comparison with the uninterrupted run is compare_restart.py's."""
import argparse
import os
import re
import shlex
import shutil
import signal
import subprocess
import sys

parser = argparse.ArgumentParser()
parser.add_argument("--stop", required=True)
parser.add_argument("--out", required=True)
parser.add_argument("--name", required=True)
parser.add_argument("--restart-status", type=int, default=0, help="exit status of the continued run")
parser.add_argument("--launcher", default="", help="the continued run starts with this (e.g. 'mpiexec -n 2'): "
                    "another rank count than the interrupted run's")
parser.add_argument("--full", help="the uninterrupted run's output directory: compare_restart.py compares")
parser.add_argument("--compare-options", default="", help="options for compare_restart.py, e.g. '--rtol 1e-12'")
parser.add_argument("command", nargs=argparse.REMAINDER)
args = parser.parse_args()
command = args.command[1:] if args.command and args.command[0] == "--" else args.command
shutil.rmtree(args.out, ignore_errors=True)
os.makedirs(args.out)
restart_file = f"{args.out}/{args.name}.restart"
first = command + ["--output-dir", args.out]

how = args.stop.split(":")
if how[0] == "steps":
    first += ["--set", f"Problem/Output/Checkpoint/Every N Increments={how[1]}",
              "--set", f"Piro/LOCA/Stepper/Max Steps={how[2]}"]
    status = subprocess.run(first, stdout=subprocess.DEVNULL).returncode
    expected = 1
elif how[0] == "signal":
    sig = getattr(signal, "SIG" + how[1])
    target = int(how[2])
    process = subprocess.Popen(first, stdout=subprocess.PIPE, text=True)
    sent = False
    for line in process.stdout:
        fields = line.split()
        if not sent and fields and fields[0].isdigit() and int(fields[0]) >= target:
            process.send_signal(sig)  # our own child, by its id
            sent = True
    status = process.wait()
    expected = 4
    if not sent:
        sys.exit(f"FAIL: the run ended (status {status}) before increment {target}")
elif how[0] == "walltime":
    first += ["--set", f"Problem/Output/Checkpoint/Max Wall Time={how[1]}"]
    status = subprocess.run(first, stdout=subprocess.DEVNULL).returncode
    expected = 4
else:
    sys.exit(f"unknown --stop {args.stop}")
if status != expected:
    sys.exit(f"FAIL: the interrupted run exited with {status}, expected {expected}")
if not os.path.isfile(restart_file):
    sys.exit(f"FAIL: no restart file {restart_file}")
rows = sum(1 for _ in open(f"{args.out}/{args.name}.history.csv")) - 1
size = os.path.getsize(restart_file)

# With its progress table (no --quiet): its first increment tells the restart file's step.
second = shlex.split(args.launcher) + [a for a in command if a != "--quiet"] + ["--output-dir", args.out, "--restart",
                                                                             restart_file]
continued = subprocess.run(second, stdout=subprocess.PIPE, text=True)
if continued.returncode != args.restart_status:
    sys.exit(f"FAIL: the continued run exited with {continued.returncode}, expected {args.restart_status}")
# The continued run's first increment in the progress table is the restart file's step + 1.
first_step = next((int(l.split()[0]) for l in continued.stdout.splitlines() if l.split() and l.split()[0].isdigit()), 0)
print(f"stopped ({args.stop}) with {rows - 1} increments in the files; restart file: step {first_step - 1}, "
      f"{size} bytes; continued run: status {continued.returncode}")
if args.full:
    compare = [sys.executable, os.path.join(os.path.dirname(os.path.abspath(__file__)), "compare_restart.py"),
               args.full, args.out, args.name] + shlex.split(args.compare_options)
    sys.exit(subprocess.run(compare).returncode)
