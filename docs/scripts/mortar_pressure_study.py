#!/usr/bin/python3
"""Mortar against node-to-segment/face: the slave pressures (issue 25, "smoother pressures (a figure in docs)").

Runs, each with Discretization = Node To Segment and = Mortar:
- the 2D non-matching patch test (inputs/verification/contact_patch_mortar.xml: 3 slave elements on 2
  master ones, and 2 on 5);
- the 3D non-matching patch test, 4 x 4 slave faces on 3 x 3 master faces (node-to-face:
  contact_patch_3d_non_matching.xml, its increments of 0.05; mortar: contact_patch_3d_mortar.xml, the same
  problem in one increment);
- the Hertz cylinder on a rigid flat (inputs/verification/hertz_cylinder.xml, 160 x 100, matching by
  construction: one slave surface on a rigid line).
Prints each slave pressure's deviation from the exact one (patch tests) or from Hertz (the cylinder) and
writes docs/figures/mortar_pressure.png (docs/verification-contact.md §9.6).

    /usr/bin/python3 docs/scripts/mortar_pressure_study.py [--contessa build/bin/contessa] [--work DIR]

About a minute on one core."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from patch_study import run_patch  # noqa: E402
from study_support import ROOT, cr, plt, run_deck, save_figure, study_arguments  # noqa: E402

VERIFICATION = os.path.join(ROOT, "inputs", "verification")
P_2D = 1.0976948408342482   # delta / (H / E* + 1 / eps_N)
P_3D = 0.999000999000999    # delta / (H / E + 1 / eps_N)
DISCRETISATIONS = ("Node To Segment", "Mortar")


def patch_2d(contessa, work, lower, upper, discretization):
    """The 2D patch with LOWER slave and UPPER master elements: slave x and pressure / exact."""
    _, done, _, res = run_patch(contessa, os.path.join(VERIFICATION, "contact_patch_mortar.xml"),
                                os.path.join(work, f"patch2d_{lower}_{upper}_{discretization.replace(' ', '')}"),
                                [f"Problem/Mesh/lower/Elements X={lower}", f"Problem/Mesh/upper/Elements X={upper}"],
                                "lower_top", False, [f"Problem/Contact/interface/Discretization={discretization}"])
    nodes, _ = cr.surface_nodes(res, "lower_top")
    return res.x[nodes], res.nodal("contact_pressure")[nodes] / P_2D


def patch_3d(contessa, work, discretization):
    """The 3D patch 4 x 4 on 3 x 3: every slave node's x and pressure / exact."""
    deck = "contact_patch_3d_mortar.xml" if discretization == "Mortar" else "contact_patch_3d_non_matching.xml"
    out = os.path.join(work, f"patch3d_{discretization.replace(' ', '')}")
    done = run_deck(contessa, os.path.join(VERIFICATION, deck), out, [])
    if done.returncode not in (0, 3):
        sys.exit(f"{deck}: contessa failed ({done.returncode}):\n{done.stderr}")
    res = cr.Results(os.path.join(out, deck.replace(".xml", ".exo")))
    nodes = res.node_set("lower_top")
    return res.x[nodes], res.nodal("contact_pressure")[nodes] / P_3D


def hertz(contessa, work, discretization):
    """The Hertz cylinder: x / a_H and pressure / p0_H of the slave nodes, with the analysis' figures."""
    out = os.path.join(work, f"hertz_{discretization.replace(' ', '')}")
    done = run_deck(contessa, os.path.join(VERIFICATION, "hertz_cylinder.xml"), out,
                    [f"Problem/Contact/flat/Discretization={discretization}"])
    if done.returncode not in (0, 3):  # 3: the deck's baselines are node-to-segment's
        sys.exit(f"hertz_cylinder.xml: contessa failed ({done.returncode}):\n{done.stderr}")
    return cr.hertz_analysis(os.path.join(out, "hertz_cylinder.exo"), os.path.join(out, "hertz_cylinder.history.csv"),
                             10.0, 1000.0, 0.3)


def main():
    args = study_arguments(__doc__, "mortar_pressure").parse_args()
    fig, axes = plt.subplots(1, 3, figsize=(13, 4.0))
    print("| case | discretisation | slave pressure / exact − 1 (min .. max) |")
    print("|---|---|---|")
    markers = {"Node To Segment": "s--", "Mortar": "o-"}
    for lower, upper in ((3, 2), (2, 5)):
        for d in DISCRETISATIONS:
            x, p = patch_2d(args.contessa, args.work, lower, upper, d)
            order = np.argsort(x)
            print(f"| 2D patch {lower} on {upper} | {d} | {p.min() - 1:+.2e} .. {p.max() - 1:+.2e} |")
            axes[0].plot(x[order], p[order], markers[d], ms=5, lw=0.8, label=f"{lower} on {upper}, {d}")
    for d in DISCRETISATIONS:
        x, p = patch_3d(args.contessa, args.work, d)
        name = d if d == "Mortar" else "Node To Face"
        print(f"| 3D patch 4 x 4 on 3 x 3 | {name} | {p.min() - 1:+.2e} .. {p.max() - 1:+.2e} |")
        axes[1].plot(x, p, markers[d][0], ms=5, mfc="none" if d == "Mortar" else None, label=name)
    for d in DISCRETISATIONS:
        r = hertz(args.contessa, args.work, d)
        print(f"| Hertz cylinder | {d} | p0 {r['p0_error']:+.1e}, profile within 0.8 a {r['profile_error']:.1e} of p0 |")
        sel = r["x"] <= 1.3 * r["a_hertz"]
        axes[2].plot(r["x"][sel] / r["a_hertz"], r["p"][sel] / r["p0_hertz"], markers[d][0], ms=4,
                     mfc="none" if d == "Mortar" else None, label=d)
    s = np.linspace(0, 1, 400)
    axes[2].plot(s, np.sqrt(1 - s * s), "k-", lw=1.0, label="Hertz")
    for ax, title, xlabel in ((axes[0], "2D patch, non-matching (exact = 1)", "x (mm)"),
                              (axes[1], "3D patch, 4 x 4 on 3 x 3, every slave node (exact = 1)", "x (mm)"),
                              (axes[2], "Hertz cylinder on a rigid flat", "$x / a_H$")):
        if ax is not axes[2]:
            ax.axhline(1.0, color="k", lw=1)
        ax.set_title(title, fontsize=9)
        ax.set_xlabel(xlabel)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    axes[0].set_ylabel("slave contact_pressure / exact")
    axes[2].set_ylabel("contact_pressure / $p_{0,H}$")
    fig.suptitle("Slave pressures: node-to-segment/face against mortar", fontsize=11)
    save_figure(fig, args.figures, "mortar_pressure.png", dpi=110)


if __name__ == "__main__":
    main()
