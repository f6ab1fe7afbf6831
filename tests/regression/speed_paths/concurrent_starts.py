#!/usr/bin/python3
"""concurrent_starts.py CONTESSA DECK N WORKDIR

Starts N runs of DECK without mpirun, 0.05 s apart, so that runs start while others end (a parameter
sweep of serial jobs on one node). Each must exit 0: Open MPI's isolated singletons share one session
directory unless each has its own (apps/contessa/ProcessEnvironment.cpp), and then a run ending can
remove it under a run starting. TMPDIR is a fresh WORKDIR/tmp, which must be empty afterwards: every
run removes its private session directory."""
import os
import shutil
import subprocess
import sys
import time

contessa, deck, n, work = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
shutil.rmtree(work, ignore_errors=True)
tmp = os.path.join(work, "tmp")
os.makedirs(tmp)
env = dict(os.environ, TMPDIR=tmp)
for k in [k for k in env if k.startswith("OMPI_") or k.startswith("PMIX_")]:
    del env[k]
runs = []
for i in range(n):
    out = os.path.join(work, f"run{i}")
    runs.append(subprocess.Popen([contessa, deck, "--quiet", "--output-dir", out], env=env,
                                 stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True))
    time.sleep(0.05)
failed = []
for i, p in enumerate(runs):
    text, _ = p.communicate(timeout=600)
    if p.returncode != 0:
        failed.append((i, p.returncode, text.strip().splitlines()[:3]))
left = os.listdir(tmp)
print(f"{n} runs, {len(failed)} failed; left in TMPDIR: {left}")
for i, code, lines in failed:
    print(f"FAIL: run {i} exited {code}: {lines}")
if left:
    print(f"FAIL: {len(left)} entries left in {tmp}")
sys.exit(1 if failed or left else 0)
