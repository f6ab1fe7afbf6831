#!/usr/bin/python3
"""Cost of the augmented Lagrangian against the penalty law (issue 21; docs/theory-contact.md section 15).

Runs build/bin/contessa on each case with `Enforcement = Penalty` and with `Enforcement = Augmented
Lagrangian` (the deck's Newton tolerances, the law's default Penetration and Elastic Slip Tolerances and Max
Augmentations), with fixed steps and with Contact Beta where the case has both, and prints two Markdown
tables, Newton iterations of every attempt (the run's last line) in each:

1. "same penalty": the penalty law at the augmented run's penalty, ratio AL / penalty, converged
   increments, the answer (the last row of the case's history column) and the augmented answer's relative
   difference to the reference (the penalty law at the case's stiffest penalty with the same stepping);
2. "same tolerances" (issue 21's words): the penalty law at the penalties that meet the augmented run's
   tolerances at every increment -- the largest penetration (history max_penetration_<interface>) at most
   Penetration Tolerance x L and, with friction, the largest elastic slip (max_elastic_slip_<interface>,
   the stick spring's whole stretch) at most Elastic Slip Tolerance x L, L the slave facet length of the
   case. Found from the penalty run of table 1 by scaling (the penetration goes as 1/eps_N, the elastic
   slip as the Slip Tolerance or 1/eps_T), 20 % beyond, and checked by the run itself (scaled again, at most
   six runs: with a prescribed overlap the force grows with eps_N and the penetration falls slower than
   1/eps_N). Only for the rows of table 1 where the penalty law misses a tolerance (elsewhere the augmented
   run makes no update and is the penalty run). Where the augmented run is "short of tolerance" (Max
   Augmentations used up) the penalty run meets tolerances the augmented one does not.

Cases (--case, several allowed; default all):
  tube           inputs/tube_bending.xml, frictionless, eps_N = 1e3, 1e5, 1e7, 1e9; fixed 1.6 mm and Contact Beta
  tube-friction  the same with Friction Coefficient = 0.2
  hertz-sphere   inputs/verification/hertz_sphere.xml (Contact Beta), eps_N = 1e7 (deck) and 1e4, Penetration
                 Tolerance 1e-4 (what keeps p0 and a as at 1e7); about 60 s of one core a run
  hertz-cylinder inputs/verification/hertz_cylinder.xml (fixed), eps_N = 1e7 (deck) and 1e4
  block, block-3d  inputs/verification/coulomb_block.xml, coulomb_block_3d.xml (fixed), eps_N = 1e6 (deck) and 1e3
  cattaneo       inputs/verification/cattaneo_mindlin.xml (fixed) with Slip Tolerance 0.005; about 100 s a run

    /usr/bin/python3 bench/augmented_cost.py [--case tube ...] [--contessa PATH] [--work DIR] [--set PATH=VALUE ...]

A run that does not reach its final load is reported as FAILED (its Newton iterations still counted).
--set adds an override to every run (e.g. "Problem/Contact/plate/Max Augmentations=20" to try a variant).
Standard library only; about 5 minutes of one core for the two tube cases (twice that with table 2), 20 for all.
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
    """`facet_length`: L of the tolerances (the slave facet length at the contact; the smallest where it
    varies). `slip_tolerance`, `tangential_penalty`: the penalty law's stick law in the case (None:
    frictionless), which the same-tolerance search stiffens. `penetration_tolerance`: the augmented law's."""

    def __init__(self, label, deck, interface, column, penalties, steppings, extra=(), reference_penalty=None,
                 facet_length=None, slip_tolerance=None, tangential_penalty=None, penetration_tolerance=1e-3):
        self.label, self.deck, self.interface, self.column = label, deck, interface, column
        self.penalties, self.steppings, self.extra = penalties, steppings, list(extra)
        self.reference_penalty = reference_penalty or penalties[-1]
        self.facet_length, self.slip_tolerance, self.tangential_penalty = facet_length, slip_tolerance, tangential_penalty
        self.penetration_tolerance = penetration_tolerance
        self.elastic_slip_tolerance = 1e-4  # the law's default

    @property
    def frictional(self):
        return self.slip_tolerance is not None


TUBE_STEPPING = [("fixed", [STEP + "Method=Constant"]), ("Contact Beta", [])]


