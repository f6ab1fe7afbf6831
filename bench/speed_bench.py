#!/usr/bin/python3
"""Speed of Contessa on the paper's tube (inputs/tube_bending.xml), phase by phase, and how it grows.

    /usr/bin/python3 bench/speed_bench.py [--repeat 5] [--refine 2 4 8] [--ranks 1 2] [--compare OLD_BINARY]
                                          [--no-calculix] [--work DIR] [--quick]

Prints three Markdown tables (bench/README.md explains every column):

1. Phases of the tube, fixed steps (47 increments of 1.6 mm) and Contact Beta N_c = 2, one rank:
   `contessa --timers` (wall seconds per phase, exclusive), the median per phase over --repeat runs;
   the wall time around the whole process with and without --timers (the timers are free when off);
   Newton iterations and the time per iteration. With --compare, the same two runs of another build
   (e.g. an older commit, which has no --timers) in the same interleaved loop, and the speed-up.
2. The tube refined 2x, 4x, 8x in each direction (13k x 101k elements), 10 fixed increments, on every
   rank count of --ranks: time, Newton iterations, time per iteration, MUMPS factorisation time per
   call, peak memory (GNU time's maximum resident set size of the largest process), and the growth
   exponents p of time ~ N^p fitted by least squares over the sizes (N the number of unknowns).
3. CalculiX (`ccx`, if on PATH; --no-calculix skips it) on the same fixed-step tube, one thread,
   its default solver, in the same run: wall time, iterations, plate force, and Contessa's ratio.

Tools: /usr/bin/python3 (standard library), /usr/bin/time -v, mpiexec for 2 ranks, ccx. Wall times
depend on the machine's load (the header prints the load average): the runs are interleaved, so
that a change of load hits every variant alike, and the minimum is printed next to the median.
"""
import argparse
import csv
import json
import math
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
COMPARE = os.path.join(ROOT, "tests", "regression", "compare_history.py")
STEP = "Piro/LOCA/Step Size/"
MESH = "Problem/Mesh/"
# The deck checks the Contact Beta answer (31 increments); the fixed-step run expects 47.
FIXED = [STEP + "Method=Constant", "Problem/Regression/increments/Expected=47"]
BETA = []
FINAL = re.compile(r"finished after (\d+) increments \((\d+) failed attempts\), (\d+) Newton iterations, "
                   r"(\d+) linear solves")
ROW = re.compile(r"^  (.+?)\s+(\d+\.\d{4})\s+(\d+\.\d)\s+(\d+)$")
TOTAL = re.compile(r"^  total\s+(\d+\.\d{4})")
MPIEXEC = ["mpiexec", "--oversubscribe", "--allow-run-as-root", "-n"]
FACTORISATION = "MUMPS factorisation (JOB=2)"


def run(cmd, out_dir, timeout, accept=(0,), fresh=True, env=None):
    """Runs cmd in out_dir under /usr/bin/time -v; returns wall and CPU (user + system) seconds, peak
    RSS (MB), stdout, exit status."""
    if fresh and os.path.isdir(out_dir):
        shutil.rmtree(out_dir)
    os.makedirs(out_dir, exist_ok=True)
    timing = os.path.join(out_dir, "time.txt")
    start = time.perf_counter()
    done = subprocess.run(["/usr/bin/time", "-v", "-o", timing] + cmd, capture_output=True, text=True, timeout=timeout,
                          cwd=out_dir, env=env)
    wall = time.perf_counter() - start
    text = open(timing).read() if os.path.exists(timing) else ""
    rss = re.search(r"Maximum resident set size \(kbytes\): (\d+)", text)
    user = re.search(r"User time \(seconds\): ([0-9.]+)", text)
    sys_ = re.search(r"System time \(seconds\): ([0-9.]+)", text)
    r = {"dir": out_dir, "wall": wall, "status": done.returncode, "stdout": done.stdout, "stderr": done.stderr,
         "rss_mb": int(rss.group(1)) / 1024 if rss else float("nan"),
         "cpu": (float(user.group(1)) + float(sys_.group(1))) if user and sys_ else float("nan")}
    if done.returncode not in accept:
        last = (done.stderr.strip().splitlines() or ["no output"])[-1]
        raise RuntimeError(f"{' '.join(cmd)}: exit {done.returncode}: {last}")
    return r


