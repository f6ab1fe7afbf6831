#!/usr/bin/python3
"""kill_during_run.py CONTESSA DECK OUTDIR [--kills N]

A run killed with SIGKILL at any moment leaves valid output: the Exodus file opens, and every
increment of the history CSV is in it, readable, with the same load factor (output_files.py). The
run is killed N times, each after a different number of increments (random moments within them);
the uniaxial deck with 400 small increments keeps the output busy, so kills often land in a write.
The killed run leaves its lock file behind: a new run into the same directory must take it over."""
import argparse
import os
import random
import signal
import subprocess
import sys
import time

from output_files import check_results, fresh_directory, rows_written, small_steps

parser = argparse.ArgumentParser()
parser.add_argument("contessa")
parser.add_argument("deck")
parser.add_argument("outdir")
parser.add_argument("--kills", type=int, default=4)
args = parser.parse_args()
name = os.path.splitext(os.path.basename(args.deck))[0]
exo, history = f"{args.outdir}/{name}.exo", f"{args.outdir}/{name}.history.csv"

failed = False
rng = random.Random()
for k in range(args.kills):
    fresh_directory(args.outdir)
    run = subprocess.Popen([args.contessa, args.deck, "--quiet", "--output-dir", args.outdir] + small_steps(400),
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    # Wait for some increments (a different number each time), then a random fraction of one more.
    target = 10 + k * 80 + rng.randrange(40)
    deadline = time.time() + 60
    while time.time() < deadline and run.poll() is None:
        if rows_written(history) >= target:
            break
        time.sleep(0.002)
    time.sleep(rng.uniform(0.0, 0.02))
    if run.poll() is not None:
        print(f"FAIL: the run ended (status {run.returncode}) before it could be killed")
        failed = True
        continue
    os.kill(run.pid, signal.SIGKILL)
    run.wait()
    problems, notes = check_results(exo, history, allow_in_flight=True)
    rows = rows_written(history)
    print(f"kill {k + 1}: after {rows} history rows; " + ("; ".join(problems + notes) or "files agree"))
    failed |= bool(problems)

# The lock file of the last killed run is still there (nobody removed it); its holder is dead, so the
# next run takes the output over and finishes.
lock = f"{args.outdir}/{name}.lock"
if not os.path.exists(lock):
    print(f"FAIL: the killed run left no {lock}: the takeover below is not tested")
    failed = True
again = subprocess.run([args.contessa, args.deck, "--quiet", "--output-dir", args.outdir],
                       stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
print(f"run after the kills: exit {again.returncode} {again.stderr.strip()}")
if again.returncode != 0 or again.stderr:
    print("FAIL: a run into the directory of a killed run did not finish cleanly")
    failed = True
problems, _ = check_results(exo, history)
for p in problems:
    print("FAIL:", p)
failed |= bool(problems)
sys.exit(1 if failed else 0)
