#!/usr/bin/python3
"""nothing_left.py OUTDIR NAME [--full-disk] -- COMMAND [ARGS...]

A run that fails before its first output step leaves no results file, and leaves the files of an
earlier run alone: OUTDIR is emptied and an earlier run's NAME.exo and NAME.history.csv are put there
(text, not results: only their bytes are compared), COMMAND (a contessa run writing NAME.* into
OUTDIR, on any number of ranks) is run, its stdout, stderr and exit status are passed through
(run_expect.sh asserts them), and OUTDIR must then hold exactly the earlier files, unchanged: no
NAME.exo of the failed run (not even empty), no piece NAME.exo.N.r, no history, no lock.
With --full-disk, OUTDIR is a 256 KiB tmpfs filled up to 16 KiB, less than the results file's mesh
needs (exit status 77, skipped, when this process may not mount one). Exit status 99 with the reason
on stderr when something is left or changed."""
import os
import shutil
import subprocess
import sys

separator = sys.argv.index("--")
options = sys.argv[1:separator]
command = sys.argv[separator + 1:]
full_disk = "--full-disk" in options
outdir, name = [o for o in options if o != "--full-disk"]

if full_disk:
    subprocess.run(["umount", outdir], stderr=subprocess.DEVNULL)  # left by an interrupted test
shutil.rmtree(outdir, ignore_errors=True)
os.makedirs(outdir)
if full_disk:
    mount = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=256k", "tmpfs", outdir],
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if mount.returncode != 0:
        print(f"cannot mount a tmpfs on {outdir}: {mount.stdout.strip()}")
        sys.exit(77)

earlier = {f"{name}.exo": b"the results of an earlier run\n" * 100,
           f"{name}.history.csv": b"step,lambda\n0,0\n1,0.5\n"}
for file, content in earlier.items():
    with open(os.path.join(outdir, file), "wb") as f:
        f.write(content)
problem = None
try:
    if full_disk:
        # Fill the file system, then free 16 KiB: the lock file fits, the results file's mesh does not.
        filler = os.path.join(outdir, "filler")
        fd = os.open(filler, os.O_WRONLY | os.O_CREAT | os.O_TRUNC)
        try:
            while os.write(fd, b"\0" * 4096) > 0:
                pass
        except OSError:
            pass
        os.close(fd)
        os.truncate(filler, max(0, os.path.getsize(filler) - 16 * 1024))
        earlier["filler"] = None
    try:
        run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=120)
    except subprocess.TimeoutExpired:
        problem = "the run did not end within 120 s (a deadlock?)"
    else:
        sys.stdout.write(run.stdout)
        sys.stderr.write(run.stderr)
        left = sorted(set(os.listdir(outdir)) - set(earlier))
        changed = [f for f, content in earlier.items()
                   if content is not None and (not os.path.exists(os.path.join(outdir, f))
                                               or open(os.path.join(outdir, f), "rb").read() != content)]
        if left:
            problem = "the failed run left " + ", ".join(
                f"{f} ({os.path.getsize(os.path.join(outdir, f))} bytes)" for f in left)
        if changed:
            problem = (problem + "; " if problem else "") + "the earlier run's " + ", ".join(changed) + " changed or gone"
        print(f"nothing_left.py: {problem or 'nothing left, the earlier files unchanged'}")
finally:
    if full_disk:
        subprocess.run(["umount", "-l", outdir])
if problem:
    print(f"nothing_left.py: {problem}", file=sys.stderr)
    sys.exit(99)
sys.exit(run.returncode)
