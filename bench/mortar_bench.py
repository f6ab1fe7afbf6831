#!/usr/bin/python3
"""Mortar against node-to-segment/face on the tube: the contact phase's wall time per evaluation, per slave
node and evaluation, and per Newton iteration.

Cases (--case, default both):
  2d  the fixed-step tube (inputs/tube_bending.xml, Method=Constant, 47 increments; 102 slave nodes on the
      outer arc against the rigid plate), frictionless and with Friction Coefficient = 0.2;
  3d  the extruded tube (inputs/tube_bending_3d.xml) on the registered 4 x 50 section, one layer (102 slave
      nodes on QUAD4 faces), the deck's Contact Beta (N_c = 4), frictionless (the 3D mortar cost figures predate 3D mortar friction);
  block
      the 3D block on a rigid base (inputs/verification/coulomb_block_3d.xml made frictionless, as the
      registered mortar3d_rigid_block test: 25 slave nodes on 4 x 4 QUAD4 faces pressed on one rigid
      quadrilateral and slid obliquely, the deck's 30 fixed increments);
  block-on-base
      the 3D block on a deformable base (inputs/verification/block_on_base_3d.xml made frictionless: 4 x 4
      slave faces on 3 x 3 master faces of a Hex8 base, 20 fixed increments), where every pair is
      differentiated in all 24 coordinates (a rigid master: its 12 slave coordinates and its motion).
A deck's own regression checks are about its own answers (exit 3 when one fails): the tube's are set off,
the blocks' (frictional baselines) are allowed to fail.
Each variant runs with `--timers`, once with Discretization = Node To Segment and once with Mortar,
--repeat times (interleaved, so that a change of machine load hits every variant alike), and one Markdown
table is printed: Newton iterations, contact evaluations (the timer's count: residual and Jacobian passes),
the median contact-phase time ("contact: search, elements, scatter": search, every slave node's term,
scatter into the matrix), that time per evaluation, per slave node and evaluation and per Newton
iteration, mortar over node-to-segment per evaluation and per Newton iteration (the two discretisations
need different numbers of iterations), the median total wall time and the median CPU time of the whole
process (user + system, from the children's resource usage: what the run cost, whatever the machine's load).

With --callgrind each variant runs once under valgrind's callgrind, counting the instructions executed
inside ContactAssembly::assemble (the same contact phase; independent of the machine's load, about 50x
slower): the table then gives instructions per evaluation and per Newton iteration and their ratios.
--max-value L stops the load at λ = L (the deck's checks are off; a shorter run for callgrind).
With --callgrind --whole-process callgrind counts every instruction of the process (start-up, mesh, element
kernels, MUMPS, output and contact alike) and the contact phase's share of them (ContactAssembly::assemble
inclusive, by callgrind_annotate): the table gives both per Newton iteration and their ratios, what
issue 25's "mortar at most 3x node-to-face per Newton iteration" is about when read as the whole run.
With --perf each run is sampled by `perf record` (cpu-clock at 4000 Hz, DWARF call stacks) and the contact
phase's time is its CPU time: the samples with ContactAssembly::assemble on the stack over the frequency.
A sampled process counts only while it runs, so on a loaded machine (wall times inflated many times by
the other processes) this stays what the contact phase costs; about ±5 % from the sampling. Slow: perf
report unwinds the DWARF stacks, minutes per run on a loaded machine.

    /usr/bin/python3 bench/mortar_bench.py [--case 2d|3d|block|block-on-base|both|all] [--repeat 3]
                                           [--contessa PATH] [--work DIR]
    /usr/bin/python3 bench/mortar_bench.py --callgrind [--whole-process] [--max-value 0.3] [--case 2d]
"""
import argparse
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
CHECKS_OFF = [  # the runs' own answers differ from the decks' baselines
    "--set", "Problem/Regression/plate force/Relative Tolerance=1",
    "--set", "Problem/Regression/contact nodes/Absolute Tolerance=1000",
    "--set", "Problem/Regression/increments/Absolute Tolerance=1000"]
CASES = {
    "2d": dict(deck="tube_bending.xml", slave_nodes=102, frictions=(0.0, 0.2), interface="plate",
               sets=["--set", "Piro/LOCA/Step Size/Method=Constant", *CHECKS_OFF]),
    "3d": dict(deck="tube_bending_3d.xml", slave_nodes=102, frictions=(0.0,), interface="plate",
               sets=["--set", "Problem/Mesh/Elements Through Thickness=4",
                     "--set", "Problem/Mesh/Elements Around Arc=50", *CHECKS_OFF]),
    "block": dict(deck="verification/coulomb_block_3d.xml", slave_nodes=25, frictions=(0.0,), interface="base",
                  sets=["--set", "Problem/Contact/base/Friction Coefficient=0"]),
    "block-on-base": dict(deck="verification/block_on_base_3d.xml", slave_nodes=25, frictions=(0.0,),
                          interface="interface",
                          sets=["--set", "Problem/Contact/interface/Friction Coefficient=0"]),
}
CASE_NOTES = ("2d: fixed steps, 3d: 4 x 50 section, Contact Beta N_c = 4; block: rigid base, 30 increments; "
              "block-on-base: deformable base, 20 increments")