def bench_arguments(doc, work=None):
    """An argument parser with the options every bench takes: the binary to run and the work directory
    (default `work`; None: a new temporary directory, work_directory); the caller adds its own."""
    p = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--contessa", default=os.path.join(ROOT, "build", "bin", "contessa"))
    p.add_argument("--work", default=work)
    return p


def punch_arguments(doc, punch, repeat, work, timeout):
    """The options the 3D punch benches share: the binary, the punch sizes (elements along x and y), the
    repetitions, the work directory and the time limit per run; the caller adds its own."""
    p = bench_arguments(doc, work)
    p.add_argument("--punch", type=int, nargs="*", default=punch)
    p.add_argument("--repeat", type=int, default=repeat)
    p.add_argument("--timeout", type=float, default=timeout)
    return p


def print_host(work=None):
    """The header line every bench prints: the host, its cores and its load (the figures depend on it), and
    the work directory when given."""
    load = os.getloadavg()
    where = f"; work directory {work}" if work else ""
    print(f"host {os.uname().nodename}, {os.cpu_count()} cores, load average {load[0]:.1f} {load[1]:.1f} {load[2]:.1f}"
          f"{where}\n")


def work_directory(args, prefix):
    """The directory of --work, or a new temporary one named after the bench; printed with the host line."""
    work = args.work or tempfile.mkdtemp(prefix=prefix)
    print_host(work)
    return work


def print_table_header(columns, align="---"):
    """The head of a Markdown table: the column names and the alignment row, one cell per column."""
    print("| " + " | ".join(columns) + " |")
    print("|" + "|".join([align] * len(columns)) + "|")


def timed_run(contessa, deck, ranks, out, sets):
    """One run of `deck` with --timers on `ranks` ranks into `out`, its log kept there (log.txt): exit status,
    output directory, last line of stderr, seconds per phase (the largest rank's) and the run summary
    (<deck>.summary.json) when it was written."""
    os.makedirs(out, exist_ok=True)
    command = ([] if ranks == 1 else MPIEXEC + [str(ranks)]) + [contessa, deck, "--quiet", "--timers", "--output-dir", out]
    for s in sets:
        command += ["--set", s]
    p = subprocess.run(command, capture_output=True, text=True)
    with open(os.path.join(out, "log.txt"), "w") as log:
        log.write(p.stdout + p.stderr)
    result = {"status": p.returncode, "out": out, "stderr": p.stderr.strip().splitlines()[-1:], "phases": {}}
    for line in p.stdout.splitlines():
        m = ROW.match(line)
        if m:
            result["phases"][m[1].strip()] = float(m[2])
    summary = os.path.join(out, os.path.splitext(os.path.basename(deck))[0] + ".summary.json")
    if os.path.exists(summary):
        result["summary"] = json.load(open(summary))
    return result


def history_difference(reference, other):
    """Whether two runs' histories agree to 1e-8 relative (compare_history.py, the solver counts left out),
    and the largest difference."""
    p = subprocess.run([sys.executable, COMPARE, reference, other, "--rtol", "1e-8", "--atol", "1e-9", "--ignore",
                        "newton_iterations,linear_iterations,residual_norm"], capture_output=True, text=True)
    m = re.search(r"largest difference ([0-9.e+-]+) at (.*)$", p.stdout.strip().splitlines()[-1] if p.stdout.strip() else "")
    verdict = "agrees" if p.returncode == 0 else "DIFFERS"
    return f"{verdict} ({m[1]} abs.)" if m else verdict


