#!/usr/bin/python3
"""Cost of the augmented Lagrangian against the penalty law (issue 21; docs/theory-contact.md section 15).

Runs build/bin/contessa on each case with `Enforcement = Penalty` and with `Enforcement = Augmented
Lagrangian` (the deck's Newton tolerances, the law's default Penetration and Elastic Slip Tolerances and Max
Augmentations), with fixed steps and with Contact Beta where the case has both, and prints one Markdown
table: Newton iterations of every attempt (the run's last line) and their ratio AL / penalty, converged
increments, the answer (the last row of the case's history column) and the augmented answer's relative
difference to the reference (the penalty law at the case's stiffest penalty with the same stepping).

Cases (--case, several allowed; default all):
  tube           inputs/tube_bending.xml, frictionless, eps_N = 1e3, 1e5, 1e7, 1e9; fixed 1.6 mm and Contact Beta
  tube-friction  the same with Friction Coefficient = 0.2
  hertz-sphere   inputs/verification/hertz_sphere.xml (Contact Beta), eps_N = 1e7 (deck) and 1e4; about 65 s a run
  hertz-cylinder inputs/verification/hertz_cylinder.xml (fixed), eps_N = 1e7 (deck) and 1e4
  block          inputs/verification/coulomb_block.xml and coulomb_block_3d.xml (fixed), eps_N = 1e6 (deck) and 1e3
  cattaneo       inputs/verification/cattaneo_mindlin.xml (fixed) with Slip Tolerance 0.005; about 100 s a run

    /usr/bin/python3 bench/augmented_cost.py [--case tube ...] [--contessa PATH] [--work DIR] [--set PATH=VALUE ...]

A run that does not reach its final load is reported as FAILED (its Newton iterations still counted).
--set adds an override to every run (e.g. "Problem/Contact/plate/Max Augmentations=20" to try a variant).
Standard library only; about 5 minutes for the two tube cases, 15 for all.
"""
import argparse
import csv
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
INPUTS = os.path.join(ROOT, "inputs")
STEP = "Piro/LOCA/Step Size/"
FINAL = re.compile(r"(\d+) increments \((\d+) failed attempts?\), (\d+) Newton iterations")
# The tube deck's increment check expects Contact Beta's count: a wide tolerance keeps it quiet for fixed
# steps (exit 3, a failed check, counts as reaching the load anyway).
NO_CHECKS = ["Problem/Regression/increments/Absolute Tolerance=1000"]


class Case:
    def __init__(self, label, deck, interface, column, penalties, steppings, extra=(), reference_penalty=None):
        self.label, self.deck, self.interface, self.column = label, deck, interface, column
        self.penalties, self.steppings, self.extra = penalties, steppings, list(extra)
        self.reference_penalty = reference_penalty or penalties[-1]


TUBE_STEPPING = [("fixed", [STEP + "Method=Constant"]), ("Contact Beta", [])]


def cases():
    tube = os.path.join(INPUTS, "tube_bending.xml")
    verification = os.path.join(INPUTS, "verification")
    return {
        "tube": Case("tube", tube, "plate", "contact_force_plate_y", ["1e3", "1e5", "1e7", "1e9"], TUBE_STEPPING,
                     NO_CHECKS),
        "tube-friction": Case("tube mu=0.2", tube, "plate", "contact_force_plate_y", ["1e3", "1e5", "1e7", "1e9"],
                              TUBE_STEPPING, ["Problem/Contact/plate/Friction Coefficient=0.2"] + NO_CHECKS),
        "hertz-sphere": Case("Hertz sphere", os.path.join(verification, "hertz_sphere.xml"), "plane",
                             "reaction_equator_z", ["1e4", "1e7"], [("Contact Beta", [])]),
        "hertz-cylinder": Case("Hertz cylinder", os.path.join(verification, "hertz_cylinder.xml"), "flat",
                               "contact_force_flat_y", ["1e4", "1e7"], [("fixed", [])]),
        "block": Case("Coulomb block 2D", os.path.join(verification, "coulomb_block.xml"), "base",
                      "reaction_top_x", ["1e3", "1e6"], [("fixed", [])]),
        "block-3d": Case("Coulomb block 3D", os.path.join(verification, "coulomb_block_3d.xml"), "base",
                         "reaction_top_x", ["1e3", "1e6"], [("fixed", [])]),
        "cattaneo": Case("Cattaneo-Mindlin", os.path.join(verification, "cattaneo_mindlin.xml"), "cylinder",
                         None, ["1e6"], [("fixed", [])], ["Problem/Contact/cylinder/Slip Tolerance=0.005"]),
    }


