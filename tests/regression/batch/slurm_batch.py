#!/usr/bin/python3
"""slurm_batch.py CONTESSA SCRIPT DECK WORKDIR [contessa options ...]

The example batch script (SCRIPT, examples/slurm/contessa.sbatch) on a real single-node Slurm started by
this test (slurm_cluster.py): submitted as a user would, with a 1-minute time limit, it must carry the
run through its time limit (the job requeues itself and continues) and through a `scontrol requeue` in
the middle of a run, and end with the history of an uninterrupted 2-rank run.

1. The uninterrupted run: `mpiexec -n 2 CONTESSA DECK options`; its wall time W sets the margin below.
2. Slurm's time limits are whole minutes; for a short test the job keeps most of its minute free:
   `--job-end-margin` (seconds before the job's end at which Contessa stops) is chosen so that a run has
   about a third of W for increments, whatever the machine's speed, hence a time-limit stop after the
   requeue.
3. `sbatch --time=1 SCRIPT DECK options --job-end-margin M` (the sbatch option and the contessa
   options must reach every run of the job); once a run has written a periodic restart file (Every N
   Increments = 2), `scontrol requeue` (Slurm stops the run with SIGTERM and starts the job again: it must continue, not
   start over).
4. Checks: the job completed with exit status 0 after at least 3 runs (the requeue and at least one
   time-limit stop), each later run continued from the restart file (--restart auto), the log kept every
   run (appended) and holds no failure banner for the planned stops, and the history agrees with the
   uninterrupted run's (compare_history.py, COMPARE options below).

Exit status 77 (ctest: skipped) when Slurm or munge is not installed (scripts/install-deps.sh installs
them). Every wait has a timeout; the cluster is stopped on any exit.
"""
import csv
import json
import os
import re
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from slurm_cluster import SlurmCluster, missing_binaries  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
COMPARE = os.path.join(HERE, "..", "compare_history.py")
# MUMPS' Reproducible makes 2-rank runs repeat bit for bit (tests/regression/CMakeLists.txt), and a continued
# run reproduces the uninterrupted one bit for bit (tests/regression/restart): the spread is zero.
COMPARE_OPTIONS = ["--rtol", "0", "--atol", "0"]
JOB_LIMIT_SECONDS = 60  # sbatch --time=1
TIMEOUT = 900           # the whole chain, on a loaded machine


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def main():
    sys.stdout.reconfigure(line_buffering=True)
    if len(sys.argv) < 5:
        sys.exit(__doc__)
    contessa, script, deck, work = (os.path.abspath(a) for a in sys.argv[1:5])
    options = sys.argv[5:]
    missing = missing_binaries()
    if missing:
        print("SKIP: Slurm is not installed (missing: " + ", ".join(missing) + "); scripts/install-deps.sh installs "
              "Debian's slurm-wlm and munge")
        return 77
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    name = os.path.splitext(os.path.basename(deck))[0]

    # 1. The uninterrupted run.
    reference = os.path.join(work, "reference")
    start = time.monotonic()
    mpiexec = ["mpiexec", "-n", "2", "--oversubscribe", "--allow-run-as-root"]
    r = subprocess.run(mpiexec + [contessa, deck, "--quiet", "--output-dir", reference] + options,
                       capture_output=True, text=True, timeout=TIMEOUT)
    wall = time.monotonic() - start
    if r.returncode != 0:
        fail(f"the uninterrupted run ended with status {r.returncode}:\n{r.stdout[-2000:]}{r.stderr[-2000:]}")
    # 2. The margin: a run gets about a third of the run's own wall time W (Contessa's, from reading the
    # deck to the end) for increments, plus what Contessa keeps for the next increment (1.5 x the longest,
    # taken from the uninterrupted run's history); the rest of the minute goes to the job's start (the
    # script, the launcher, MPI, the deck and mesh: measured 2.4-4.9 s under load 11 where the
    # uninterrupted run spent 1.5 s outside its own wall time, hence twice that, plus 0.5 s) and the margin.
    # A longer start leaves less (more runs); a shorter one more, and a run after the requeue (in one of the
    # first runs) must still meet the limit, so the allowance stays close to the measurement.
    run_wall = json.load(open(os.path.join(reference, name + ".summary.json")))["wall_seconds"]
    walls = [float(row["wall_s"]) for row in csv.DictReader(open(os.path.join(reference, name + ".history.csv")))]
    longest = max(b - a for a, b in zip(walls, walls[1:]))
    start_up = 2 * max(0.0, wall - run_wall) + 0.5
    window = run_wall / 3 + 1.5 * longest
    margin = max(10.0, JOB_LIMIT_SECONDS - start_up - window)
    print(f"uninterrupted run: {wall:.1f} s ({run_wall:.1f} s Contessa's own); --job-end-margin {margin:.0f} (about "
          f"{window:.0f} s of each 1-minute job for increments)")

    with SlurmCluster(cpus=2) as cluster:
        # 3. The job, as a user submits it (CONTESSA: the build under test).
        log = os.path.join(work, "job.log")
        out = os.path.join(work, "chain")
        env = {"CONTESSA": contessa, "OUT": out, "MAX_JOBS": "60"}
        job = cluster.sbatch(["--time=1", "--output=" + log, script, deck] + options +
                             ["--job-end-margin", f"{margin:.0f}",
                              "--set", "Problem/Output/Checkpoint/Every N Increments=2"],
                             env=env, cwd=work)
        print(f"submitted job {job}")
        end = time.monotonic() + TIMEOUT
        requeued = False
        fields = {}
        while time.monotonic() < end:
            fields = cluster.job(job)
            state = fields.get("JobState")
            if state in {"COMPLETED", "FAILED", "CANCELLED", "TIMEOUT", "NODE_FAIL", "OUT_OF_MEMORY"}:
                break
            text = open(log, errors="replace").read() if os.path.exists(log) else ""
            # The requeue: once a run has written a periodic restart file (the stop's own write prints
            # no such line), in the middle of that run.
            if not requeued and state == "RUNNING" and "contessa: checkpoint: wrote" in text:
                r = cluster.run(["scontrol", "requeue", job])
                if r.returncode == 0:
                    requeued = True
                    run = len(re.findall(r"^job \d+ \(run \d+ ", text, re.M))
                    print(f"requeued job {job} in the middle of its run {run} ({time.monotonic() - start:.0f} s)")
            time.sleep(0.3)
        else:
            fail(f"job {job} not done after {TIMEOUT} s (state {fields.get('JobState')}); log:\n" +
                 (open(log).read()[-3000:] if os.path.exists(log) else "(none)") + cluster.daemon_logs())
        text = open(log, errors="replace").read()
        print(f"job {job}: {fields.get('JobState')}, exit code {fields.get('ExitCode')}, "
              f"{int(fields.get('Restarts', 0)) + 1} runs, {time.monotonic() - start:.0f} s in all")

    # 4. Checks.
    errors = []

    def check(ok, what):
        if not ok:
            errors.append(what)

    runs = int(fields.get("Restarts", 0)) + 1
    check(fields.get("JobState") == "COMPLETED" and fields.get("ExitCode") == "0:0",
          f"job state {fields.get('JobState')}, exit code {fields.get('ExitCode')} (expected COMPLETED 0:0)")
    check(requeued, "the test never requeued the job (no periodic restart file seen while it ran)")
    starts = re.findall(r"^job \d+ \(run (\d+) of at most \d+\)", text, re.M)
    check(starts == [str(k) for k in range(1, runs + 1)],
          f"the log holds runs {starts}, Slurm counts {runs} (the log must keep every run)")
    limit_stops = len(re.findall(r"^stopped with a restart file: requeueing job \d+", text, re.M))
    # Every self-requeue follows a stop at the time limit (a stop that Slurm's requeue overtook has none).
    limit_reasons = len(re.findall(r"the time limit of Slurm job \d+ would not hold another increment", text))
    check(limit_stops <= limit_reasons, f"{limit_stops} self-requeues, {limit_reasons} stops at the time limit")
    check(limit_stops >= 1, f"no run stopped at the job's time limit ({runs} runs)")
    check(runs >= 3, f"{runs} runs: expected the requeue and at least one time-limit stop")
    continued = len(re.findall(r"^contessa: --restart auto: continuing from .*/" + re.escape(name) + r"\.restart$",
                               text, re.M))
    check(continued == runs - 1, f"{continued} runs continued from the restart file, expected {runs - 1}")
    first = re.search(r"^contessa: --restart auto: (.*)$", text, re.M)
    check(first is not None and first[1].startswith("no restart file"), "the first run did not start afresh")
    for banner in ["srun: error", "contessa: error", "non-zero exit code", "stopped early"]:
        check(banner not in text, f"the log holds '{banner}'")
    check(re.search(r"^finished: ", text, re.M) is not None, "no 'finished:' line")
    summary_path = os.path.join(out, name + ".summary.json")
    summary = json.load(open(summary_path)) if os.path.exists(summary_path) else {}
    check(summary.get("exit_status") == 0 and summary.get("whole_run", {}).get("continued"),
          f"summary: exit status {summary.get('exit_status')}, whole run {summary.get('whole_run')}")
    # Both scopes of the last run: it began after step 1; the whole run has every increment of the
    # history, at least the history's Newton iterations, and more wall time than this job.
    rows = list(csv.DictReader(open(os.path.join(out, name + ".history.csv"))))
    job, whole = summary.get("this_job", {}), summary.get("whole_run", {})
    check(job.get("first_step", 0) > 1 and job.get("first_step", 0) + job.get("increments", 0) == len(rows),
          f"this_job {job} with {len(rows) - 1} increments in the history")
    check(whole.get("increments") == len(rows) - 1 and summary.get("increments") == len(rows) - 1,
          f"whole_run {whole}, {len(rows) - 1} increments in the history")
    check(whole.get("newton_iterations", 0) >= sum(int(r["newton_iterations"]) for r in rows[1:]) and
          whole.get("wall_seconds", 0) > job.get("wall_seconds", 0), f"whole_run {whole}, this job {job}")
    # The restart files carry the run's Newton count (failed attempts included), so the chain's whole run
    # counts what the uninterrupted run did, exactly.
    reference_summary = json.load(open(os.path.join(reference, name + ".summary.json")))
    check(whole.get("newton_iterations") == reference_summary.get("newton_iterations"),
          f"whole_run Newton iterations {whole.get('newton_iterations')}, uninterrupted run "
          f"{reference_summary.get('newton_iterations')}")
    history = subprocess.run([COMPARE, os.path.join(reference, name + ".history.csv"),
                              os.path.join(out, name + ".history.csv")] + COMPARE_OPTIONS,
                             capture_output=True, text=True, timeout=60)
    print("history against the uninterrupted run: " + (history.stdout + history.stderr).strip().splitlines()[-1])
    check(history.returncode == 0, "history differs:\n" + history.stdout[-2000:])
    if errors:
        print(text[-6000:])
        fail("; ".join(errors))
    print(f"PASS: {runs} runs ({limit_stops} requeued by the job at its time limit, 1 by scontrol), history as "
          f"uninterrupted")
    return 0


if __name__ == "__main__":
    sys.exit(main())
