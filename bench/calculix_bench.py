#!/usr/bin/python3
"""Contessa against CalculiX on identical meshes: the tube in 2D and 3D, the 3D punch at a few sizes.

    /usr/bin/python3 bench/calculix_bench.py [--repeat 3] [--punch 10 20] [--punch-solvers MUMPS Belos]
                                             [--cases tube2d tube3d punch] [--work DIR] [--baseline OLD/contessa]

Every case runs Contessa and CalculiX (`ccx`, Debian's calculix-ccx 2.20, one thread, its default
SPOOLES solver) in turn, the pairs interleaved over --repeat rounds (every case once, then again), so that
a change of the machine's load hits both codes alike; each run is timed as a whole process by
/usr/bin/time -v (CPU = user + system seconds) and by the wall clock. Printed per case: Newton iterations
of each code, the median CPU and wall seconds, the time per iteration, and the ratios CalculiX / Contessa
(bench/README.md, "Contessa against CalculiX").

Cases (the meshes are the same node for node):
- tube3d: inputs/tube_bending_3d.xml, 47 fixed increments (Hex8 Enhanced, one layer of 13 x 101
  hexahedra, u_z = 0), against CalculiX C3D8I (incompatible modes) on that mesh, the plate a rigid body
  (speed_bench.calculix_input). Like for like: the same mesh and an enhanced/incompatible-mode brick.
- tube2d: inputs/tube_bending.xml, 47 fixed increments (Q4 Enhanced on the 13 x 101 section) against the
  same CalculiX run: the 2D model against CalculiX's one-layer bricks, the pairing of the figures before
  this script (not like for like: CalculiX solves the 3D layer, three unknowns per node on two layers).
- punch N: inputs/punch_3d.xml with N x N x N/2 Hex8 (linear elastic), Contessa with each solver of
  --punch-solvers, against CalculiX C3D8 on the same box, the punch a rigid body of bricks moved down
  1 mm in two increments, node-to-surface penalty contact (punch_input). Per-iteration figures compare
  best here: the two codes' contact algorithms take different numbers of iterations.

With --baseline, another Contessa build runs every tube and punch case too, in the same interleaved loop
(a row "(baseline)" per case): a before/after pair measured under the same load as the CalculiX run.
`--punch-solvers Automatic` lets Contessa choose (MUMPS up to 15 000 unknowns in 3D, then Belos + MueLu).

Tools: /usr/bin/python3 (standard library), /usr/bin/time, ccx.
"""
import argparse
import os
import re
import shutil
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from speed_bench import ROOT, calculix_input, run  # noqa: E402

FIXED = ["Piro/LOCA/Step Size/Method=Constant", "Problem/Regression/increments/Expected=47"]
# The punch deck does not converge on these coarse meshes (its first increment is cut back 3 times, then
# every increment fails at the punch's free edge, issue 22): without --punch-converge Contessa stops after
# its first attempt, 25 Newton iterations at λ = 0.5, whose cost per iteration is what is compared.
FIRST_ATTEMPT = "Piro/LOCA/Stepper/Max Steps=1"
NEWTON = re.compile(r"(\d+) Newton iterations")
CCX_ENV = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_EQUATION_SOLVER="1", CCX_NPROC_RESULTS="1",
               CCX_NPROC_STIFFNESS="1", OPENBLAS_NUM_THREADS="1")