def contessa_cmd(binary, ranks, out_dir, sets, timers):
    cmd = ([shutil.which("mpiexec") or "mpiexec"] + MPIEXEC[1:] + [str(ranks)] if ranks > 1 else []) + [binary, DECK]
    cmd += ["--quiet", "--output-dir", out_dir] + (["--timers"] if timers else [])
    for s in sets:
        cmd += ["--set", s]
    return cmd


def parse(r):
    """Newton iterations, increments and the phase table (name -> (seconds, count)) of a run."""
    m = FINAL.search(r["stdout"])
    if not m:
        raise RuntimeError("no final line in contessa's output:\n" + r["stdout"][-500:] + r["stderr"][-500:])
    r.update(increments=int(m.group(1)), newton=int(m.group(3)), solves=int(m.group(4)))
    phases = {}
    lines = r["stdout"].splitlines()
    for i, line in enumerate(lines):
        if line.startswith("contessa: phase timers"):
            for row in lines[i + 2:]:
                p = ROW.match(row)
                if not p:
                    t = TOTAL.match(row)
                    r["timer_total"] = float(t.group(1)) if t else float("nan")
                    break
                phases[p.group(1)] = (float(p.group(2)), int(p.group(4)))
    r["phases"] = phases
    history = [f for f in os.listdir(r["dir"]) if f.endswith(".history.csv")] if "dir" in r else []
    if history:
        with open(os.path.join(r["dir"], history[0]), newline="") as f:
            last = list(csv.DictReader(f))[-1]
        r["force"] = -float(last["contact_force_plate_y"])
    return r


def fit_exponent(ns, ts):
    """Least-squares slope of log t over log n."""
    x = [math.log(n) for n in ns]
    y = [math.log(t) for t in ts]
    mx, my = statistics.fmean(x), statistics.fmean(y)
    sxx = sum((a - mx) ** 2 for a in x)
    return sum((a - mx) * (b - my) for a, b in zip(x, y)) / sxx if sxx > 0 else float("nan")


# ---- 1. phase tables ---------------------------------------------------------------------------------

