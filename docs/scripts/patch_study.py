#!/usr/bin/python3
"""Contact patch test study: which mesh pairings node-to-segment (NTS) passes, single- and two-pass.

Runs inputs/verification/contact_patch.xml (two blocks 1 x 0.5 mm, E = 1000 MPa, nu = 0.3, free lateral
expansion, top pushed down delta, eps_N = 1e6) with --set overrides for the mesh pairing, the slave side
and Two Pass; compares the slave pressures with the uniform exact value
    p = delta / (H / E* + c / eps_N),  c = 1 (single pass) or 1/2 (two-pass: both passes push),
(each two-pass slave node reports its own pass's pressure, so p/2 there) and the total contact force
with p x 1 mm. Prints a Markdown table and writes docs/figures/patch_pressure.png. Also runs two
pairings at delta = 0.01 (1 %) to show the free-end defect (docs/verification-contact.md, Limits).

    /usr/bin/python3 docs/scripts/patch_study.py [--contessa build/bin/contessa] [--work DIR]

A few seconds."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from study_support import ROOT, cr, plt, run_deck, study_arguments  # noqa: E402

DECK = os.path.join(ROOT, "inputs", "verification", "contact_patch.xml")
E, NU, H, EPS_N = 1000.0, 0.3, 1.0, 1e6
E_STAR = E / (1 - NU * NU)

# (label, lower elements, upper elements, slave side, two pass)
CASES = [
    ("matching 4 / 4, single pass", 4, 4, "lower_top", False),
    ("matching 4 / 4, two-pass", 4, 4, "lower_top", True),
    ("nested: fine slave 4 on master 2 (deck)", 4, 2, "lower_top", False),
    ("nested: coarse slave 2 on master 4", 4, 2, "upper_bottom", False),
    ("nested 4 / 2, two-pass", 4, 2, "lower_top", True),
    ("non-nested: fine slave 4 on master 3", 4, 3, "lower_top", False),
    ("non-nested: coarse slave 3 on master 4", 4, 3, "upper_bottom", False),
    ("non-nested 4 / 3, two-pass", 4, 3, "lower_top", True),
]


def run_patch(contessa, deck, out, mesh_sets, slave, two_pass, extra_sets=()):
    """Runs a contact patch deck (2D or 3D: the same side-set names) with the given mesh overrides, slave
    side and Two Pass; returns the master side, the run, its history and its results."""
    master = "upper_bottom" if slave == "lower_top" else "lower_top"
    sets = list(mesh_sets) + [f"Problem/Contact/interface/Slave Side Set={slave}",
                              f"Problem/Contact/interface/Master Side Set={master}",
                              f"Problem/Contact/interface/Two Pass={'true' if two_pass else 'false'}"] + list(extra_sets)
    done = run_deck(contessa, deck, out, sets)
    stem = os.path.splitext(os.path.basename(deck))[0]
    hist = cr.read_history(os.path.join(out, stem + ".history.csv"))
    res = cr.Results(os.path.join(out, stem + ".exo"))
    return master, done, hist, res


def run(contessa, work, tag, lower, upper, slave, two_pass, delta):
    master, done, hist, res = run_patch(
        contessa, DECK, os.path.join(work, tag),
        [f"Problem/Mesh/lower/Elements X={lower}", f"Problem/Mesh/upper/Elements X={upper}"], slave, two_pass,
        [f"Problem/Dirichlet Conditions/press/Value={-delta}"])
    passes = [slave] + ([master] if two_pass else [])
    pressure = res.nodal("contact_pressure")
    data = []
    for name in passes:
        nodes, _ = cr.surface_nodes(res, name)
        data.append((name, res.x[nodes], pressure[nodes]))
    # The answer is linear in the load factor: compare a stopped run at the load it reached.
    exact = hist[-1]["lambda"] * delta / (H / E_STAR + (0.5 if two_pass else 1.0) / EPS_N)
    per_pass = exact / 2 if two_pass else exact
    stderr = done.stderr.strip().splitlines()
    return {"status": done.returncode, "lambda": hist[-1]["lambda"], "force": abs(hist[-1]["contact_force_interface_y"]),
            "exact": exact, "per_pass": per_pass, "passes": data, "active": int(hist[-1]["active_contacts"]),
            "message": stderr[-1] if stderr else ""}


def main():
    args = study_arguments(__doc__, "patch").parse_args()

    print("delta = 0.001 mm (0.1 %). Exact p = 1.0976948 (single pass), 1.0982976 (two-pass; each pass "
          "reports half).\n")
    print("| pairing (lower / upper elements) | run | active | total force / exact − 1 | "
          "slave pressure / uniform − 1 (min .. max) | pressures |")
    print("|---|---|---|---|---|---|")
    results = []
    for i, (label, lower, upper, slave, two_pass) in enumerate(CASES):
        r = run(args.contessa, args.work, f"case{i}", lower, upper, slave, two_pass, 0.001)
        results.append((label, r))
        dev = np.concatenate([p / r["per_pass"] - 1 for _, _, p in r["passes"]])
        texts = "; ".join(f"{name}: " + " ".join(f"{v:.4f}" for v in p) for name, _, p in r["passes"])
        # Exit 3 only says the deck's own checks (for its default pairing) do not apply to this pairing.
        status = "λ = 1" if r["lambda"] == 1.0 else f"stopped at λ = {r['lambda']:.4f} (exit {r['status']})"
        print(f"| {label} | {status} | {r['active']} | {r['force'] / r['exact'] - 1:+.2e} | "
              f"{dev.min():+.2e} .. {dev.max():+.2e} | {texts} |")

    print("\nAt delta = 0.01 mm (1 %):")
    for i, (label, lower, upper, slave, two_pass) in enumerate([CASES[2], CASES[5], CASES[0]]):
        r = run(args.contessa, args.work, f"large{i}", lower, upper, slave, two_pass, 0.01)
        print(f"- {label}: load factor reached {r['lambda']:.5f}"
              + (f" ({r['message']})" if r["lambda"] < 1.0 else ""))

    os.makedirs(args.figures, exist_ok=True)
    fig, axes = plt.subplots(1, 3, figsize=(11, 3.8))
    panels = [("Single pass, nested / matching", [0, 2]), ("Single pass, non-nested (4 / 3)", [5, 6]),
              ("Two-pass", [1, 4, 7])]
    markers = ["o", "s", "^", "v", "d", "x"]
    for ax, (title, idx) in zip(axes, panels):
        k = 0
        for i in idx:
            label, r = results[i]
            for name, x, p in r["passes"]:
                side = "lower" if name.startswith("lower") else "upper"
                ax.plot(x, p / r["per_pass"], markers[k % len(markers)] + "-", ms=5, lw=0.8,
                        label=f"{lower_upper(label)}: {side} side as slave")
                k += 1
        ax.axhline(1.0, color="k", lw=1)
        ax.set_title(title, fontsize=10)
        ax.set_xlabel("x (mm)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="upper center" if ax is axes[2] else "lower center")
    axes[0].set_ylabel("slave contact_pressure / exact (per pass)")
    for ax in axes[:2]:
        ax.set_ylim(0.8, 1.2)
    axes[2].set_ylim(-0.05, 2.2)
    fig.suptitle("Contact patch test: slave pressures (uniform exact answer = 1)", fontsize=11)
    fig.tight_layout()
    fig.savefig(os.path.join(args.figures, "patch_pressure.png"), dpi=120)
    print(f"\nwrote {args.figures}/patch_pressure.png")


def lower_upper(label):
    """Short legend name: the element counts (lower / upper) or slave on master."""
    for token in ("4 on master 2", "2 on master 4", "4 on master 3", "3 on master 4", "4 / 4", "4 / 2", "4 / 3"):
        if token in label:
            kind = "two-pass " if "two-pass" in label else ""
            return kind + token.replace(" on master ", " on ")
    return label


if __name__ == "__main__":
    main()
