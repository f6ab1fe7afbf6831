#!/usr/bin/python3
"""progress_flushed.py CONTESSA DECK OUTDIR [ARGS...]

A batch log shows each increment as it happens: contessa's progress table goes to a pipe (as under a
scheduler, where stdout is a file or a pipe, never a terminal) and every line must be there as soon as
its increment is done. The check does not depend on timing: the run is frozen (SIGSTOP) three times,
when its history CSV (written with write(2) just before each progress line) reaches increments 7, 61
and 133, and each time everything it wrote to the pipe so far is read; the last increment on stdout
must then be the last row of the history, or the one before it when the run was frozen between the two.
A block-buffered stdout (4 KiB for a pipe, about 50 lines here) would lag behind by up to 50 increments
(checked with a stand-in that buffers: it fails)."""
import csv
import fcntl
import os
import signal
import subprocess
import sys
import time

contessa, deck, outdir = sys.argv[1:4]
extra = sys.argv[4:]
name = os.path.splitext(os.path.basename(deck))[0]
history = os.path.join(outdir, f"{name}.history.csv")
os.makedirs(outdir, exist_ok=True)
for f in (history,):
    if os.path.exists(f):
        os.remove(f)

run = subprocess.Popen([contessa, deck, "--output-dir", outdir] + extra, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
fd = run.stdout.fileno()
text = b""


def last_increment_on_stdout():
    last = None
    for line in text.decode(errors="replace").splitlines():
        fields = line.split()
        if len(fields) >= 9 and fields[0].isdigit():
            last = int(fields[0])
    return last


def last_history_step():
    rows = list(csv.reader(open(history)))
    return int(rows[-1][0]) if len(rows) > 1 else None


def drain():
    """Reads everything the pipe holds now (never blocks)."""
    global text
    while True:
        try:
            chunk = os.read(fd, 65536)
        except BlockingIOError:
            return True
        if not chunk:
            return False  # the run closed its stdout: it has ended
        text += chunk


problems = []
fcntl.fcntl(fd, fcntl.F_SETFL, fcntl.fcntl(fd, fcntl.F_GETFL) | os.O_NONBLOCK)
# The run is frozen when its history reaches an increment (not when stdout shows something: a reader
# woken by stdout would always find a block-buffered stream just flushed). Increments 7, 61 and 133:
# unrelated to any buffer size.
for target in (7, 61, 133):
    running = True
    while running and not ((last_history_step() if os.path.exists(history) else None) or 0) >= target:
        running = drain()
        time.sleep(0.002)
    if not running:
        problems.append(f"the run ended before increment {target}")
        break
    os.kill(run.pid, signal.SIGSTOP)
    drain()  # everything the frozen run wrote
    shown, written = last_increment_on_stdout(), last_history_step()
    print(f"frozen: history up to increment {written}, stdout up to increment {shown}")
    if shown is None or not (written - 1 <= shown <= written):
        problems.append(f"stdout shows increment {shown} while the history has reached increment {written}: "
                        "the progress line is not flushed at once")
    os.kill(run.pid, signal.SIGCONT)

fcntl.fcntl(fd, fcntl.F_SETFL, fcntl.fcntl(fd, fcntl.F_GETFL) & ~os.O_NONBLOCK)
rest, err = run.communicate(timeout=300)
if run.returncode != 0:
    problems.append(f"exit status {run.returncode}: {err.decode(errors='replace').strip()}")
for p in problems:
    print("FAIL:", p)
print("progress lines flushed at once" if not problems else "")
sys.exit(1 if problems else 0)
