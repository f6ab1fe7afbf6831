#!/usr/bin/python3
"""Step-size strategies on the paper's tube benchmark (inputs/tube_bending.xml, Vulovic et al. section 6).

Runs build/bin/contessa on the frictionless tube deck with
  fixed                  Method=Constant (1.6 mm steps, the paper's 47 increments)
  LOCA Adaptive          Method=Adaptive, Initial Step Size 1.6 mm (1/47), Max Step Size 0.25,
                         default Aggressiveness: LOCA's convergence-based control, the baseline
  Contact Beta Restart   N_c = 1, 2, 4, 8 (the paper's Table 1: beta at the first Newton iteration, restart)
  Contact Beta Predictor N_c = 1, 2, 4, 8 (beta from the predicted state, no restart)
  Contact Beta, cheapest N_c = 16, Max Corrections Per Increment = 0 (fewest Newton iterations)
and on the frictional tube (the same deck with Friction Coefficient = 0.2 and nothing else changed) with
fixed, LOCA Adaptive and Contact Beta Restart N_c = 1, 2, 4, 8. Prints one Markdown table per deck:
increments, attempts, restarts/cut-backs, Newton iterations, linear solves, new events per increment
(min / median / max of the history's new_events, the status changes Contact Beta counts: closures
with the default Counted Events), wall time, final plate force and its relative difference to the
fixed-step run.

    /usr/bin/python3 bench/tube_bench.py [--repeat 3] [--quick] [--case frictionless|frictional|both]
                                         [--contessa PATH] [--work DIR]

Wall time is the median over --repeat runs of each variant, measured around the whole contessa process
(time.perf_counter() around subprocess.run, so start-up, mesh generation and output are included);
the repeats are interleaved (all variants once, then again) so that a change of machine load hits
every variant alike. A run that does not reach the final load is reported as FAILED, not a crash.
About 3-8 s per run on one core: both tables with --repeat 1 take about 2 minutes, --quick 30 s.
"""
import argparse
import csv
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
DECK = os.path.join(ROOT, "inputs", "tube_bending.xml")
NAME = "tube_bending"
STEP = "Piro/LOCA/Step Size/"
# The deck's regression checks expect the Contact Beta N_c = 2 answer (32 increments); a wide
# tolerance keeps the increment check from failing the other variants (exit status 3).
COMMON = ["Problem/Regression/increments/Absolute Tolerance=1000"]
USER_STEP = 1.0 / 47.0  # 1.6 mm of 75.2 mm

FINAL = re.compile(r"finished after (\d+) increments \((\d+) failed attempts\), (\d+) Newton iterations, "
                   r"(\d+) linear solves; load factor ([0-9.eE+-]+)")


FRICTION = ["Problem/Contact/plate/Friction Coefficient=0.2"]


def variants(quick, frictional):
    v = [("fixed (Constant, 1.6 mm)", [STEP + "Method=Constant"]),
         ("LOCA Adaptive", [STEP + "Method=Adaptive", STEP + f"Initial Step Size={USER_STEP!r}",
                            STEP + "Max Step Size=0.25"])]
    for mode in (("Restart",) if frictional else ("Restart", "Predictor")):
        for nc in ((2,) if quick else (1, 2, 4, 8)):
            v.append((f"Contact Beta {mode}, N_c = {nc}",
                      [STEP + "Method=Contact Beta", STEP + f"Mode={mode}", STEP + f"Contacts Per Step={nc}"]))
    if not frictional and not quick:
        v.append(("Contact Beta Restart, N_c = 16, Max Corrections 0",
                  [STEP + "Method=Contact Beta", STEP + "Contacts Per Step=16",
                   STEP + "Max Corrections Per Increment=0"]))
    extra = FRICTION if frictional else []
    return [(label, extra + sets) for label, sets in v]


def run_once(contessa, out_dir, sets, timeout):
    """One contessa run; returns a dict of results (ok False with a reason when it did not finish)."""
    if os.path.isdir(out_dir):
        shutil.rmtree(out_dir)
    args = [contessa, DECK, "--quiet", "--output-dir", out_dir]
    for s in COMMON + sets:
        args += ["--set", s]
    start = time.perf_counter()
    try:
        done = subprocess.run(args, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"ok": False, "reason": f"timeout after {timeout:g} s", "seconds": time.perf_counter() - start}
    seconds = time.perf_counter() - start
    r = {"seconds": seconds, "status": done.returncode}
    m = FINAL.search(done.stdout + done.stderr)
    hist_path = os.path.join(out_dir, NAME + ".history.csv")
    rows = []
    if os.path.exists(hist_path):
        with open(hist_path, newline="") as f:
            rows = list(csv.DictReader(f))
    if rows:
        r["lambda"] = float(rows[-1]["lambda"])
    # Exit 0 = reached the final load; 3 = reached it but a deck regression check failed (still a result).
    if done.returncode not in (0, 3) or not m or not rows or abs(float(rows[-1]["lambda"]) - 1.0) > 1e-12:
        last = (done.stderr.strip().splitlines() or done.stdout.strip().splitlines() or ["no output"])[-1]
        r.update(ok=False, reason=f"exit {done.returncode}, lambda {r.get('lambda', 0):.4g}: {last}")
        return r
    increments = int(rows[-1]["step"])
    events = sorted(int(row["new_events"]) for row in rows[1:])
    attempts = sum(int(float(row["attempts"])) for row in rows[1:])
    r.update(ok=True, increments=increments, attempts=attempts, restarts=attempts - increments,
             failed=int(m.group(2)), newton=int(m.group(3)), solves=int(m.group(4)),
             force=-float(rows[-1]["contact_force_plate_y"]),
             events=f"{events[0]} / {statistics.median(events):g} / {events[-1]}",
             checks_failed=done.returncode == 3)
    if int(m.group(1)) != increments:
        print(f"warning: {out_dir}: final line says {m.group(1)} increments, history {increments}", file=sys.stderr)
    if r["failed"] != r["restarts"]:
        print(f"warning: {out_dir}: history attempts give {r['restarts']} restarts, final line "
              f"{r['failed']} failed attempts", file=sys.stderr)
    return r


