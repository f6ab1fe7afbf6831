#!/usr/bin/python3
"""second_run.py CONTESSA DECK OUTDIR -- COMMAND [ARGS...]

One run per output: while a first run of DECK writes into OUTDIR (400 small increments, a few
seconds), COMMAND (a second run into the same directory, on any number of ranks) is run, the first
one being paused meanwhile (SIGSTOP, then SIGCONT) so that it is still running. This script passes COMMAND's stdout, stderr and exit status through (run_expect.sh asserts them: exit 2 and
one line naming the directory), after checking that the first run was not disturbed: it finishes
(exit 0), reaches load factor 1, and its Exodus file and history agree step for step. When the first
run is disturbed, or ends before COMMAND starts, the exit status is 99 and the reason is on stderr."""
import os
import signal
import subprocess
import sys
import time

from output_files import check_results, fresh_directory, history_rows, rows_written, small_steps

separator = sys.argv.index("--")
contessa, deck, outdir = sys.argv[1:separator]
command = sys.argv[separator + 1:]
name = os.path.splitext(os.path.basename(deck))[0]
exo, history = f"{outdir}/{name}.exo", f"{outdir}/{name}.history.csv"


def fail(reason):
    print(f"second_run.py: {reason}")  # run_expect.sh shows the end of stdout when a test fails
    print(f"second_run.py: {reason}", file=sys.stderr)
    sys.exit(99)


fresh_directory(outdir)
first = subprocess.Popen([contessa, deck, "--quiet", "--output-dir", outdir] + small_steps(400),
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
deadline = time.time() + 60
while rows_written(history) < 3 and first.poll() is None and time.time() < deadline:
    time.sleep(0.01)
if first.poll() is not None or not os.path.exists(f"{outdir}/{name}.lock"):
    fail(f"the first run ended (status {first.poll()}) or holds no lock before the second started")

# The first run is paused while the second one runs (however long MPI takes to start it), so that
# the second one certainly meets a run in progress; the lock is held all the while.
first.send_signal(signal.SIGSTOP)
try:
    second = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=120)
finally:
    first.send_signal(signal.SIGCONT)
during = first.poll() is None
first_stderr = first.communicate(timeout=120)[1]
sys.stdout.write(second.stdout)
sys.stderr.write(second.stderr)
if not during:
    fail("the first run had ended when the second one did: the test proves nothing")
if first.returncode != 0:
    fail(f"the first run exited with {first.returncode}: {first_stderr.strip()}")
problems, _ = check_results(exo, history)
if problems:
    fail("; ".join(problems))
if float(history_rows(history)[-1]["lambda"]) != 1.0:
    fail("the first run did not reach load factor 1")
if os.path.exists(f"{outdir}/{name}.lock"):
    fail("the first run left its lock file behind")
sys.exit(second.returncode)
