#!/usr/bin/python3
"""Mortar against node-to-segment/face: the slave pressures (issue 25, "smoother pressures (a figure in docs)").

Runs, each with Discretization = Node To Segment and = Mortar:
- the 2D non-matching patch test (inputs/verification/contact_patch_mortar.xml: 3 slave elements on 2
  master ones, and 2 on 5);
- the 3D non-matching patch test, 4 x 4 slave faces on 3 x 3 master faces (node-to-face:
  contact_patch_3d_non_matching.xml, its increments of 0.05; mortar: contact_patch_3d_mortar.xml, the same
  problem in one increment);
- the Hertz cylinder on a rigid flat (inputs/verification/hertz_cylinder.xml, 160 x 100, matching by
  construction: one slave surface on a rigid line);
- the Hertz sphere on Tet10 (tests/regression/hertz3d/hertz_sphere_tet.xml, TRI6 slave faces on a rigid
  plane; node-to-face's nodal values on TRI6 faces are no traction, so its traction is recovered from its
  nodal forces as check_hertz_sphere.py --pressure recovered does).
Prints each slave pressure's deviation from the exact one (patch tests) or from Hertz (max and RMS over
r <= 0.8 a, and for the cylinder the largest second difference of the error there: the roughness), and
for the cylinder also mortar's weighted-gap pressures p_k = eps_N <-g~_k> / A_k, recovered from the output
p~ = D^-1 M p at the closed nodes (eq. M6', contact/MortarPressureRecovery.hpp; 0 at open ones, where
p_k = 0 too) as p_C = M_CC^-1 D_C p~_C; writes
docs/figures/mortar_pressure.png (docs/verification-contact.md §9.6).

    /usr/bin/python3 docs/scripts/mortar_pressure_study.py [--contessa build/bin/contessa] [--work DIR]

About three minutes on one core."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from patch_study import run_patch  # noqa: E402
from study_support import ROOT, cr, plt, run_deck, save_figure, study_arguments  # noqa: E402

sys.path.insert(0, os.path.join(ROOT, "tests", "regression", "hertz3d"))
import check_hertz_sphere as sphere  # noqa: E402

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


def line_mass(res, nodes):
    """The mass matrix int N_a N_b ds of the slave line through NODES (in order), reference chords."""
    xy = np.stack([res.x[nodes], res.y[nodes]], axis=1)
    length = np.linalg.norm(np.diff(xy, axis=0), axis=1)
    m = np.zeros((len(nodes), len(nodes)))
    for e, h in enumerate(length):
        m[e:e + 2, e:e + 2] += h / 6.0 * np.array([[2.0, 1.0], [1.0, 2.0]])
    return m


def profile_measures(x, p, p_hertz, a, p0):
    """Max and RMS of (p - p_H)/p0 over x <= 0.8 a, and the largest second difference of that error there
    (nodes in order along the surface): the roughness."""
    inner = x <= 0.8 * a
    e = (p - p_hertz) / p0
    return np.abs(e[inner]).max(), np.sqrt(np.mean(e[inner] ** 2)), np.abs(np.diff(e[inner], 2)).max()


def hertz_sphere_tet(contessa, work, discretization):
    """The Tet10 Hertz sphere: r / a_H and traction / p0_H of the slave nodes (node-to-face: recovered from
    its nodal forces), with a_H and p0_H."""
    out = os.path.join(work, f"sphere_tet10_{discretization.replace(' ', '')}")
    deck = os.path.join(ROOT, "tests", "regression", "hertz3d", "hertz_sphere_tet.xml")
    done = run_deck(contessa, deck, out, [f"Problem/Contact/plane/Discretization={discretization}"])
    if done.returncode not in (0, 3):  # 3: the deck's baselines are node-to-face's
        sys.exit(f"hertz_sphere_tet.xml: contessa failed ({done.returncode}):\n{done.stderr}")
    res = cr.Results(os.path.join(out, "hertz_sphere_tet.exo"))
    p = res.nodal("contact_pressure")
    if discretization != "Mortar":
        displaced = np.stack([c + res.nodal("displ_" + k) for k, c in zip("xyz", (res.x, res.y, res.z))], axis=1)
        p, _ = sphere.recovered_traction(res.ds, "surface", p, displaced)
    force = cr.read_history(os.path.join(out, "hertz_sphere_tet.history.csv"))[-1]["contact_force_plane_z"]
    a, p0 = cr.hertz_sphere(4.0 * abs(force), 50.0, 20000.0, 0.3)
    nodes = res.node_set("surface")
    r = np.hypot(res.x[nodes], res.y[nodes])
    return r / a, p[nodes] / p0


def main():
    args = study_arguments(__doc__, "mortar_pressure").parse_args()
    fig, axes = plt.subplots(2, 2, figsize=(12, 8.0))
    axes = axes.ravel()
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
    print()
    print("| Hertz | discretisation, nodal value | p0 / p0_H - 1 | max \\|p - p_H\\| / p0, r <= 0.8 a | RMS | max second difference |")
    print("|---|---|---|---|---|---|")
    for d in DISCRETISATIONS:
        r = hertz(args.contessa, args.work, d)
        a, p0 = r["a_hertz"], r["p0_hertz"]
        x, p = r["x"], r["p"]
        profiles = [(d, p)]
        if d == "Mortar":  # the weighted-gap pressures behind the reported ones: M_CC p_C = D_C p~_C on the
            res = cr.Results(os.path.join(args.work, "hertz_Mortar", "hertz_cylinder.exo"))  # closed set C
            nodes = res.node_set("outer")
            nodes = nodes[np.argsort(np.abs(res.x[nodes]))]
            m = line_mass(res, nodes)
            reported = res.nodal("contact_pressure")[nodes]
            closed = reported > 0  # an open node reports 0 and has p_k = 0
            coefficients = np.zeros_like(reported)
            coefficients[closed] = np.linalg.solve(m[np.ix_(closed, closed)], m.sum(axis=1)[closed] * reported[closed])
            profiles = [("Mortar, weighted-gap p_k", coefficients), ("Mortar (reported, eq. M6')", p)]
        for name, q in profiles:
            worst, rms, rough = profile_measures(x, q, r["p_hertz"], a, p0)
            print(f"| cylinder | {name} | {q[0] / p0 - 1:+.1e} | {worst:.1e} | {rms:.1e} | {rough:.1e} |")
            sel = x <= 1.1 * a
            style = {"Node To Segment": "s--", "Mortar, weighted-gap p_k": "^:"}.get(name, "o-")
            axes[2].plot(x[sel] / a, (q[sel] - r["p_hertz"][sel]) / p0, style, ms=4, lw=0.8, label=name)
    for d in DISCRETISATIONS:
        s, q = hertz_sphere_tet(args.contessa, args.work, d)
        inner = s <= 0.8
        e = q - np.sqrt(np.clip(1 - s * s, 0, None))
        name = "Mortar (reported, eq. M6')" if d == "Mortar" else "Node To Face (traction from M^-1 f)"
        print(f"| sphere, Tet10 | {name} | {q[np.argmin(s)] - 1:+.1e} | {np.abs(e[inner]).max():.1e} | "
              f"{np.sqrt(np.mean(e[inner] ** 2)):.1e} | - |")
        sel = s <= 1.1
        axes[3].plot(s[sel], e[sel], "s" if d != "Mortar" else "o", ms=3, mfc="none" if d == "Mortar" else None,
                     label=name)
    for ax in axes[2:]:
        ax.axhline(0.0, color="k", lw=1)
        ax.axvline(0.8, color="0.6", lw=0.8, ls=":")
    axes[2].set_ylim(-0.05, 0.05)
    axes[3].set_ylim(-0.3, 0.3)
    for ax, title, xlabel in ((axes[0], "2D patch, non-matching (exact = 1)", "x (mm)"),
                              (axes[1], "3D patch, 4 x 4 on 3 x 3, every slave node (exact = 1)", "x (mm)"),
                              (axes[2], "Hertz cylinder on a rigid flat: (p - p_H) / p0_H", "$x / a_H$"),
                              (axes[3], "Hertz sphere, Tet10: (p - p_H) / p0_H", "$r / a_H$")):
        if ax in (axes[0], axes[1]):
            ax.axhline(1.0, color="k", lw=1)
        ax.set_title(title, fontsize=9)
        ax.set_xlabel(xlabel)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    axes[0].set_ylabel("slave contact_pressure / exact")
    axes[2].set_ylabel("error / $p_{0,H}$")
    axes[3].set_ylabel("error / $p_{0,H}$")
    fig.suptitle("Slave pressures: node-to-segment/face against mortar", fontsize=11)
    save_figure(fig, args.figures, "mortar_pressure.png", dpi=110)


if __name__ == "__main__":
    main()
