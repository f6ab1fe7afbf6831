#!/usr/bin/python3
"""full_disk.py MOUNTPOINT DECK -- COMMAND [ARGS...]

A full disk stops the run with one line and exit status 1, on every rank, without a hang, and leaves
the results valid: a tmpfs of 256 KiB is mounted on MOUNTPOINT (about 55 increments of the uniaxial
deck fit), COMMAND (a contessa run, on any number of ranks, writing into MOUNTPOINT) is run with a
time limit, its stdout, stderr and exit status are passed through (run_expect.sh asserts them), and
the files are checked: the Exodus file opens, and the history and the Exodus file hold the same
increments, every one readable (output_files.py). Exit status 77 (skipped) when this process may not
mount a file system (not root, or a container without CAP_SYS_ADMIN); 99 with the reason on stderr
when the files are wrong or the run hangs."""
import os
import subprocess
import sys

from output_files import check_results, history_rows

separator = sys.argv.index("--")
mountpoint, deck = sys.argv[1:separator]
command = sys.argv[separator + 1:]
name = os.path.splitext(os.path.basename(deck))[0]
exo, history = f"{mountpoint}/{name}.exo", f"{mountpoint}/{name}.history.csv"

subprocess.run(["umount", mountpoint], stderr=subprocess.DEVNULL)  # left by an interrupted test
os.makedirs(mountpoint, exist_ok=True)
mount = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=256k", "tmpfs", mountpoint],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
if mount.returncode != 0:
    print(f"cannot mount a tmpfs on {mountpoint}: {mount.stdout.strip()}")
    sys.exit(77)

problem = None
try:
    try:
        run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=120)
    except subprocess.TimeoutExpired as e:
        sys.stderr.write(e.stderr.decode() if e.stderr else "")
        problem = "the run did not end within 120 s (a deadlock?)"
    else:
        sys.stdout.write(run.stdout)
        sys.stderr.write(run.stderr)
        problems, notes = check_results(exo, history)
        rows = len(history_rows(history)) if os.path.exists(history) else 0
        print(f"full_disk.py: the files hold {rows} increments; " + ("; ".join(problems + notes) or "they agree"))
        if problems:
            problem = "; ".join(problems)
        elif rows < 10:
            problem = f"only {rows} increments were written before the disk was full: the test proves little"
finally:
    subprocess.run(["umount", "-l", mountpoint])
if problem:
    print(f"full_disk.py: {problem}", file=sys.stderr)
    sys.exit(99)
sys.exit(run.returncode)