def table(a, work, name, vs):
    os.makedirs(work, exist_ok=True)
    results = {label: [] for label, _ in vs}
    t0 = time.perf_counter()
    for rep in range(a.repeat):
        for i, (label, sets) in enumerate(vs):
            r = run_once(a.contessa, os.path.join(work, f"v{i}"), sets, a.timeout)
            results[label].append(r)
            state = f"{r['seconds']:.2f} s" if r["ok"] else "FAILED: " + r["reason"]
            print(f"[{rep + 1}/{a.repeat}] {label}: {state}", file=sys.stderr, flush=True)
    total = time.perf_counter() - t0

    fixed_runs = results[vs[0][0]]
    fixed_force = fixed_runs[0]["force"] if fixed_runs[0]["ok"] else None

    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    deck = "inputs/tube_bending.xml" + (" with Friction Coefficient=0.2" if name == "frictional" else "")
    print(f"Tube benchmark, {name} ({deck}, 1 rank, {platform.node()}, "
          f"{os.cpu_count()} cores, load average {load:.2f} at the end).")
    print(f"Wall time: median of {a.repeat} run(s) per variant, time.perf_counter() around the whole "
          f"contessa process (subprocess.run); total {total:.0f} s.")
    print("Restarts = sum of the history's attempts - increments (Contact Beta: restarts with beta; "
          "Constant/Adaptive: cut-backs); Newton iterations and linear solves from contessa's final line "
          "(they include the iterations of restarted attempts).")
    print()
    print("| variant | increments | attempts | restarts | Newton it. | linear solves | wall time [s] "
          "| min–max [s] | new events per increment: min / median / max | plate force [N/mm] | rel. diff. to fixed |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for label, _ in vs:
        runs = results[label]
        ok = [r for r in runs if r["ok"]]
        if len(ok) < len(runs):
            bad = next(r for r in runs if not r["ok"])
            print(f"| {label} | FAILED | | | | | | | | | {bad['reason']} |")
            continue
        r = ok[0]
        if any((o["increments"], o["newton"], o["force"]) != (r["increments"], r["newton"], r["force"]) for o in ok):
            print(f"warning: {label}: the repeats differ", file=sys.stderr)
        times = [o["seconds"] for o in ok]
        wall = statistics.median(times)
        spread = f"{min(times):.2f}–{max(times):.2f}" if len(times) > 1 else "—"
        if label == vs[0][0]:
            diff = "(reference)"
        elif fixed_force is None:
            diff = "—"
        else:
            diff = f"{abs(r['force'] - fixed_force) / abs(fixed_force):.1e}"
        note = " (a deck check failed)" if r["checks_failed"] else ""
        print(f"| {label}{note} | {r['increments']} | {r['attempts']} | {r['restarts']} | {r['newton']} "
              f"| {r['solves']} | {wall:.2f} | {spread} | {r['events']} | {r['force']:.5f} | {diff} |")
    print()


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--repeat", type=int, default=3, help="runs per variant; wall time is their median (default 3)")
    p.add_argument("--quick", action="store_true", help="one run each, N_c = 2 only (4 variants)")
    p.add_argument("--case", choices=("frictionless", "frictional", "both"), default="both")
    p.add_argument("--contessa", default=os.path.join(ROOT, "build", "bin", "contessa"))
    p.add_argument("--work", help="keep the runs' outputs here (default: a temporary directory, removed)")
    p.add_argument("--timeout", type=float, default=600.0, help="seconds before a run counts as FAILED")
    a = p.parse_args()
    if a.quick:
        a.repeat = 1
    if a.repeat < 1:
        p.error("--repeat must be >= 1")
    if not os.access(a.contessa, os.X_OK):
        sys.exit(f"tube_bench.py: {a.contessa} not found; build it with scripts/build.sh")

    work = a.work or tempfile.mkdtemp(prefix="contessa_tube_bench_")
    cases = {"frictionless": False, "frictional": True}
    chosen = list(cases) if a.case == "both" else [a.case]
    for name in chosen:
        table(a, os.path.join(work, name), name, variants(a.quick, cases[name]))
    if not a.work:
        shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