def run(contessa, deck, sets, out):
    cmd = [contessa, deck, "--output-dir", out]
    for s in sets:
        cmd += ["--set", s]
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    m = None
    for line in (p.stdout + p.stderr).splitlines():
        m = FINAL.search(line) or m
    newton = int(m.group(3)) if m else None
    increments = int(m.group(1)) if m else None
    name = os.path.splitext(os.path.basename(deck))[0]
    rows = []
    try:
        with open(os.path.join(out, name + ".history.csv")) as f:
            rows = list(csv.DictReader(f))
    except OSError:
        pass
    reached = p.returncode in (0, 3)
    warned = sum(1 for l in p.stderr.splitlines() if "Max Augmentations" in l)
    return {"reached": reached, "newton": newton, "increments": increments, "rows": rows, "warned": warned,
            "stderr": p.stderr.strip().splitlines()[-1:] if p.returncode not in (0, 3) else []}


def answer(result, column):
    if not result["rows"]:
        return None
    row = result["rows"][-1]
    if column is None or column not in row:
        return None
    return float(row[column])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--case", action="append", choices=sorted(cases().keys()))
    parser.add_argument("--contessa", default=os.path.join(ROOT, "build", "bin", "contessa"))
    parser.add_argument("--work", default=None)
    parser.add_argument("--set", action="append", default=[], dest="sets")
    args = parser.parse_args()
    selected = args.case or ["tube", "tube-friction", "hertz-sphere", "block", "block-3d", "cattaneo"]
    work = args.work or tempfile.mkdtemp(prefix="augmented_cost_")
    print("| case | stepping | eps_N | Newton penalty | Newton AL | AL / penalty | increments (penalty / AL) "
          "| answer penalty | answer AL | AL vs reference |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    n = 0
    for key in selected:
        case = cases()[key]
        base = case.extra + args.sets
        for stepping, step_sets in case.steppings:
            results = {}
            for penalty in case.penalties:
                for law in ("Penalty", "Augmented Lagrangian"):
                    n += 1
                    out = os.path.join(work, f"r{n}")
                    sets = base + step_sets + [f"Problem/Contact/{case.interface}/Normal Penalty={penalty}",
                                               f"Problem/Contact/{case.interface}/Enforcement={law}"]
                    results[(penalty, law)] = run(args.contessa, case.deck, sets, out)
            reference = answer(results[(case.reference_penalty, "Penalty")], case.column)
            for penalty in case.penalties:
                p, a = results[(penalty, "Penalty")], results[(penalty, "Augmented Lagrangian")]

                def newton(r):
                    text = str(r["newton"]) if r["newton"] is not None else "?"
                    return text if r["reached"] else text + " FAILED"

                ratio = f"{a['newton'] / p['newton']:.2f}" if a["newton"] and p["newton"] else "-"
                fp, fa = answer(p, case.column), answer(a, case.column)
                rel = f"{abs(fa - reference) / abs(reference):.1e}" if fa is not None and reference else "-"
                warned = " (short of tolerance)" if a["warned"] else ""
                print(f"| {case.label} | {stepping} | {penalty} | {newton(p)} | {newton(a)}{warned} | {ratio} | "
                      f"{p['increments']} / {a['increments']} | {fp if fp is not None else '-'} | "
                      f"{fa if fa is not None else '-'} | {rel} |", flush=True)
                for r in (p, a):
                    for line in r["stderr"]:
                        print(f"<!-- {line} -->", file=sys.stderr)
    print(f"\n(runs in {work})")


if __name__ == "__main__":
    main()