def cases():
    tube = os.path.join(INPUTS, "tube_bending.xml")
    verification = os.path.join(INPUTS, "verification")
    return {
        # L: the tube's outer node spacing; the blocks' bottom facets (1/8, 1/4 mm); the sphere's and the
        # cylinder's smallest facet in the contact zone (their graded meshes).
        "tube": Case("tube", tube, "plate", "contact_force_plate_y", ["1e3", "1e5", "1e7", "1e9"], TUBE_STEPPING,
                     NO_CHECKS, facet_length=1.8663),
        "tube-friction": Case("tube mu=0.2", tube, "plate", "contact_force_plate_y", ["1e3", "1e5", "1e7", "1e9"],
                              TUBE_STEPPING, ["Problem/Contact/plate/Friction Coefficient=0.2"] + NO_CHECKS,
                              facet_length=1.8663, slip_tolerance=0.005, tangential_penalty=1e9),
        "hertz-sphere": Case("Hertz sphere", os.path.join(verification, "hertz_sphere.xml"), "plane",
                             "reaction_equator_z", ["1e4", "1e7"], [("Contact Beta", [])],
                             ["Problem/Contact/plane/Penetration Tolerance=1e-4"], facet_length=1.12,
                             penetration_tolerance=1e-4),
        "hertz-cylinder": Case("Hertz cylinder", os.path.join(verification, "hertz_cylinder.xml"), "flat",
                               "contact_force_flat_y", ["1e4", "1e7"], [("fixed", [])], facet_length=None),
        "block": Case("Coulomb block 2D", os.path.join(verification, "coulomb_block.xml"), "base",
                      "reaction_top_x", ["1e3", "1e6"], [("fixed", [])], facet_length=0.125, slip_tolerance=0.0,
                      tangential_penalty=1e6),
        "block-3d": Case("Coulomb block 3D", os.path.join(verification, "coulomb_block_3d.xml"), "base",
                         "reaction_top_x", ["1e3", "1e6"], [("fixed", [])], facet_length=0.25, slip_tolerance=0.0,
                         tangential_penalty=1e6),
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


def largest(result, prefix, interface):
    """The largest value of history column <prefix>_<interface> over the run's increments (None: no rows)."""
    column = f"{prefix}_{interface}"
    values = [float(r[column]) for r in result["rows"] if column in r and r[column] not in ("", "nan")]
    return max(values) if values else None


def newton_text(r):
    text = str(r["newton"]) if r["newton"] is not None else "?"
    return text if r["reached"] else text + " FAILED"


def short(x):
    return f"{x:.3g}"


class Runner:
    def __init__(self, contessa, work):
        self.contessa, self.work, self.n = contessa, work, 0

    def __call__(self, deck, sets):
        self.n += 1
        return run(self.contessa, deck, sets, os.path.join(self.work, f"r{self.n}"))


def same_penalty_table(selected, runner, extra_sets):
    """Table 1; returns {(case key, stepping, penalty): (penalty result, augmented result)}."""
    print("| case | stepping | eps_N | Newton penalty | Newton AL | AL / penalty | increments (penalty / AL) "
          "| answer penalty | answer AL | AL vs reference |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    runs = {}
    for key in selected:
        case = cases()[key]
        base = case.extra + extra_sets
        for stepping, step_sets in case.steppings:
            results = {}
            for penalty in case.penalties:
                for law in ("Penalty", "Augmented Lagrangian"):
                    sets = base + step_sets + [f"Problem/Contact/{case.interface}/Normal Penalty={penalty}",
                                               f"Problem/Contact/{case.interface}/Enforcement={law}"]
                    results[(penalty, law)] = runner(case.deck, sets)
            reference = answer(results[(case.reference_penalty, "Penalty")], case.column)
            for penalty in case.penalties:
                p, a = results[(penalty, "Penalty")], results[(penalty, "Augmented Lagrangian")]
                runs[(key, stepping, penalty)] = (p, a)
                ratio = f"{a['newton'] / p['newton']:.2f}" if a["newton"] and p["newton"] else "-"
                fp, fa = answer(p, case.column), answer(a, case.column)
                rel = f"{abs(fa - reference) / abs(reference):.1e}" if fa is not None and reference else "-"
                warned = " (short of tolerance)" if a["warned"] else ""
                print(f"| {case.label} | {stepping} | {penalty} | {newton_text(p)} | {newton_text(a)}{warned} | {ratio} | "
                      f"{p['increments']} / {a['increments']} | {fp if fp is not None else '-'} | "
                      f"{fa if fa is not None else '-'} | {rel} |", flush=True)
                for r in (p, a):
                    for line in r["stderr"]:
                        print(f"<!-- {line} -->", file=sys.stderr)
    return runs


def violations(case, result):
    """The penalty run's largest penetration and elastic slip over their bounds (ratios; 0 where absent)."""
    L = case.facet_length
    penetration = largest(result, "max_penetration", case.interface) or 0.0
    slip = (largest(result, "max_elastic_slip", case.interface) or 0.0) if case.frictional else 0.0
    return penetration / (case.penetration_tolerance * L), slip / (case.elastic_slip_tolerance * L)


def same_tolerance_row(case, stepping, step_sets, penalty, first, runner, extra_sets):
    """The penalty law stiffened until it meets the augmented law's tolerances; returns its run, the
    penalties (eps_N, stick setting) and the number of runs (the first included)."""
    eps_n = float(penalty)
    slip_tolerance, eps_t = case.slip_tolerance, case.tangential_penalty
    result, tries = first, 1
    while True:
        over_n, over_t = violations(case, result)
        if (over_n <= 1 and over_t <= 1) or tries == 6 or not result["reached"]:
            return result, eps_n, slip_tolerance, eps_t, tries
        # Penetration ~ 1/eps_N; the stick spring's stretch ~ the Slip Tolerance (or 1/eps_T without one).
        if over_n > 1:
            eps_n = float(f"{eps_n * over_n * 1.2:.2g}")
        if over_t > 1:
            if slip_tolerance:
                slip_tolerance = float(f"{slip_tolerance / (over_t * 1.2):.2g}")
            else:
                eps_t = float(f"{eps_t * over_t * 1.2:.2g}")
        sets = case.extra + extra_sets + step_sets + [f"Problem/Contact/{case.interface}/Normal Penalty={eps_n:g}",
                                                      f"Problem/Contact/{case.interface}/Enforcement=Penalty"]
        if case.frictional:
            sets += [f"Problem/Contact/{case.interface}/Slip Tolerance={slip_tolerance:g}",
                     f"Problem/Contact/{case.interface}/Tangential Penalty={eps_t:g}"]
        result = runner(case.deck, sets)
        tries += 1


def same_tolerance_table(selected, runner, extra_sets, runs):
    print("\n| case | stepping | AL: eps_N | Newton AL | penalty meeting the same tolerances: eps_N | stick "
          "| its penetration / bound | its elastic slip / bound | Newton penalty | AL / penalty |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for key in selected:
        case = cases()[key]
        if case.facet_length is None:
            continue
        for stepping, step_sets in case.steppings:
            for penalty in case.penalties:
                p, a = runs[(key, stepping, penalty)]
                over_n, over_t = violations(case, p)
                if over_n <= 1 and over_t <= 1:
                    continue  # the penalty law meets the tolerances: the augmented run is the penalty run
                q, eps_n, slip_tolerance, eps_t, tries = same_tolerance_row(case, stepping, step_sets, penalty, p,
                                                                            runner, extra_sets)
                over_n, over_t = violations(case, q)
                met = "" if over_n <= 1 and over_t <= 1 else f" (not met after {tries} runs)"
                stick = "-" if not case.frictional else (
                    f"Slip Tolerance {slip_tolerance:g}" if slip_tolerance else f"eps_T {eps_t:g}")
                ratio = f"{a['newton'] / q['newton']:.2f}" if a["newton"] and q["newton"] else "-"
                print(f"| {case.label} | {stepping} | {penalty} | {newton_text(a)} | {eps_n:g}{met} | {stick} | "
                      f"{short(over_n)} | {short(over_t) if case.frictional else '-'} | {newton_text(q)} | {ratio} |",
                      flush=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--case", action="append", choices=sorted(cases().keys()))
    parser.add_argument("--contessa", default=os.path.join(ROOT, "build", "bin", "contessa"))
    parser.add_argument("--work", default=None)
    parser.add_argument("--set", action="append", default=[], dest="sets")
    args = parser.parse_args()
    selected = args.case or ["tube", "tube-friction", "hertz-sphere", "block", "block-3d", "cattaneo"]
    work = args.work or tempfile.mkdtemp(prefix="augmented_cost_")
    runner = Runner(args.contessa, work)
    runs = same_penalty_table(selected, runner, args.sets)
    same_tolerance_table(selected, runner, args.sets, runs)
    print(f"\n(runs in {work})")


if __name__ == "__main__":
    main()