CASE_CHOICES = {"both": ("2d", "3d"), "all": tuple(CASES)}
CONTACT = re.compile(r"^\s*contact: search, elements, scatter\s+(\S+)\s+\S+\s+(\d+)\s*$")
TOTAL = re.compile(r"^\s*total\s+(\S+)")
NEWTON = re.compile(r"(\d+) Newton iterations")
PERF_FREQUENCY = 4000


def contact_cpu_seconds(samples):
    """CPU seconds of the contact phase from a perf record file: samples under ContactAssembly::assemble."""
    def report(*args):
        return subprocess.run(["perf", "report", "-i", samples, "--stdio", "-g", "none", *args],
                              capture_output=True, text=True).stdout
    total = sum(int(line.split()[1]) for line in report("--no-children", "--sort", "pid", "-n").splitlines()
                if line.strip() and not line.startswith("#") and line.split()[0].endswith("%"))
    share = 0.0
    for line in report("--children", "--sort", "symbol").splitlines():
        fields = line.split()
        if len(fields) >= 4 and fields[3] == "contessa::model::ContactAssembly::assemble":
            share = float(line.split()[0].rstrip("%")) / 100
    os.remove(samples)
    return share * total / PERF_FREQUENCY


def contact_instructions(profile):
    """Instructions inside ContactAssembly::assemble (inclusive) in a whole-process callgrind profile."""
    report = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", profile],
                            capture_output=True, text=True).stdout
    for line in report.splitlines():
        if "contessa::model::ContactAssembly::assemble" in line:
            return int(line.split()[0].replace(",", ""))
    sys.exit(f"no ContactAssembly::assemble in {profile}")


