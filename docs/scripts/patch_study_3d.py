#!/usr/bin/python3
"""3D contact patch test study: node-to-face on matching and non-matching faces, single and two-pass.

Runs inputs/verification/contact_patch_3d_non_matching.xml (two blocks 1 x 0.5 x 1 mm of Hex8 Enhanced,
E = 1000 MPa, nu = 0.3, free lateral expansion, top pushed down delta = 0.001 mm, eps_N = 1e6) with --set
overrides for the face meshes (elements along x and z of each block), the slave side and Two Pass, and
compares the slave pressures with the uniform exact value
    p = delta / (H / E + c / eps_N),  c = 1 (single pass) or 1/2 (two-pass: both passes push),
(each two-pass slave node reports its own pass's pressure, so p/2 there), and the total contact force with
p x 1 mm^2. Prints a Markdown table (docs/verification-contact.md, section 5).

    /usr/bin/python3 docs/scripts/patch_study_3d.py [--contessa build/bin/contessa] [--work DIR]

About 10 s."""
import argparse
import os
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import patch_study  # noqa: E402  (the shared run of a patch deck)

import numpy as np  # noqa: E402

DECK = os.path.join(ROOT, "inputs", "verification", "contact_patch_3d_non_matching.xml")
E, H, EPS_N, DELTA = 1000.0, 1.0, 1e6, 0.001

# (label, lower elements (x, z), upper elements (x, z), slave side, two pass)
CASES = [
    ("matching 4 × 4 / 4 × 4, single pass", (4, 4), (4, 4), "lower_top", False),
    ("matching 4 × 4 / 4 × 4, two-pass", (4, 4), (4, 4), "lower_top", True),
    ("nested: fine slave 4 × 4 on master 2 × 2", (4, 4), (2, 2), "lower_top", False),
    ("**non-matching: fine slave 4 × 4 on master 3 × 3** (deck)", (4, 4), (3, 3), "lower_top", False),
    ("non-matching: coarse slave 3 × 3 on master 4 × 4", (4, 4), (3, 3), "upper_bottom", False),
    ("non-matching 4 × 4 / 3 × 3, two-pass", (4, 4), (3, 3), "lower_top", True),
    ("crossed: slave 4 × 3 on master 3 × 4", (4, 3), (3, 4), "lower_top", False),
    ("refined: slave 8 × 8 on master 6 × 6", (8, 8), (6, 6), "lower_top", False),
]


def run(contessa, work, tag, lower, upper, slave, two_pass):
    master, done, hist, res = patch_study.run_patch(
        contessa, DECK, os.path.join(work, tag),
        [f"Problem/Mesh/lower/Elements X={lower[0]}", f"Problem/Mesh/lower/Elements Z={lower[1]}",
         f"Problem/Mesh/upper/Elements X={upper[0]}", f"Problem/Mesh/upper/Elements Z={upper[1]}"], slave, two_pass)
    exact = hist[-1]["lambda"] * DELTA / (H / E + (0.5 if two_pass else 1.0) / EPS_N)
    per_pass = exact / 2 if two_pass else exact
    pressure = res.nodal("contact_pressure")
    dev = np.concatenate([pressure[res.node_set(name)] / per_pass - 1
                          for name in [slave] + ([master] if two_pass else [])])
    return {"status": done.returncode, "lambda": hist[-1]["lambda"], "force": abs(hist[-1]["contact_force_interface_y"]),
            "exact": exact, "dev": dev, "active": int(hist[-1]["active_contacts"]),
            "failed": sum(int(r["attempts"]) - 1 for r in hist)}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--contessa", default=os.path.join(ROOT, "build", "bin", "contessa"))
    parser.add_argument("--work", default="/tmp/contessa_patch_study_3d")
    args = parser.parse_args()
    print("delta = 0.001 mm. Exact p = 0.999000999 (single pass), 0.9995002499 (two-pass; each pass reports half).\n")
    print("| pairing (lower / upper face elements) | contact nodes | total force / exact − 1 | "
          "slave pressure / uniform − 1 (min … max) | RMS |")
    print("|---|---|---|---|---|")
    for i, (label, lower, upper, slave, two_pass) in enumerate(CASES):
        r = run(args.contessa, args.work, f"case{i}", lower, upper, slave, two_pass)
        status = "" if r["lambda"] == 1.0 else f" (stopped at λ = {r['lambda']:.4f}, exit {r['status']})"
        print(f"| {label}{status} | {r['active']} | {r['force'] / r['exact'] - 1:+.2e} | "
              f"{r['dev'].min():+.2e} … {r['dev'].max():+.2e} | {np.sqrt(np.mean(r['dev'] ** 2)):.2e} |")


if __name__ == "__main__":
    main()