def punch_input(n):
    """inputs/punch_3d.xml's quarter block (100 x 100 x 50 mm, n x n x n/2 C3D8, E = 200 000, ν = 0.3,
    symmetry on x = 0 and y = 0, z = 0 held) and its punch: a rigid body of 7 x 7 bricks over
    [-10, 60]² at z = 50, moved down 1 mm in two increments of 0.5. Penalty 1e8 N/mm per node as in the
    deck, i.e. 1e8 / h² N/mm³ over a node's share h² of the face."""
    nz = max(n // 2, 1)
    h = 100.0 / n
    lines = ["*HEADING", f"Block pressed by a rigid punch, {n} x {n} x {nz} (Contessa bench/calculix_bench.py)",
             "*NODE, NSET=NALL"]

    def node(i, j, k):
        return 1 + k * (n + 1) * (n + 1) + j * (n + 1) + i
    for k in range(nz + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                lines.append(f"{node(i, j, k)}, {i * h:.12g}, {j * h:.12g}, {50.0 * k / nz:.12g}")
    first = (nz + 1) * (n + 1) * (n + 1) + 1
    pnode = {}
    for k, z in enumerate((50.0, 55.0)):
        for j in range(8):
            for i in range(8):
                pnode[(i, j, k)] = first + len(pnode)
                lines.append(f"{pnode[(i, j, k)]}, {-10.0 + 10.0 * i:.12g}, {-10.0 + 10.0 * j:.12g}, {z}")
    ref = first + len(pnode)
    rot = ref + 1
    lines += [f"{ref}, 25.0, 25.0, 52.5", f"{rot}, 25.0, 25.0, 52.5", "*ELEMENT, TYPE=C3D8, ELSET=BLOCK"]
    e = 0
    top = []
    for k in range(nz):
        for j in range(n):
            for i in range(n):
                e += 1
                b = [node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k)]
                lines.append(", ".join(str(x) for x in [e] + b + [m + (n + 1) * (n + 1) for m in b]))
                if k == nz - 1:
                    top.append(e)
    lines.append("*ELEMENT, TYPE=C3D8, ELSET=PUNCH")
    punch_first = e + 1
    for j in range(7):
        for i in range(7):
            e += 1
            b = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
            lines.append(", ".join(str(x) for x in [e] + [pnode[(a, c, 0)] for a, c in b] + [pnode[(a, c, 1)] for a, c in b]))
    lines += ["*NSET, NSET=LEFT"] + [str(node(0, j, k)) for k in range(nz + 1) for j in range(n + 1)]
    lines += ["*NSET, NSET=BOTTOM"] + [str(node(i, 0, k)) for k in range(nz + 1) for i in range(n + 1)]
    lines += ["*NSET, NSET=BASE"] + [str(node(i, j, 0)) for j in range(n + 1) for i in range(n + 1)]
    lines += ["*SURFACE, NAME=SLAVE"] + [f"{x}, S2" for x in top]  # face 2: nodes 5-8-7-6, z = 50
    lines += ["*SURFACE, NAME=MASTER"] + [f"{x}, S1" for x in range(punch_first, e + 1)]  # face 1: z = 50
    lines += ["*MATERIAL, NAME=STEEL", "*ELASTIC", "200000.0, 0.3", "*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL",
              "*MATERIAL, NAME=RIGID", "*ELASTIC", "2e8, 0.3", "*SOLID SECTION, ELSET=PUNCH, MATERIAL=RIGID",
              f"*RIGID BODY, ELSET=PUNCH, REF NODE={ref}, ROT NODE={rot}",
              "*BOUNDARY", "LEFT, 1, 1, 0.0", "BOTTOM, 2, 2, 0.0", "BASE, 3, 3, 0.0",
              f"{ref}, 1, 2, 0.0", f"{rot}, 1, 3, 0.0",
              "*SURFACE INTERACTION, NAME=SI", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR", f"{1e8 / (h * h):.6g}",
              "*CONTACT PAIR, INTERACTION=SI, TYPE=NODE TO SURFACE", "SLAVE, MASTER",
              "*STEP, INC=1000", "*STATIC, DIRECT", "0.5, 1.0", "*BOUNDARY", f"{ref}, 3, 3, -1.0",
              "*NODE PRINT, NSET=BASE, TOTALS=ONLY", "RF", "*END STEP"]
    return "\n".join(lines) + "\n"


def ccx_iterations(directory, job):
    sta = os.path.join(directory, job + ".sta")
    if not os.path.exists(sta):
        return 0
    rows = [l.split() for l in open(sta).read().splitlines() if re.match(r"^\s+\d+\s+\d+\s+\d+\s+\d+", l)]
    return sum(int(r[3]) for r in rows)


def contessa_run(a, case, work):
    deck, sets = case["deck"], case["sets"]
    cmd = [case.get("binary", a.contessa), os.path.join(ROOT, "inputs", deck), "--quiet", "--output-dir", work]
    for s in sets:
        cmd += ["--set", s]
    r = run(cmd, work, a.timeout, accept=(0, 1, 3))
    m = NEWTON.search(r["stdout"])
    r["iterations"] = int(m.group(1)) if m else 0
    r["finished"] = r["status"] == 0
    return r


def ccx_run(a, job, text, work):
    os.makedirs(work, exist_ok=True)
    with open(os.path.join(work, job + ".inp"), "w") as f:
        f.write(text)
    r = run([a.ccx, "-i", job], work, a.timeout, accept=(0, 1, 201), fresh=False, env=CCX_ENV)
    r["iterations"] = ccx_iterations(work, job)
    r["finished"] = "Job finished" in r["stdout"]
    return r


def cases(a):
    out = []
    if "tube3d" in a.cases or "tube2d" in a.cases:
        out.append({"name": "tube", "ccx": ("tube", calculix_input(47)), "contessa": []})
        if "tube2d" in a.cases:
            out[-1]["contessa"].append({"label": "tube 2D (Q4 Enhanced) vs one-layer C3D8I", "deck": "tube_bending.xml",
                                        "sets": FIXED})
        if "tube3d" in a.cases:
            out[-1]["contessa"].append({"label": "tube 3D (Hex8 Enhanced) vs C3D8I, same mesh",
                                        "deck": "tube_bending_3d.xml", "sets": FIXED})
    if a.baseline and out:
        out[-1]["contessa"] += [dict(v, label=v["label"] + " (baseline)", binary=a.baseline) for v in out[-1]["contessa"]]
    if "punch" in a.cases:
        for n in a.punch:
            mesh = [f"Problem/Mesh/Elements X={n}", f"Problem/Mesh/Elements Y={n}", f"Problem/Mesh/Elements Z={max(n // 2, 1)}"]
            unknowns = 3 * (n + 1) * (n + 1) * (max(n // 2, 1) + 1)
            out.append({"name": f"punch{n}", "ccx": ("punch", punch_input(n)), "contessa": [
                {"label": f"punch {n}x{n}x{max(n // 2, 1)} ({unknowns} unknowns), {s}", "deck": "punch_3d.xml",
                 "sets": mesh + [f"Piro/Stratimikos/Linear Solver Type={s}"] + ([] if a.punch_converge else [FIRST_ATTEMPT]) +
                 (["Piro/Stratimikos/Preconditioner Type=MueLu"] if s == "Belos" else [])}
                for s in a.punch_solvers]})
            if a.baseline:
                out[-1]["contessa"] += [dict(v, label=v["label"] + " (baseline)", binary=a.baseline)
                                        for v in out[-1]["contessa"]]
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--contessa", default=os.path.join(ROOT, "build", "bin", "contessa"))
    p.add_argument("--baseline", help="another contessa build to run on every case in the same loop (before/after)")
    p.add_argument("--ccx", default=shutil.which("ccx") or "ccx")
    p.add_argument("--repeat", type=int, default=3, help="interleaved rounds (default 3)")
    p.add_argument("--cases", nargs="+", default=["tube2d", "tube3d", "punch"])
    p.add_argument("--punch", type=int, nargs="+", default=[10, 20], help="punch sizes N: N x N x N/2 elements")
    p.add_argument("--punch-converge", action="store_true",
                   help="run the punch deck to the end (cut-backs included) instead of its first attempt")
    p.add_argument("--punch-solvers", nargs="+", default=["MUMPS"], help="Contessa's linear solvers on the punch")
    p.add_argument("--work", default="/tmp/contessa-calculix-bench")
    p.add_argument("--timeout", type=float, default=1800)
    a = p.parse_args()
    if shutil.which(a.ccx) is None:
        sys.exit("calculix_bench: ccx not found (Debian: apt-get install calculix-ccx)")
    load = os.getloadavg()
    print(f"host {os.uname().nodename}, {os.cpu_count()} cores, load average {load[0]:.1f} {load[1]:.1f} {load[2]:.1f}\n")
    todo = cases(a)
    results = {}
    for rep in range(a.repeat):
        for c in todo:
            job, text = c["ccx"]
            results.setdefault((c["name"], "ccx"), []).append(ccx_run(a, job, text, os.path.join(a.work, c["name"], "ccx")))
            for k, v in enumerate(c["contessa"]):
                results.setdefault((c["name"], k), []).append(contessa_run(a, v, os.path.join(a.work, c["name"], f"contessa{k}")))
            print(f"[{rep + 1}/{a.repeat}] {c['name']} done", file=sys.stderr, flush=True)
    print("| case | Contessa it. | CalculiX it. | Contessa CPU s | CalculiX CPU s | CPU ratio | Contessa wall s | "
          "CalculiX wall s | wall ratio | ms/it. Contessa | ms/it. CalculiX | per-iteration CPU ratio |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for c in todo:
        x = results[(c["name"], "ccx")]
        xc, xw, xi = statistics.median(r["cpu"] for r in x), statistics.median(r["wall"] for r in x), x[-1]["iterations"]
        for k, v in enumerate(c["contessa"]):
            y = results[(c["name"], k)]
            yc, yw, yi = statistics.median(r["cpu"] for r in y), statistics.median(r["wall"] for r in y), y[-1]["iterations"]
            flags = ("" if y[-1]["finished"] else " (Contessa did not finish)") + ("" if x[-1]["finished"] else " (CalculiX did not finish)")
            print(f"| {v['label']}{flags} | {yi} | {xi} | {yc:.2f} | {xc:.2f} | {xc / yc:.1f} | {yw:.2f} | {xw:.2f} | "
                  f"{xw / yw:.1f} | {1000 * yc / max(yi, 1):.1f} | {1000 * xc / max(xi, 1):.1f} | "
                  f"{(xc / max(xi, 1)) / (yc / max(yi, 1)):.1f} |")


if __name__ == "__main__":
    main()