def run(contessa, work, case, discretization, mu, index, callgrind=False, max_value=None, perf=False, whole=False):
    c = CASES[case]
    out = os.path.join(work, f"{case}_{discretization.replace(' ', '')}_mu{mu}_{index}")
    cmd = [contessa, os.path.join(ROOT, "inputs", c["deck"]), "--quiet", "--timers", "--output-dir", out,
           *c["sets"], "--set", f"Problem/Contact/{c['interface']}/Discretization={discretization}"]
    if mu > 0:
        cmd += ["--set", f"Problem/Contact/{c['interface']}/Friction Coefficient={mu}"]
    if max_value is not None:
        cmd += ["--set", f"Piro/LOCA/Stepper/Max Value={max_value}"]
    profile = out + ".callgrind"
    samples = out + ".perf"
    if perf:
        cmd = ["perf", "record", "-q", "-F", str(PERF_FREQUENCY), "--call-graph", "dwarf,16384", "-o", samples, *cmd]
    if callgrind:
        collect = [] if whole else ["--collect-atstart=no", "--toggle-collect=contessa::model::ContactAssembly::assemble*"]
        cmd = ["valgrind", "--tool=callgrind", *collect, f"--callgrind-out-file={profile}", *cmd]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    p = subprocess.run(cmd, capture_output=True, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)  # the run's own CPU seconds
    if p.returncode not in (0, 3):  # 3: a deck's own check of its own answer failed (above)
        sys.exit(f"{' '.join(cmd)} exited with {p.returncode}:\n{p.stderr[-2000:]}")
    if callgrind:
        with open(profile) as f:
            instructions = next(int(line.split()[1]) for line in f if line.startswith("summary:"))
        if whole:  # (the process' instructions, the contact phase's)
            instructions = (instructions, contact_instructions(profile))
    contact = total = newton = None
    for line in (p.stdout + p.stderr).splitlines():
        if (m := CONTACT.match(line)):
            contact = (float(m.group(1)), int(m.group(2)))
        elif (m := TOTAL.match(line)):
            total = float(m.group(1))
        elif (m := NEWTON.search(line)) and "finished after" in line:
            newton = int(m.group(1))
    if contact is None or total is None or newton is None:
        sys.exit(f"no timer table or Newton count in the output of {' '.join(cmd)}")
    if perf:
        return contact_cpu_seconds(samples), contact[1], total, newton, cpu
    return (instructions if callgrind else contact[0]), contact[1], total, newton, cpu


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--case", choices=(*CASES, *CASE_CHOICES), default="both")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--contessa", default=os.path.join(ROOT, "build", "bin", "contessa"))
    parser.add_argument("--work", default=None)
    parser.add_argument("--callgrind", action="store_true", help="count instructions (one run per variant)")
    parser.add_argument("--max-value", type=float, default=None, help="stop the load at this λ")
    parser.add_argument("--perf", action="store_true", help="the contact phase's CPU time, sampled by perf")
    parser.add_argument("--whole-process", action="store_true",
                        help="with --callgrind: every instruction of the process, and the contact phase's share")
    args = parser.parse_args()
    if args.callgrind:
        args.repeat = 1
    work = args.work or tempfile.mkdtemp(prefix="mortar_bench_")
    os.makedirs(work, exist_ok=True)
    cases = CASE_CHOICES.get(args.case, (args.case,))
    variants = [(case, d, mu) for case in cases for mu in CASES[case]["frictions"]
                for d in ("Node To Segment", "Mortar")]
    results = {v: [] for v in variants}
    for i in range(args.repeat):
        for v in variants:
            results[v].append(run(args.contessa, work, *v, i, args.callgrind, args.max_value, args.perf,
                                  args.whole_process))
    load = os.getloadavg()[0]
    if args.callgrind and args.whole_process:
        return print_whole_process(variants, results, args.max_value)
    if args.callgrind:
        return print_instructions(variants, results, args.max_value)
    clock = "CPU time sampled by perf" if args.perf else "wall time"
    print(f"1 rank, median of {args.repeat}, load average {load:.1f} on {os.cpu_count()} cores; contact phase = "
          f"search, every slave node's term, scatter ({clock}); {CASE_NOTES}\n")
    print("| case | friction | discretisation | Newton | contact evaluations | contact s | ms / evaluation "
          "| µs / (slave node · evaluation) | ms / Newton iteration | mortar / NTS per evaluation "
          "| mortar / NTS per Newton iteration | total s | process CPU s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    per_eval, per_newton = {}, {}
    for v in variants:
        rows = results[v]
        contact = statistics.median(r[0] for r in rows)
        evaluations, newton = rows[0][1], rows[0][3]
        total = statistics.median(r[2] for r in rows)
        cpu = statistics.median(r[4] for r in rows)
        per_eval[v] = contact / evaluations
        per_newton[v] = contact / newton
        base = (v[0], "Node To Segment", v[2])
        name = v[1] if v[0] == "2d" or v[1] == "Mortar" else "Node To Face"
        print(f"| {v[0]} | {v[2]:g} | {name} | {newton} | {evaluations} | {contact:.4f} | {1e3 * per_eval[v]:.3f} "
              f"| {1e6 * per_eval[v] / CASES[v[0]]['slave_nodes']:.2f} | {1e3 * per_newton[v]:.3f} "
              f"| {per_eval[v] / per_eval[base]:.2f} | {per_newton[v] / per_newton[base]:.2f} | {total:.2f} | {cpu:.2f} |")


def print_instructions(variants, results, max_value):
    print(f"callgrind: instructions inside ContactAssembly::assemble, 1 rank, load to λ = {max_value or 1:g}; "
          f"{CASE_NOTES}\n")
    print("| case | friction | discretisation | Newton | contact evaluations | instructions (10^6) "
          "| per evaluation (10^3) | per Newton iteration (10^3) | mortar / NTS per evaluation "
          "| mortar / NTS per Newton iteration |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for v in variants:
        instructions, evaluations, _, newton, _ = results[v][0]
        base = results[(v[0], "Node To Segment", v[2])][0]
        name = v[1] if v[0] == "2d" or v[1] == "Mortar" else "Node To Face"
        print(f"| {v[0]} | {v[2]:g} | {name} | {newton} | {evaluations} | {instructions / 1e6:.1f} "
              f"| {instructions / evaluations / 1e3:.1f} | {instructions / newton / 1e3:.1f} "
              f"| {instructions / evaluations / (base[0] / base[1]):.2f} "
              f"| {instructions / newton / (base[0] / base[3]):.2f} |")


def print_whole_process(variants, results, max_value):
    print(f"callgrind: every instruction of the process, and those inside ContactAssembly::assemble, 1 rank, "
          f"load to λ = {max_value or 1:g}; {CASE_NOTES}\n")
    print("| case | friction | discretisation | Newton | contact evaluations | process (10^6) | contact (10^6) "
          "| contact share | process per Newton iteration (10^6) | contact per Newton iteration (10^6) "
          "| mortar / NTS: process per Newton iteration | mortar / NTS: contact per Newton iteration "
          "| mortar / NTS: whole run |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for v in variants:
        (process, contact), evaluations, _, newton, _ = results[v][0]
        (base_process, base_contact), _, _, base_newton, _ = results[(v[0], "Node To Segment", v[2])][0]
        name = v[1] if v[0] == "2d" or v[1] == "Mortar" else "Node To Face"
        print(f"| {v[0]} | {v[2]:g} | {name} | {newton} | {evaluations} | {process / 1e6:.0f} | {contact / 1e6:.0f} "
              f"| {contact / process:.1%} | {process / newton / 1e6:.1f} | {contact / newton / 1e6:.2f} "
              f"| {process / newton / (base_process / base_newton):.2f} "
              f"| {contact / newton / (base_contact / base_newton):.2f} | {process / base_process:.2f} |")


if __name__ == "__main__":
    main()