def phase_tables(a, work):
    variants = [("fixed", FIXED), ("beta", BETA)]
    runs = {(v, mode): [] for v, _ in variants for mode in ("timers", "off", "compare")}
    for rep in range(a.repeat):
        for v, sets in variants:
            modes = ["timers", "off"] + (["compare"] if a.compare else [])
            for mode in modes:
                binary = a.compare if mode == "compare" else a.contessa
                out = os.path.join(work, f"{v}_{mode}")
                r = parse(run(contessa_cmd(binary, 1, out, sets, mode == "timers"), out, a.timeout))
                runs[(v, mode)].append(r)
                print(f"[{rep + 1}/{a.repeat}] tube {v} {mode}: {r['wall']:.2f} s", file=sys.stderr, flush=True)

    names = list(runs[("fixed", "timers")][0]["phases"])
    print("### Phases of the tube, one rank (`contessa --timers`, median per phase of "
          f"{a.repeat} run(s))\n")
    print("| phase | fixed s | % | count | Contact Beta N_c = 2 s | % | count |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    med = {}
    for v, _ in variants:
        rs = runs[(v, "timers")]
        med[v] = {n: statistics.median(r["phases"][n][0] for r in rs) for n in names}
        med[v]["total"] = statistics.median(r["timer_total"] for r in rs)
    for n in names + ["total"]:
        cells = []
        for v, _ in variants:
            count = runs[(v, "timers")][0]["phases"][n][1] if n != "total" else ""
            cells += [f"{med[v][n]:.3f}", f"{100 * med[v][n] / med[v]['total']:.0f}", f"{count}"]
        print(f"| {n} | " + " | ".join(cells) + " |")
    print()
    print("| run | increments | Newton it. | wall s, median (min) | CPU s | ms per Newton it. | with --timers: wall s |"
          + (" other build: Newton it., wall s, median (min) | CPU s | speed-up (wall, CPU) |" if a.compare else ""))
    print("|---|---:|---:|---:|---:|---:|---:|" + ("---:|---:|---:|" if a.compare else ""))
    summary = {}
    for v, _ in variants:
        off, on = runs[(v, "off")], runs[(v, "timers")]
        w = statistics.median(r["wall"] for r in off)
        summary[v] = {"wall": w, "min": min(r["wall"] for r in off), "newton": off[0]["newton"],
                      "cpu": statistics.median(r["cpu"] for r in off), "force": off[0]["force"]}
        line = (f"| tube {v} | {off[0]['increments']} | {off[0]['newton']} | {w:.2f} ({summary[v]['min']:.2f}) | "
                f"{statistics.median(r['cpu'] for r in off):.2f} | {1000 * w / off[0]['newton']:.1f} | "
                f"{statistics.median(r['wall'] for r in on):.2f} |")
        if a.compare:
            c = runs[(v, "compare")]
            wc = statistics.median(r["wall"] for r in c)
            cc = statistics.median(r["cpu"] for r in c)
            line += (f" {c[0]['newton']}, {wc:.2f} ({min(r['wall'] for r in c):.2f}) | {cc:.2f} | "
                     f"×{wc / w:.1f}, ×{cc / summary[v]['cpu']:.1f} |")
        print(line)
    print()
    return summary


# ---- 2. refinement -----------------------------------------------------------------------------------

def refinement(a, work):
    rows = []
    for k in [1] + a.refine:
        for ranks in a.ranks:
            nr, nt = 13 * k, 101 * k
            sets = [STEP + "Method=Constant", STEP + "Initial Step Size=0.1", MESH + f"Elements Through Thickness={nr}",
                    MESH + f"Elements Around Arc={nt}"]
            out = os.path.join(work, f"refine{k}_np{ranks}")
            # Exit 3: the deck's checks are for the standard mesh and 31 increments; the run itself finished.
            r = parse(run(contessa_cmd(a.contessa, ranks, out, sets, True), out, a.timeout, accept=(0, 3)))
            fact = r["phases"].get(FACTORISATION, (float("nan"), 1))
            rows.append({"k": k, "ranks": ranks, "elements": nr * nt, "unknowns": 2 * (nr + 1) * (nt + 1),
                         "wall": r["wall"], "newton": r["newton"], "rss": r["rss_mb"], "cpu": r["cpu"],
                         "fact": fact[0], "fact_n": fact[1]})
            print(f"refined {k}x, {ranks} rank(s): {r['wall']:.2f} s, {r['newton']} it.", file=sys.stderr, flush=True)
    print("### The tube refined k times in each direction, 10 fixed increments\n")
    print("| k | elements | unknowns | ranks | Newton it. | wall s | CPU s | ms per it. | factorisation ms per call "
          "| factorisation % | peak memory MB |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        print(f"| {r['k']} | {r['elements']} | {r['unknowns']} | {r['ranks']} | {r['newton']} | {r['wall']:.2f} | "
              f"{r['cpu']:.2f} | {1000 * r['wall'] / r['newton']:.1f} | {1000 * r['fact'] / r['fact_n']:.1f} | "
              f"{100 * r['fact'] / r['wall']:.0f} | {r['rss']:.0f} |")
    print()
    print("Growth exponents p (time ~ N^p, least squares over the sizes; between consecutive sizes in brackets):\n")
    print("| ranks | total time | time per Newton it. | factorisation per call | peak memory |")
    print("|---:|---:|---:|---:|---:|")
    for ranks in a.ranks:
        rs = [r for r in rows if r["ranks"] == ranks]
        if len(rs) < 2:
            continue
        n = [r["unknowns"] for r in rs]

        def cell(values):
            local = ", ".join(f"{fit_exponent(n[i:i + 2], values[i:i + 2]):.2f}" for i in range(len(rs) - 1))
            return f"{fit_exponent(n, values):.2f} ({local})"
        print(f"| {ranks} | {cell([r['wall'] for r in rs])} | {cell([r['wall'] / r['newton'] for r in rs])} | "
              f"{cell([r['fact'] / r['fact_n'] for r in rs])} | {cell([r['rss'] for r in rs])} |")
    if 1 in a.ranks and 2 in a.ranks:
        print()
        print("Two ranks against one (wall time ratio, < 1: two are faster): " + ", ".join(
            f"k = {k}: {next(r['wall'] for r in rows if r['k'] == k and r['ranks'] == 2) / next(r['wall'] for r in rows if r['k'] == k and r['ranks'] == 1):.2f}"
            for k in [1] + a.refine))
    print()


# ---- 3. CalculiX ------------------------------------------------------------------------------------

def calculix_input(increments):
    """The tube as C3D8I bricks one millimetre thick (plane strain: every z displacement held), the
    same 13 x 101 mesh, symmetry planes, and a rigid plate (a rigid body of C3D8 bricks) moved down
    75.2 mm in `increments` fixed increments; node-to-surface penalty contact, frictionless."""
    nr, nt = 13, 101
    lines = ["*HEADING", "Tube pressed by a rigid plate (Contessa bench/speed_bench.py)", "*NODE, NSET=NALL"]

    def tube(i, j, z):
        return 1 + z * (nr + 1) * (nt + 1) + j * (nr + 1) + i
    for z in (0, 1):
        for j in range(nt + 1):
            th = math.radians(90.0 * j / nt)
            for i in range(nr + 1):
                r = 100.0 + 20.0 * i / nr
                lines.append(f"{tube(i, j, z)}, {r * math.cos(th):.12g}, {r * math.sin(th):.12g}, {z}")
    plate_x = [-20.0 + 320.0 * k / 32 for k in range(33)]
    first_plate = 2 * (nr + 1) * (nt + 1) + 1
    pnode = {}
    for z in (0, 1):
        for yi, y in enumerate((120.0, 130.0)):
            for k, x in enumerate(plate_x):
                pnode[(k, yi, z)] = first_plate + len(pnode)
                lines.append(f"{pnode[(k, yi, z)]}, {x:.12g}, {y}, {z}")
    ref, rot = first_plate + len(pnode), first_plate + len(pnode) + 1
    lines += [f"{ref}, 140.0, 125.0, 0.5", f"{rot}, 140.0, 125.0, 0.5"]
    lines.append("*ELEMENT, TYPE=C3D8I, ELSET=TUBE")
    e = 0
    outer = []
    for j in range(nt):
        for i in range(nr):
            e += 1
            n = [tube(i, j, 0), tube(i + 1, j, 0), tube(i + 1, j + 1, 0), tube(i, j + 1, 0)]
            lines.append(", ".join(str(x) for x in [e] + n + [m + (nr + 1) * (nt + 1) for m in n]))
            if i == nr - 1:
                outer.append(e)
    lines.append("*ELEMENT, TYPE=C3D8, ELSET=PLATE")
    for k in range(32):
        e += 1
        n = [pnode[(k, 0, 0)], pnode[(k + 1, 0, 0)], pnode[(k + 1, 1, 0)], pnode[(k, 1, 0)]]
        lines.append(", ".join(str(x) for x in [e] + n + [pnode[(kk, yy, 1)] for kk, yy in
                                                          ((k, 0), (k + 1, 0), (k + 1, 1), (k, 1))]))
    plate_first = e - 31
    lines.append("*NSET, NSET=START")
    lines += [str(tube(i, 0, z)) for z in (0, 1) for i in range(nr + 1)]
    lines.append("*NSET, NSET=END")
    lines += [str(tube(i, nt, z)) for z in (0, 1) for i in range(nr + 1)]
    lines.append("*NSET, NSET=TUBENODES")
    lines += [str(tube(i, j, z)) for z in (0, 1) for j in range(nt + 1) for i in range(nr + 1)]
    lines += [f"*NSET, NSET=REF", str(ref), f"*NSET, NSET=ROT", str(rot)]
    lines.append("*SURFACE, NAME=SLAVE")  # face 4 (nodes 2-6-7-3) of the outer elements: r = 120 mm
    lines += [f"{x}, S4" for x in outer]
    lines.append("*SURFACE, NAME=MASTER")  # face 3 (nodes 1-5-6-2) of the plate bricks: y = 120 mm
    lines += [f"{x}, S3" for x in range(plate_first, plate_first + 32)]
    lines += ["*MATERIAL, NAME=TUBE", "*ELASTIC", "400.0, 0.25", "*SOLID SECTION, ELSET=TUBE, MATERIAL=TUBE",
              "*MATERIAL, NAME=PLATE", "*ELASTIC", "4e5, 0.25", "*SOLID SECTION, ELSET=PLATE, MATERIAL=PLATE",
              f"*RIGID BODY, ELSET=PLATE, REF NODE={ref}, ROT NODE={rot}",
              "*BOUNDARY", "TUBENODES, 3, 3, 0.0", "START, 2, 2, 0.0", "END, 1, 1, 0.0",
              f"{ref}, 1, 1, 0.0", f"{ref}, 3, 3, 0.0", f"{rot}, 1, 3, 0.0",
              "*SURFACE INTERACTION, NAME=SI", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR",
              # penalty stiffness per area (N/mm^3): about Contessa's 1e9 N/mm per node over the
              # 1.9 mm x 1 mm a node carries
              "5e8",
              "*CONTACT PAIR, INTERACTION=SI, TYPE=NODE TO SURFACE", "SLAVE, MASTER",
              "*STEP, NLGEOM, INC=1000", "*STATIC, DIRECT", f"{1.0 / increments:.15g}, 1.0",
              "*BOUNDARY", f"{ref}, 2, 2, -75.2",
              "*NODE PRINT, NSET=REF, TOTALS=ONLY", "RF", "*END STEP"]
    return "\n".join(lines) + "\n"


def calculix(a, work, contessa_fixed):
    ccx = shutil.which("ccx")
    if a.no_calculix or ccx is None:
        print("CalculiX: " + ("skipped (--no-calculix)" if a.no_calculix else "not installed (ccx not on PATH)") + "\n")
        return
    d = os.path.join(work, "ccx")
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, "tube.inp"), "w") as f:
        f.write(calculix_input(47))
    env = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_EQUATION_SOLVER="1", CCX_NPROC_RESULTS="1",
               CCX_NPROC_STIFFNESS="1", OPENBLAS_NUM_THREADS="1")
    runs = []
    for rep in range(a.ccx_repeat):
        runs.append(run([ccx, "-i", "tube"], d, a.timeout, accept=(0, 1, 201), fresh=False, env=env))
        print(f"[{rep + 1}/{a.ccx_repeat}] CalculiX: {runs[-1]['wall']:.2f} s", file=sys.stderr, flush=True)
    done = runs[-1]
    version = re.search(r"Version (\S+)", done["stdout"])
    sta = open(os.path.join(d, "tube.sta")).read().splitlines() if os.path.exists(os.path.join(d, "tube.sta")) else []
    incs = [l.split() for l in sta if re.match(r"^\s+\d+\s+\d+\s+\d+\s+\d+", l)]
    iterations = sum(int(x[3]) for x in incs)
    dat = open(os.path.join(d, "tube.dat")).read() if os.path.exists(os.path.join(d, "tube.dat")) else ""
    forces = re.findall(r"^\s*(-?[0-9.]+E[+-]\d+)\s+(-?[0-9.]+E[+-]\d+)\s+(-?[0-9.]+E[+-]\d+)\s*$", dat, re.M)
    finished = "Job finished" in done["stdout"]
    w = statistics.median(r["wall"] for r in runs)
    cpu = statistics.median(r["cpu"] for r in runs)
    print("### CalculiX on the same fixed-step tube (47 increments of 1.6 mm)\n")
    print("| code | increments | iterations | wall s, median (min) | CPU s | ms per iteration | plate force N/mm |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    force = f"{float(forces[-1][1]):.2f}" if forces else "—"
    print(f"| CalculiX {version.group(1) if version else ''} (C3D8I, one thread){'' if finished else ' FAILED'} "
          f"| {len(incs)} | {iterations} | {w:.2f} ({min(r['wall'] for r in runs):.2f}) | {cpu:.2f} | "
          f"{1000 * w / max(iterations, 1):.1f} | {force} |")
    print(f"| Contessa (Q4 Enhanced, one rank) | 47 | {contessa_fixed['newton']} | {contessa_fixed['wall']:.2f} "
          f"({contessa_fixed['min']:.2f}) | {contessa_fixed['cpu']:.2f} | "
          f"{1000 * contessa_fixed['wall'] / contessa_fixed['newton']:.1f} | {contessa_fixed['force']:.2f} |")
    print(f"\nContessa is {w / contessa_fixed['wall']:.1f} times faster than CalculiX in wall time "
          f"({cpu / contessa_fixed['cpu']:.1f} times in CPU time; "
          f"{(w / max(iterations, 1)) / (contessa_fixed['wall'] / contessa_fixed['newton']):.1f} times per iteration).\n")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--contessa", default=os.path.join(ROOT, "build", "bin", "contessa"))
    p.add_argument("--compare", help="another contessa binary (e.g. an older build): wall time of the same tube runs")
    p.add_argument("--repeat", type=int, default=5, help="runs per tube variant (default 5)")
    p.add_argument("--refine", type=int, nargs="*", default=[2, 4, 8], help="refinement factors (default 2 4 8)")
    p.add_argument("--ranks", type=int, nargs="+", default=[1, 2], help="rank counts of the refined runs (default 1 2)")
    p.add_argument("--no-calculix", action="store_true")
    p.add_argument("--ccx-repeat", type=int, default=1, help="CalculiX runs (default 1)")
    p.add_argument("--parts", nargs="+", choices=["phases", "refine", "calculix"], default=["phases", "refine", "calculix"],
                   help="which tables (default all; CalculiX compares with the phases' fixed run)")
    p.add_argument("--quick", action="store_true", help="--repeat 1 --refine 2 --ranks 1 (about 20 s)")
    p.add_argument("--work", help="keep the runs' outputs here (default: a temporary directory, removed)")
    p.add_argument("--timeout", type=float, default=1800.0)
    a = p.parse_args()
    if a.quick:
        a.repeat, a.refine, a.ranks = 1, [2], [1]
    if not os.access(a.contessa, os.X_OK):
        sys.exit(f"speed_bench.py: {a.contessa} not found; build it first (README.md)")
    work = a.work or tempfile.mkdtemp(prefix="contessa_speed_bench_")
    t0 = time.perf_counter()
    print(f"Speed benchmark: {a.contessa} on {platform.node()}, {os.cpu_count()} cores, "
          f"load average {os.getloadavg()[0]:.1f} at the start.\n")
    try:
        if "phases" in a.parts or "calculix" in a.parts:
            fixed = phase_tables(a, work)["fixed"]
        if "refine" in a.parts:
            refinement(a, work)
        if "calculix" in a.parts:
            calculix(a, work, fixed)
    finally:
        if not a.work:
            shutil.rmtree(work, ignore_errors=True)
    print(f"Total {time.perf_counter() - t0:.0f} s; load average {os.getloadavg()[0]:.1f} at the end.")
    return 0


if __name__ == "__main__":
    sys.exit(main())
