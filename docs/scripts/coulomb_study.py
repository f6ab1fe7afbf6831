#!/usr/bin/python3
"""Coulomb block study: inputs/verification/coulomb_block.xml (nu = 0, the registered deck) and two
variants: nu = 0.3, and the registered deck with 40 increments instead of 10.

Prints, per history row, the load factor, the stick/slip counts and |F_x|/F_y of the contact force,
checks that rows where every node slips have |F_x|/F_y = mu, and writes docs/figures/coulomb_friction.png.

    /usr/bin/python3 docs/scripts/coulomb_study.py [--contessa build/bin/contessa] [--work DIR]

A few seconds."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from study_support import ROOT, cr, plt, run_deck, save_figure, study_arguments  # noqa: E402

DECK = os.path.join(ROOT, "inputs", "verification", "coulomb_block.xml")
MU, SHEAR = 0.3, 0.002  # friction coefficient, top displacement at load factor 1 (mm)
CASES = [
    ("nu = 0 (deck), 10 increments", []),
    ("nu = 0, 40 increments", ["Piro/LOCA/Step Size/Initial Step Size=0.025", "Piro/LOCA/Step Size/Max Step Size=0.025"]),
    ("nu = 0.3, 10 increments", ["Problem/Materials/elastic/Poisson's Ratio=0.3"]),
]


def main():
    args = study_arguments(__doc__, "coulomb").parse_args()

    fig, (ax, bx) = plt.subplots(1, 2, figsize=(10, 3.8))
    for k, (label, sets) in enumerate(CASES):
        out = os.path.join(args.work, f"case{k}")
        done = run_deck(args.contessa, DECK, out, sets)
        rows = cr.read_history(os.path.join(out, "coulomb_block.history.csv"))
        # exit 3 for nu = 0.3: the deck's exact normal-force checks hold for nu = 0 only.
        print(f"\n{label}: exit {done.returncode}, {len(rows) - 1} increments")
        print("| row | load factor | shear (mm) | stick | slip | F_y (N/mm) | F_x (N/mm) | abs(F_x)/F_y |")
        print("|---|---|---|---|---|---|---|---|")
        worst = 0.0
        for i, r in enumerate(rows):
            fx, fy = r["contact_force_base_x"], r["contact_force_base_y"]
            if r["stick"] == 0 and r["slip"] == r["active_contacts"] > 0:
                worst = max(worst, abs(abs(fx) / fy / MU - 1))
            if len(rows) <= 11 or i % 4 == 0:
                print(f"| {i} | {r['lambda']:.3f} | {SHEAR * r['lambda']:.5f} | {int(r['stick'])} | {int(r['slip'])} | "
                      f"{fy:.10f} | {fx:+.10f} | {abs(fx) / fy:.10f} |")
        print(f"rows where every node slips: max | |F_x|/F_y / mu - 1 | = {worst:.1e}")
        s = [SHEAR * r["lambda"] * 1e3 for r in rows]
        ax.plot(s, [abs(r["contact_force_base_x"]) / r["contact_force_base_y"] for r in rows],
                ["o-", ".-", "s--"][k], ms=[5, 3, 4][k], label=label)
        if k != 1:
            bx.plot(s, [r["slip"] for r in rows], ["o-", ".-", "s--"][k], ms=4, label=f"{label}")
    ax.axhline(MU, color="k", lw=1, ls=":", label="μ = 0.3")
    ax.set_xlabel("shear displacement of the top (µm)")
    ax.set_ylabel("|contact_force_base_x| / contact_force_base_y")
    ax.set_title("Friction force over normal force")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    bx.set_xlabel("shear displacement of the top (µm)")
    bx.set_ylabel("slipping nodes (of 9)")
    bx.set_title("History column 'slip'")
    bx.legend(fontsize=8)
    bx.grid(alpha=0.3)
    save_figure(fig, args.figures, "coulomb_friction.png")


if __name__ == "__main__":
    main()
