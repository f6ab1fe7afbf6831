#!/usr/bin/python3
"""reader_during_run.py CONTESSA DECK OUTDIR

Looking at the results does not stop the job: this script opens `<name>.exo` with netCDF4 (HDF5's
default file locking on, as ParaView has it) while the run writes it, holds it open for the rest of
the run, and meanwhile has another process open it again and again. The run must finish (exit 0),
every reader must open the file and see the steps grow, and the final file must agree with the
history (output_files.py). HDF5 has no consistent view of a file while a writer flushes it: an open
that lands in the middle of a step's flush may fail, and opening again works (docs/user-guide.md);
each look may therefore take up to 5 attempts, and the retries are printed."""
import argparse
import os
import signal
import subprocess
import sys
import time

import netCDF4

from output_files import check_results, fresh_directory, history_rows, rows_written, small_steps

parser = argparse.ArgumentParser()
parser.add_argument("contessa")
parser.add_argument("deck")
parser.add_argument("outdir")
args = parser.parse_args()
name = os.path.splitext(os.path.basename(args.deck))[0]
exo, history = f"{args.outdir}/{name}.exo", f"{args.outdir}/{name}.history.csv"
os.environ.pop("HDF5_USE_FILE_LOCKING", None)  # the readers use HDF5's default: locking on

fresh_directory(args.outdir)
run = subprocess.Popen([args.contessa, args.deck, "--quiet", "--output-dir", args.outdir] + small_steps(400),
                       stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
problems = []
deadline = time.time() + 60
while rows_written(history) < 5 and run.poll() is None and time.time() < deadline:
    time.sleep(0.01)

# Another process looks again and again, as a user reloading in ParaView: it opens the file, counts
# the steps and closes it, until its stdin closes. An open that fails is repeated (up to 5 times).
LOOKER = """
import netCDF4, select, sys, time
while not select.select([sys.stdin], [], [], 0)[0]:
    for attempt in range(5):
        try:
            d = netCDF4.Dataset(sys.argv[1])
            print(len(d.variables["time_whole"]), attempt, flush=True)
            d.close()
            break
        except OSError as e:
            time.sleep(0.02)
    else:
        print("FAILED", e, flush=True)
    time.sleep(0.05)
"""
def open_held(path):
    for attempt in range(5):
        try:
            return netCDF4.Dataset(path), attempt
        except OSError:
            time.sleep(0.05)
    return None, 5


# The run is paused (SIGSTOP) while a reader opens the file, as a ParaView user opens it between two
# steps; it then writes on while the file is held open and looked at again and again. Pausing makes
# the test independent of how fast the run is: the second look is taken at least 50 steps later.
os.kill(run.pid, signal.SIGSTOP)
held, retries = open_held(exo)  # held open until the run ends
if held is None:
    problems.append(f"this process could not open {exo} in 5 attempts")
else:
    print(f"holding {exo} open at step {len(held.variables['time_whole'])}")
looker = subprocess.Popen([sys.executable, "-c", LOOKER, exo], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
lines = [looker.stdout.readline()]  # the first look, while the run is paused
first_rows = rows_written(history)
os.kill(run.pid, signal.SIGCONT)
while rows_written(history) < first_rows + 50 and run.poll() is None and time.time() < deadline + 60:
    time.sleep(0.01)
if run.poll() is None:  # a look at least 50 steps later, the run paused again
    os.kill(run.pid, signal.SIGSTOP)
    while len(lines) < 200:
        lines.append(looker.stdout.readline())
        if lines[-1].startswith("FAILED") or int(lines[-1].split()[0]) > first_rows + 49:
            break
    os.kill(run.pid, signal.SIGCONT)
run.wait()
looker.stdin.close()
counts = []
for line in lines + list(looker.stdout):
    if line.startswith("FAILED"):
        problems.append(f"a reader could not open {exo} in 5 attempts: {line.strip()}")
    elif line.strip():
        count, attempts = map(int, line.split())
        counts.append(count)
        retries += attempts
looker.wait()
stderr = run.communicate()[1]
if held is not None:
    held.close()
print(f"{len(counts)} looks during the run saw {counts[:1]} .. {counts[-1:]} steps ({retries} opens repeated)")
if run.returncode != 0:
    problems.append(f"the run exited with {run.returncode} while a reader held the file: {stderr.strip()}")
if len(counts) < 2 or counts[-1] <= counts[0]:
    problems.append(f"the readers did not see the steps grow ({counts})")
file_problems, _ = check_results(exo, history)
problems += file_problems
if not file_problems and float(history_rows(history)[-1]["lambda"]) != 1.0:
    problems.append(f"{history}: the run did not reach load factor 1")
for p in problems:
    print("FAIL:", p)
sys.exit(1 if problems else 0)
